/* SPDX-License-Identifier: MIT */
/*
 * rt_features: the one list of the effects and shapes a build can remove.
 * Each entry gives its NAME (RT_FEAT_<NAME> is its bit in a feature set,
 * RT_NO_<NAME> the flag that removes it, RT_HAS_<NAME> in rt_config.h the
 * 0/1 constant the code reads) and its short name for messages. The bits
 * follow the list's order; rt_scene_features, rt_build_features,
 * rt_feature_name, fixtrace --build-flags and the test suites' flag lists
 * all come from it. The shapes follow rt_kind's order.
 */
#ifndef RT_FEATURES_H
#define RT_FEATURES_H

#define RT_FEATURE_LIST(X)                                                    \
    X(SHADOWS, "shadows")                                                     \
    X(REFLECTION, "reflection")                                               \
    X(REFRACTION, "refraction")                                               \
    X(TEXTURES, "textures")                                                   \
    X(BUMP, "bump")                                                           \
    X(SPECULAR, "specular")                                                   \
    X(MULTILIGHT, "multiple lights")                                          \
    X(SUPERSAMPLING, "supersampling")                                         \
    X(SPHERE, "sphere")                                                       \
    X(QUAD, "quad")                                                           \
    X(BOX, "box")                                                             \
    X(CYLINDER, "cylinder")                                                   \
    X(CONE, "cone")                                                           \
    X(MESH, "mesh")

/* Bit positions: RT_FEAT_BIT_SHADOWS = 0, ... and RT_FEAT_COUNT. */
enum {
#define RT_FEAT_BIT_(name, text) RT_FEAT_BIT_##name,
    RT_FEATURE_LIST(RT_FEAT_BIT_)
#undef RT_FEAT_BIT_
    RT_FEAT_COUNT
};

/* Feature bits: RT_FEAT_SHADOWS = 1 << 0, RT_FEAT_REFLECTION, ... */
enum {
#define RT_FEAT_(name, text) RT_FEAT_##name = 1 << RT_FEAT_BIT_##name,
    RT_FEATURE_LIST(RT_FEAT_)
#undef RT_FEAT_
    RT_FEAT_ALL = (1 << RT_FEAT_COUNT) - 1
};

#endif /* RT_FEATURES_H */
