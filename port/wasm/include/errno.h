/* SPDX-License-Identifier: MIT */
/* errno.h of the WebAssembly port. */
#ifndef FT_WASM_ERRNO_H
#define FT_WASM_ERRNO_H

#define ENOENT 2
#define ERANGE 34

extern int errno;

#endif /* FT_WASM_ERRNO_H */
