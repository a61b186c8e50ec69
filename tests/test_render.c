/* SPDX-License-Identifier: MIT */
/*
 * End-to-end renders of every scene in scenes/ at a small size:
 * - the bytes match a stored checksum (tests/render_checksums.txt), which
 *   guards bit-exactness across compilers and devices;
 * - the image shows more than background;
 * - a render split into row bands gives the same bytes;
 * - the RGB565 formats agree with the RGB888 render.
 * UPDATE_CHECKSUMS=1 rewrites the stored file (make update-checksums).
 */
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "harness.h"
#include "mesh_obj.h"
#include "rt_parse.h"
#include "rt_render.h"

#define TW 64
#define TH 48
#define CHECKSUMS "tests/render_checksums.txt"

static uint64_t fnv1a(const uint8_t *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

static rt_status render(const rt_scene *s, rt_options *o, uint8_t *img,
                        int band)
{
    uint8_t row[TW * 3];
    th_sink k = { img, rt_row_bytes(o) };
    rt_status st = RT_OK;
    for (int y = 0; y < o->height && st == RT_OK; y += band) {
        int y1 = y + band > o->height ? o->height : y + band;
        st = rt_render_rows(s, o, y, y1, row, th_to_image, &k, NULL);
    }
    return st;
}

static const char *stored_sum(const char *stored, const char *name)
{
    static char hex[17];
    size_t n = strlen(name);
    for (const char *p = stored; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : p) {
        if (strncmp(p, name, n) == 0 && p[n] == ' ') {
            memcpy(hex, p + n + 1, 16);
            hex[16] = 0;
            return hex;
        }
    }
    return NULL;
}

int main(void)
{
    static rt_scene scene;
    static mesh_obj_ctx meshes;
    static uint8_t img[TW * TH * 3], img2[TW * TH * 3], img565[TW * TH * 2];
    char *names[256];
    int count;
    int update = getenv("UPDATE_CHECKSUMS") != NULL;
    size_t slen = 0;
    char err[256];
    char *stored = update ? NULL : cli_read_file(CHECKSUMS, &slen, err,
                                                 sizeof err);
    FILE *out = update ? fopen(CHECKSUMS, "w") : NULL;

    count = th_scene_names(names, 256);
    CHECK(count >= 2);

    for (int i = 0; i < count; i++) {
        char path[512];
        size_t len;
        rt_parse_error pe;
        snprintf(path, sizeof path, "scenes/%s", names[i]);
        char *text = cli_read_file(path, &len, err, sizeof err);
        if (!CHECK(text != NULL))
            continue;
        /* Meshes of the scene before are released; this one's are kept
         * until the next (or the end). */
        mesh_obj_free(&meshes);
        mesh_obj_init(&meshes, path, stdout, 1);
        rt_status st = mesh_obj_parse_scene(text, len, path, &scene, &pe,
                                            &meshes);
        free(text);
        if (!CHECK(st == RT_OK)) {
            printf("    %s:%u:%u: %s\n", path, (unsigned)pe.line,
                   (unsigned)pe.col, pe.msg);
            continue;
        }
        rt_options o;
        rt_options_from_scene(&o, &scene);
        o.width = TW;
        o.height = TH;
        CHECK_EQ(render(&scene, &o, img, TH), RT_OK);

        /* More than background: at least 10% of pixels differ from it. */
        int fg = 0;
        uint8_t bg[3] = { fx_to_u8(scene.background.r),
                          fx_to_u8(scene.background.g),
                          fx_to_u8(scene.background.b) };
        for (int p = 0; p < TW * TH; p++)
            fg += memcmp(img + 3 * p, bg, 3) != 0;
        if (!CHECK(fg * 10 >= TW * TH))
            printf("    %s: only %d of %d pixels differ from the "
                   "background\n", names[i], fg, TW * TH);

        /* Bands of 7 rows give the same bytes as one band. */
        CHECK_EQ(render(&scene, &o, img2, 7), RT_OK);
        CHECK(memcmp(img, img2, sizeof img) == 0);

        /* RGB565: each pixel is the 888 pixel's top bits. */
        o.format = RT_RGB565_BE;
        CHECK_EQ(render(&scene, &o, img565, TH), RT_OK);
        int same = 1;
        for (int p = 0; p < TW * TH; p++) {
            unsigned v = (unsigned)img565[2 * p] << 8 | img565[2 * p + 1];
            unsigned want = (unsigned)(img[3 * p] >> 3) << 11 |
                            (unsigned)(img[3 * p + 1] >> 2) << 5 |
                            (unsigned)(img[3 * p + 2] >> 3);
            same &= v == want;
        }
        CHECK(same);

        char hex[17];
        snprintf(hex, sizeof hex, "%016llx",
                 (unsigned long long)fnv1a(img, sizeof img));
        if (update) {
            fprintf(out, "%s %s\n", names[i], hex);
        } else {
            const char *want = stored_sum(stored, names[i]);
            if (!CHECK(want && strcmp(want, hex) == 0))
                printf("    %s: checksum %s, stored %s (if the change is "
                       "intended: make update-checksums)\n", names[i], hex,
                       want ? want : "none");
        }
        printf("%s %dx%d %s\n", names[i], TW, TH, hex);
        free(names[i]);
    }
    if (out)
        fclose(out);
    free(stored);
    mesh_obj_free(&meshes);
    return th_summary();
}
