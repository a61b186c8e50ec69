/* SPDX-License-Identifier: MIT */
/*
 * scene.S: the scene text, embedded byte for byte in the image's read-only
 * data. FW_SCENE_FILE (an absolute path, from the generated fw_config.h)
 * names the file, so changing SCENE changes the firmware without touching
 * any C. The firmware parses this text on the device (main.c).
 */
#include "fw_config.h"

    .section .rodata.fw_scene, "a"
    .global fw_scene_text
    .global fw_scene_len
fw_scene_text:
    .incbin FW_SCENE_FILE
fw_scene_end:
    .balign 4
fw_scene_len:
    .4byte fw_scene_end - fw_scene_text
