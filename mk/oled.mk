# SPDX-License-Identifier: MIT
# The LM3S6965 board's OLED (BOARD=lm3s6965, port/baremetal/README.md):
#
#   make grey4                   build/posix/grey4, the host's picture of
#                                a 4-bit panel (tools/grey4.c)
#   make oled-picture            docs/img/oled-seed.png: the seed scene on
#                                the emulated panel, from QEMU's screendump
#
# tests/suite_oled.sh compares the panel with grey4's picture.

GREY4 := $(HOST_BUILD)/grey4
# ppm.c reads PNG too, so the POSIX port's library links in whole.
GREY4_OBJ := $(HOST_BUILD)/tools/grey4.o $(HOST_CORE_OBJ) $(HOST_PORT_OBJ)

$(HOST_BUILD)/tools/grey4.o: tools/grey4.c $(HOST_STAMP)
	@$(if $(Q),echo "  CC      $<")
	$(Q)mkdir -p $(@D)
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) $(CORE_INC) -Iport/posix -MMD -MP -c $< -o $@

$(GREY4): $(GREY4_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_LDFLAGS) $^ -o $@ $(HOST_LIBS)

-include $(HOST_BUILD)/tools/grey4.d

.PHONY: grey4 oled-picture
grey4: $(GREY4)

# The seed scene rendered on the board at the panel's 128x64, as QEMU's
# monitor saw the screen (build/lm3s6965/screen.ppm, 512x256).
oled-picture:
	$(Q)$(MAKE) --no-print-directory qemu BOARD=lm3s6965 \
	    SCENE=scenes/seed.scene WIDTH=128 HEIGHT=64
	$(Q)mkdir -p docs/img
	$(Q)pnmtopng build/lm3s6965/screen.ppm >docs/img/oled-seed.png.tmp && \
	    mv -f docs/img/oled-seed.png.tmp docs/img/oled-seed.png
	@echo "wrote docs/img/oled-seed.png"
