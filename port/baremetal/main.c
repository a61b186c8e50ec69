/* SPDX-License-Identifier: MIT */
/*
 * main.c: the fixtrace firmware. It renders the scene one scanline at a
 * time and streams the image through port_write(): a binary PPM (P6) over
 * semihosting, or a checked frame over a UART (OUTPUT=uart, out_uart.c).
 * There is no frame buffer, only one row. The scene comes in one of two forms
 * (mk/firmware.mk):
 *
 *   FW_SCENE_TABLES 1  the scene parsed on the host (`fixtrace --emit-c`,
 *                      scene_tables.c): a constant rt_scene in flash, and
 *                      no parser in the image. The pruned build (PRUNE=1).
 *   FW_SCENE_TABLES 0  the scene text embedded in the image (scene.S),
 *                      parsed here with the same rt_parse() the host uses
 *                      (PRUNE=0).
 *
 * The figures go to the text channel as lines "name value":
 *
 *   instructions N   retired guest instructions from just before the first
 *                    row to just after the last (rendering and output);
 *                    on a two-core board, both cores' together (the
 *                    virtual clock counts both; tools/dual_table.sh
 *                    counts each core)
 *   pixels N         width * height
 *   stack_bytes N    stack high-water mark of the whole run
 *   stack_reserved N stack size reserved by the linker script
 *
 * On a two-core board (FW_CORES=2) both cores render (dual.c), and
 * core 1's rows and stack follow: core1_rows, stack_bytes_core1,
 * stack_reserved_core1.
 *
 * Errors print "fixtrace: ..." on the text channel and exit with a code
 * from port.h (2 parse, 3 options, 4 render, including a scene that needs
 * an effect this build removed (docs/effects.md), 5 stack, 6 the second
 * core never started).
 *
 * The build generates fw_config.h with FW_SCENE_TABLES, FW_WIDTH,
 * FW_HEIGHT and FW_SPP (0 means "the scene's default"), FW_ADAPTIVE
 * (0, or the adaptive anti-aliasing threshold of rt_options) and FW_DRAFT
 * (0, or the draft threshold of rt_options).
 */
#include "port.h"
#include "fw_buffers.h"
#include "dual.h"

#ifndef FW_SCENE_TABLES
#define FW_SCENE_TABLES 0
#endif

#if FW_SCENE_TABLES
/* The parsed scene (scene_tables.c), read in place from flash. */
extern const rt_scene fw_scene;
#else
#include "rt_parse.h"

/* The scene text and its length in bytes (scene.S). */
extern const char fw_scene_text[];
extern const uint32_t fw_scene_len;

/* In .bss, so `make size` accounts for it. */
static rt_scene scene;
#endif

/* A stack that came this close to its reserved bottom may have overflowed
 * (a frame can skip over a few painted words). */
#define STACK_GUARD 64u

/* In .bss, so `make size` accounts for it. */
static uint8_t row_buf[FW_BUF_BYTES];

static void log_status(const char *what, rt_status st)
{
    port_log("fixtrace: ");
    port_log(what);
    port_log(" failed, status -");
    port_log_u64((uint64_t)-(int64_t)st);
    port_log("\n");
}

/* Hands a finished row straight to the output, and to the panel on a board
 * with one; the row buffer is ours again when they return. */
static int send_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    (void)ctx;
    port_write(row, nbytes);
    if (FW_DISPLAY)
        port_display_row(y, row, (unsigned)(nbytes / 3));
    return 0;
}

/* Names the effects in `missing` (RT_FEAT_* bits) that the scene needs and
 * this build removed, as the host does. */
static void log_missing(uint32_t missing)
{
    const char *sep = "";
    port_log("fixtrace: the scene needs ");
    for (uint32_t bit = 1; bit != 0; bit <<= 1) {
        if (missing & bit) {
            port_log(sep);
            port_log(rt_feature_name(bit));
            sep = ", ";
        }
    }
    port_log((missing & (missing - 1)) ? ", but this firmware was built "
             "without them" : ", but this firmware was built without it");
    port_log(" (build it for this scene, or with PRUNE=0)\n");
}


/* The scene to render, or NULL (after saying why) when the text does not
 * parse. */
static const rt_scene *load_scene(void)
{
#if FW_SCENE_TABLES
    return &fw_scene;
#else
    rt_parse_error err;
    if (rt_parse(fw_scene_text, fw_scene_len, &scene, &err) == RT_OK)
        return &scene;
    port_log("fixtrace: scene line ");
    port_log_u64(err.line);
    port_log(" col ");
    port_log_u64(err.col);
    port_log(": ");
    port_log(err.msg);
    port_log("\n");
    return 0;
#endif
}

int main(void)
{
    const rt_scene *s;
    rt_options opt;
    rt_status st;

    port_init();
    s = load_scene();
    if (!s)
        return PORT_EXIT_PARSE;

    rt_options_from_scene(&opt, s);
    if (FW_WIDTH > 0)
        opt.width = FW_WIDTH;
    if (FW_HEIGHT > 0)
        opt.height = FW_HEIGHT;
    if (FW_SPP > 0)
        opt.spp = FW_SPP;
    opt.adaptive = FW_ADAPTIVE;
    opt.draft = FW_DRAFT;
    if (opt.width > RT_MAX_WIDTH || opt.height > RT_MAX_HEIGHT ||
        rt_buffer_bytes(&opt) > sizeof row_buf) {
        port_log("fixtrace: image ");
        port_log_u64(opt.width);
        port_log("x");
        port_log_u64(opt.height);
        port_log(" is larger than this build allows: ");
        port_log_u64(FW_ROW_PIXELS < RT_MAX_WIDTH ? FW_ROW_PIXELS
                                                  : RT_MAX_WIDTH);
        port_log("x");
        port_log_u64(RT_MAX_HEIGHT);
        port_log(" (set WIDTH and HEIGHT)\n");
        return PORT_EXIT_OPTIONS;
    }

    uint32_t missing = rt_scene_features(s, opt.spp) &
                       ~rt_build_features();
    if (missing) {
        log_missing(missing);
        return PORT_EXIT_RENDER;
    }

    port_image_begin(opt.width, opt.height, opt.format,
                     (uint32_t)(rt_row_bytes(&opt) * opt.height));
    uint64_t t0 = port_cycles();
    if (FW_CORES > 1) {
        int dst = dual_render(s, &opt, row_buf, send_row, 0);
        if (dst == DUAL_NO_CORE1)
            return PORT_EXIT_CORE1;
        st = (rt_status)dst;
    } else {
        st = rt_render_rows(s, &opt, 0, opt.height, row_buf, send_row, 0,
                            0);
    }
    uint64_t t1 = port_cycles();
    if (st != RT_OK) {
        log_status("rt_render_rows", st);
        return st == RT_ERR_ARG ? PORT_EXIT_OPTIONS : PORT_EXIT_RENDER;
    }
    port_image_end();

    size_t used = port_stack_used();
    port_log_value("instructions", port_cycles_to_insns(t1 - t0));
    port_log_value("pixels", (uint64_t)opt.width * opt.height);
    port_log_value("stack_bytes", used);
    port_log_value("stack_reserved", port_stack_size());
    if (FW_CORES > 1 && dual_report(STACK_GUARD) != 0)
        return PORT_EXIT_STACK;
    if (used + STACK_GUARD > port_stack_size()) {
        port_log("fixtrace: stack overflow (raise STACK_SIZE in the "
                 "linker script)\n");
        return PORT_EXIT_STACK;
    }
    if (FW_DISPLAY)
        port_display_done();
    return PORT_EXIT_OK;
}
