# SPDX-License-Identifier: MIT
# Tests: every tests/test_*.c is its own binary (one topic each); the
# harness and all non-CLI host code link in. tests/run.sh runs them and the
# script-level suites, and prints the final "N passed, N failed" line.

TEST_SRC := $(sort $(wildcard tests/test_*.c))
TEST_BIN := $(TEST_SRC:tests/%.c=$(HOST_BUILD)/tests/%)
TEST_HARNESS_OBJ := $(HOST_BUILD)/tests/harness.o

$(HOST_BUILD)/tests/%.o: tests/%.c $(HOST_STAMP) | $(HOST_BUILD)/tests
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) -Wno-missing-prototypes $(CORE_INC) \
	    -Iport/posix -Itests -MMD -MP -c $< -o $@

$(HOST_BUILD)/tests/test_%: $(HOST_BUILD)/tests/test_%.o $(TEST_HARNESS_OBJ) \
                            $(HOST_CORE_OBJ) $(HOST_PORT_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_LDFLAGS) $^ -o $@ $(HOST_LIBS)

# test_stability is its runner plus the case files in tests/stability/
# (not named test_*.c, so they are no binaries of their own).
STAB_SRC := $(sort $(wildcard tests/stability/*.c))
STAB_OBJ := $(STAB_SRC:tests/%.c=$(HOST_BUILD)/tests/%.o)
$(HOST_BUILD)/tests/test_stability: $(STAB_OBJ)
$(HOST_BUILD)/tests/stability/%.o: tests/stability/%.c $(HOST_STAMP) \
                                   | $(HOST_BUILD)/tests/stability
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) -Wno-missing-prototypes $(CORE_INC) \
	    -Iport/posix -Itests -Itests/stability -MMD -MP -c $< -o $@

$(HOST_BUILD)/tests $(HOST_BUILD)/tests/stability:
	$(Q)mkdir -p $@

# Objects are made by pattern rules; keep them (make would otherwise delete
# the harness object as an intermediate between two test links).
.SECONDARY:

-include $(TEST_SRC:tests/%.c=$(HOST_BUILD)/tests/%.d)
-include $(STAB_OBJ:.o=.d)

# The random scene generator of the randomized differential test
# (tools/random_test.sh): a host tool, not a unit-test binary.
RANDSCENE := $(HOST_BUILD)/tests/randscene
$(RANDSCENE): tests/randscene.c $(HOST_STAMP) | $(HOST_BUILD)/tests
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) $(HOST_LDFLAGS) $< -o $@ -lm

# Its verdict on one scene's renders (speckles against the reference).
RANDJUDGE := $(HOST_BUILD)/tests/randjudge
$(RANDJUDGE): tests/randjudge.c $(HOST_PORT_OBJ) $(HOST_CORE_OBJ) \
              | $(HOST_BUILD)/tests
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) -Iport/posix $(CORE_INC) $(HOST_LDFLAGS) \
	    $< $(HOST_PORT_OBJ) $(HOST_CORE_OBJ) -o $@ $(HOST_LIBS)

# The POV-Ray translator of tests/suite_povray.sh: reads a scene with the
# core's parser.
SCENE2POV := $(HOST_BUILD)/tests/scene2pov
$(SCENE2POV): tests/scene2pov.c $(HOST_CORE_OBJ) | $(HOST_BUILD)/tests
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) $(CORE_INC) $(HOST_LDFLAGS) $< \
	    $(HOST_CORE_OBJ) -o $@ -lm

.PHONY: test test-build test-quick random-test
test-build: $(FIXTRACE) $(TEST_BIN) $(RANDSCENE) $(RANDJUDGE) $(SCENE2POV)

# Many more random scenes than make test runs: make random-test
# [RANDOM_FIRST=1] [RANDOM_COUNT=5000].
RANDOM_FIRST ?= 1
RANDOM_COUNT ?= 5000
random-test: $(FIXTRACE) $(RANDSCENE) $(RANDJUDGE)
	$(Q)HOST_BUILD=$(HOST_BUILD) bash tools/random_test.sh $(RANDOM_FIRST) \
	    $(RANDOM_COUNT)

test: test-build
	$(Q)HOST_BUILD=$(HOST_BUILD) SANITIZE=$(SANITIZE) MAKE="$(MAKE)" \
	    bash tests/run.sh

# The edit-compile loop: every unit binary and the quick host suites (no
# QEMU, no fuzzing, no lint), under a minute on two cores. `make test`
# before committing.
QUICK_SUITES ?= cli png reference
test-quick: test-build
	$(Q)HOST_BUILD=$(HOST_BUILD) SANITIZE=$(SANITIZE) MAKE="$(MAKE)" \
	    TEST_SUITES="$(QUICK_SUITES)" bash tests/run.sh

.PHONY: update-checksums
# Re-records the end-to-end render checksums after an intended image change.
update-checksums: $(HOST_BUILD)/tests/test_render
	UPDATE_CHECKSUMS=1 $(HOST_BUILD)/tests/test_render
