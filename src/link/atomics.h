/* The ring's two sides share nothing but head, tail and a counter: these
 * are the only accesses to them, each with the ordering it needs (C11
 * atomics, the GCC/clang builtins, or a port's barrier), never `volatile`
 * alone. */
#ifndef DARAN_ATOMICS_H
#define DARAN_ATOMICS_H

#include <stdint.h>

#include "daran_drive.h"

#if DARAN_ATOMIC_C11
#include <stdatomic.h>
#define DARAN_LOAD_ACQUIRE(p) atomic_load_explicit((p), memory_order_acquire)
#define DARAN_LOAD_OWN(p) atomic_load_explicit((p), memory_order_relaxed)
#define DARAN_STORE_RELEASE(p, v) atomic_store_explicit((p), (v), memory_order_release)
#define DARAN_COUNT_DROPPED(p, n) \
    atomic_store_explicit((p), atomic_load_explicit((p), memory_order_relaxed) + (n), memory_order_relaxed)
#define DARAN_LOAD_COUNTER(p) atomic_load_explicit((p), memory_order_relaxed)
#elif defined(DARAN_PORT_BARRIER)
/* The port's barrier orders the plain accesses around the volatile ones. */
#define DARAN_LOAD_ACQUIRE(p) daran_load_acquire_u16(p)
#define DARAN_LOAD_OWN(p) (*(p))
#define DARAN_STORE_RELEASE(p, v) (DARAN_PORT_BARRIER(), *(volatile uint16_t *)(p) = (uint16_t)(v))
#define DARAN_COUNT_DROPPED(p, n) (*(volatile uint32_t *)(p) += (n))
#define DARAN_LOAD_COUNTER(p) (*(const volatile uint32_t *)(p))
static inline uint16_t daran_load_acquire_u16(const uint16_t *p)
{
    uint16_t v = *(const volatile uint16_t *)p;
    DARAN_PORT_BARRIER();
    return v;
}
#elif defined(__GNUC__) || defined(__clang__)
#define DARAN_LOAD_ACQUIRE(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)
#define DARAN_LOAD_OWN(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define DARAN_STORE_RELEASE(p, v) __atomic_store_n((p), (uint16_t)(v), __ATOMIC_RELEASE)
#define DARAN_COUNT_DROPPED(p, n) \
    __atomic_store_n((p), __atomic_load_n((p), __ATOMIC_RELAXED) + (n), __ATOMIC_RELAXED)
#define DARAN_LOAD_COUNTER(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#else
#error "daran-ascii needs C11 atomics, the GCC/clang __atomic builtins or a DARAN_PORT_BARRIER() macro"
#endif

#endif /* DARAN_ATOMICS_H */
