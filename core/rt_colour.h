/* SPDX-License-Identifier: MIT */
/* rt_colour: linear RGB arithmetic of the shading loop. Internal. */
#ifndef RT_COLOUR_H
#define RT_COLOUR_H

#include "rt_scene.h"

/* Colour arithmetic needs no saturation: rt_render_rows accepts only
 * scenes whose colours and coefficients lie in the parser's ranges (lights
 * and ambient <= 16, the rest <= 1, kr + kt <= 1), so a channel stays below
 * RT_COLOUR_BOUND through every bounce, which rt_config.h keeps below a
 * sixteenth of the Q16.16 range (it limits RT_MAX_DEPTH with
 * RT_MAX_LIGHTS). Rounding is fx_mul's. */

static inline rt_rgb rt_rgb3(fx_t r, fx_t g, fx_t b)
{
    rt_rgb c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

/* a b, rounded to nearest, without saturation (see above). */
static inline fx_t rt_cmul(fx_t a, fx_t b)
{
    return (fx_t)((fx_imul64(a, b) + 0x8000) >> 16);
}

/* c += w * a (per channel). */
static inline void rt_rgb_madd(rt_rgb *c, rt_rgb a, fx_t w)
{
    c->r += rt_cmul(a.r, w);
    c->g += rt_cmul(a.g, w);
    c->b += rt_cmul(a.b, w);
}

/* a (*) b, per channel. */
static inline rt_rgb rt_rgb_mul(rt_rgb a, rt_rgb b)
{
    return rt_rgb3(rt_cmul(a.r, b.r), rt_cmul(a.g, b.g), rt_cmul(a.b, b.b));
}

#endif /* RT_COLOUR_H */
