/* SPDX-License-Identifier: MIT */
/*
 * rt_sealed: closed glass that nothing else reaches into (an
 * optimisation; RT_SEALED in rt_config.h). A ray inside such an object
 * can hit only it, and when every light lies outside it and shadows are
 * on, no light reaches its inside. The stubs at the end answer "no" to
 * both, and the tracer then tests every object and every light.
 */
#ifndef RT_SEALED_H
#define RT_SEALED_H

#include "rt_scene.h"

#if RT_SEALED

/* Bit sets over objects. alone: closed convex (a sphere, a box, a capped
 * cylinder or cone) whose bounding sphere no other object's meets, so a
 * ray inside it can hit only it. dark: closed convex with every light
 * outside its bounding sphere and shadows on, so no light reaches its
 * inside. Only transparent objects are listed: inside rays come only
 * from refraction. */
typedef struct {
    uint32_t alone[(RT_MAX_OBJECTS + 31) / 32];
    uint32_t dark[(RT_MAX_OBJECTS + 31) / 32];
} rt_sealed;

/* Fills *sl for scene s; shadows: the render casts shadows. */
void rt_sealed_find(rt_sealed *sl, const rt_scene *s, int shadows);

/* 1 if a ray inside object i can hit only i. */
static inline int rt_sealed_alone(const rt_sealed *sl, unsigned i)
{
    return (int)((sl->alone[i / 32] >> (i % 32)) & 1u);
}

/* 1 if no light reaches the inside of object i. */
static inline int rt_sealed_dark(const rt_sealed *sl, unsigned i)
{
    return (int)((sl->dark[i / 32] >> (i % 32)) & 1u);
}

#else /* the stubs */

typedef struct {
    uint8_t none;
} rt_sealed;

static inline void rt_sealed_find(rt_sealed *sl, const rt_scene *s,
                                  int shadows)
{
    (void)sl, (void)s, (void)shadows;
}

static inline int rt_sealed_alone(const rt_sealed *sl, unsigned i)
{
    (void)sl, (void)i;
    return 0;
}

static inline int rt_sealed_dark(const rt_sealed *sl, unsigned i)
{
    (void)sl, (void)i;
    return 0;
}

#endif
#endif /* RT_SEALED_H */
