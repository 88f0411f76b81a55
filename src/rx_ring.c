/* The receive ring: single producer (the UART/USB interrupt) and single
 * consumer (daran_poll in the main loop), lock-free. The producer writes only
 * `head`, the consumer only `tail`; a fence orders the slot data against the
 * index that publishes it.
 *
 * When the ring is full the producer loses the byte, and with it the line
 * it belonged to: it discards the rest of that line and marks the '\n' that
 * ends it as damaged, so the framer rejects the line instead of executing a
 * line with a hole in it. */
#include "internal.h"

#define MASK ((uint16_t)(DARAN_RX_RING_SIZE - 1u))

#if defined(__GNUC__) || defined(__clang__)
#define FENCE() __atomic_thread_fence(__ATOMIC_SEQ_CST)
#else
#define FENCE() ((void)0)
#endif

static void mark_slot(daran_rx_ring_t *ring, uint16_t slot, bool damaged)
{
    uint8_t bit = (uint8_t)(1u << (slot & 7u));
    if (damaged) {
        ring->damaged[slot >> 3] = (uint8_t)(ring->damaged[slot >> 3] | bit);
    } else {
        ring->damaged[slot >> 3] = (uint8_t)(ring->damaged[slot >> 3] & (uint8_t)~bit);
    }
}

bool daran_rx_byte(daran_drive_t *drive, uint8_t byte)
{
    daran_rx_ring_t *ring = &drive->rx;
    uint16_t head = ring->head;
    uint16_t tail = ring->tail;
    if ((uint16_t)(head - tail) >= DARAN_RX_RING_SIZE) {
        ring->producer_dropping = 1;
        ring->dropped++;
        return false;
    }
    bool damaged = false;
    if (ring->producer_dropping) {
        if (byte != '\n') {
            ring->dropped++;
            return false;
        }
        damaged = true;
        ring->producer_dropping = 0;
    }
    uint16_t slot = (uint16_t)(head & MASK);
    ring->bytes[slot] = byte;
    mark_slot(ring, slot, damaged);
    FENCE();
    ring->head = (uint16_t)(head + 1u);
    return true;
}

size_t daran_rx_write(daran_drive_t *drive, const void *data, size_t len)
{
    const uint8_t *bytes = (const uint8_t *)data;
    size_t queued = 0;
    for (size_t i = 0; i < len; i++) {
        if (daran_rx_byte(drive, bytes[i])) {
            queued++;
        }
    }
    return queued;
}

uint32_t daran_rx_dropped(const daran_drive_t *drive)
{
    return drive->rx.dropped;
}

size_t daran_poll(daran_drive_t *drive)
{
    daran_rx_ring_t *ring = &drive->rx;
    uint16_t head = ring->head;
    uint16_t tail = ring->tail;
    size_t lines = 0;
    FENCE();
    while (tail != head) {
        uint16_t slot = (uint16_t)(tail & MASK);
        uint8_t byte = ring->bytes[slot];
        bool damaged = (((unsigned)ring->damaged[slot >> 3] >> (slot & 7u)) & 1u) != 0u;
        FENCE();
        tail = (uint16_t)(tail + 1u);
        ring->tail = tail; /* free the slot before the line runs: the producer may refill it */
        if (daran_framer_feed(drive, byte, damaged)) {
            lines++;
        }
    }
    return lines;
}
