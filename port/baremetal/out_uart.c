/* SPDX-License-Identifier: MIT */
/*
 * out_uart.c: the output channels over the board's UART (OUTPUT=uart in
 * mk/firmware.mk), for a board on a desk: one serial line carries the
 * text and the image, which goes in a frame that `fixtrace receive`
 * checks (port/posix/receive.c):
 *
 *   bytes  field
 *   4      magic "FXIM"
 *   1      version, 1
 *   1      format: rt_format (0 RGB888, 1 RGB565 LE, 2 RGB565 BE)
 *   2      width, little-endian
 *   2      height, little-endian
 *   2      reserved, 0
 *   4      payload bytes, little-endian: width * height * bytes per pixel
 *   N      the payload: the rows, top to bottom, as rt_render_rows()
 *          hands them over
 *   4      CRC-32 (the one of PNG and zlib) of the 12 header bytes after
 *          the magic and of the payload, little-endian
 *
 * Text (port_log) goes out as it is, before and after the frame; the
 * receiver shows it. port_exit() ends the transmission with an EOT byte
 * (0x04), so a receiver reading a serial port knows when to stop, and
 * then leaves through semihosting when FW_SEMIHOST_EXIT is 1 (under QEMU,
 * the default: the exit status reaches `make qemu`); with 0 (SEMIHOST=0,
 * a board without a debugger) it stops in a loop.
 *
 * The board provides port_uart_init() and port_uart_putc() (port.h).
 */
#include "port.h"
#include "fw_config.h"

#ifndef FW_SEMIHOST_EXIT
#define FW_SEMIHOST_EXIT 1
#endif

#define EOT 0x04u

static uint32_t crc = 0;

/* CRC-32, reflected polynomial 0xEDB88320, one nibble at a time: a
 * 64-byte table instead of 1 KB. */
static uint32_t crc32_update(uint32_t c, const uint8_t *p, size_t n)
{
    static const uint32_t tab[16] = {
        0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu,
        0x76DC4190u, 0x6B6B51F4u, 0x4DB26158u, 0x5005713Cu,
        0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu,
        0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu
    };
    while (n-- > 0) {
        c ^= *p++;
        c = (c >> 4) ^ tab[c & 15u];
        c = (c >> 4) ^ tab[c & 15u];
    }
    return c;
}

static void put_bytes(const uint8_t *p, size_t n)
{
    while (n-- > 0)
        port_uart_putc(*p++);
}

void port_output_init(void)
{
    port_uart_init();
}

void port_image_begin(unsigned w, unsigned h, unsigned format,
                      uint32_t payload)
{
    static const uint8_t magic[4] = { 'F', 'X', 'I', 'M' };
    uint8_t hdr[12];
    hdr[0] = 1; /* version */
    hdr[1] = (uint8_t)format;
    hdr[2] = (uint8_t)w;
    hdr[3] = (uint8_t)(w >> 8);
    hdr[4] = (uint8_t)h;
    hdr[5] = (uint8_t)(h >> 8);
    hdr[6] = 0;
    hdr[7] = 0;
    hdr[8] = (uint8_t)payload;
    hdr[9] = (uint8_t)(payload >> 8);
    hdr[10] = (uint8_t)(payload >> 16);
    hdr[11] = (uint8_t)(payload >> 24);
    put_bytes(magic, sizeof magic);
    put_bytes(hdr, sizeof hdr);
    crc = crc32_update(0xFFFFFFFFu, hdr, sizeof hdr);
}

void port_image_end(void)
{
    uint32_t c = crc ^ 0xFFFFFFFFu;
    uint8_t out[4];
    out[0] = (uint8_t)c;
    out[1] = (uint8_t)(c >> 8);
    out[2] = (uint8_t)(c >> 16);
    out[3] = (uint8_t)(c >> 24);
    put_bytes(out, sizeof out);
}

void port_write(const void *buf, size_t n)
{
    crc = crc32_update(crc, buf, n);
    put_bytes(buf, n);
}

void port_log(const char *s)
{
    while (*s != '\0')
        port_uart_putc((uint8_t)*s++);
}

void port_exit(int code)
{
    port_uart_putc(EOT);
    if (FW_SEMIHOST_EXIT)
        port_semihost_exit(code);
    for (;;) {
    }
}
