/* SPDX-License-Identifier: MIT */
/*
 * ref32: the float32 build of the reference renderer, the yardstick a
 * fixed-point image is held to besides the double one (docs/accuracy.md).
 * mk/posix.mk compiles port/posix/ref_*.c a second time with this header
 * forced in (-include) and -fsingle-precision-constant: every `double`
 * becomes float, constants included, exactly as bench/softref builds the
 * same files for firmware (-Ddouble=float), so the renderer is written
 * once. The public names get a ref32_ prefix, so both builds link into
 * one fixtrace (`fixtrace --reference-float`).
 *
 * The system headers come first, with their own double prototypes; after
 * them each libm call the renderer makes is mapped to its float version
 * (glibc's sqrtf is correctly rounded, like sqrt), so no value is
 * silently widened to double and rounded back.
 */
#ifndef REF32_H
#define REF32_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#undef HUGE_VAL
#define HUGE_VAL HUGE_VALF
#define sqrt sqrtf
#define fabs fabsf
#define copysign copysignf
#define floor floorf
#define fmax fmaxf
#define fmin fminf
#define tan tanf
#define pow powf

#define double float

#define ref_render_rows ref32_render_rows
#define ref_shape_from_object ref32_shape_from_object
#define ref_intersect ref32_intersect
#define ref_mesh_setup ref32_mesh_setup
#define ref_mesh_release ref32_mesh_release
#define ref_mesh_hit ref32_mesh_hit
#define ref_lattice ref32_lattice
#define ref_noise ref32_noise
#define ref_shape_ok ref32_shape_ok

#endif /* REF32_H */
