/* SPDX-License-Identifier: MIT */
/* Just enough of the Arduino core for tests/suite_package.sh to build the
 * library's example sketch as the Arduino builder does (the .ino as C++,
 * after #include <Arduino.h>) and run it on the bare-metal port: Serial
 * writes to the port's image channel. */
#ifndef ARDUINO_H_STUB
#define ARDUINO_H_STUB
#include <stddef.h>
#include <stdint.h>
extern "C" {
#include "port.h"
}

struct SerialStub {
    void begin(unsigned long baud) { (void)baud; }
    size_t write(const uint8_t *p, size_t n)
    {
        port_write(p, n);
        return n;
    }
    size_t print(const char *s)
    {
        size_t n = 0;
        while (s[n])
            n++;
        port_write(s, n);
        return n;
    }
    size_t println(const char *s) { return print(s) + print("\r\n"); }
};
extern SerialStub Serial;

void setup(void);
void loop(void);
#endif
