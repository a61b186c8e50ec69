/* SPDX-License-Identifier: MIT */
/*
 * semihost.c: the semihosting traps, shared by every board (ARM: bkpt 0xAB;
 * RISC-V: the slli/ebreak/srai sequence): the host's stdout and stderr,
 * and the exit status. out_semihost.c builds the output channels on them
 * (OUTPUT=semihost, the default); out_uart.c uses only the exit.
 *
 * Why semihosting: SYS_WRITE moves a whole scanline per trap and is
 * binary-clean, and the image (":tt" opened for writing, the host's
 * stdout) and the text (":tt" opened for appending, the host's stderr)
 * arrive on separate host files, so the PPM gets only image bytes. QEMU
 * must run with -semihosting-config enable=on,target=native and
 * -serial none (PLATFORM.md: -serial stdio makes stdout non-blocking and
 * cuts writes short). Without semihosting the first trap faults, which the
 * fault handlers turn into a non-zero exit.
 */
#include "port.h"

#define SYS_OPEN 0x01
#define SYS_WRITE 0x05
#define SYS_EXIT 0x18
#define SYS_EXIT_EXTENDED 0x20

#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR 0x20023u

/* ":tt" open modes: 4 = "w" (stdout), 8 = "a" (stderr). */
#define SH_MODE_STDOUT 4
#define SH_MODE_STDERR 8

static uintptr_t sh_out = (uintptr_t)-1;
static uintptr_t sh_err = (uintptr_t)-1;

/* One semihosting call: operation op, argument block arg; returns r0/a0.
 * Kept out of line so the RISC-V sequence exists once, 16-byte aligned
 * (it must not straddle a page). */
__attribute__((noinline)) static uintptr_t sh_call(uintptr_t op,
                                                   const void *arg)
{
#if defined(__arm__)
    register uintptr_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
#elif defined(__riscv)
    register uintptr_t a0 __asm__("a0") = op;
    register const void *a1 __asm__("a1") = arg;
    __asm__ volatile(".option push\n\t"
                     ".option norvc\n\t"
                     ".balign 16\n\t"
                     "slli zero, zero, 0x1f\n\t"
                     "ebreak\n\t"
                     "srai zero, zero, 7\n\t"
                     ".option pop"
                     : "+r"(a0)
                     : "r"(a1)
                     : "memory");
    return a0;
#else
#error "semihost.c: no semihosting trap for this architecture"
#endif
}

static uintptr_t sh_open_tt(uintptr_t mode)
{
    static const char name[] = ":tt";
    uintptr_t blk[3];
    blk[0] = (uintptr_t)name;
    blk[1] = mode;
    blk[2] = sizeof name - 1;
    return sh_call(SYS_OPEN, blk);
}

/* Writes all n bytes to fd; SYS_WRITE returns how many were NOT written.
 * Gives up if a call makes no progress, rather than spinning. */
static void sh_write_all(uintptr_t fd, const uint8_t *p, size_t n)
{
    while (n > 0) {
        uintptr_t blk[3];
        blk[0] = fd;
        blk[1] = (uintptr_t)p;
        blk[2] = n;
        uintptr_t left = sh_call(SYS_WRITE, blk);
        if (left >= n)
            return;
        p += n - left;
        n = left;
    }
}

void port_semihost_init(void)
{
    sh_out = sh_open_tt(SH_MODE_STDOUT);
    sh_err = sh_open_tt(SH_MODE_STDERR);
}

void port_semihost_write(int to_stderr, const void *buf, size_t n)
{
    sh_write_all(to_stderr ? sh_err : sh_out, buf, n);
}

void port_semihost_exit(int code)
{
    uintptr_t blk[2];
    blk[0] = ADP_STOPPED_APPLICATION_EXIT;
    blk[1] = (uintptr_t)code;
    sh_call(SYS_EXIT_EXTENDED, blk);
    /* Only reached if the host lacks SYS_EXIT_EXTENDED: plain SYS_EXIT can
     * still tell success from failure. */
    sh_call(SYS_EXIT, (const void *)(uintptr_t)(code == 0
                                                    ? ADP_STOPPED_APPLICATION_EXIT
                                                    : ADP_STOPPED_RUNTIME_ERROR));
    for (;;) {
    }
}
