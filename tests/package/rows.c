/* SPDX-License-Identifier: MIT */
/* The program of tests/suite_package.sh: built with exactly the sources,
 * include folders and flags a packaging manifest declares, it parses the
 * scene in scene_text.h (generated) and sends its first ROWS rows, raw
 * RGB888, through the bare-metal port (semihosting stdout under QEMU).
 * Includes the core by its bare names, as each package provides them. */
#include "port.h"
#include "rt_parse.h"
#include "rt_render.h"
#include "scene_text.h"

#ifndef ROWS
#define ROWS 8
#endif

static rt_scene scene;
static uint8_t row[256 * 3];

static int send_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    (void)ctx;
    (void)y;
    port_write(px, n);
    return 0;
}

int main(void)
{
    rt_parse_error err;
    rt_options opt;
    port_init();
    if (rt_parse(scene_text, sizeof scene_text, &scene, &err) != RT_OK) {
        port_log("rows: the scene does not parse\n");
        return 2;
    }
    rt_options_from_scene(&opt, &scene);
    if (rt_buffer_bytes(&opt) > sizeof row || opt.height < ROWS)
        return 3;
    if (rt_render_rows(&scene, &opt, 0, ROWS, row, send_row, 0, 0) != RT_OK)
        return 4;
    return 0;
}
