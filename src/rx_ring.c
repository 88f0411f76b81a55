/* The receive ring: single producer (the UART/USB interrupt) and single
 * consumer (daran_poll in the main loop), lock-free. The producer writes the
 * bytes, then publishes them with a release store of `head`; the consumer
 * reads `head` with acquire, frames the bytes, then frees them with a release
 * store of `tail`, which the producer reads with acquire before reusing the
 * slots. Each byte belongs to one side at a time, and nothing else is
 * shared but `dropped`, a counter only the producer writes.
 *
 * When the ring is full the producer loses the byte, and with it the line
 * it belonged to: it discards the rest of that line and stores the '\n' that
 * ends it as DARAN_RX_DAMAGED_END, so the framer rejects the line instead of
 * executing a line with a hole in it. */
#include "internal.h"

#define MASK ((uint16_t)(DARAN_RX_RING_SIZE - 1u))

#if DARAN_ATOMIC_C11
#include <stdatomic.h>
#define LOAD_ACQUIRE(p) atomic_load_explicit((p), memory_order_acquire)
#define LOAD_OWN(p) atomic_load_explicit((p), memory_order_relaxed)
#define STORE_RELEASE(p, v) atomic_store_explicit((p), (v), memory_order_release)
#define COUNT_DROPPED(p, n) \
    atomic_store_explicit((p), atomic_load_explicit((p), memory_order_relaxed) + (n), memory_order_relaxed)
#define LOAD_COUNTER(p) atomic_load_explicit((p), memory_order_relaxed)
#elif defined(DARAN_PORT_BARRIER)
/* The port's barrier orders the plain accesses around the volatile ones. */
#define LOAD_ACQUIRE(p) load_acquire_u16(p)
#define LOAD_OWN(p) (*(p))
#define STORE_RELEASE(p, v) (DARAN_PORT_BARRIER(), *(volatile uint16_t *)(p) = (uint16_t)(v))
#define COUNT_DROPPED(p, n) (*(volatile uint32_t *)(p) += (n))
#define LOAD_COUNTER(p) (*(const volatile uint32_t *)(p))
static uint16_t load_acquire_u16(const uint16_t *p)
{
    uint16_t v = *(const volatile uint16_t *)p;
    DARAN_PORT_BARRIER();
    return v;
}
#elif defined(__GNUC__) || defined(__clang__)
#define LOAD_ACQUIRE(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)
#define LOAD_OWN(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define STORE_RELEASE(p, v) __atomic_store_n((p), (uint16_t)(v), __ATOMIC_RELEASE)
#define COUNT_DROPPED(p, n) \
    __atomic_store_n((p), __atomic_load_n((p), __ATOMIC_RELAXED) + (n), __ATOMIC_RELAXED)
#define LOAD_COUNTER(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#else
#error "daran-ascii needs C11 atomics, the GCC/clang __atomic builtins or a DARAN_PORT_BARRIER() macro"
#endif

/* What the ring stores for a received byte: the marker value is reserved. */
static uint8_t stored(uint8_t byte)
{
    return byte == DARAN_RX_DAMAGED_END ? DARAN_RX_INVALID_BYTE : byte;
}

/* The byte-by-byte road: a full ring, or a line being discarded. Returns
 * the new head. */
static uint16_t put_slow(daran_rx_ring_t *ring, uint16_t head, uint16_t tail, uint8_t byte,
                         bool *queued)
{
    *queued = false;
    if ((uint16_t)(head - tail) >= DARAN_RX_RING_SIZE) {
        ring->producer_dropping = 1;
        COUNT_DROPPED(&ring->dropped, 1u);
        return head;
    }
    uint8_t value = stored(byte);
    if (ring->producer_dropping) {
        if (byte != '\n') {
            COUNT_DROPPED(&ring->dropped, 1u);
            return head;
        }
        value = DARAN_RX_DAMAGED_END;
        ring->producer_dropping = 0;
    }
    ring->bytes[head & MASK] = value;
    *queued = true;
    return (uint16_t)(head + 1u);
}

bool daran_rx_byte(daran_drive_t *drive, uint8_t byte)
{
    return daran_rx_write(drive, &byte, 1) == 1u;
}

size_t daran_rx_write(daran_drive_t *drive, const void *data, size_t len)
{
    daran_rx_ring_t *ring = &drive->rx;
    const uint8_t *bytes = (const uint8_t *)data;
    uint16_t head = LOAD_OWN(&ring->head);
    uint16_t tail = LOAD_ACQUIRE(&ring->tail);
    size_t room = DARAN_RX_RING_SIZE - (uint16_t)(head - tail);
    size_t i = 0;
    if (!ring->producer_dropping) {
        /* The common case: copy what fits, one release for all of it. */
        size_t fast = len < room ? len : room;
        for (; i < fast; i++) {
            ring->bytes[(head + i) & MASK] = stored(bytes[i]);
        }
        head = (uint16_t)(head + fast);
    }
    size_t queued = i;
    for (; i < len; i++) {
        bool one;
        head = put_slow(ring, head, tail, bytes[i], &one);
        queued += one ? 1u : 0u;
    }
    STORE_RELEASE(&ring->head, head);
    return queued;
}

uint32_t daran_rx_dropped(const daran_drive_t *drive)
{
    return LOAD_COUNTER(&drive->rx.dropped);
}

size_t daran_rx_free(const daran_drive_t *drive)
{
    const daran_rx_ring_t *ring = &drive->rx;
    uint16_t used = (uint16_t)(LOAD_ACQUIRE(&ring->head) - LOAD_ACQUIRE(&ring->tail));
    return DARAN_RX_RING_SIZE - used;
}

size_t daran_poll(daran_drive_t *drive)
{
    daran_rx_ring_t *ring = &drive->rx;
    uint16_t head = LOAD_ACQUIRE(&ring->head);
    uint16_t tail = LOAD_OWN(&ring->tail);
    size_t lines = 0;
    while (tail != head) {
        /* The queued bytes up to the ring's end: one contiguous run, framed
         * in one pass up to the first line end. */
        uint16_t slot = (uint16_t)(tail & MASK);
        size_t run = (uint16_t)(head - tail);
        if (run > (size_t)(DARAN_RX_RING_SIZE - slot)) {
            run = (size_t)(DARAN_RX_RING_SIZE - slot);
        }
        bool ended = false;
        tail = (uint16_t)(tail + daran_framer_feed(drive, &ring->bytes[slot], run, true, &ended));
        if (ended) {
            /* Free the line's slots before it runs: the producer may refill them. */
            STORE_RELEASE(&ring->tail, tail);
            (void)daran_run_framed_line(drive);
            lines++;
        }
    }
    STORE_RELEASE(&ring->tail, tail);
    return lines;
}
