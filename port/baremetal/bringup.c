/* SPDX-License-Identifier: MIT */
/*
 * bringup.c: a stand-in for main.c when bringing up a board (build with
 * `make firmware BOARD=<b> FW_APP=bringup`). It needs nothing from the
 * core: it writes a fixed 2x1 PPM, then checks the cycle counter against a
 * loop of known length and logs the figures the real firmware logs.
 *
 * FW_BRINGUP selects a deliberate failure, to check that each one ends the
 * run with its exit code: 1 = a load from an unmapped address (a fault),
 * 2 = unbounded recursion (a stack overflow).
 */
#include "port.h"

#include "fw_config.h"

/* Iterations of the timed loop; above 700000000 the counters wrap. */
#ifndef FW_LOOP
#define FW_LOOP 1000000
#endif

/* Runs n > 0 iterations of a loop of exactly two instructions. */
__attribute__((noinline)) static void spin(uint32_t n)
{
#if defined(__arm__)
    __asm__ volatile(".syntax unified\n"
                     "1: subs %0, %0, #1\n\t"
                     "bne 1b"
                     : "+l"(n)
                     :
                     : "cc");
#elif defined(__riscv)
    __asm__ volatile("1: addi %0, %0, -1\n\t"
                     "bnez %0, 1b"
                     : "+r"(n));
#endif
}

__attribute__((noinline)) static uint64_t measure(uint32_t n)
{
    uint64_t t0 = port_cycles();
    spin(n);
    return port_cycles() - t0;
}

#if FW_BRINGUP == 2
__attribute__((noinline)) static uint32_t deep(volatile uint32_t *p)
{
    volatile uint32_t local[16];
    local[0] = *p + 1;
    if (local[0] == 0) /* never: the depth would pass 2^32 */
        return 0;
    return deep(local) + local[1];
}
#endif

int main(void)
{
    static const uint8_t px[] = "\xff\x80\x00\x00\x80\xff";
    port_init();
    port_image_begin(2, 1, 0, sizeof px - 1);
    port_write(px, sizeof px - 1);
    port_image_end();

    /* The call overhead cancels in the difference of two runs. */
    const uint32_t n = FW_LOOP;
    uint64_t one = port_cycles_to_insns(measure(n));
    uint64_t two = port_cycles_to_insns(measure(2 * n));
    port_log_value("loop_instructions", two - one);
    port_log_value("loop_expected", 2 * (uint64_t)n);

#if FW_BRINGUP == 1
    port_log_value("unmapped", *(volatile const uint32_t *)0xFFFFFFF0u);
#elif FW_BRINGUP == 2
    static volatile uint32_t seed;
    port_log_value("deep", deep(&seed));
#endif
    port_log_value("pixels", 2);
    port_log_value("stack_bytes", port_stack_used());
    return two - one == 2 * (uint64_t)n ? PORT_EXIT_OK : 1;
}
