# SPDX-License-Identifier: MIT
# Static analysis (docs/static-analysis.md says what is checked and why):
#
#   make lint [LINT_JOBS=n]    cppcheck and clang-tidy on core/, port/posix/
#                              and port/baremetal/; fails on any finding
#
# cppcheck runs once per configuration (host; bare metal as Arm and as
# RISC-V). clang-tidy runs once per file (bare-metal files once per
# architecture they build for), in parallel, each writing its findings to
# build/lint/<file>[.<arch>].log; a finding is an error. The tools are
# CPPCHECK and CLANG_TIDY.

CPPCHECK ?= cppcheck
CLANG_TIDY ?= clang-tidy
LINT_BUILD := build/lint
LINT_JOBS ?= $(shell nproc 2>/dev/null || echo 2)

# ---- cppcheck ---------------------------------------------------------------
# shiftTooManyBitsSigned: "x >> 31" of a negative int32 is implementation-
# defined, and the tree relies on arithmetic right shifts by design
# (docs/numerics.md; tests/test_fx.c checks it).
# -URT_CONFIG_FILE: cppcheck would try that configuration with an empty
# value, `#include` of nothing (core/fx/rt_config.h includes the named file).
CPPCHECK_FLAGS := --enable=warning,portability,performance --std=c99 \
    --inline-suppr --error-exitcode=1 --quiet \
    --suppress=shiftTooManyBitsSigned -URT_CONFIG_FILE \
    --template='{file}:{line}:{column}: {severity}: {message} [{id}]'

# The generated firmware header, with the defaults, for analysis only.
LINT_FW_CONFIG := $(LINT_BUILD)/fw_config.h

# ---- clang-tidy ---------------------------------------------------------------
# Whole families, less the checks that only make noise here; each exclusion
# is explained in docs/static-analysis.md.
LINT_TIDY_CHECKS := -*,bugprone-*,cert-*,clang-analyzer-*,misc-*,\
performance-*,portability-*,\
-bugprone-easily-swappable-parameters,\
-bugprone-implicit-widening-of-multiplication-result,\
-bugprone-narrowing-conversions,\
-cert-err33-c,\
-clang-analyzer-security.insecureAPI.strcpy,\
-clang-analyzer-valist.Uninitialized,\
-misc-no-recursion

LINT_RESERVED_OK := _start;_sidata;_sdata;_edata;_sbss;_ebss;_sstack;_estack;\
    _sstack1;_estack1
LINT_TIDY_CONFIG := {CheckOptions: [\
{key: bugprone-signed-char-misuse.CharTypdefsToIgnore, value: int8_t},\
{key: cert-str34-c.CharTypdefsToIgnore, value: int8_t},\
{key: bugprone-suspicious-string-compare.WarnOnImplicitComparison, value: false},\
{key: bugprone-reserved-identifier.AllowedIdentifiers, value: '$(LINT_RESERVED_OK)'},\
{key: cert-dcl37-c.AllowedIdentifiers, value: '$(LINT_RESERVED_OK)'},\
{key: cert-dcl51-cpp.AllowedIdentifiers, value: '$(LINT_RESERVED_OK)'}]}

# The analyzer follows calls 10 deep instead of 5: helpers deep below an
# entry point otherwise lose their error returns and are reported as
# impossible paths.
LINT_TIDY_FLAGS := --quiet --warnings-as-errors='*' \
    --header-filter='.*/(core|port)/.*' \
    --extra-arg=-Xclang --extra-arg=-analyzer-inline-max-stack-depth=10

# Per-file exclusions, for analyzer false positives that need a change to
# the file to go away (docs/static-analysis.md, "Per-file exclusions").
LINT_TIDY_NOT_port/posix/main.c := ,-clang-analyzer-core.NonNullParamChecker,\
-bugprone-not-null-terminated-result
LINT_TIDY_NOT_port/baremetal/main.c := ,-bugprone-branch-clone
# The shapes' dispatch unit includes the shapes' files on purpose, so that
# each hit test inlines into the switch (its comment says why).
LINT_TIDY_NOT_core/shapes/rt_shape.c := ,-bugprone-suspicious-include
# Bare metal reaches registers through integer addresses by nature.
LINT_TIDY_NOT_BAREMETAL := ,-performance-no-int-to-ptr

LINT_HOST_SRC := $(CORE_SRC) $(sort $(wildcard port/posix/*.c))
LINT_BM_SRC := $(sort $(wildcard port/baremetal/*.c))

# Bare-metal architectures: the board files build for one, the shared files
# for both (they hold an #if branch for each).
LINT_ARCH_arm := --target=arm-none-eabi -mcpu=cortex-m3 -mthumb
LINT_ARCH_m33 := --target=arm-none-eabi -mcpu=cortex-m33 -mthumb \
    -mfloat-abi=soft
LINT_ARCH_rv32 := --target=riscv32-unknown-elf -march=rv32imac -mabi=ilp32
lint_bm_arch = $(if $(filter %_rv32.c,$1),rv32,$(if $(filter \
    %_an505.c %_an521.c %/dual.c,$1),m33,$(if $(filter %_an385.c %_microbit.c %_lm3s6965.c \
    %_cortexm.c,$1),arm,arm rv32)))

LINT_HOST_LOGS := $(LINT_HOST_SRC:%=$(LINT_BUILD)/%.log)
LINT_BM_LOGS := $(foreach f,$(LINT_BM_SRC),$(foreach a,$(call \
    lint_bm_arch,$f),$(LINT_BUILD)/$f.$a.log))
LINT_CPPCHECK_LOGS := $(LINT_BUILD)/cppcheck-host.log \
    $(LINT_BUILD)/cppcheck-arm.log $(LINT_BUILD)/cppcheck-rv32.log
LINT_LOGS := $(LINT_CPPCHECK_LOGS) $(LINT_HOST_LOGS) $(LINT_BM_LOGS)

.PHONY: lint lint-all lint-tools lint-force
lint: lint-tools
	$(Q)rm -f $(LINT_BUILD)/failed
	$(Q)$(MAKE) --no-print-directory -k -j$(LINT_JOBS) lint-all || true
	$(Q)n=$(words $(LINT_LOGS)); \
	if [ -s $(LINT_BUILD)/failed ]; then \
	    f=$$(sort -u $(LINT_BUILD)/failed | wc -l); \
	    echo "lint: findings in $$f of $$n runs:"; \
	    for l in $$(sort -u $(LINT_BUILD)/failed); do \
	        echo "--- $$l"; grep -vE '^[0-9]+ warnings? generated\.$$' "$$l"; \
	    done; \
	    echo "lint: $$f of $$n runs failed"; exit 1; \
	fi; \
	echo "lint: $$n runs clean (cppcheck $$($(CPPCHECK) --version | \
	    sed 's/^Cppcheck //'), clang-tidy $$($(CLANG_TIDY) --version | \
	    sed -nE 's/.*version ([0-9.]+).*/\1/p' | head -n 1))"

lint-tools:
	$(Q)for t in $(CPPCHECK) $(CLANG_TIDY); do \
	    command -v $$t >/dev/null || { echo "lint: $$t not found" >&2; \
	        exit 1; }; \
	done

lint-all: $(LINT_LOGS)

# A run records its log; when it fails, the log's name goes to the list.
lint_run = { $1; } >$@ 2>&1 || echo $@ >>$(LINT_BUILD)/failed

# Every FW_* name mk/firmware.mk writes into fw_config.h, as 0 (the scene
# file as a string), so the stub follows the real header.
LINT_FW_MK := $(wildcard mk/firmware.mk)
$(LINT_FW_CONFIG): $(LINT_FW_MK)
	$(Q)mkdir -p $(@D)
	$(Q){ echo '/* Stub for static analysis (mk/lint.mk). */'; \
	for n in $$( { grep -oE "#define FW_[A-Z0-9_]+" $(or $(LINT_FW_MK),\
	        /dev/null); echo '#define FW_SCENE_FILE'; } | \
	        sed 's/^#define //' | sort -u); do \
	    if [ $$n = FW_SCENE_FILE ]; then \
	        echo '#define FW_SCENE_FILE "scenes/seed.scene"'; \
	    else echo "#define $$n 0"; fi; \
	done; } >$@

# The host code twice: as built by default (everything kept) and with
# every RT_NO_* flag of the feature list and RT_NO_DRAFT, the two ends of
# what a build can remove. Left to choose, cppcheck would try a dozen
# combinations of its own (four times the time) and still not these two.
LINT_FEATURE_SED := 's/^ *X\(([A-Z]+), .*/\1/p'
LINT_NO_ALL := $(patsubst %,-DRT_NO_%,$(shell sed -nE $(LINT_FEATURE_SED) \
    core/scene/rt_features.h) DRAFT)
$(LINT_BUILD)/cppcheck-host.log: lint-force
	@$(if $(Q),echo "  CPPCHECK core/ port/posix/")
	$(Q)mkdir -p $(@D)
	$(Q)$(call lint_run,$(CPPCHECK) $(CPPCHECK_FLAGS) --max-configs=1 \
	    $(CORE_INC) -Iport/posix core/ port/posix/ && \
	    $(CPPCHECK) $(CPPCHECK_FLAGS) $(LINT_NO_ALL) $(CORE_INC) \
	    -Iport/posix core/ port/posix/)

$(LINT_BUILD)/cppcheck-%.log: lint-force $(LINT_FW_CONFIG)
	@$(if $(Q),echo "  CPPCHECK port/baremetal/ ($*)")
	$(Q)$(call lint_run,$(CPPCHECK) $(CPPCHECK_FLAGS) \
	    $(if $(filter rv32,$*),-D__riscv,-D__arm__) $(CORE_INC) \
	    -Iport/baremetal -I$(LINT_BUILD) port/baremetal/)

$(LINT_BUILD)/%.c.log: %.c lint-force
	@$(if $(Q),echo "  TIDY    $<")
	$(Q)mkdir -p $(@D)
	$(Q)$(call lint_run,$(CLANG_TIDY) $(LINT_TIDY_FLAGS) \
	    -checks='$(LINT_TIDY_CHECKS)$(LINT_TIDY_NOT_$<)' \
	    --config="$(LINT_TIDY_CONFIG)" $< -- -std=c99 \
	    -D_POSIX_C_SOURCE=200809L $(CORE_INC) -Iport/posix)

# port/baremetal/x.c.<arch>.log
define lint_bm_rule
$(LINT_BUILD)/%.c.$1.log: %.c lint-force $(LINT_FW_CONFIG)
	@$$(if $$(Q),echo "  TIDY    $$< ($1)")
	$$(Q)mkdir -p $$(@D)
	$$(Q)$$(call lint_run,$$(CLANG_TIDY) $$(LINT_TIDY_FLAGS) \
	    -checks='$$(LINT_TIDY_CHECKS)$$(LINT_TIDY_NOT_BAREMETAL)$$(strip \
	    )$$(LINT_TIDY_NOT_$$<)' \
	    --config="$$(LINT_TIDY_CONFIG)" $$< -- -std=c99 -ffreestanding \
	    $$(LINT_ARCH_$1) $(CORE_INC) -Iport/baremetal -I$(LINT_BUILD))
endef
$(foreach a,arm m33 rv32,$(eval $(call lint_bm_rule,$a)))

lint-force:
