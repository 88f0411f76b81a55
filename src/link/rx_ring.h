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

/* The oldest of the `queued` bytes (what daran_rx_queued() said, less what
 * was skipped since) up to the ring's end, as one contiguous run: sets
 * *bytes and returns the run's length. The consumer's own count spares a
 * second acquire of `head` per run. */
static inline size_t daran_rx_run(daran_rx_ring_t *ring, size_t queued, const uint8_t **bytes)
{
    uint16_t slot = (uint16_t)(DARAN_LOAD_OWN(&ring->tail) & DARAN_RX_MASK);
    size_t to_end = (size_t)(DARAN_RX_RING_SIZE - slot);
    *bytes = &ring->bytes[slot];
    return queued < to_end ? queued : to_end;
}

/* Hand the oldest n queued bytes (n <= the last run) back to the producer. */
static inline void daran_rx_skip(daran_rx_ring_t *ring, size_t n)
{
    DARAN_STORE_RELEASE(&ring->tail, (uint16_t)(DARAN_LOAD_OWN(&ring->tail) + n));
}

#endif /* DARAN_RX_RING_H */
