# SPDX-License-Identifier: MIT
# Documentation: the gallery of every scene in scenes/, rendered by
# fixtrace itself into docs/img/ (shown in README.md).
#
#   make gallery [GALLERY_W=320 GALLERY_H=240 GALLERY_SPP=4]
#
# The names are not WIDTH/HEIGHT/SPP: those belong to the firmware build,
# where 0 means "the scene's default".

GALLERY_W ?= 320
GALLERY_H ?= 240
GALLERY_SPP ?= 4
GALLERY_DIR ?= docs/img

.PHONY: gallery
gallery: $(FIXTRACE)
	$(Q)FIXTRACE=$(FIXTRACE) bash tools/gallery.sh -W $(GALLERY_W) \
	    -H $(GALLERY_H) -s $(GALLERY_SPP) $(GALLERY_DIR)
