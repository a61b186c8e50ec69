# SPDX-License-Identifier: MIT
# Bare-metal firmware (port/baremetal/README.md):
#
#   make firmware BOARD=b [SCENE=scenes/x.scene WIDTH=w HEIGHT=h SPP=n]
#   make qemu     BOARD=b [same]    render under QEMU to build/<b>/out.ppm
#   make size     BOARD=b           flash, RAM and stack of the firmware
#
# Boards (mk/boards/*.mk): an385 (Cortex-M3), m0 (Cortex-M0 code on
# mps2-an385), microbit (nRF51, Cortex-M0, 16 KB RAM), an505 (Cortex-M33),
# an521 (two Cortex-M33 rendering together; port/baremetal/dual.c, and
# mk/dual.mk for each core's count), rv32 (QEMU virt), lm3s6965 (Cortex-M3
# with a 128x64 OLED; mk/oled.mk).
# WIDTH, HEIGHT and SPP of 0 mean "the scene's default"; ADAPTIVE=T
# (1..255, with SPP > 1) turns on adaptive anti-aliasing (docs/effects.md);
# DRAFT=T (1..255) a draft render, traced at every other pixel and
# interpolated where the neighbours agree within T levels (docs/effects.md).
# FW_APP=bringup builds port/baremetal/bringup.c instead of the renderer
# (no core needed).
# FW_DEFS adds -D options to every C file (for example -DRT_MAX_DEPTH=3).
#
# PRUNE=1 (the default) builds the firmware for SCENE alone
# (docs/effects.md):
# - the host tool (build/posix/fixtrace) parses SCENE; a scene it cannot
#   parse fails the build with the parser's file:line:col message;
# - `fixtrace --emit-c` writes the parsed scene as constant tables,
#   build/<b>/scene_tables.c, which the image carries instead of the text:
#   no parser (core/parse/) and no scene text are
#   linked;
# - `fixtrace --build-flags` derives the RT_NO_* flags that remove every
#   effect the scene does not need at the SPP the firmware renders;
# - RT_MAX_OBJECTS, RT_MAX_MATERIALS and RT_MAX_LIGHTS are the scene's
#   counts. A capacity the board (FW_CAPS) or FW_DEFS sets is an upper
#   limit: a scene above it fails the build, naming the limit.
# The flags and capacities go to build/<b>/fw_effects.h, which every C file
# includes first, so changing SCENE or SPP rebuilds what it must.
# A FW_CAPS or FW_DEFS that changes the parsed values (-DRT_UNIT_BITS=n,
# -DRT_MAX_DEPTH=n; port/posix/emit_c.c lists them) gets a host tool
# built with it and with the build's light limit (RT_MAX_LIGHTS of
# FW_CAPS or FW_DEFS, else the default), under build/posix-fw*: depth and
# lights must fit the colour bound together (core/fx/rt_config.h: depth <= 13
# with 4 lights, 17 with 3, 24 with 2, 41 with 1), in the host tool as in
# the firmware. For example FW_DEFS="-DRT_MAX_DEPTH=16 -DRT_MAX_LIGHTS=3";
# a pair that does not fit stops the build before anything is compiled,
# with rt_config.h's message.
#
# OUTPUT=semihost (the default) sends the image and the figures through
# semihosting (port/baremetal/out_semihost.c); OUTPUT=uart sends both on
# the board's UART, the image in a checked frame (out_uart.c), which
# `make qemu` captures from QEMU's serial port into build/<b>/uart.bin and
# hands to `fixtrace receive`. SEMIHOST=0 (with OUTPUT=uart) makes the
# firmware stop in a loop instead of leaving through semihosting, for a
# board without a debugger. The core objects are shared between the two;
# the image is build/<b>/fixtrace-uart.elf.
#
# PRUNE=0 builds every effect, embeds the scene text (port/baremetal/
# scene.S) and parses it on the device, as the host does: any scene, and
# the device reports a scene that does not parse. FW_BUILD (default
# build/<b>) moves the build, e.g. to keep two variants apart.

BOARD ?= an385
SCENE ?= scenes/seed.scene
WIDTH ?= 0
HEIGHT ?= 0
SPP ?= 0
ADAPTIVE ?= 0
DRAFT ?= 0
FW_APP ?= main
FW_BRINGUP ?= 0
FW_DEFS ?=
PRUNE ?= 1
OUTPUT ?= semihost
SEMIHOST ?= 1
QEMU_TIMEOUT ?= 300

ARM_PREFIX ?= arm-none-eabi-
RISCV_PREFIX ?= riscv64-unknown-elf-

# ---- Boards -----------------------------------------------------------------
# One file per board, mk/boards/<board>.mk (docs/porting.md), sets:
# FW_PREFIX: the compiler prefix ($(ARM_PREFIX) or $(RISCV_PREFIX));
# FW_CPU: code generation; FW_OPT: optimisation; FW_CAPS: capacity
# overrides (rt_config.h, and FW_ROW_PIXELS, the row buffer of main.c);
# FW_LD: the linker script; FW_BOARD_SRC: the board and startup files;
# FW_QEMU: the QEMU command without -icount and -kernel; FW_ICOUNT: the
# -icount shift whose instruction count the board's port_cycles_to_insns()
# undoes.

FW_ARM_QEMU := qemu-system-arm -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native

FW_BOARDS := $(sort $(basename $(notdir $(wildcard mk/boards/*.mk))))
ifneq ($(filter $(BOARD),$(FW_BOARDS)),)
include mk/boards/$(BOARD).mk
endif

# ---- Build ------------------------------------------------------------------

FW_BUILD ?= build/$(BOARD)
FW_CC := $(FW_PREFIX)gcc
FW_SIZE := $(FW_PREFIX)size
FW_NAME := $(if $(filter bringup,$(FW_APP)),bringup,fixtrace)$(if $(filter \
    uart,$(OUTPUT)),-uart)
FW_ELF := $(FW_BUILD)/$(FW_NAME).elf
# FW_PRUNING: 1 for a renderer built for SCENE alone (PRUNE=1), which
# carries the scene as tables (FW_TABLES_C) instead of its text (scene.S).
FW_PRUNING := $(if $(filter 1,$(PRUNE)),$(if $(filter bringup,$(FW_APP)),,1))

# The capacities a pruned build takes from the scene (fw_effects.h); the
# board's or FW_DEFS' values of them are limits, not -D options, there.
# (PRUNE alone decides, so that a bringup build has the same flags as the
# renderer and switching between them rebuilds nothing.)
FW_SCENE_CAPS := RT_MAX_OBJECTS RT_MAX_MATERIALS RT_MAX_LIGHTS
FW_CAP_OPTS := $(FW_SCENE_CAPS:%=-D%=%)
fw_scene_caps_out = $(if $(filter 1,$(PRUNE)),$(filter-out \
    $(FW_CAP_OPTS),$1),$1)
# fw_cap_limit NAME: the last -DNAME=v of FW_CAPS and FW_DEFS, if any.
fw_cap_limit = $(lastword $(patsubst -D$1=%,%,$(filter -D$1=%,$(FW_CAPS) \
    $(FW_DEFS))))

FW_EFFECTS := $(FW_BUILD)/fw_effects.h
# DRAFT=0 (the default): main.c never asks for a draft render, so the core
# is built without draft renders (RT_NO_DRAFT, core/fx/rt_config.h) and links
# neither rt_draft.c nor rt_thin.c, with PRUNE=0 as with PRUNE=1.
FW_DRAFT_OPT := $(if $(filter 0,$(DRAFT)),-DRT_NO_DRAFT)
FW_CFLAGS := -std=c99 $(FW_OPT) -g $(FW_CPU) -ffreestanding \
    -ffunction-sections -fdata-sections -DRT_STATS=0 $(FW_DRAFT_OPT) \
    $(call fw_scene_caps_out,$(FW_CAPS)) -include $(FW_EFFECTS) \
    $(call fw_scene_caps_out,$(FW_DEFS))
FW_LDFLAGS := $(FW_CPU) -nostdlib -T $(FW_LD) -Wl,--gc-sections \
    -Wl,-Map=$(FW_BUILD)/$(FW_NAME).map -Wl,--no-warn-rwx-segments

FW_OUT_SRC := port/baremetal/out_$(OUTPUT).c
FW_PORT_SRC := port/baremetal/common.c port/baremetal/semihost.c \
    $(FW_OUT_SRC) port/baremetal/libc.c $(FW_BOARD_SRC)
FW_TABLES_C := $(FW_BUILD)/scene_tables.c
# The scene parser's files, which a pruned build leaves out.
FW_PARSER_SRC := core/parse/rt_parse.c core/parse/rt_parse_obj.c core/parse/rt_parse_mesh.c \
    core/parse/rt_lex.c \
    core/parse/rt_lex_field.c
ifeq ($(FW_APP),bringup)
FW_SRC := $(FW_PORT_SRC) port/baremetal/bringup.c
FW_SCENE_OBJ :=
else ifeq ($(FW_PRUNING),1)
FW_SRC := $(filter-out $(FW_PARSER_SRC),$(CORE_SRC)) $(FW_PORT_SRC) \
    port/baremetal/main.c
FW_SCENE_OBJ := $(FW_BUILD)/scene_tables.o
else
FW_SRC := $(CORE_SRC) $(FW_PORT_SRC) port/baremetal/main.c
FW_SCENE_OBJ := $(FW_BUILD)/scene.o
endif
FW_OBJ := $(FW_SRC:%.c=$(FW_BUILD)/%.o) $(FW_SCENE_OBJ)
FW_CONFIG := $(FW_BUILD)/fw_config.h
FW_FLAGS_STAMP := $(FW_BUILD)/cflags.txt

# Rewrites $1 with the text on stdin only when it changed, so that changing
# a variable rebuilds exactly what depends on it. The temporary file is
# per process, so two builds that race here both end up correct.
fw_update = cat >$1.$$$$ && if cmp -s $1.$$$$ $1; then rm -f $1.$$$$; \
    else mv -f $1.$$$$ $1; fi

.PHONY: firmware qemu size fw-check-board fw-force
firmware: $(FW_ELF)

# Checks that need no build, made before anything is built: the board,
# its compiler, that SCENE exists, and that an explicit WIDTH fits the
# board's row buffer (FW_ROW_PIXELS, as FW_CAPS or FW_DEFS sets it).
FW_ROW_LIMIT = $(call fw_cap_limit,FW_ROW_PIXELS)
fw-check-board:
	@$(if $(FW_LD),true,echo "Unknown BOARD=$(BOARD); the boards are" \
	    "$(FW_BOARDS) (mk/boards/*.mk)" >&2; exit 1)
	@case '$(OUTPUT)' in semihost|uart) ;; *) echo "OUTPUT must be" \
	    "semihost or uart, got '$(OUTPUT)'" >&2; exit 1;; esac
	@command -v $(FW_CC) >/dev/null || { echo "$(FW_CC) not found; install" \
	    "it with: apt-get install --no-install-recommends $(FW_CC_PKG)" >&2; \
	    exit 1; }
	@$(if $(filter bringup,$(FW_APP)),true,test -f '$(SCENE)') || { \
	    echo "SCENE=$(SCENE): no such file" >&2; exit 1; }
	@lim='$(FW_ROW_LIMIT)'; [ -z "$$lim" ] || case '$(WIDTH)' in \
	    ''|*[!0-9]*) ;; *) test '$(WIDTH)' -le "$$lim" || { \
	    echo "WIDTH=$(WIDTH): BOARD=$(BOARD) renders rows of at most" \
	    "$$lim pixels (FW_ROW_PIXELS=$$lim); give WIDTH=$$lim or less" >&2; \
	    exit 1; };; esac

$(FW_CONFIG): fw-force | fw-check-board
	$(Q)mkdir -p $(@D)
	$(Q)for v in '$(WIDTH)' '$(HEIGHT)' '$(SPP)' '$(ADAPTIVE)' \
	    '$(DRAFT)' '$(FW_BRINGUP)'; do \
	    case "$$v" in ''|*[!0-9]*) echo "WIDTH, HEIGHT, SPP, ADAPTIVE," \
	        "DRAFT and FW_BRINGUP must be numbers, got '$$v'" >&2; exit 1;; \
	    esac; \
	done
	$(Q)test '$(ADAPTIVE)' -le 255 || { echo "ADAPTIVE must be 0..255," \
	    "got '$(ADAPTIVE)'" >&2; exit 1; }
	$(Q)test '$(DRAFT)' -le 255 || { echo "DRAFT must be 0..255," \
	    "got '$(DRAFT)'" >&2; exit 1; }
	$(Q)printf '%s\n' '/* Generated by mk/firmware.mk. */' \
	    '#define FW_SCENE_FILE "$(abspath $(SCENE))"' \
	    '#define FW_WIDTH $(WIDTH)' '#define FW_HEIGHT $(HEIGHT)' \
	    '#define FW_SPP $(SPP)' '#define FW_ADAPTIVE $(ADAPTIVE)' \
	    '#define FW_DRAFT $(DRAFT)' \
	    '#define FW_BRINGUP $(FW_BRINGUP)' \
	    '#define FW_SEMIHOST_EXIT $(if $(filter 0,$(SEMIHOST)),0,1)' \
	    '#define FW_SCENE_TABLES $(if $(FW_PRUNING),1,0)' \
	    | $(call fw_update,$@)

# The host tool is built first, under a lock: parallel firmware builds
# (tests/suite_firmware.sh runs one per board) would otherwise compile the
# same host objects at the same time. Settings that change the parsed
# scene need a host tool built with them (scene_tables.c refuses to
# compile under other values), and with the light limit the firmware is
# built against, which bounds the depth (rt_config.h): FW_HOST_DEFS.
fw_host_set = $(foreach v,$1,$(if $(call fw_cap_limit,$v),-D$v=$(call \
    fw_cap_limit,$v)))
FW_HOST_DEFS := $(strip $(call fw_host_set,RT_UNIT_BITS RT_MAX_DEPTH))
FW_HOST_DEFS += $(if $(FW_HOST_DEFS),$(call fw_host_set,RT_MAX_LIGHTS))
FW_HOST_DEFS := $(strip $(FW_HOST_DEFS))
fw_empty :=
fw_space := $(fw_empty) $(fw_empty)
FW_HOST_BUILD := $(if $(FW_HOST_DEFS),build/posix-fw$(subst =,-,$(subst \
    $(fw_space),,$(FW_HOST_DEFS:-DRT%=%))),$(HOST_BUILD))
FW_FIXTRACE := $(if $(FW_HOST_DEFS),$(FW_HOST_BUILD)/fixtrace,$(FIXTRACE))
FW_SPP_ARG := $(if $(filter-out 0,$(SPP)),-s $(SPP))
FW_EFFECTS_NOTE := $(if $(FW_PRUNING),built for $(SCENE)$(if \
    $(FW_SPP_ARG), at $(SPP) spp) alone,every effect is kept \
    (PRUNE=$(PRUNE) FW_APP=$(FW_APP)))
FW_LOCK := $(if $(shell command -v flock 2>/dev/null),\
    flock $(dir $(FW_FIXTRACE)).fw-host.lock)

# A configuration rt_config.h refuses (a depth too deep for the lights)
# is said once, before any host object is compiled.
.PHONY: fw-host-tool
fw-host-tool:
	$(Q)$(if $(FW_HOST_DEFS),echo '#include "rt_config.h"' | $(CC) \
	    -std=c99 -fsyntax-only $(FW_HOST_DEFS) $(CORE_INC) -x c - || { echo \
	    "firmware: the host tool cannot be built with $(FW_HOST_DEFS)" \
	    "(above; FW_CAPS and FW_DEFS)" >&2; exit 1; })
	$(Q)mkdir -p $(dir $(FW_FIXTRACE))
	$(Q)$(FW_LOCK) $(MAKE) --no-print-directory -s -f $(firstword \
	    $(MAKEFILE_LIST)) $(if $(FW_HOST_DEFS),HOST_BUILD=$(FW_HOST_BUILD) \
	    RT_DEFS='$(FW_HOST_DEFS)') $(FW_FIXTRACE)

# The scene as tables (PRUNE=1). A scene the host cannot parse stops the
# build here, with the parser's message.
$(FW_TABLES_C): fw-force fw-host-tool | fw-check-board
	$(Q)mkdir -p $(@D)
	$(Q)$(FW_FIXTRACE) --emit-c '$(SCENE)' >$@.$$$$ || { rm -f $@.$$$$; \
	    echo "firmware: $(SCENE) does not parse (above); PRUNE=0 embeds" \
	    "the text and lets the device report it" >&2; exit 1; }; \
	if cmp -s $@.$$$$ $@; then rm -f $@.$$$$; else mv -f $@.$$$$ $@; \
	    $(if $(Q),echo "  TABLES  $(SCENE)";) fi

# What the firmware is built for: the RT_NO_* flags of the effects SCENE
# does not need and, as its counts, the capacities (PRUNE=1); nothing with
# PRUNE=0. A bringup build needs no core and leaves the file as it is, so
# that switching between it and the renderer does not rebuild the core.
$(FW_EFFECTS): fw-force $(if $(FW_PRUNING),fw-host-tool $(FW_TABLES_C)) \
               | fw-check-board
	$(Q)mkdir -p $(@D)
	$(Q)case '$(PRUNE)' in 0|1) ;; *) echo "PRUNE must be 0 or 1, got" \
	    "'$(PRUNE)'" >&2; exit 1;; esac
	$(Q)$(if $(filter bringup,$(FW_APP)),test ! -f $@ || exit 0;) \
	flags=; caps=; \
	if [ -n '$(FW_PRUNING)' ]; then \
	    flags=$$($(FW_FIXTRACE) --build-flags $(FW_SPP_ARG) '$(SCENE)') \
	        || exit 1; \
	    for c in $(foreach c,$(FW_SCENE_CAPS),$c=$(call fw_cap_limit,$c)); do \
	        cap=$${c%=*}; lim=$${c#*=}; what=$${cap#RT_MAX_}; \
	        n=$$(sed -n "s/^#define FW_SCENE_$$what \([0-9]*\)$$/\1/p" \
	            $(FW_TABLES_C)); \
	        [ -n "$$lim" ] || lim=$$(sed -n \
	            "s/^#define $$cap \([0-9]*\)$$/\1/p" core/fx/rt_config.h); \
	        if [ -z "$$n" ] || [ -z "$$lim" ]; then \
	            echo "firmware: no count for $$cap" >&2; exit 1; fi; \
	        if [ "$$n" -gt "$$lim" ]; then \
	            echo "firmware: $(SCENE) has $$n" \
	                "$$(echo $$what | tr A-Z a-z), but the build for" \
	                "BOARD=$(BOARD) allows at most $$lim ($$cap=$$lim)" >&2; \
	            exit 1; fi; \
	        caps="$$caps $$cap=$$n"; \
	    done; \
	    w=$$(sed -n 's/^ *\.width = \([0-9]*\),$$/\1/p' $(FW_TABLES_C)); \
	    if [ '$(WIDTH)' = 0 ] && [ -n '$(FW_ROW_LIMIT)' ] && \
	        [ "$${w:-0}" -gt '$(FW_ROW_LIMIT)' ]; then \
	        echo "firmware: $(SCENE) is $$w pixels wide, but BOARD=$(BOARD)" \
	            "renders rows of at most $(FW_ROW_LIMIT) pixels" \
	            "(FW_ROW_PIXELS=$(FW_ROW_LIMIT)); give WIDTH=$(FW_ROW_LIMIT)" \
	            "or less" >&2; exit 1; fi; \
	fi; \
	{ echo "/* Generated by mk/firmware.mk: $(FW_EFFECTS_NOTE). */"; \
	  for f in $$flags; do echo "#define $${f#-D} 1"; done; \
	  for c in $$caps; do echo "#ifndef $${c%=*}"; \
	      echo "#define $${c%=*} $${c#*=}"; echo "#endif"; done; \
	} >$@.$$$$; \
	if cmp -s $@.$$$$ $@; then rm -f $@.$$$$; else mv -f $@.$$$$ $@; \
	    $(if $(Q),echo "  EFFECTS $(if $(FW_PRUNING),$(SCENE): )$${flags:-$(FW_EFFECTS_NOTE)}$${caps}";) \
	fi

$(FW_FLAGS_STAMP): fw-force | fw-check-board
	$(Q)mkdir -p $(@D)
	$(Q)echo '$(FW_CC) $(FW_CFLAGS) -T $(FW_LD) -Os: $(FW_COLD_SRC)' | \
	    $(call fw_update,$@)

$(FW_BUILD)/core/%.o: core/%.c $(FW_FLAGS_STAMP) $(FW_EFFECTS)
	@$(if $(Q),echo "  CC      $< ($(BOARD))")
	$(Q)mkdir -p $(@D)
	$(Q)$(FW_CC) $(FW_CFLAGS) $(FW_EXTRA) $(CORE_WARN) $(CORE_INC) -MMD -MP \
	    -c $< -o $@

# The core's set-up code runs once a render, before the first pixel (the
# tracer's tables, the direction grids, the cut-off bounds, the scene's
# checks), and the row culling once a row: compiled for size, they leave
# flash for the per-pixel code, which -O2 makes faster, at no measurable
# cost per pixel on any board (make variant-gains measures it). One list for every CPU. FW_COLD_OPT is empty where FW_OPT is
# -Os.
FW_COLD_SRC := rt_tracer rt_dirgrid rt_cutoff rt_sealed rt_scene rt_features \
    fx_trig fx_vec rt_cull
FW_COLD_OPT := $(if $(filter -Os,$(FW_OPT)),,-Os)
$(patsubst %.c,$(FW_BUILD)/%.o,$(foreach n,$(FW_COLD_SRC),$(filter %/$(n).c,$(CORE_SRC)))): \
    FW_EXTRA := $(FW_COLD_OPT)

# libc.c must not have its loops turned back into calls to itself.
$(FW_BUILD)/port/baremetal/libc.o: FW_EXTRA := -fno-tree-loop-distribute-patterns
$(FW_BUILD)/port/baremetal/main.o: $(FW_CONFIG)
$(FW_BUILD)/port/baremetal/dual.o: $(FW_CONFIG)
$(FW_BUILD)/port/baremetal/bringup.o: $(FW_CONFIG)
$(FW_BUILD)/port/baremetal/out_uart.o: $(FW_CONFIG)

$(FW_BUILD)/port/baremetal/%.o: port/baremetal/%.c $(FW_FLAGS_STAMP) \
                                $(FW_EFFECTS)
	@$(if $(Q),echo "  CC      $< ($(BOARD))")
	$(Q)mkdir -p $(@D)
	$(Q)$(FW_CC) $(FW_CFLAGS) $(FW_EXTRA) $(WARN) $(CORE_INC) -Iport/baremetal \
	    -I$(FW_BUILD) -MMD -MP -c $< -o $@

$(FW_BUILD)/scene_tables.o: $(FW_TABLES_C) $(FW_FLAGS_STAMP) $(FW_EFFECTS)
	@$(if $(Q),echo "  CC      $< ($(BOARD))")
	$(Q)$(FW_CC) $(FW_CFLAGS) $(CORE_WARN) $(CORE_INC) -MMD -MP -c $< -o $@

$(FW_BUILD)/scene.o: port/baremetal/scene.S $(FW_CONFIG) $(SCENE) \
                     $(FW_FLAGS_STAMP)
	@$(if $(Q),echo "  AS      $(SCENE) ($(BOARD))")
	$(Q)$(FW_CC) $(FW_CPU) -I$(FW_BUILD) -c $< -o $@

$(FW_ELF): $(FW_OBJ) $(FW_LD) $(FW_FLAGS_STAMP)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(FW_CC) $(FW_LDFLAGS) $(FW_OBJ) -o $@ -lgcc

-include $(patsubst %.o,%.d,$(filter %.o,$(FW_OBJ)))

# ---- Run and measure ----------------------------------------------------------

# The image goes to out.ppm (semihosting stdout), the figures to stderr
# (semihosting stderr) and to qemu.log. The exit status is the firmware's.
# The Debian packages of the board's compiler and QEMU, for messages.
FW_RISCV_BOARD = $(filter $(RISCV_PREFIX),$(FW_PREFIX))
FW_CC_PKG = $(if $(FW_RISCV_BOARD),gcc-riscv64-unknown-elf,gcc-arm-none-eabi)
FW_QEMU_PKG = $(if $(FW_RISCV_BOARD),qemu-system-misc,qemu-system-arm)

# OUTPUT=uart: QEMU's first serial port goes to uart.bin (a file chardev:
# -serial stdio would make stdout non-blocking, PLATFORM.md), which
# `fixtrace receive` checks and turns into out.ppm; the device's text
# arrives on the same line and goes to qemu.log.
FW_UART_BIN := $(FW_BUILD)/uart.bin
FW_QEMU_RUN = $(if $(filter uart,$(OUTPUT)),$(subst -serial none,-chardev \
    file$(comma)id=fwuart$(comma)path=$(FW_UART_BIN) -serial \
    chardev:fwuart,$(FW_QEMU)),$(FW_QEMU))
comma := ,

qemu: $(FW_ELF) $(if $(filter uart,$(OUTPUT)),fw-host-tool)
	$(Q)command -v $(firstword $(FW_QEMU)) >/dev/null || { \
	    echo "$(firstword $(FW_QEMU)) not found; install it with:" \
	    "apt-get install --no-install-recommends $(FW_QEMU_PKG)" >&2; \
	    exit 1; }
	$(Q)rc=0; rm -f $(FW_UART_BIN); timeout $(QEMU_TIMEOUT) $(FW_QEMU_RUN) \
	    -icount shift=$(FW_ICOUNT),align=off,sleep=off -kernel $< \
	    </dev/null >$(FW_BUILD)/out.ppm 2>$(FW_BUILD)/qemu.log || rc=$$?; \
	$(if $(filter uart,$(OUTPUT)),if [ $$rc -ne 124 ]; then \
	    rm -f $(FW_BUILD)/out.ppm; \
	    $(FW_FIXTRACE) receive -o $(FW_BUILD)/out.ppm <$(FW_UART_BIN) \
	        2>>$(FW_BUILD)/qemu.log || { [ $$rc -ne 0 ] || rc=1; \
	        echo "fixtrace receive: no valid frame in $(FW_UART_BIN)" \
	            >>$(FW_BUILD)/qemu.log; }; fi;) \
	cat $(FW_BUILD)/qemu.log >&2; \
	if [ $$rc -eq 124 ]; then \
	    echo "qemu: no exit after $(QEMU_TIMEOUT) s (hang?)" >&2; \
	elif [ $$rc -ne 0 ]; then \
	    echo "qemu: firmware exit status $$rc (see port/baremetal/port.h)" >&2; \
	else \
	    awk '/^instructions /{i=$$2} /^pixels /{p=$$2} END{if (i > 0 && p > 0) \
	        printf "instructions_per_pixel %.1f\n", i / p}' \
	        $(FW_BUILD)/qemu.log >&2; \
	    echo "wrote $(FW_BUILD)/out.ppm" >&2; \
	fi; \
	exit $$rc

# Flash holds .text, .rodata (with the scene, as tables or text),
# .ARM.exidx and the initial .data; RAM holds .data, .bss and the reserved
# stack (on a two-core board, a stack for each core).
size: $(FW_ELF)
	$(Q)$(FW_SIZE) -A $< | awk -v board=$(BOARD) ' \
	    $$1 == ".text" { t = $$2 } $$1 == ".rodata" { r = $$2 } \
	    $$1 == ".ARM.exidx" { x = $$2 } $$1 == ".data" { d = $$2 } \
	    $$1 == ".bss" { b = $$2 } $$1 == ".stack" { s = $$2 } \
	    $$1 == ".stack1" { s1 = $$2 } \
	    END { \
	        printf "%s: flash %d bytes (text %d, rodata %d, exidx %d, data %d)\n", \
	            board, t + r + x + d, t, r, x, d; \
	        printf "%s: ram %d bytes (data %d, bss %d), stack %d reserved%s, total %d\n", \
	            board, d + b, d, b, s, s1 ? sprintf(" (and %d for core 1)", s1) : "", \
	            d + b + s + s1 }'
