/* SPDX-License-Identifier: MIT */
/*
 * heap.h: the WebAssembly port's heap, for the host code the page reuses
 * (the OBJ reader and hierarchy builder of port/posix, the reference's
 * mesh boxes). It is a stack of regions: malloc takes from the top,
 * free() returns nothing, and the port releases everything above a mark
 * at once (the meshes of a scene when the next parse starts, the
 * reference's boxes after each band).
 */
#ifndef FT_WASM_HEAP_H
#define FT_WASM_HEAP_H

#include <stddef.h>

/* The top of the heap now, for wasm_heap_release(). */
size_t wasm_heap_mark(void);

/* Frees every block allocated since wasm_heap_mark() returned mark. */
void wasm_heap_release(size_t mark);

#endif /* FT_WASM_HEAP_H */
