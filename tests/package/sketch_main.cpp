/* SPDX-License-Identifier: MIT */
/* The Arduino core's main(), as tests/suite_package.sh needs it: setup()
 * once, loop() once (the sketch's loop() does nothing). */
#include "Arduino.h"

SerialStub Serial;

extern "C" int main(void)
{
    port_init();
    setup();
    loop();
    return 0;
}
