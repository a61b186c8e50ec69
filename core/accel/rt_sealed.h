/* SPDX-License-Identifier: MIT */
/*
 * rt_sealed: closed glass whose inside reaches at most one other object
 * (an optimisation; RT_SEALED in rt_config.h). A ray inside such an
 * object can hit only it and that one, decided from the shapes' own
 * geometry (rt_sealed.c); and when every light lies outside it and
 * shadows are on, no light reaches its inside. The stubs at the end
 * answer "no" to both, and the tracer then tests every object and every
 * light.
 */
#ifndef RT_SEALED_H
#define RT_SEALED_H

#include "rt_scene.h"

/* An object index meaning "not sealed" (rt_ray.h's RT_NO_OBJECT). */
#define RT_SEALED_NONE 0xFFFFu

#if RT_SEALED

/* with[i]: for closed convex glass (a sphere, a box, a capped cylinder
 * or cone) the one object other than i whose shape comes near i's
 * inside, or i itself when none does; RT_SEALED_NONE when two or more
 * do, or i is not closed glass. Only transparent objects are listed:
 * inside rays come only from refraction. dark: closed convex with every
 * light outside its bounding sphere and shadows on, so no light reaches
 * its inside. */
typedef struct {
    uint16_t with[RT_MAX_OBJECTS];
    uint32_t dark[(RT_MAX_OBJECTS + 31) / 32];
} rt_sealed;

/* Fills *sl for scene s; shadows: the render casts shadows. */
void rt_sealed_find(rt_sealed *sl, const rt_scene *s, int shadows);

/* What a ray inside object i can hit besides i: rt_sealed.with[i]. A
 * ray that starts inside i and hits i before it hits that object hits
 * nothing else first: the nearest hit among the two is the nearest of
 * all, exact ties included, when it is i's. */
static inline unsigned rt_sealed_with(const rt_sealed *sl, unsigned i)
{
    return sl->with[i];
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

static inline unsigned rt_sealed_with(const rt_sealed *sl, unsigned i)
{
    (void)sl, (void)i;
    return RT_SEALED_NONE;
}

static inline int rt_sealed_dark(const rt_sealed *sl, unsigned i)
{
    (void)sl, (void)i;
    return 0;
}

#endif
#endif /* RT_SEALED_H */
