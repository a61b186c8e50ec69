/* SPDX-License-Identifier: MIT */
/* mpu_guard: an overflowing stack faults at once on the Arm boards whose
 * memory below RAM reads as zero and ignores writes (an overflow would
 * otherwise go unnoticed). The lowest 32 bytes of the stack become a
 * no-access MPU region: a push into them faults (exit 101). The linker
 * scripts align the stack to 32 bytes. The ARMv7-M MPU registers are
 * plain stores, so M0 code running on an M3 machine reaches them too. */
#ifndef MPU_GUARD_H
#define MPU_GUARD_H

#include <stdint.h>

extern uint32_t _sstack[];

static inline void mpu_guard_stack(void)
{
    volatile uint32_t *const rnr = (volatile uint32_t *)0xE000ED98u;
    volatile uint32_t *const rbar = (volatile uint32_t *)0xE000ED9Cu;
    volatile uint32_t *const rasr = (volatile uint32_t *)0xE000EDA0u;
    volatile uint32_t *const ctrl = (volatile uint32_t *)0xE000ED94u;
    *rnr = 0;
    *rbar = (uint32_t)(uintptr_t)_sstack;
    *rasr = (1u << 28) | (4u << 1) | 1u; /* XN, no access, 32 B, on */
    *ctrl = 5u; /* enable, default map for everything else */
    __asm__ volatile("dsb\n\tisb" : : : "memory");
}

#endif /* MPU_GUARD_H */
