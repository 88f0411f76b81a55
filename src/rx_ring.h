/* The receive ring's consumer side, inline so the poll loop pays no call
 * for it; the producer side is the public daran_rx_write() (rx_ring.c). The ring knows nothing of lines; its reader
 * takes runs of bytes and gives back how many it is done with. */
#ifndef DARAN_RX_RING_H
#define DARAN_RX_RING_H

#include <stddef.h>
#include <stdint.h>

#include "atomics.h"
#include "daran_drive.h"

/* How the ring stores a line end whose line lost bytes, and what it stores
 * for a received byte of that value (both are invalid characters). */
#define DARAN_RX_DAMAGED_END 0x8Au
#define DARAN_RX_INVALID_BYTE 0x80u

#define DARAN_RX_MASK ((uint16_t)(DARAN_RX_RING_SIZE - 1u))

/* How many bytes are queued now. */
static inline size_t daran_rx_queued(daran_rx_ring_t *ring)
{
    return (uint16_t)(DARAN_LOAD_ACQUIRE(&ring->head) - DARAN_LOAD_OWN(&ring->tail));
}

/* The oldest queued bytes up to the ring's end, as one contiguous run:
 * sets *bytes and returns the run's length (0 when nothing is queued). */
static inline size_t daran_rx_run(daran_rx_ring_t *ring, const uint8_t **bytes)
{
    uint16_t tail = DARAN_LOAD_OWN(&ring->tail);
    uint16_t slot = (uint16_t)(tail & DARAN_RX_MASK);
    size_t run = (uint16_t)(DARAN_LOAD_ACQUIRE(&ring->head) - tail);
    if (run > (size_t)(DARAN_RX_RING_SIZE - slot)) {
        run = (size_t)(DARAN_RX_RING_SIZE - slot);
    }
    *bytes = &ring->bytes[slot];
    return run;
}

/* Hand the oldest n queued bytes (n <= the last run) back to the producer. */
static inline void daran_rx_skip(daran_rx_ring_t *ring, size_t n)
{
    DARAN_STORE_RELEASE(&ring->tail, (uint16_t)(DARAN_LOAD_OWN(&ring->tail) + n));
}

#endif /* DARAN_RX_RING_H */
