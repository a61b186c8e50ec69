# SPDX-License-Identifier: MIT
# Benchmarks (docs/effects.md):
#
#   make minimal BOARD=an385 [WIDTH=w HEIGHT=h]
#
# builds bench/minimal/minimal.c, a renderer hard-coded for exactly
# scenes/diffuse.scene, with the firmware's board files, compiler flags
# and linker script (mk/firmware.mk), runs it under QEMU with the same
# -icount setting as `make qemu`, and prints its instructions, pixels,
# instructions per pixel and flash (text + rodata), and whether its image
# is byte-identical to the host renderer's (or the PSNR if it is not).
# WIDTH and HEIGHT of 0 mean 320x240. Output goes to build/minimal/<b>/.

MIN_BUILD := build/minimal/$(BOARD)
MIN_ELF := $(MIN_BUILD)/minimal.elf
MIN_W := $(if $(filter 0,$(WIDTH)),320,$(WIDTH))
MIN_H := $(if $(filter 0,$(HEIGHT)),240,$(HEIGHT))
MIN_SRC := bench/minimal/minimal.c core/fx/fx_vec.c core/fx/fx_dir.c core/fx/fx_rsqrt.c \
    core/fx/fx_sqrt.c core/fx/fx_math.c core/fx/fx_trig.c core/scene/rt_camera.c \
    $(filter-out port/baremetal/main.c,$(FW_PORT_SRC))
MIN_OBJ := $(MIN_SRC:%.c=$(MIN_BUILD)/%.o)
MIN_CFLAGS := -std=c99 $(FW_OPT) -g $(FW_CPU) -ffreestanding \
    -ffunction-sections -fdata-sections -DMIN_W=$(MIN_W) -DMIN_H=$(MIN_H)
MIN_STAMP := $(MIN_BUILD)/cflags.txt

$(MIN_STAMP): fw-force | fw-check-board
	$(Q)mkdir -p $(@D)
	$(Q)echo '$(FW_CC) $(MIN_CFLAGS) -T $(FW_LD)' | $(call fw_update,$@)

$(MIN_BUILD)/port/baremetal/libc.o: FW_EXTRA := -fno-tree-loop-distribute-patterns

$(MIN_BUILD)/%.o: %.c $(MIN_STAMP)
	@$(if $(Q),echo "  CC      $< (minimal, $(BOARD))")
	$(Q)mkdir -p $(@D)
	$(Q)$(FW_CC) $(MIN_CFLAGS) $(FW_EXTRA) $(CORE_WARN) $(CORE_INC) \
	    -Iport/baremetal -MMD -MP -c $< -o $@

$(MIN_ELF): $(MIN_OBJ) $(FW_LD) $(MIN_STAMP)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(FW_CC) $(FW_CPU) -nostdlib -T $(FW_LD) -Wl,--gc-sections \
	    -Wl,-Map=$(MIN_BUILD)/minimal.map -Wl,--no-warn-rwx-segments \
	    $(MIN_OBJ) -o $@ -lgcc

-include $(MIN_OBJ:.o=.d)

# Prints "name value" lines like `make qemu`, then compares the image with
# the host renderer's at the same size.
.PHONY: minimal
minimal: $(MIN_ELF) fw-host-tool
	$(Q)rc=0; timeout $(QEMU_TIMEOUT) $(FW_QEMU) \
	    -icount shift=$(FW_ICOUNT),align=off,sleep=off -kernel $< \
	    </dev/null >$(MIN_BUILD)/out.ppm 2>$(MIN_BUILD)/qemu.log || rc=$$?; \
	cat $(MIN_BUILD)/qemu.log; \
	if [ $$rc -ne 0 ]; then \
	    echo "minimal: exit status $$rc (124: timeout)" >&2; exit $$rc; fi
	$(Q)awk '/^instructions /{i=$$2} /^pixels /{p=$$2} END{if (p > 0) \
	    printf "instructions_per_pixel %.1f\n", i / p}' $(MIN_BUILD)/qemu.log
	$(Q)$(FW_SIZE) -A $(MIN_ELF) | awk '$$1 == ".text" { t = $$2 } \
	    $$1 == ".rodata" { r = $$2 } \
	    END { printf "flash %d (text %d, rodata %d)\n", t + r, t, r }'
	$(Q)$(FIXTRACE) -q -W $(MIN_W) -H $(MIN_H) -o $(MIN_BUILD)/host.ppm \
	    scenes/diffuse.scene
	$(Q)if cmp -s $(MIN_BUILD)/out.ppm $(MIN_BUILD)/host.ppm; then \
	    echo "image identical to: $(FIXTRACE) -W $(MIN_W) -H $(MIN_H)" \
	        "scenes/diffuse.scene"; \
	else \
	    echo "image differs from the host's:"; \
	    $(FIXTRACE) compare $(MIN_BUILD)/out.ppm $(MIN_BUILD)/host.ppm; \
	fi

.PHONY: bench
# What fixtrace costs, written to docs/bench.md (tools/bench.sh).
bench:
	$(Q)MAKE="$(MAKE)" bash tools/bench.sh

.PHONY: stack
# The painted stack high-water mark per scene and board, and per level of
# depth, measured under QEMU into docs/stack.md, which the docs quote
# (tools/stack_table.sh; STACK_JOBS=n builds at once, default 2).
stack:
	$(Q)MAKE="$(MAKE)" bash tools/stack_table.sh

# make variant-gains: what each kernel variant and piece of compiler
# steering kept in core/ saves (tools/variant_gains.sh, the list in
# tools/variants.txt), written to docs/variants.md.
.PHONY: variant-gains
variant-gains:
	$(Q)bash tools/variant_gains.sh
