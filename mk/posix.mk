# SPDX-License-Identifier: MIT
# Host build: the core, the POSIX port and the double reference renderer.

ifeq ($(SANITIZE),1)
HOST_BUILD ?= build/posix-san
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all \
             -fno-omit-frame-pointer
else
HOST_BUILD ?= build/posix
SAN_FLAGS :=
endif

HOST_OPT ?= -O2
# RT_DEFS: core configuration for this build, e.g. -DRT_NO_REFRACTION.
RT_DEFS ?=
HOST_CFLAGS ?= -std=c99 $(HOST_OPT) -g -D_POSIX_C_SOURCE=200809L $(SAN_FLAGS) \
               $(RT_DEFS)
HOST_LDFLAGS ?= $(SAN_FLAGS)
HOST_LIBS := -lm -lpthread

# port/posix/main.c is the CLI; everything else there is a library the tests
# link too.
POSIX_MAIN := port/posix/main.c
POSIX_LIB_SRC := $(filter-out $(POSIX_MAIN),$(sort $(wildcard port/posix/*.c)))

HOST_CORE_OBJ := $(CORE_SRC:%.c=$(HOST_BUILD)/%.o)
# The reference renderer a second time in float32 (port/posix/ref32.h):
# its objects go under $(HOST_BUILD)/ref32/ with ref32_ names.
REF32_SRC := $(sort $(wildcard port/posix/ref_*.c))
REF32_OBJ := $(REF32_SRC:%.c=$(HOST_BUILD)/ref32/%.o)
HOST_PORT_OBJ := $(POSIX_LIB_SRC:%.c=$(HOST_BUILD)/%.o) $(REF32_OBJ)
HOST_MAIN_OBJ := $(POSIX_MAIN:%.c=$(HOST_BUILD)/%.o)
HOST_ALL_OBJ := $(HOST_CORE_OBJ) $(HOST_PORT_OBJ) $(HOST_MAIN_OBJ)

FIXTRACE := $(HOST_BUILD)/fixtrace

# The flags a build directory was made with: objects depend on this file,
# which changes only when the flags do, so reusing a directory with other
# flags (SANITIZE=1, RT_DEFS=...) rebuilds instead of linking stale objects.
HOST_STAMP := $(HOST_BUILD)/cflags.txt
$(HOST_STAMP): host-force
	$(Q)mkdir -p $(@D)
	$(Q)echo '$(CC) $(HOST_CFLAGS) $(HOST_LDFLAGS)' >$@.tmp; \
	if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

.PHONY: host-force
host-force:

$(HOST_ALL_OBJ): $(HOST_STAMP)

$(HOST_BUILD)/core/%.o: core/%.c
	@$(if $(Q),echo "  CC      $<")
	$(Q)mkdir -p $(@D)
	$(Q)$(CC) $(HOST_CFLAGS) $(CORE_WARN) $(CORE_INC) -MMD -MP -c $< -o $@

$(HOST_BUILD)/port/posix/%.o: port/posix/%.c | $(HOST_BUILD)/port/posix
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) $(CORE_INC) -Iport/posix -MMD -MP -c $< -o $@

$(HOST_BUILD)/ref32/port/posix/%.o: port/posix/%.c port/posix/ref32.h
	@$(if $(Q),echo "  CC      $< (float32)")
	$(Q)mkdir -p $(@D)
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) -fsingle-precision-constant \
	    -include port/posix/ref32.h $(CORE_INC) -Iport/posix -MMD -MP \
	    -c $< -o $@

$(FIXTRACE): $(HOST_ALL_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_LDFLAGS) $^ -o $@ $(HOST_LIBS)

$(HOST_BUILD)/port/posix:
	$(Q)mkdir -p $@

-include $(HOST_ALL_OBJ:.o=.d)

.PHONY: run
run: $(FIXTRACE)
	$(FIXTRACE) -q -W 640 -H 480 -o seed.ppm scenes/seed.scene
	@echo "wrote $(CURDIR)/seed.ppm (640x480)"

# The model generator (tools/mkmodel.c) and the gallery's models, made by
# it: `make models` regenerates scenes/models/.
MKMODEL := $(HOST_BUILD)/mkmodel
$(MKMODEL): tools/mkmodel.c $(HOST_CORE_OBJ) $(HOST_PORT_OBJ) $(HOST_STAMP)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(HOST_CFLAGS) $(WARN) $(CORE_INC) -Iport/posix $(HOST_LDFLAGS) \
	    tools/mkmodel.c $(HOST_PORT_OBJ) $(HOST_CORE_OBJ) -o $@ $(HOST_LIBS)

.PHONY: models
models: $(MKMODEL)
	$(Q)mkdir -p scenes/models
	$(Q)$(MKMODEL) icosphere 3 >scenes/models/icosphere.obj
	$(Q)$(MKMODEL) torus 32 16 >scenes/models/torus.obj
