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
 * RT_MAX_LIGHTS). Every product is fx_wmul's: fx_mul's rounding, which
 * cannot saturate here. */

static inline rt_rgb rt_rgb3(fx_t r, fx_t g, fx_t b)
{
    rt_rgb c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

/* c += w * a (per channel), for a weight w (a coefficient, a cosine:
 * usually in [0, 1]). */
static inline void rt_rgb_madd(rt_rgb *c, rt_rgb a, fx_t w)
{
    c->r += fx_wmul(a.r, w);
    c->g += fx_wmul(a.g, w);
    c->b += fx_wmul(a.b, w);
}

/* a (*) b, per channel: b's channels (a light's, up to 16) weigh a's
 * (a material's, at most 1). */
static inline rt_rgb rt_rgb_mul(rt_rgb a, rt_rgb b)
{
    return rt_rgb3(fx_wmul(b.r, a.r), fx_wmul(b.g, a.g), fx_wmul(b.b, a.b));
}

#endif /* RT_COLOUR_H */
