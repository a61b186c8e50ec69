/* SPDX-License-Identifier: MIT */
/*
 * startup_cortexm.c: vector table and reset handler for every Cortex-M
 * board (M0, M3, M33). The reset handler copies .data from flash, zeroes
 * .bss, paints the stack for the high-water mark and runs main(). Every
 * fault exits through semihosting with its own code (port.h), so a crash on
 * the device fails a test loudly instead of hanging it.
 */
#include "port.h"

/* Set by the linker script (linker/<board>.ld). */
extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[];
extern uint32_t _sstack[], _estack[];

int main(void);
void reset_handler(void) __attribute__((noreturn));
void port_fault(const uint32_t *frame, int code) __attribute__((noreturn));
void fault_hard(void);
void fault_mem(void);
void fault_bus(void);
void fault_usage(void);
void fault_secure(void);
void fault_other(void);
/* A board that uses the SysTick interrupt defines this (board_lm3s6965.c);
 * on the others it is fault_other. */
void systick_handler(void) __attribute__((weak, alias("fault_other")));

typedef void (*vector_fn)(void);

__attribute__((section(".vectors"), used)) static const vector_fn
    vectors[16] = {
        (vector_fn)(uintptr_t)_estack, /* initial stack pointer */
        reset_handler,
        fault_other,  /* NMI */
        fault_hard,
        fault_mem,
        fault_bus,
        fault_usage,
        fault_secure, /* ARMv8-M only; reserved on v6-M and v7-M */
        0, 0, 0,
        fault_other,  /* SVCall */
        fault_other,  /* DebugMonitor */
        0,
        fault_other,  /* PendSV */
        systick_handler
};

void reset_handler(void)
{
    /* Addresses as integers: the symbols are distinct C objects. */
    uintptr_t src = (uintptr_t)_sidata;
    uintptr_t dst = (uintptr_t)_sdata;
    for (; dst < (uintptr_t)_edata; dst += 4, src += 4)
        *(uint32_t *)dst = *(const uint32_t *)src;
    for (dst = (uintptr_t)_sbss; dst < (uintptr_t)_ebss; dst += 4)
        *(uint32_t *)dst = 0;
#if defined(__ARM_ARCH_8M_MAIN__)
    /* ARMv8-M checks the stack limit in hardware: an overflow becomes a
     * UsageFault (or HardFault) instead of silent corruption. */
    __asm__ volatile("msr msplim, %0" : : "r"(_sstack));
#endif
    port_stack_paint();
    port_exit(main());
}

/* Each fault entry moves the stack pointer back to the top of the stack
 * (it may have overflowed) and hands the old one, which points at the
 * exception frame when it is still inside the stack, to port_fault(). */
#define FAULT_ENTRY(name, code)                                          \
    __attribute__((naked)) void name(void)                               \
    {                                                                    \
        __asm__ volatile(".syntax unified\n\t"                           \
                         "mrs r0, msp\n\t"                               \
                         "ldr r2, =_estack\n\t"                          \
                         "mov sp, r2\n\t"                                \
                         "movs r1, #" #code "\n\t"                       \
                         "bl port_fault\n\t");                           \
    }

FAULT_ENTRY(fault_hard, 101)
FAULT_ENTRY(fault_mem, 102)
FAULT_ENTRY(fault_bus, 103)
FAULT_ENTRY(fault_usage, 104)
FAULT_ENTRY(fault_secure, 105)
FAULT_ENTRY(fault_other, 106)

static char *put_hex(char *p, uint32_t v)
{
    for (int shift = 28; shift >= 0; shift -= 4)
        *p++ = "0123456789abcdef"[(v >> shift) & 0xFu];
    return p;
}

void port_fault(const uint32_t *frame, int code)
{
    static char msg[] = "fixtrace: fault, pc 0x00000000 lr 0x00000000\n";
    /* Exception frame: r0, r1, r2, r3, r12, lr, pc, xPSR. Read it only if
     * it lies inside the stack and above the 32-byte guard that some
     * boards make inaccessible, or the report would fault too. */
    if (frame >= _sstack + 8 && frame + 8 <= _estack) {
        put_hex(msg + 22, frame[6]);
        put_hex(msg + 36, frame[5]);
    }
    port_log(msg);
    port_exit(code);
}
