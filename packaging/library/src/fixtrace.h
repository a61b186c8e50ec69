/* SPDX-License-Identifier: MIT */
/*
 * fixtrace.h: the whole public API in one header, for Arduino sketches
 * and PlatformIO projects (the packaged library's src/ is flat). The core
 * is C; from C++ its names keep C linkage.
 */
#ifndef FIXTRACE_H
#define FIXTRACE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "fixtrace_version.h"
#include "rt_parse.h"
#include "rt_render.h"

#ifdef __cplusplus
}
#endif

#endif
