# SPDX-License-Identifier: MIT
# The browser page (port/wasm/README.md):
#
#   make web          the core, the double reference and the OBJ reader
#                     as WebAssembly, and the page, in build/web/ (open index.html through
#                     a server: browsers fetch no WebAssembly from file://)
#   make web-serve    serves build/web/ on http://127.0.0.1:$(WEB_PORT)/
#   make web-screenshot  docs/img/web.png, the page in headless Chromium
#   make web-cost-fit refits the page's microcontroller cost model
#                     (port/wasm/cost_model.js) from `make qemu`
#
# clang builds for wasm32 with no C library and no runtime (no Emscripten);
# wasm-ld (Debian package lld) links. port/wasm/libc.c has the memory
# functions, port/wasm/libm.c the reference's maths.

WASM_CC ?= clang
WASM_LD ?= wasm-ld
WEB_BUILD ?= build/web
WEB_PORT ?= 8000
# Objects beside the served folder, not in it.
WEB_OBJ_DIR := $(WEB_BUILD)-obj

WASM_CFLAGS := --target=wasm32 -std=c99 -O2 -ffreestanding -nostdlib \
    -mbulk-memory -fno-common -ffunction-sections -fdata-sections
# The host's own files for the reference and the OBJ reader, unchanged:
# their C library is port/wasm's (include/, libc.c, libm.c, heap.c,
# format.c).
WASM_HOST_SRC := port/posix/ref_render.c port/posix/ref_shapes.c \
    port/posix/ref_mesh.c port/posix/mesh_obj.c port/posix/mesh_build.c
WASM_PORT_SRC := port/wasm/api.c port/wasm/mesh.c port/wasm/libc.c \
    port/wasm/libm.c port/wasm/heap.c port/wasm/format.c
WASM_SRC := $(CORE_SRC) $(WASM_PORT_SRC) $(WASM_HOST_SRC)
WASM_OBJ := $(WASM_SRC:%.c=$(WEB_OBJ_DIR)/%.o)
# Changed flags rebuild every object: they are kept in this stamp.
WASM_STAMP := $(WEB_OBJ_DIR)/flags.txt
WASM := $(WEB_BUILD)/fixtrace.wasm
# A stack of 1 MiB: the reference keeps its double copy of the scene on
# it. The heap (port/wasm/heap.c) grows the memory, up to 256 MiB. No
# import: the module needs nothing from JavaScript.
WASM_LDFLAGS := --no-entry --gc-sections -z stack-size=1048576 \
    --max-memory=268435456 --strip-all

WEB_PAGE := $(WEB_BUILD)/index.html $(WEB_BUILD)/style.css \
    $(WEB_BUILD)/app.js $(WEB_BUILD)/compare.js $(WEB_BUILD)/cost_model.js
WEB_SCENES := $(patsubst scenes/%,$(WEB_BUILD)/scenes/%,\
    $(wildcard scenes/*.scene) $(wildcard scenes/models/*.obj))

.PHONY: web web-serve web-screenshot web-cost-fit web-check-tools web-force
web: $(WASM) $(WEB_PAGE) $(WEB_BUILD)/scenes/index.txt

web-check-tools:
	@command -v $(WASM_CC) >/dev/null || { echo "$(WASM_CC) not found;" \
	    "install it with: apt-get install --no-install-recommends clang" >&2; \
	    exit 1; }
	@command -v $(WASM_LD) >/dev/null || { echo "$(WASM_LD) not found;" \
	    "install it with: apt-get install --no-install-recommends lld" >&2; \
	    exit 1; }

$(WASM_STAMP): web-force | web-check-tools
	$(Q)mkdir -p $(@D)
	$(Q)echo '$(WASM_CC) $(WASM_CFLAGS) $(WASM_LD) $(WASM_LDFLAGS)' \
	    >$@.tmp && if cmp -s $@.tmp $@; then rm -f $@.tmp; \
	    else mv -f $@.tmp $@; fi

$(WEB_OBJ_DIR)/core/%.o: core/%.c $(WASM_STAMP) | web-check-tools
	@$(if $(Q),echo "  CC      $< (wasm)")
	$(Q)mkdir -p $(@D)
	$(Q)$(WASM_CC) $(WASM_CFLAGS) $(CORE_WARN) $(CORE_INC) -MMD -MP -c $< -o $@

$(WEB_OBJ_DIR)/port/wasm/%.o: port/wasm/%.c $(WASM_STAMP) | web-check-tools
	@$(if $(Q),echo "  CC      $< (wasm)")
	$(Q)mkdir -p $(@D)
	$(Q)$(WASM_CC) $(WASM_CFLAGS) $(WARN) -Iport/wasm/include $(CORE_INC) \
	    -Iport/posix -MMD -MP -c $< -o $@

$(WEB_OBJ_DIR)/port/posix/%.o: port/posix/%.c $(WASM_STAMP) | web-check-tools
	@$(if $(Q),echo "  CC      $< (wasm)")
	$(Q)mkdir -p $(@D)
	$(Q)$(WASM_CC) $(WASM_CFLAGS) $(WARN) -Iport/wasm/include $(CORE_INC) \
	    -Iport/posix -MMD -MP -c $< -o $@

$(WASM): $(WASM_OBJ) $(WASM_STAMP)
	@$(if $(Q),echo "  LD      $@")
	$(Q)mkdir -p $(@D)
	$(Q)$(WASM_LD) $(WASM_LDFLAGS) $(WASM_OBJ) -o $@.tmp && mv -f $@.tmp $@

$(WEB_BUILD)/%: port/wasm/web/%
	$(Q)mkdir -p $(@D)
	$(Q)cp $< $@
$(WEB_BUILD)/cost_model.js: port/wasm/cost_model.js
	$(Q)mkdir -p $(@D)
	$(Q)cp $< $@

web-force:

# Every scene (and the meshes they name) beside the page, and their list.
$(WEB_BUILD)/scenes/%: scenes/%
	$(Q)mkdir -p $(@D)
	$(Q)cp $< $@
$(WEB_BUILD)/scenes/index.txt: $(WEB_SCENES)
	$(Q)(cd $(WEB_BUILD)/scenes && ls *.scene models/*.obj) >$@

web-serve: web
	@echo "fixtrace in the browser: http://127.0.0.1:$(WEB_PORT)/"
	$(Q)cd $(WEB_BUILD) && python3 -m http.server $(WEB_PORT) --bind 127.0.0.1

web-screenshot: web
	$(Q)python3 tools/web_screenshot.py $(WEB_BUILD) docs/img/web.png

web-cost-fit: $(FIXTRACE)
	$(Q)MAKE="$(MAKE)" python3 tools/web_cost_fit.py

-include $(WASM_OBJ:.o=.d)
