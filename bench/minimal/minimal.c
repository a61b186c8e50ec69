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
 * rt_object_prepare), copied as integers; the camera frame is
 * rt_cam_setup's, once per frame. Image size: -DMIN_W=... -DMIN_H=...
 * (mk/bench.mk passes WIDTH and HEIGHT).
 */
#include "port.h"
#include "rt_camera.h"
#include "rt_ray.h" /* RT_PAR_DOT */

#ifndef MIN_W
#define MIN_W 320
#endif
#ifndef MIN_H
#define MIN_H 240
#endif

#define EPS ((fx_t)128) /* 1/512: t_min and the secondary-ray offset */
#define NONE 4u         /* "skip no object" */
#define UHALF ((int64_t)1 << (FX_UBITS - 1))

/* Camera: eye (0, 5, -14) looking at (0, 1, 0), up (0, 1, 0), fov 50;
 * rt_cam_setup derives the frame (right is exactly (1, 0, 0)). */
static const fx_vec3 eye = { 0, 327680, -917504 };

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
/* 1 / RADIUS for the normals, as rt_object_prepare derives it. */
static uint32_t rinv;
#define RADIUS_BITS 17 /* bit length of RADIUS */

/* Material colours; ambient term ka * colour (ka = 0.1, ambient light 1)
 * and kd = 0.9 as the parser's defaults give them. */
#define KA ((fx_t)6554)
#define KD ((fx_t)58982)
static const fx_t colour[4][3] = {
    { 52429, 52429, 49152 }, { 55706, 16384, 13107 },
    { 19661, 49152, 22938 }, { 16384, 26214, 55706 }
};

/* Ray against the floor plane: t in (EPS, tmax), or 0. As the core's quad
 * test with n = (0, 1, 0), dist = 0 and in-plane axes z and x: t = -o.y /
 * d.y, rounded, by a division by den's top 32 bits. */
static fx_t hit_floor(fx_vec3 o, fx_dir3 d, fx_t tmax)
{
    int64_t den = fx_imul64(d.y, FX_UONE), num = -fx_imul64(o.y, FX_UONE);
    if (den < RT_PAR_DOT && den > -RT_PAR_DOT)
        return 0;
    if ((num < 0) != (den < 0))
        return 0;
    uint64_t un = (uint64_t)(num < 0 ? -num : num);
    uint64_t uden = (uint64_t)(den < 0 ? -den : den);
    int sd = 32 - fx_clz64(uden);
    if (sd < 0)
        sd = 0;
    const uint32_t ud = (uint32_t)(uden >> sd);
    const int lsh = FX_UBITS - sd;
    if ((un >> (32 - lsh)) >= ud)
        return 0;
    const uint64_t n2 = (un << lsh) + (ud >> 1);
    if ((n2 >> 32) >= ud)
        return 0;
    int64_t tt = fx_udiv64_32(n2, ud);
    if (tt <= EPS || tt >= tmax)
        return 0;
    int64_t qx = (int64_t)o.x + ((tt * d.x + UHALF) >> FX_UBITS) - FLOOR_MIN;
    int64_t qz = (int64_t)o.z + ((tt * d.z + UHALF) >> FX_UBITS) - FLOOR_MIN;
    if (qx < 0 || qz < 0 || qx > FLOOR_SIZE || qz > FLOOR_SIZE)
        return 0;
    return (fx_t)tt;
}

/* Ray against sphere i: the nearer root in (EPS, tmax), or 0. The core's
 * geometric test (closest approach corrected for |d|, then the half
 * chord, formed again with 12 more bits near the silhouette). */
static fx_t hit_sphere(unsigned i, fx_vec3 o, fx_dir3 d, int32_t e,
                       fx_t tmax)
{
    const int32_t r = RADIUS;
    int32_t ox = centre[i].x - o.x, oy = centre[i].y - o.y;
    int32_t oz = centre[i].z - o.z;
    int64_t q = fx_imul64(ox, d.x) + fx_imul64(oy, d.y) + fx_imul64(oz, d.z);
    int32_t t = (int32_t)((q + UHALF) >> FX_UBITS);
    t -= (int32_t)((fx_imul64(t, e) + ((int64_t)1 << 31)) >> 32);
    if ((int64_t)t + r <= EPS || (int64_t)t - r >= tmax)
        return 0;
    int32_t hx = ox - (int32_t)((fx_imul64(t, d.x) + UHALF) >> FX_UBITS);
    int32_t hy = oy - (int32_t)((fx_imul64(t, d.y) + UHALF) >> FX_UBITS);
    int32_t hz = oz - (int32_t)((fx_imul64(t, d.z) + UHALF) >> FX_UBITS);
    if (hx > r + 1 || hx < -r - 1 || hy > r + 1 || hy < -r - 1 ||
        hz > r + 1 || hz < -r - 1)
        return 0;
    uint64_t h2 = (uint64_t)fx_imul64(hx, hx) + (uint64_t)fx_imul64(hy, hy) +
                  (uint64_t)fx_imul64(hz, hz);
    uint64_t r2 = (uint64_t)fx_imul64(r, r), disc;
    if ((h2 > r2 ? h2 - r2 : r2 - h2) <= 2 * (uint64_t)r + 8) {
        /* bsphere_fine: e = 12 bits more (clz(r) - 2 = 12 <= 14). */
        const int eb = 12, sh = FX_UBITS - eb;
        const int64_t half = (int64_t)1 << (sh - 1);
        const int64_t fx = (int64_t)ox * 4096 - ((fx_imul64(t, d.x) + half) >> sh);
        const int64_t fy = (int64_t)oy * 4096 - ((fx_imul64(t, d.y) + half) >> sh);
        const int64_t fz = (int64_t)oz * 4096 - ((fx_imul64(t, d.z) + half) >> sh);
        const uint64_t f2 = (uint64_t)(fx * fx) + (uint64_t)(fy * fy) +
                            (uint64_t)(fz * fz);
        const uint64_t re = (uint64_t)r << eb, rr = re * re;
        if (f2 > rr)
            return 0;
        disc = (rr - f2) >> (2 * eb);
    } else {
        if (h2 > r2)
            return 0;
        disc = r2 - h2;
    }
    int64_t thc = fx_sqrt_q32(disc);
    thc -= (thc * e + ((int64_t)1 << 32)) >> 33;
    if (t - thc > EPS && t - thc < tmax)
        return (fx_t)(t - thc);
    if (t + thc > EPS && t + thc < tmax)
        return (fx_t)(t + thc);
    return 0;
}

/* Object i's hit distance below tmax, or 0. */
static fx_t hit(unsigned i, fx_vec3 o, fx_dir3 d, int32_t e, fx_t tmax)
{
    return i == 0 ? hit_floor(o, d, tmax) : hit_sphere(i, o, d, e, tmax);
}

/* Colour of a camera ray (unclamped), one channel per entry. */
static void trace(fx_dir3 d, fx_t c[3])
{
    fx_t best = FX_MAX, t;
    unsigned oi = NONE;
    const int32_t e = fx_d3_unit_err(d);
    for (unsigned i = 0; i < 4; i++) {
        if ((t = hit(i, eye, d, e, best)) != 0) {
            best = t;
            oi = i;
        }
    }
    if (oi == NONE) {
        c[0] = background[0], c[1] = background[1], c[2] = background[2];
        return;
    }
    fx_vec3 p = fx_v3_madd_d(eye, d, best);
    fx_dir3 n = fx_d3(0, FX_UONE, 0);
    if (oi != 0) { /* (p - c) / r and one Newton step, as rt_normal */
        const int sh = RADIUS_BITS + 1;
        const int64_t half = (int64_t)1 << (sh - 1);
        const fx_vec3 v = fx_v3_sub(p, centre[oi]);
        n = fx_d3_renorm(
            fx_d3((int32_t)((fx_iumul64(v.x, rinv) + half) >> sh),
                  (int32_t)((fx_iumul64(v.y, rinv) + half) >> sh),
                  (int32_t)((fx_iumul64(v.z, rinv) + half) >> sh)));
    }
    const int64_t dn = fx_d3_dot_raw(d, n);
    int outside = oi == 0 || dn <= 0;
    if (dn > 0)
        n = fx_d3_neg(n); /* face the ray */
    const fx_t *base = colour[oi];
    for (int k = 0; k < 3; k++)
        c[k] = fx_mul(base[k], KA);

    /* The light is seen from p_out, where the shadow ray starts. */
    fx_vec3 p_out = fx_v3_madd_d(p, n, EPS);
    fx_vec3 lv = fx_v3_sub(light, p_out);
    fx_dir3 ld = fx_d3_normalize(lv);
    fx_t ndl = fx_d3_dot(n, ld);
    if (ndl <= 0)
        return;
    /* Hard shadow: any blocker between the surface and the light. A
     * convex object cannot shadow the outside of itself. */
    fx_t tmax = fx_sub(fx_pd_dot(lv, ld), EPS); /* |lv| = lv . norm(lv) */
    const int32_t el = fx_d3_unit_err(ld);
    unsigned skip = outside ? oi : NONE;
    for (unsigned i = 0; i < 4; i++)
        if (i != skip && hit(i, p_out, ld, el, tmax))
            return;
    fx_t w = fx_mul(KD, ndl); /* Lambert */
    for (int k = 0; k < 3; k++)
        c[k] = fx_add(c[k], fx_mul(base[k], w));
}

static uint8_t row[3 * MIN_W];

#define STR2(x) #x
#define STR(x) STR2(x)

int main(void)
{
    static const char header[] = "P6\n" STR(MIN_W) " " STR(MIN_H) "\n255\n";
    static rt_scene s; /* only its camera: rt_cam_setup's frame */
    s.cam.eye = eye;
    s.cam.look = fx_v3(0, 65536, 0);
    s.cam.up = fx_v3(0, 65536, 0);
    s.cam.fov = FX_INT(50);
    rt_cam_frame cf;
    rt_cam_setup(&cf, &s, MIN_W, MIN_H, 1);
    rinv = fx_udiv64_32(((uint64_t)1 << (31 + RADIUS_BITS)) - 1u,
                        (uint32_t)RADIUS);
    port_init();
    port_write(header, sizeof header - 1);
    uint64_t t0 = port_cycles();
    for (int32_t y = 0; y < MIN_H; y++) {
        const rt_cam_ray base =
            rt_cam_row_base(&cf, rt_cam_soff(&cf, MIN_H - 2 * y - 1));
        for (int32_t x = 0; x < MIN_W; x++) {
            fx_t c[3];
            trace(rt_cam_dir(&cf, &base, rt_cam_soff(&cf, 2 * x + 1 - MIN_W)),
                  c);
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
