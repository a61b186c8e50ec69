/* SPDX-License-Identifier: MIT */
/*
 * rt_cutoff: the colour bounds the faint-ray cut-off weighs rays with
 * (rt_cutoff.h), derived once per render from the scene's coefficients.
 */
#include "rt_cutoff.h"

static fx_t channel(rt_rgb c, unsigned k)
{
    return k == 0 ? c.r : (k == 1 ? c.g : c.b);
}

/* a b / 2^16 rounded up, for a, b >= 0. */
static int64_t mul_up(int64_t a, int64_t b)
{
    return (a * b + 0xFFFF) >> 16;
}

/* Above every channel of any colour shade() can return before it adds
 * reflected and refracted light, and of the background (Q16.16). Each
 * term is rounded up. A highlight is allowed 1/8 more than ks, because
 * a cosine rounded to just past 1 grows under a high power; 16 ulps per
 * light cover the rest of shade()'s roundings. */
static int64_t local_bound(const rt_scene *s)
{
    int64_t top = 0;
    for (unsigned k = 0; k < 3; k++) {
        if (channel(s->background, k) > top)
            top = channel(s->background, k);
        for (unsigned i = 0; i < s->n_materials; i++) {
            const rt_material *m = &s->mat[i];
            int64_t base = channel(m->color, k), wl;
            if (m->texture != RT_TEX_NONE && channel(m->color2, k) > base)
                base = channel(m->color2, k);
            wl = (int64_t)FX_ONE - m->reflect - m->transparency;
            wl = wl < 0 ? 0 : wl;
            int64_t c = mul_up(mul_up(base, channel(s->ambient, k)),
                               mul_up(wl, m->ambient));
            int64_t spec = m->specular + m->specular / 8 + 1;
            for (unsigned li = 0; li < s->n_lights; li++) {
                int64_t lc = channel(s->light[li].color, k);
                c += mul_up(lc, mul_up(mul_up(wl, m->diffuse), base) + spec) +
                     16;
            }
            if (c > top)
                top = c;
        }
    }
    return top;
}
void rt_cutoff_bounds(uint32_t bound[RT_MAX_DEPTH + 1], const rt_scene *s)
{
    /* With k bounces left a ray adds at most kr + kt <= 1 times the
     * bound for k - 1 (plus two roundings) to its local colour. */
    int64_t local = local_bound(s), kmax = 0;
    for (unsigned i = 0; i < s->n_materials; i++)
        if ((int64_t)s->mat[i].reflect + s->mat[i].transparency > kmax)
            kmax = (int64_t)s->mat[i].reflect + s->mat[i].transparency;
    int64_t b = local;
    for (unsigned k = 0; k <= RT_MAX_DEPTH; k++) {
        bound[k] = b > INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)b;
        b = local + mul_up(kmax, b) + 2;
    }
}
