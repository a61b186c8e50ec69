/* SPDX-License-Identifier: MIT */
/*
 * grey4: what a 4-bit grey panel shows for an RGB888 image, as the host
 * sees it. Reads a P6 PPM (for example `fixtrace -W 128 -H 64` output),
 * maps every pixel to a level 0..15 with the library's panel converter
 * (core/frame/rt_panel.h, RT_PANEL_GREY4 with the ordered dither: what
 * the LM3S6965 firmware sends to its OLED) and writes a P6
 * PPM in which level L is the grey 17 * L, each pixel drawn SCALE x SCALE.
 *
 *   grey4 [-s SCALE] IN.ppm OUT.ppm
 *
 * With -s 4 the output is what QEMU's ssd0323 model draws on a 24- or
 * 32-bit display surface ((L << 4) | L in R, G and B, each panel pixel
 * 4x4), so it compares byte for byte with the monitor's `screendump` of a
 * 128x64 image (tests/suite_oled.sh). Built by mk/oled.mk.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ppm.h"
#include "rt_panel.h"

static int usage(void)
{
    fprintf(stderr, "usage: grey4 [-s SCALE] IN.ppm OUT.ppm\n"
                    "  maps IN to 16 grey levels (core/frame/rt_panel.h) and writes"
                    " them as greys 17 * L,\n  each pixel SCALE x SCALE "
                    "(1..16, default 1)\n");
    return 2;
}

int main(int argc, char **argv)
{
    int scale = 1, a = 1;
    if (a + 1 < argc && strcmp(argv[a], "-s") == 0) {
        char *end;
        long v = strtol(argv[a + 1], &end, 10);
        if (*end != '\0' || v < 1 || v > 16)
            return usage();
        scale = (int)v;
        a += 2;
    }
    if (argc - a != 2)
        return usage();

    char err[256];
    ppm_image in, out;
    if (ppm_read(argv[a], &in, err, sizeof err) != 0) {
        fprintf(stderr, "grey4: %s\n", err);
        return 1;
    }
    if (in.width > PPM_MAX_SIDE / scale || in.height > PPM_MAX_SIDE / scale ||
        ppm_alloc(&out, in.width * scale, in.height * scale) != 0) {
        fprintf(stderr, "grey4: %dx%d at scale %d is too large\n", in.width,
                in.height, scale);
        ppm_free(&in);
        return 1;
    }
    uint8_t *levels = malloc((size_t)in.width); /* two levels a byte */
    rt_panel panel;
    if (!levels || rt_panel_init(&panel, RT_PANEL_GREY4, RT_PANEL_ORDERED, 0,
                                 (unsigned)in.width, levels, NULL) != RT_OK) {
        fprintf(stderr, "grey4: out of memory\n");
        return 1;
    }
    size_t out_row = (size_t)out.width * 3;
    for (int y = 0; y < in.height; y++) {
        rt_panel_row(&panel, (unsigned)y,
                     in.data + (size_t)y * in.width * 3);
        uint8_t *dst = out.data + (size_t)y * scale * out_row;
        for (int x = 0; x < in.width; x++) {
            unsigned l = x % 2 ? levels[x / 2] & 15u : levels[x / 2] >> 4;
            uint8_t g = (uint8_t)(l * 17);
            memset(dst + (size_t)x * scale * 3, g, (size_t)scale * 3);
        }
        for (int k = 1; k < scale; k++)
            memcpy(dst + k * out_row, dst, out_row);
    }
    free(levels);
    ppm_free(&in);
    int rc = ppm_save(argv[a + 1], &out, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "grey4: %s\n", err);
    ppm_free(&out);
    return rc != 0;
}
