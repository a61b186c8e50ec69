/* SPDX-License-Identifier: MIT */
/*
 * out_semihost.c: the output channels over semihosting (OUTPUT=semihost,
 * the default; semihost.c has the traps). The image is a binary PPM on
 * the host's stdout, the text goes to its stderr, the exit status to
 * QEMU's own. Needs a debugger or QEMU on the other end; out_uart.c is
 * the choice for a board on a desk.
 */
#include "port.h"

void port_output_init(void)
{
    port_semihost_init();
}

void port_image_begin(unsigned w, unsigned h, unsigned format,
                      uint32_t payload)
{
    /* The firmware sends RGB888 rows (format 0), which is what a PPM
     * holds; the size follows from the header. */
    (void)format;
    (void)payload;
    port_write_ppm_header(w, h);
}

void port_image_end(void)
{
}

void port_write(const void *buf, size_t n)
{
    port_semihost_write(0, buf, n);
}

void port_log(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0')
        n++;
    port_semihost_write(1, s, n);
}

void port_exit(int code)
{
    port_semihost_exit(code);
}
