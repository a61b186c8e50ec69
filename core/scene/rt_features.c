/* SPDX-License-Identifier: MIT */
/*
 * rt_features: what a scene needs and what this build can render, as
 * RT_FEAT_* sets over the one list in rt_features.h.
 */
#include "rt_options.h"

/* A shape's bit follows from its kind: the list keeps rt_kind's order. */
typedef char kinds_in_list_order[
    RT_FEAT_QUAD == RT_FEAT_SPHERE << RT_QUAD &&
    RT_FEAT_BOX == RT_FEAT_SPHERE << RT_BOX &&
    RT_FEAT_CYLINDER == RT_FEAT_SPHERE << RT_CYLINDER &&
    RT_FEAT_CONE == RT_FEAT_SPHERE << RT_CONE &&
    RT_FEAT_MESH == RT_FEAT_SPHERE << RT_MESH ? 1 : -1];

uint32_t rt_scene_features(const rt_scene *s, uint8_t spp)
{
    uint32_t f = 0;
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_material *m = &s->mat[s->obj[i].material];
        f |= (uint32_t)RT_FEAT_SPHERE << s->obj[i].kind;
        if (m->reflect > 0)
            f |= RT_FEAT_REFLECTION;
        if (m->transparency > 0)
            f |= RT_FEAT_REFRACTION;
        if (m->texture != RT_TEX_NONE)
            f |= RT_FEAT_TEXTURES;
        if (m->bump != 0)
            f |= RT_FEAT_BUMP;
        if (m->specular > 0 && s->n_lights > 0)
            f |= RT_FEAT_SPECULAR;
    }
    if (s->shadows && s->n_lights > 0 && s->n_objects > 0)
        f |= RT_FEAT_SHADOWS;
    if (s->n_lights > 1)
        f |= RT_FEAT_MULTILIGHT;
    if (spp > 1)
        f |= RT_FEAT_SUPERSAMPLING;
    return f;
}

uint32_t rt_build_features(void)
{
    return 0
#define RT_HAS_(name, text) | (RT_HAS_##name ? (uint32_t)RT_FEAT_##name : 0u)
        RT_FEATURE_LIST(RT_HAS_)
#undef RT_HAS_
        ;
}

const char *rt_feature_name(uint32_t bit)
{
    static const char *const names[] = {
#define RT_NAME_(name, text) text,
        RT_FEATURE_LIST(RT_NAME_)
#undef RT_NAME_
    };
    for (unsigned i = 0; i < RT_FEAT_COUNT; i++)
        if (bit == (1u << i))
            return names[i];
    return "unknown";
}
