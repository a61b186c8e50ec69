# SPDX-License-Identifier: MIT
# Where a firmware's instructions go (port/baremetal/README.md):
#
#   make profile BOARD=b [SCENE=... WIDTH=w HEIGHT=h SPP=n] [PROFILE=opts]
#
# runs the firmware under QEMU as `make qemu` does (-icount, the same
# image), with tools/profile/insncount.c loaded as a TCG plugin, and
# writes build/<b>/profile.md: self instructions per pixel per function.
# PROFILE passes options to tools/profile/report.py: --inline (per
# innermost inlined function), --lines N (the N hottest source lines),
# --inclusive (inclusive, self and calls per function, and a table by
# ray depth, the frames of --depth-fn NAME, default trace, on the
# stack). With --inclusive the plugin is tools/profile/callstack.c
# instead, a shadow call stack, given the function entries of the ELF
# from nm ($(FW_BUILD)/profile-entries.txt); profile.txt then holds
# counts per call context and block. Arm (Thumb) boards only.

PROF_INCL := $(filter --inclusive,$(PROFILE))
PROF_PLUGIN := $(HOST_BUILD)/tools/$(if $(PROF_INCL),callstack,insncount).so
PROF_COUNTS := $(FW_BUILD)/profile.txt
PROF_ENTRIES := $(FW_BUILD)/profile-entries.txt
PROF_ENTRY_ARG = $(if $(PROF_INCL),$(comma)entries=$(PROF_ENTRIES))

$(HOST_BUILD)/tools/%.so: tools/profile/%.c tools/profile/qemu_plugin.h
	@$(if $(Q),echo "  CC      $@")
	$(Q)mkdir -p $(@D)
	$(Q)$(CC) -O2 -Wall -Wextra -shared -fPIC -o $@ $<

# Function entries: text and weak symbols (bit 0, Thumb, the plugin drops),
# without the mapping symbols ($t, $d).
$(PROF_ENTRIES): $(FW_ELF)
	$(Q)$(FW_PREFIX)nm --defined-only $< | \
	    sed -n 's/^\([0-9a-fA-F]*\) [tTwW] [^$$].*/\1/p' >$@.tmp
	$(Q)mv -f $@.tmp $@

.PHONY: profile
profile: $(FW_ELF) $(PROF_PLUGIN) $(if $(PROF_INCL),$(PROF_ENTRIES))
	$(if $(and $(PROF_INCL),$(FW_RISCV_BOARD)),$(Q)echo "PROFILE=--inclusive" \
	    "reads Thumb code only (Arm boards); $(BOARD) is RISC-V" >&2; exit 1)
	$(Q)command -v $(firstword $(FW_QEMU)) >/dev/null || { \
	    echo "$(firstword $(FW_QEMU)) not found; install it with:" \
	    "apt-get install --no-install-recommends $(FW_QEMU_PKG)" >&2; \
	    exit 1; }
	$(Q)command -v python3 >/dev/null || { echo "python3 not found;" \
	    "install it with: apt-get install --no-install-recommends" \
	    "python3" >&2; exit 1; }
	$(Q)rm -f $(PROF_COUNTS) $(FW_BUILD)/profile.md; \
	timeout $(QEMU_TIMEOUT) $(FW_QEMU) \
	    -icount shift=$(FW_ICOUNT),align=off,sleep=off -kernel $< \
	    -plugin $(PROF_PLUGIN),out=$(PROF_COUNTS)$(PROF_ENTRY_ARG) \
	    </dev/null >$(FW_BUILD)/profile.ppm 2>$(FW_BUILD)/profile.log || { \
	    rc=$$?; cat $(FW_BUILD)/profile.log >&2; \
	    echo "qemu: exit status $$rc under the profiler" >&2; exit 1; }
	$(Q)test -f $(PROF_COUNTS) || { \
	    grep -E '^(insncount|callstack):' $(FW_BUILD)/profile.log >&2; \
	    echo "the plugin wrote no $(PROF_COUNTS)" >&2; exit 1; }
	$(Q)python3 tools/profile/report.py --tools $(FW_PREFIX) $(PROFILE) \
	    $< $(PROF_COUNTS) $(FW_BUILD)/profile.log \
	    >$(FW_BUILD)/profile.md.tmp || { \
	    rm -f $(FW_BUILD)/profile.md.tmp; exit 1; }
	$(Q)mv -f $(FW_BUILD)/profile.md.tmp $(FW_BUILD)/profile.md
	$(Q)head -n 16 $(FW_BUILD)/profile.md
	@echo "wrote $(FW_BUILD)/profile.md"
