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

/* a w rounded as rt_cmul (and as fx_mul, which cannot saturate here),
 * for any a and 0 <= w <= FX_ONE, in two 32-bit products: a = ah 2^16 +
 * al with 0 <= al < 2^16, so a w + 2^15 = ah w 2^16 + (al w + 2^15),
 * where ah w lies in [-2^31, 2^31 - 2^16] and al w + 2^15 below 2^32, and
 * the sum below 2^31. Where the core has no 64-bit multiply
 * (FX_SOFT_MUL64, the M0) that is a few instructions instead of a call.
 * The rounding is floor((floor(x / 2^15) + 1) / 2) = floor((x + 2^15) /
 * 2^16): two shifts and an add of 1, where the Thumb-1 M0 built 2^15 in
 * a register at every use (#17: seed 7,005.1 -> 6,985.3 instructions a
 * pixel on the M0, 64 bytes less flash). */
static inline fx_t rt_wmul_fast(fx_t a, fx_t w)
{
    const int32_t ah = a >> 16;
    const uint32_t al = (uint32_t)a & 0xFFFFu;
    return ah * w + (fx_t)((((al * (uint32_t)w) >> 15) + 1u) >> 1);
}

/* 1 if rt_wmul_fast pays and applies to the weight w. */
static inline int rt_wmul_ok(fx_t w)
{
    return FX_SOFT_MUL64 && (uint32_t)w <= (uint32_t)FX_ONE;
}

/* rt_cmul(a, w) for a weight w (a coefficient, a cosine: usually in
 * [0, 1], see rt_wmul_fast). */
static inline fx_t rt_wmul(fx_t a, fx_t w)
{
    return rt_wmul_ok(w) ? rt_wmul_fast(a, w) : rt_cmul(a, w);
}

/* c += w * a (per channel). */
static inline void rt_rgb_madd(rt_rgb *c, rt_rgb a, fx_t w)
{
    if (rt_wmul_ok(w)) {
        c->r += rt_wmul_fast(a.r, w);
        c->g += rt_wmul_fast(a.g, w);
        c->b += rt_wmul_fast(a.b, w);
        return;
    }
    c->r += rt_cmul(a.r, w);
    c->g += rt_cmul(a.g, w);
    c->b += rt_cmul(a.b, w);
}

/* a (*) b, per channel: b's channels (a light's, up to 16) weigh a's
 * (a material's, at most 1). */
static inline rt_rgb rt_rgb_mul(rt_rgb a, rt_rgb b)
{
    return rt_rgb3(rt_wmul(b.r, a.r), rt_wmul(b.g, a.g), rt_wmul(b.b, a.b));
}

#endif /* RT_COLOUR_H */
