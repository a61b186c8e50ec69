/* SPDX-License-Identifier: MIT */
/*
 * softref: the double-precision reference renderer (port/posix/ref_render.c,
 * unchanged) as bare-metal firmware, to measure what a floating-point
 * renderer costs on a microcontroller: in soft double or soft float on the
 * Cortex-M3, or in float on the Cortex-M4F's FPU. Bench only (docs/
 * accuracy.md); mk/accuracy.mk builds it.
 *
 * Like port/baremetal/main.c, it parses the scene text embedded by scene.S
 * with rt_parse(), streams the rows as a binary PPM through port_write()
 * and reports "instructions N" and "pixels N" on the text channel; it
 * reuses that port's startup, board, semihosting and libc files. The build
 * generates fw_config.h (FW_SCENE_FILE, FW_WIDTH, FW_HEIGHT, FW_SPP; 0
 * means the scene's value).
 */
#include "port.h"
#include "fw_config.h"
#include "ref_render.h"
#include "rt_parse.h"

extern const char fw_scene_text[];
extern const uint32_t fw_scene_len;

#ifndef SOFTREF_ROW_PIXELS
#define SOFTREF_ROW_PIXELS 1024
#endif

static rt_scene scene;
static uint8_t row_buf[SOFTREF_ROW_PIXELS * 3];

static int send_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    (void)ctx;
    (void)y;
    port_write(row, nbytes);
    return 0;
}


/* The work, kept out of main() so that on the M4F no floating-point
 * instruction (not even a register save) runs before the FPU is on. */
__attribute__((noinline)) static int softref_main(void)
{
    rt_parse_error err;
    rt_options opt;
    rt_status st;

    port_init();
    st = rt_parse(fw_scene_text, fw_scene_len, &scene, &err);
    if (st != RT_OK) {
        port_log("softref: scene line ");
        port_log_u64(err.line);
        port_log(": ");
        port_log(err.msg);
        port_log("\n");
        return PORT_EXIT_PARSE;
    }
    rt_options_from_scene(&opt, &scene);
    if (FW_WIDTH > 0)
        opt.width = FW_WIDTH;
    if (FW_HEIGHT > 0)
        opt.height = FW_HEIGHT;
    if (FW_SPP > 0)
        opt.spp = FW_SPP;
    if (opt.width > SOFTREF_ROW_PIXELS) {
        port_log("softref: image too wide\n");
        return PORT_EXIT_OPTIONS;
    }
    port_write_ppm_header(opt.width, opt.height);
    uint64_t t0 = port_cycles();
    st = ref_render_rows(&scene, &opt, 0, opt.height, row_buf, send_row, 0,
                         0);
    uint64_t t1 = port_cycles();
    if (st != RT_OK) {
        port_log("softref: ref_render_rows failed\n");
        return PORT_EXIT_RENDER;
    }
    port_log_value("instructions", port_cycles_to_insns(t1 - t0));
    port_log_value("pixels", (uint64_t)opt.width * opt.height);
    port_log_value("stack_bytes", port_stack_used());
    return PORT_EXIT_OK;
}

int main(void)
{
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11, the FPU. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" : : : "memory");
#endif
    return softref_main();
}
