# SPDX-License-Identifier: MIT
# Fuzzing the scene parser and the renderers behind it (tests/fuzz/):
#
#   make fuzz [FUZZ_SECONDS=60 FUZZ_JOBS=1]   fuzz, then print the totals
#   make fuzz-build                           only build build/fuzz/fuzz_scene
#   make fuzz-repro                           run the seeds and regressions once
#
# The harness is built with clang's libFuzzer, ASan and UBSan, every UBSan
# finding fatal. A run works on build/fuzz/corpus (the repository's seeds,
# scenes/*.scene and tests/fuzz/regressions/ are merged into it first, and
# what the run discovers stays there for the next run); the repository's
# files are never written. A crash exits non-zero and leaves its input in
# build/fuzz/crashes/. FUZZ_JOBS > 1 runs that many fuzzers side by side on
# the shared corpus. tests/fuzz/fuzz.sh does the running.

FUZZ_CC ?= clang
FUZZ_BUILD := build/fuzz
FUZZ_BIN := $(FUZZ_BUILD)/fuzz_scene
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
# Room for RT_MAX_OBJECTS + 1 of the shortest object lines (~40 bytes), so
# the capacity error stays reachable.
FUZZ_MAX_LEN ?= 6144

FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
# Warnings are shown but not fatal: clang's set differs from gcc's, and the
# gcc builds already hold the tree to -Werror.
FUZZ_CFLAGS := -std=c99 -O1 -g -D_POSIX_C_SOURCE=200809L -Wall -Wextra \
               $(FUZZ_SAN) $(CORE_INC) -Iport/posix

FUZZ_SRC := $(CORE_SRC) port/posix/ref_render.c port/posix/ref_shapes.c \
    port/posix/ref_mesh.c
FUZZ_OBJ := $(FUZZ_SRC:%.c=$(FUZZ_BUILD)/%.o)
FUZZ_MAIN_OBJ := $(FUZZ_BUILD)/tests/fuzz/fuzz_scene.o

# Library code gets coverage instrumentation only; libFuzzer's main() comes
# in at the link.
$(FUZZ_BUILD)/%.o: %.c
	@$(if $(Q),echo "  CC      $< (fuzz)")
	$(Q)mkdir -p $(@D)
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -MMD -MP \
	    -c $< -o $@

$(FUZZ_BIN): $(FUZZ_OBJ) $(FUZZ_MAIN_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(FUZZ_CC) $(FUZZ_SAN) -fsanitize=fuzzer $^ -o $@ -lm

-include $(FUZZ_OBJ:.o=.d) $(FUZZ_MAIN_OBJ:.o=.d)

.PHONY: fuzz fuzz-build fuzz-repro
fuzz-build: $(FUZZ_BIN)

fuzz: $(FUZZ_BIN)
	$(Q)FUZZ_BIN=$(FUZZ_BIN) FUZZ_DIR=$(FUZZ_BUILD) \
	    FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_JOBS=$(FUZZ_JOBS) \
	    FUZZ_MAX_LEN=$(FUZZ_MAX_LEN) bash tests/fuzz/fuzz.sh run

fuzz-repro: $(FUZZ_BIN)
	$(Q)FUZZ_BIN=$(FUZZ_BIN) FUZZ_DIR=$(FUZZ_BUILD) \
	    bash tests/fuzz/fuzz.sh repro
