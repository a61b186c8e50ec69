/* SPDX-License-Identifier: MIT */
/* Renders a scene to a 128x64 SSD1306 OLED (1 bit a pixel), page by
 * page, with error-diffusion dithering; no frame buffer. */
#include <fixtrace/rt_panel.h>
#include <fixtrace/rt_parse.h>
#include <fixtrace/rt_render.h>

#define OLED_W 128
#define OLED_H 64

/* Your display driver: sends one page (8 rows, a byte a column) to page
 * `page` of the panel, in page addressing mode. */
void oled_page(unsigned page, const uint8_t *bytes, size_t n);

/* What your main() calls. */
int render_to_oled(rt_parse_error *err);

static const char scene_text[] =
    "camera eye 0 3 -7 look 0 1 0 fov 45\n"
    "background 0.3 0.4 0.6\n"
    "light 5 10 -6\n"
    "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.25 1\n"
    "material ball color 0.9 0.3 0.2 specular 0.6 shininess 40\n"
    "quad corner -8 0 -8 edge1 0 0 16 edge2 16 0 0 material floor\n"
    "sphere center 0 1 0 radius 1 material ball\n";

static rt_scene scene;
static uint8_t row[OLED_W * 3];   /* one RGB888 row (rt_buffer_bytes()) */
static uint8_t page[OLED_W];      /* rt_panel_out_bytes(): 8 rows of bits */
static int16_t err_row[OLED_W + 2]; /* rt_panel_err_count(): next row's */
static rt_panel panel;

/* Converts each finished row; sends a page once its 8 rows are in. */
static int to_panel(void *ctx, int y, const uint8_t *rgb, size_t n)
{
    (void)ctx;
    (void)n;
    size_t ready = rt_panel_row(&panel, (unsigned)y, rgb);
    if (ready)
        oled_page((unsigned)y / 8, page, ready);
    return 0;
}

/* Returns 0 on success, else an rt_status. */
int render_to_oled(rt_parse_error *err)
{
    rt_options opt;
    rt_status st = rt_parse(scene_text, sizeof scene_text - 1, &scene, err);
    if (st != RT_OK)
        return st;
    rt_options_from_scene(&opt, &scene);
    opt.width = OLED_W;
    opt.height = OLED_H;                  /* RGB888 rows: rt_panel's input */
    if (rt_buffer_bytes(&opt) > sizeof row)
        return RT_ERR_ARG;
    st = rt_panel_init(&panel, RT_PANEL_MONO_PAGE, RT_PANEL_DIFFUSION, 0,
                       OLED_W, page, err_row);
    if (st != RT_OK)
        return st;
    st = rt_render_rows(&scene, &opt, 0, OLED_H, row, to_panel, NULL, NULL);
    if (st == RT_OK && rt_panel_flush(&panel)) /* a height not 8 k */
        oled_page(OLED_H / 8, page, OLED_W);
    return st;
}
