# SPDX-License-Identifier: MIT
# Each core's instructions on a two-core board (port/baremetal/dual.c):
#
#   make dual-count BOARD=an521 [SCENE=... WIDTH=w HEIGHT=h SPP=n]
#
# runs the firmware under QEMU as `make qemu` does (the same image, the
# same -icount), with tools/profile/vcpucount.c as a TCG plugin that counts
# the instructions each core retires in its frame: from the core's call of
# dual_mark_start() to its call of dual_mark_end() after its last row, and
# of those the ones in its wait functions (_swait.._ewait, the linker
# script). It prints the firmware's figures, then "coreN_frame" and
# "coreN_wait" for each core; the image goes to build/<b>/out.ppm.
#
#   make dual-table [DUAL_ARGS=...]
#
# runs tools/dual_table.sh: every scene of `make bench` at 320x240, 1 spp,
# on the an505 (one Cortex-M33) and the an521 (two), written to
# docs/dual-core.md.

DUAL_PLUGIN := $(HOST_BUILD)/tools/vcpucount.so
DUAL_COUNTS := $(FW_BUILD)/vcpucount.txt
# An address from the ELF's symbols, for the plugin's arguments.
dual_sym = $$($(FW_PREFIX)nm $< | awk '$$3 == "$1" { print $$1 }')

.PHONY: dual-count dual-table
dual-count: $(FW_ELF) $(DUAL_PLUGIN)
	$(Q)grep -q 'FW_CORES=2' mk/boards/$(BOARD).mk || { echo "dual-count:" \
	    "BOARD=$(BOARD) has one core (FW_CORES=2 in its mk/boards file)" >&2; \
	    exit 1; }
	$(Q)command -v $(firstword $(FW_QEMU)) >/dev/null || { \
	    echo "$(firstword $(FW_QEMU)) not found; install it with:" \
	    "apt-get install --no-install-recommends $(FW_QEMU_PKG)" >&2; \
	    exit 1; }
	$(Q)rm -f $(DUAL_COUNTS); rc=0; timeout $(QEMU_TIMEOUT) $(FW_QEMU) \
	    -icount shift=$(FW_ICOUNT),align=off,sleep=off -kernel $< \
	    -plugin $(DUAL_PLUGIN),out=$(DUAL_COUNTS),start=$(call \
	    dual_sym,dual_mark_start),end=$(call dual_sym,dual_mark_end),wait=$(call \
	    dual_sym,_swait)-$(call dual_sym,_ewait) \
	    </dev/null >$(FW_BUILD)/out.ppm 2>$(FW_BUILD)/qemu.log || rc=$$?; \
	cat $(FW_BUILD)/qemu.log >&2; \
	if [ $$rc -ne 0 ]; then \
	    echo "qemu: firmware exit status $$rc (see port/baremetal/port.h)" >&2; \
	    exit $$rc; fi; \
	test -f $(DUAL_COUNTS) || { echo "the plugin wrote no $(DUAL_COUNTS)" >&2; \
	    exit 1; }; \
	awk '$$1 == "vcpu" && $$3 == "frame" { print "core" $$2 "_frame " $$4; \
	        print "core" $$2 "_wait " $$6; n++ } \
	    $$1 == "vcpu" && $$3 != "frame" { print "core " $$2 " never reached" \
	        " the end of its frame" >"/dev/stderr"; bad = 1 } \
	    END { if (n != 2 || bad) { print "dual-count: expected two cores" \
	        " with a frame each" >"/dev/stderr"; exit 1 } }' $(DUAL_COUNTS)

# The plugin is built by mk/profile.mk's rule for tools/profile/*.c.

dual-table:
	$(Q)MAKE="$(MAKE)" bash tools/dual_table.sh $(DUAL_ARGS)
