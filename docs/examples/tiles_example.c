/* SPDX-License-Identifier: MIT */
/* Renders a scene to a 320x240 SPI display in tiles, each sent by DMA
 * while the next is rendered; redraws a dirty rectangle the same way. */
#include <fixtrace/rt_parse.h>
#include <fixtrace/rt_render.h>

#define LCD_W 320
#define LCD_H 240
#define TILE_W 48 /* tiles at the right and bottom edges are smaller */
#define TILE_H 40

/* Your display driver: lcd_command() sends a command byte (D/C low),
 * spi_write() its argument bytes (D/C high, blocking); dma_start() starts
 * sending pixel bytes and returns at once, dma_wait() waits until that
 * transfer has ended (at once if none is in flight). */
void lcd_command(uint8_t cmd);
void spi_write(const uint8_t *data, size_t n);
void dma_start(const uint8_t *data, size_t n);
void dma_wait(void);

/* What your application calls. */
int tiles_init(rt_parse_error *err);
int draw_rect(int x0, int y0, int x1, int y1);

static const char scene_text[] =
    "camera eye 0 3 -7 look 0 1 0 fov 45\n"
    "background 0.3 0.4 0.6\n"
    "light 5 10 -6\n"
    "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.25 1\n"
    "material ball color 0.9 0.3 0.2 specular 0.6 shininess 40\n"
    "quad corner -8 0 -8 edge1 0 0 16 edge2 16 0 0 material floor\n"
    "sphere center 0 1 0 radius 1 material ball\n";

static rt_scene scene;
static rt_options opt;
/* A tile's RGB565 pixels, twice: DMA sends one while the other fills. */
static uint8_t tile[2][TILE_W * TILE_H * 2];
/* The renderer's buffer for windows up to TILE_W wide: the row alone
 * here; rt_window_bytes() says how much adaptive anti-aliasing or a
 * draft would add. */
static uint8_t row_buf[TILE_W * 2];

/* Where the rows of the tile being rendered go. */
typedef struct {
    uint8_t *dst;
    int y0;
    size_t row_bytes;
} tile_fill;

/* Copies each finished row of a window into its place in the tile. */
static int copy_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    const tile_fill *t = ctx;
    uint8_t *d = t->dst + (size_t)(y - t->y0) * t->row_bytes;
    for (size_t i = 0; i < n; i++)
        d[i] = px[i];
    return 0;
}

/* Opens the panel's rectangle x0 <= x < x1, y0 <= y < y1 for pixels
 * (ST7735/ILI9341/ST7789 commands). */
static void lcd_window(int x0, int y0, int x1, int y1)
{
    uint8_t cols[4] = { (uint8_t)(x0 >> 8), (uint8_t)x0,
                        (uint8_t)((x1 - 1) >> 8), (uint8_t)(x1 - 1) };
    uint8_t rows[4] = { (uint8_t)(y0 >> 8), (uint8_t)y0,
                        (uint8_t)((y1 - 1) >> 8), (uint8_t)(y1 - 1) };
    lcd_command(0x2A); spi_write(cols, 4);   /* CASET */
    lcd_command(0x2B); spi_write(rows, 4);   /* RASET */
    lcd_command(0x2C);                       /* RAMWR: pixels follow */
}

/* Parses the scene and sets the options up. Returns 0, else an
 * rt_status (err says where a parse failed). */
int tiles_init(rt_parse_error *err)
{
    rt_status st = rt_parse(scene_text, sizeof scene_text - 1, &scene, err);
    if (st != RT_OK)
        return st;
    rt_options_from_scene(&opt, &scene);
    opt.width = LCD_W;
    opt.height = LCD_H;
    opt.format = RT_RGB565_BE;
    opt.dither = 1; /* by frame position: tiles meet without seams */
    return rt_window_bytes(&opt, TILE_W) > sizeof row_buf ? RT_ERR_ARG : 0;
}

/* Renders the rectangle x0 <= x < x1, y0 <= y < y1 of the frame tile by
 * tile and sends each: the whole screen, or a dirty rectangle after a
 * change there. Each tile's pixels are those of a full render. Returns 0,
 * else an rt_status. */
int draw_rect(int x0, int y0, int x1, int y1)
{
    int k = 0;
    for (int ty = y0; ty < y1; ty += TILE_H) {
        for (int tx = x0; tx < x1; tx += TILE_W) {
            const int tx1 = tx + TILE_W < x1 ? tx + TILE_W : x1;
            const int ty1 = ty + TILE_H < y1 ? ty + TILE_H : y1;
            tile_fill t = { tile[k], ty, (size_t)(tx1 - tx) * 2 };
            /* Rendered into tile[k] while tile[k ^ 1] is on its way. */
            rt_status st = rt_render_window(&scene, &opt, tx, ty, tx1, ty1,
                                            row_buf, copy_row, &t, NULL);
            dma_wait(); /* the previous tile has gone: the bus is free */
            if (st != RT_OK)
                return st;
            lcd_window(tx, ty, tx1, ty1);
            dma_start(tile[k], t.row_bytes * (size_t)(ty1 - ty));
            k ^= 1;
        }
    }
    dma_wait();
    return 0;
}
