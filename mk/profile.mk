# SPDX-License-Identifier: MIT
# Where a firmware's instructions go (port/baremetal/README.md):
#
#   make profile BOARD=b [SCENE=... WIDTH=w HEIGHT=h SPP=n] [PROFILE=opts]
#
# runs the firmware under QEMU as `make qemu` does (-icount, the same
# image), with tools/profile/insncount.c loaded as a TCG plugin, and
# writes build/<b>/profile.md: self instructions per pixel per function.
# PROFILE passes options to tools/profile/report.py: --inline (per
# innermost inlined function), --lines N (the N hottest source lines).

PROF_PLUGIN := $(HOST_BUILD)/tools/insncount.so
PROF_COUNTS := $(FW_BUILD)/profile.txt

$(PROF_PLUGIN): tools/profile/insncount.c
	@$(if $(Q),echo "  CC      $@")
	$(Q)mkdir -p $(@D)
	$(Q)$(CC) -O2 -Wall -Wextra -shared -fPIC -o $@ $<

.PHONY: profile
profile: $(FW_ELF) $(PROF_PLUGIN)
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
	    -plugin $(PROF_PLUGIN),out=$(PROF_COUNTS) \
	    </dev/null >$(FW_BUILD)/profile.ppm 2>$(FW_BUILD)/profile.log || { \
	    rc=$$?; cat $(FW_BUILD)/profile.log >&2; \
	    echo "qemu: exit status $$rc under the profiler" >&2; exit 1; }
	$(Q)python3 tools/profile/report.py --tools $(FW_PREFIX) $(PROFILE) \
	    $< $(PROF_COUNTS) $(FW_BUILD)/profile.log \
	    >$(FW_BUILD)/profile.md.tmp || { \
	    rm -f $(FW_BUILD)/profile.md.tmp; exit 1; }
	$(Q)mv -f $(FW_BUILD)/profile.md.tmp $(FW_BUILD)/profile.md
	$(Q)head -n 16 $(FW_BUILD)/profile.md
	@echo "wrote $(FW_BUILD)/profile.md"
