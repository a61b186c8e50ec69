// SPDX-License-Identifier: MIT
// Renders a small scene and sends it over Serial as a binary PPM (P6),
// one row at a time: capture the port to a file to see it on a computer.
// For an SPI panel, send each row to the panel in send_row() instead
// (docs/embedding.md shows an RGB565 panel).
#include <fixtrace.h>

static const char scene_text[] =
    "camera eye 0 2 -6 look 0 1 0 fov 50\n"
    "background 0.3 0.4 0.6\n"
    "light 5 10 -5\n"
    "material red color 0.9 0.2 0.2 specular 0.5 shininess 30 reflect 0.2\n"
    "material floor color 0.8 0.8 0.8 checker 0.2 0.2 0.2 1\n"
    "quad corner -5 0 -5 edge1 0 0 10 edge2 10 0 0 material floor\n"
    "sphere center 0 1 0 radius 1 material red\n"
    "image 32 24\n";

static rt_scene scene;        // about 19 KB: keep it off the stack
static uint8_t row[32 * 3];   // one RGB888 row (rt_buffer_bytes())

// Called with each finished row; px is ours only until we return.
static int send_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    (void)ctx;
    (void)y;
    Serial.write(px, n);
    return 0;
}

void setup()
{
    rt_parse_error err;
    rt_options opt;
    Serial.begin(115200);
    if (rt_parse(scene_text, sizeof scene_text - 1, &scene, &err) != RT_OK) {
        Serial.print("scene error: ");
        Serial.println(err.msg);
        return;
    }
    rt_options_from_scene(&opt, &scene);   // 32x24 from the scene
    if (rt_buffer_bytes(&opt) > sizeof row)
        return;
    Serial.print("P6\n32 24\n255\n");
    rt_render_rows(&scene, &opt, 0, opt.height, row, send_row, NULL, NULL);
}

void loop()
{
}
