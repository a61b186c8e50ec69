/* SPDX-License-Identifier: MIT */
/* Renders a scene to a 160x128 SPI display, one RGB565 row at a time. */
#include <fixtrace/rt_parse.h>
#include <fixtrace/rt_render.h>

#define LCD_W 160
#define LCD_H 128

/* Your display driver: spi_write() sends bytes with D/C high (pixel data),
 * lcd_command() sends one command byte with D/C low. */
void spi_write(const uint8_t *data, size_t n);
void lcd_command(uint8_t cmd);

/* What your main() calls (usually declared in a header of yours). */
int render_to_lcd(rt_parse_error *err);

static const char scene_text[] =
    "camera eye 0 3 -7 look 0 1 0 fov 45\n"
    "background 0.3 0.4 0.6\n"
    "light 5 10 -6\n"
    "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.25 1\n"
    "material ball color 0.9 0.3 0.2 specular 0.6 shininess 40\n"
    "quad corner -8 0 -8 edge1 0 0 16 edge2 16 0 0 material floor\n"
    "sphere center 0 1 0 radius 1 material ball\n";

static rt_scene scene;         /* 19 KB by default: keep it off the stack */
static uint8_t row[LCD_W * 2]; /* one RGB565 row (rt_buffer_bytes()) */

/* Opens the whole panel for writing (ST7735/ILI9341/ST7789 commands). */
static void lcd_window(uint16_t w, uint16_t h)
{
    uint8_t cols[4] = { 0, 0, (uint8_t)((w - 1) >> 8), (uint8_t)(w - 1) };
    uint8_t rows[4] = { 0, 0, (uint8_t)((h - 1) >> 8), (uint8_t)(h - 1) };
    lcd_command(0x2A); spi_write(cols, 4);   /* CASET: x 0..w-1 */
    lcd_command(0x2B); spi_write(rows, 4);   /* RASET: y 0..h-1 */
    lcd_command(0x2C);                       /* RAMWR: pixels follow */
}

/* Called after each finished row; `px` is ours only until we return. */
static int send_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    (void)ctx;
    (void)y;
    spi_write(px, n); /* a blocking write; copy px first if DMA sends it */
    return 0;         /* non-zero would stop the render */
}

/* Returns 0 on success, else an rt_status (err says where a parse failed). */
int render_to_lcd(rt_parse_error *err)
{
    rt_options opt;
    rt_status st = rt_parse(scene_text, sizeof scene_text - 1, &scene, err);
    if (st != RT_OK)
        return st;
    rt_options_from_scene(&opt, &scene);   /* spp, depth from the scene */
    opt.width = LCD_W;
    opt.height = LCD_H;
    opt.format = RT_RGB565_BE;             /* high byte first, for SPI */
    opt.dither = 1;                        /* hides 565 banding */
    if (rt_buffer_bytes(&opt) > sizeof row)
        return RT_ERR_ARG;
    lcd_window(LCD_W, LCD_H);
    return rt_render_rows(&scene, &opt, 0, LCD_H, row, send_row, NULL, NULL);
}
