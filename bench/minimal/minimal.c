/* SPDX-License-Identifier: MIT */
/*
 * minimal.c: a renderer written for exactly scenes/diffuse.scene, as a
 * yardstick for what the general renderer's structure costs
 * (docs/effects.md). Same camera model, sample positions, shading model
 * and Q16.16 arithmetic as the core (docs/render-model.md), the same
 * fx_*.h math, so it renders the same bytes as
 *
 *     build/posix/fixtrace -W 320 -H 240 scenes/diffuse.scene
 *
 * but everything the scene does not need is simply not written: three
 * spheres and one floor quad, one white light, ambient + Lambert, hard
 * shadows, 1 sample per pixel, no recursion, no material or object
 * tables walked by kind, no options.
 *
 * The constants are what the core derives from the scene text (rt_parse,
 * rt_object_prepare, cam_setup), copied as integers. Image size:
 * -DMIN_W=... -DMIN_H=... (mk/bench.mk passes WIDTH and HEIGHT).
 */
#include "port.h"
#include "fx_vec.h"

#ifndef MIN_W
#define MIN_W 320
#endif
#ifndef MIN_H
#define MIN_H 240
#endif

#define EPS ((fx_t)128) /* 1/512: t_min and the secondary-ray offset */
#define NONE 4u         /* "skip no object" */

/* Camera: eye (0, 5, -14) looking at (0, 1, 0), fov 50. right is exactly
 * (1, 0, 0), so a ray direction is (sx, base.y, base.z) before
 * normalising; HALF is tan(25 degrees). */
static const fx_vec3 eye = { 0, 327680, -917504 };
static const fx_vec3 cam_w = { 0, -18004, 63014 };
static const fx_vec3 cam_up = { 0, 63014, 18004 };
#define HALF ((int64_t)30560)

static const fx_vec3 light = { 655360, 2621440, -327680 }; /* colour 1 */
static const fx_t background[3] = { 19661, 22938, 32768 };

/* Object 0 is the floor quad: y = 0, -15 <= x, z <= 15, normal +y. Objects
 * 1-3 are the spheres, radius 1.5. Order matters on exact ties. */
#define FLOOR_MIN ((fx_t)-983040)
#define FLOOR_SIZE ((int64_t)1966080)
#define RADIUS ((fx_t)98304)
static const fx_vec3 centre[4] = {
    { 0, 0, 0 }, { -229376, 98304, 65536 }, { 0, 98304, -65536 },
    { 229376, 98304, 65536 }
};

/* Material colours; ambient term ka * colour (ka = 0.1, ambient light 1)
 * and kd = 0.9 as the parser's defaults give them. */
#define KA ((fx_t)6554)
#define KD ((fx_t)58982)
static const fx_t colour[4][3] = {
    { 52429, 52429, 49152 }, { 55706, 16384, 13107 },
    { 19661, 49152, 22938 }, { 16384, 26214, 55706 }
};

/* Ray against the floor plane: t in (EPS, tmax), or 0. As the core's quad
 * test with n = (0, 1, 0), dist = 0 and in-plane axes z and x. */
static fx_t hit_floor(fx_vec3 o, fx_vec3 d, fx_t tmax)
{
    int64_t den = (int64_t)d.y << 16, num = -((int64_t)o.y << 16);
    if (den < 65536 && den > -65536)
        return 0;
    if ((num < 0) != (den < 0))
        return 0;
    int64_t tt = (num * 256) / (den >> 8);
    if (tt <= EPS || tt >= tmax)
        return 0;
    int64_t qx = (int64_t)o.x + ((tt * d.x + 0x8000) >> 16) - FLOOR_MIN;
    int64_t qz = (int64_t)o.z + ((tt * d.z + 0x8000) >> 16) - FLOOR_MIN;
    if (qx < 0 || qz < 0 || qx > FLOOR_SIZE || qz > FLOOR_SIZE)
        return 0;
    return (fx_t)tt;
}

/* Ray against sphere i: the nearer root in (EPS, tmax), or 0. The core's
 * geometric test (closest approach, then the half chord), exact in 64
 * bits. */
static fx_t hit_sphere(unsigned i, fx_vec3 o, fx_vec3 d, fx_t tmax)
{
    const int64_t r = RADIUS;
    int64_t ox = (int64_t)centre[i].x - o.x;
    int64_t oy = (int64_t)centre[i].y - o.y;
    int64_t oz = (int64_t)centre[i].z - o.z;
    int64_t t = (ox * d.x + oy * d.y + oz * d.z + 0x8000) >> 16;
    int64_t hx = ox - ((t * d.x + 0x8000) >> 16);
    int64_t hy = oy - ((t * d.y + 0x8000) >> 16);
    int64_t hz = oz - ((t * d.z + 0x8000) >> 16);
    if (hx > r || hx < -r || hy > r || hy < -r || hz > r || hz < -r)
        return 0;
    uint64_t h2 = (uint64_t)(hx * hx) + (uint64_t)(hy * hy) +
                  (uint64_t)(hz * hz);
    if (h2 > (uint64_t)(r * r))
        return 0;
    int64_t thc = fx_sqrt_q32((uint64_t)(r * r) - h2);
    if (t - thc > EPS && t - thc < tmax)
        return (fx_t)(t - thc);
    if (t + thc > EPS && t + thc < tmax)
        return (fx_t)(t + thc);
    return 0;
}

/* Object i's hit distance below tmax, or 0. */
static fx_t hit(unsigned i, fx_vec3 o, fx_vec3 d, fx_t tmax)
{
    return i == 0 ? hit_floor(o, d, tmax) : hit_sphere(i, o, d, tmax);
}

/* Colour of a camera ray (unclamped), one channel per entry. */
static void trace(fx_vec3 d, fx_t c[3])
{
    fx_t best = FX_MAX, t;
    unsigned oi = NONE;
    for (unsigned i = 0; i < 4; i++) {
        if ((t = hit(i, eye, d, best)) != 0) {
            best = t;
            oi = i;
        }
    }
    if (oi == NONE) {
        c[0] = background[0], c[1] = background[1], c[2] = background[2];
        return;
    }
    fx_vec3 p = fx_v3_madd(eye, d, best);
    fx_vec3 n = oi == 0 ? fx_v3(0, FX_ONE, 0)
                        : fx_v3_normalize(fx_v3_sub(p, centre[oi]));
    int outside = oi == 0 || fx_v3_dot_q32(d, n) <= 0;
    if (fx_v3_dot_q32(d, n) > 0)
        n = fx_v3_neg(n); /* face the ray */
    const fx_t *base = colour[oi];
    for (int k = 0; k < 3; k++)
        c[k] = fx_mul(base[k], KA);

    fx_vec3 lv = fx_v3_sub(light, p);
    fx_vec3 ld = fx_v3_normalize(lv);
    fx_t ndl = fx_v3_dotn(n, ld);
    if (ndl <= 0)
        return;
    /* Hard shadow: any blocker between the surface and the light. A
     * convex object cannot shadow the outside of itself. */
    fx_vec3 p_out = fx_v3_madd(p, n, EPS);
    fx_t tmax = fx_sub(fx_v3_dotn(lv, ld), EPS); /* |lv| = lv . norm(lv) */
    unsigned skip = outside ? oi : NONE;
    for (unsigned i = 0; i < 4; i++)
        if (i != skip && hit(i, p_out, ld, tmax))
            return;
    fx_t w = fx_mul(KD, ndl); /* Lambert */
    for (int k = 0; k < 3; k++)
        c[k] = fx_add(c[k], fx_mul(base[k], w));
}

/* Screen offset k * tan(fov/2) / H as Q16.16, as the core's cam_offset. */
static fx_t offset(int64_t step, int32_t k)
{
    return fx_sat64(((int64_t)k * step + 0x8000) >> 16);
}

#define STR2(x) #x
#define STR(x) STR2(x)

static uint8_t row[3 * MIN_W];

int main(void)
{
    static const char header[] = "P6\n" STR(MIN_W) " " STR(MIN_H) "\n255\n";
    const int64_t step = (HALF * 65536) / MIN_H;
    port_init();
    port_write(header, sizeof header - 1);
    uint64_t t0 = port_cycles();
    for (int32_t y = 0; y < MIN_H; y++) {
        fx_vec3 base = fx_v3_madd(cam_w, cam_up, offset(step, MIN_H - 2 * y - 1));
        for (int32_t x = 0; x < MIN_W; x++) {
            fx_t sx = offset(step, 2 * x + 1 - MIN_W), c[3];
            trace(fx_v3_normalize(fx_v3(sx, base.y, base.z)), c);
            for (int k = 0; k < 3; k++)
                row[3 * x + k] = fx_to_u8(c[k]); /* clamps to [0, 1] */
        }
        port_write(row, sizeof row);
    }
    uint64_t t1 = port_cycles();
    port_log_value("instructions", port_cycles_to_insns(t1 - t0));
    port_log_value("pixels", (uint64_t)MIN_W * MIN_H);
    port_log_value("stack_bytes", port_stack_used());
    return PORT_EXIT_OK;
}
