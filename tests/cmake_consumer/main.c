/* SPDX-License-Identifier: MIT */
/* The consumer of tests/cmake_consumer: renders tiny.scene as a PPM, on
 * the host to stdout, on bare metal through fixtrace's port (semihosting
 * stdout). Uses only the installed header names. */
#include <fixtrace/rt_parse.h>
#include <fixtrace/rt_render.h>

#include "tiny_scene.h"

#ifdef CONSUMER_BAREMETAL
#include "port.h"
#else
#include <stdio.h>
#endif

static rt_scene scene;
static uint8_t row[4096 * 3];

static int send_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    (void)ctx;
    (void)y;
#ifdef CONSUMER_BAREMETAL
    port_write(px, n);
    return 0;
#else
    return fwrite(px, 1, n, stdout) != n;
#endif
}

int main(void)
{
    rt_parse_error err;
    rt_options opt;
#ifdef CONSUMER_BAREMETAL
    port_init();
#endif
    if (rt_parse(scene_text, sizeof scene_text, &scene, &err) != RT_OK)
        return 2;
    rt_options_from_scene(&opt, &scene);
    if (rt_buffer_bytes(&opt) > sizeof row)
        return 3;
#ifdef CONSUMER_BAREMETAL
    port_image_begin(opt.width, opt.height, opt.format,
                     (uint32_t)(rt_row_bytes(&opt) * opt.height));
#else
    printf("P6\n%u %u\n255\n", (unsigned)opt.width, (unsigned)opt.height);
#endif
    if (rt_render_rows(&scene, &opt, 0, opt.height, row, send_row, 0, 0) !=
        RT_OK)
        return 4;
#ifdef CONSUMER_BAREMETAL
    port_image_end();
#endif
    return 0;
}
