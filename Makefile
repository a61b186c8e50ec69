# SPDX-License-Identifier: MIT
# fixtrace: a Q16.16 ray tracer for microcontrollers without an FPU.
#
#   make            build the host renderer (build/posix/fixtrace)
#   make run        render scenes/seed.scene to seed.ppm
#   make test       build and run every test (tests/run.sh)
#   make test-quick the unit tests and the quick host suites (QUICK_SUITES)
#   make firmware BOARD=an385 [SCENE=... WIDTH=... HEIGHT=... SPP=...]
#   make qemu     BOARD=an385 [same]     make size BOARD=an385
#   make SANITIZE=1 test                 host tests under ASan + UBSan
#   make web        the page in build/web/ (WebAssembly); make web-serve
#
# V=1 shows full command lines; `make print-VAR` prints a variable.
# Build output goes under build/<target>/ only.

.DEFAULT_GOAL := all
.SUFFIXES:

V ?= 0
Q := $(if $(filter 1,$(V)),,@)

ifeq ($(origin CC),default)
CC := gcc
endif

# Warnings every build keeps clean. Core code is held to -Wconversion too.
WARN := -Wall -Wextra -Werror -Wshadow -Wundef -Wdouble-promotion \
        -Wstrict-prototypes -Wmissing-prototypes -fno-common
CORE_WARN := $(WARN) -Wconversion -Wno-sign-conversion

# The core's layer folders, lowest first (docs/architecture.md). Every
# file includes its headers by name; CORE_INC puts every folder on the path.
CORE_DIRS := core/fx core/scene core/shapes core/parse core/accel core/trace core/frame
# The shapes' files that their dispatch unit, core/shapes/rt_shape.c,
# includes (its comment says why): compiled there, not on their own.
CORE_INCLUDED := $(addprefix core/shapes/,rt_sphere.c rt_quad.c rt_box.c \
    rt_upright.c)
CORE_SRC := $(filter-out $(CORE_INCLUDED),\
    $(sort $(wildcard $(addsuffix /*.c,$(CORE_DIRS)))))
CORE_HDR := $(sort $(wildcard $(addsuffix /*.h,$(CORE_DIRS))))
CORE_INC := $(addprefix -I,$(CORE_DIRS))
export CORE_INC

include mk/posix.mk
include mk/test.mk
-include mk/firmware.mk
-include mk/fuzz.mk
-include mk/lint.mk
-include mk/bench.mk
-include mk/docs.mk
-include mk/accuracy.mk
-include mk/oled.mk
-include mk/profile.mk
-include mk/dual.mk
-include mk/web.mk

.PHONY: all clean print-%
all: $(FIXTRACE)

clean:
	rm -rf build

print-%:
	@echo '$*=$($*)'
