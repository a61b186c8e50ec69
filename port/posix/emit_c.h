/* SPDX-License-Identifier: MIT */
/* emit_c: a parsed scene as C source, so firmware can carry the scene as
 * constant data instead of the text and the parser. */
#ifndef EMIT_C_H
#define EMIT_C_H

#include <stdio.h>
#include "rt_scene.h"

/* Writes a C file defining `const rt_scene fw_scene` with every field of
 * s (derived fields included) as designated initialisers, and
 * FW_SCENE_OBJECTS / _MATERIALS / _LIGHTS counts. Returns 0, or -1 on a
 * write error. */
int emit_c_scene(FILE *f, const rt_scene *s, const char *source);

#endif /* EMIT_C_H */
