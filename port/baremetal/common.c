/* SPDX-License-Identifier: MIT */
/*
 * common.c: board-independent helpers: the stack high-water mark and
 * number output for the text channel.
 *
 * Stack high-water mark by painting. The startup code fills the
 * free stack with a pattern before main(); at the end the firmware finds
 * the lowest word that changed. The linker scripts put the stack at the
 * bottom of RAM (it grows down towards the start of RAM), so an overflow
 * faults instead of silently overwriting .bss.
 */
#include "port.h"

/* Set by the linker script: the stack occupies [_sstack, _estack). */
extern uint32_t _sstack[], _estack[];

#define STACK_PAINT 0xA55AC33Cu

static uintptr_t current_sp(void)
{
    uintptr_t sp;
#if defined(__arm__)
    __asm__ volatile("mov %0, sp" : "=r"(sp));
#elif defined(__riscv)
    __asm__ volatile("mv %0, sp" : "=r"(sp));
#else
#error "common.c: no way to read the stack pointer on this architecture"
#endif
    return sp;
}

void port_stack_paint(void)
{
    /* Everything below the stack pointer is free (neither ABI has a red
     * zone), so paint up to it. */
    uintptr_t end = current_sp() & ~(uintptr_t)3;
    for (uintptr_t p = (uintptr_t)_sstack; p < end; p += sizeof(uint32_t))
        *(volatile uint32_t *)p = STACK_PAINT;
}

/* Some boards make the lowest 32 bytes of the stack a no-access guard
 * (board_an385.c, board_rv32.c), so the scan starts above them. */
#define GUARD_WORDS 8

size_t port_stack_used(void)
{
    uintptr_t top = (uintptr_t)_estack;
    uintptr_t p = (uintptr_t)(_sstack + GUARD_WORDS);
    while (p < top && *(const volatile uint32_t *)p == STACK_PAINT)
        p += sizeof(uint32_t);
    return (size_t)(top - p);
}

size_t port_stack_size(void)
{
    return (size_t)((uintptr_t)_estack - (uintptr_t)_sstack);
}

void port_log_u64(uint64_t v)
{
    char buf[24];
    char *p = buf + sizeof buf;
    *--p = '\0';
    do {
        *--p = (char)('0' + v % 10);
        v /= 10;
    } while (v != 0);
    port_log(p);
}

void port_log_value(const char *name, uint64_t v)
{
    port_log(name);
    port_log(" ");
    port_log_u64(v);
    port_log("\n");
}

/* "P6\n<w> <h>\n255\n", as the host writes it. */
void port_write_ppm_header(unsigned w, unsigned h)
{
    char buf[32];
    char *p = buf + sizeof buf;
    const char *tail = "\n255\n";
    unsigned n;
    p -= 5;
    for (n = 0; n < 5; n++)
        p[n] = tail[n];
    do {
        *--p = (char)('0' + h % 10);
        h /= 10;
    } while (h != 0);
    *--p = ' ';
    do {
        *--p = (char)('0' + w % 10);
        w /= 10;
    } while (w != 0);
    *--p = '\n';
    *--p = '6';
    *--p = 'P';
    port_write(p, (size_t)(buf + sizeof buf - p));
}
