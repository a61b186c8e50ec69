/* SPDX-License-Identifier: MIT */
/* receive: `fixtrace receive`, the host end of the firmware's UART output
 * (port/baremetal/out_uart.c). */
#ifndef RECEIVE_H
#define RECEIVE_H

/* `fixtrace receive -o OUT [-i INPUT] [-q]`; argv[0] is "receive". Reads
 * the serial stream from INPUT or stdin, copies the device's text to
 * stderr and writes the framed image to OUT (PPM or PNG) only when its
 * header and CRC-32 check out. Returns the exit status: 0 written, 1 no
 * frame, a bad or cut frame, or a write error (nothing written), 2 bad
 * usage. */
int receive_main(int argc, char **argv);

#endif /* RECEIVE_H */
