/* The receive ring: single producer (the UART/USB interrupt) and single
 * consumer (daran_poll in the main loop), lock-free. The producer writes only
 * `head`, the consumer only `tail`; a fence orders the slot data against the
 * index that publishes it.
 *
 * When the ring is full the producer loses the byte, and with it the line
 * it belonged to: it discards the rest of that line and marks the '\n' that
 * ends it as damaged, so the framer rejects the line instead of executing a
 * line with a hole in it. Only '\n' slots carry a mark, so only they update
 * the bitmap. */
#include "internal.h"

#define MASK ((uint16_t)(DARAN_RX_RING_SIZE - 1u))

#if defined(__GNUC__) || defined(__clang__)
#define FENCE() __atomic_thread_fence(__ATOMIC_SEQ_CST)
#else
#define FENCE() ((void)0)
#endif

static void mark_newline(daran_rx_ring_t *ring, uint16_t slot, bool damaged)
{
    uint8_t bit = (uint8_t)(1u << (slot & 7u));
    uint8_t *cell = &ring->damaged[slot >> 3];
    *cell = damaged ? (uint8_t)(*cell | bit) : (uint8_t)(*cell & (uint8_t)~bit);
}

bool daran_rx_byte(daran_drive_t *drive, uint8_t byte)
{
    daran_rx_ring_t *ring = &drive->rx;
    uint16_t head = ring->head;
    if ((uint16_t)(head - ring->tail) >= DARAN_RX_RING_SIZE) {
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
    if (byte == '\n') {
        mark_newline(ring, slot, damaged);
    }
    FENCE();
    ring->head = (uint16_t)(head + 1u);
    return true;
}

size_t daran_rx_write(daran_drive_t *drive, const void *data, size_t len)
{
    const uint8_t *bytes = (const uint8_t *)data;
    size_t queued = 0;
    for (size_t i = 0; i < len; i++) {
        queued += daran_rx_byte(drive, bytes[i]) ? 1u : 0u;
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
        /* The queued bytes up to the ring's end: one contiguous run. */
        uint16_t slot = (uint16_t)(tail & MASK);
        size_t run = (uint16_t)(head - tail);
        if (run > (size_t)(DARAN_RX_RING_SIZE - slot)) {
            run = (size_t)(DARAN_RX_RING_SIZE - slot);
        }
        size_t taken = daran_framer_append(drive, &ring->bytes[slot], run);
        tail = (uint16_t)(tail + taken);
        if (taken == run) {
            continue;
        }
        slot = (uint16_t)(tail & MASK); /* the '\n' */
        bool damaged = (((unsigned)ring->damaged[slot >> 3] >> (slot & 7u)) & 1u) != 0u;
        tail++;
        FENCE();
        ring->tail = tail; /* free the slots before the line runs: the producer may refill them */
        daran_framer_end_line(drive, damaged);
        lines++;
    }
    FENCE();
    ring->tail = tail;
    return lines;
}
