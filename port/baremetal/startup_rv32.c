/* SPDX-License-Identifier: MIT */
/*
 * startup_rv32.c: reset and trap entry for the RV32 board (QEMU virt,
 * machine mode, started with -bios none at the image's first byte). The
 * naked entry sets gp, sp and mtvec, then C zeroes .bss, paints the stack
 * and runs main(). Any trap (an illegal instruction, a misaligned or bad
 * access, an ebreak without semihosting) exits with PORT_EXIT_TRAP.
 */
#include "port.h"

/* Set by the linker script (linker/rv32.ld). The image is loaded straight
 * into RAM, so .data needs no copy. */
extern uint32_t _sbss[], _ebss[], _sstack[], _estack[];

int main(void);
void _start(void);
void trap_entry(void);
void reset_c(void) __attribute__((noreturn));
void port_trap(uint32_t mcause, uint32_t mepc) __attribute__((noreturn));

__attribute__((naked, section(".text.start"))) void _start(void)
{
    __asm__ volatile(".option push\n\t"
                     ".option norelax\n\t"
                     "la gp, __global_pointer$\n\t"
                     ".option pop\n\t"
                     "la sp, _estack\n\t"
                     "la t0, trap_entry\n\t"
                     "csrw mtvec, t0\n\t"
                     "j reset_c");
}

/* mtvec needs a 4-byte aligned handler (direct mode). Like the Cortex-M
 * fault entries, it moves sp back to the top of the stack first. */
__attribute__((naked, aligned(4))) void trap_entry(void)
{
    __asm__ volatile("la sp, _estack\n\t"
                     "csrr a0, mcause\n\t"
                     "csrr a1, mepc\n\t"
                     "j port_trap");
}

void reset_c(void)
{
    for (uintptr_t p = (uintptr_t)_sbss; p < (uintptr_t)_ebss; p += 4)
        *(uint32_t *)p = 0;
    port_stack_paint();
    port_exit(main());
}

static char *put_hex(char *p, uint32_t v)
{
    for (int shift = 28; shift >= 0; shift -= 4)
        *p++ = "0123456789abcdef"[(v >> shift) & 0xFu];
    return p;
}

void port_trap(uint32_t mcause, uint32_t mepc)
{
    static char msg[] = "fixtrace: trap, mcause 0x00000000 pc 0x00000000\n";
    static volatile int nested;
    if (nested) {
        /* The report itself trapped (no semihosting?): leave through the
         * virt test device, which QEMU turns into exit status 106. */
        *(volatile uint32_t *)0x100000u = (PORT_EXIT_TRAP << 16) | 0x3333u;
        for (;;) {
        }
    }
    nested = 1;
    put_hex(msg + 25, mcause);
    put_hex(msg + 39, mepc);
    port_log(msg);
    port_exit(PORT_EXIT_TRAP);
}
