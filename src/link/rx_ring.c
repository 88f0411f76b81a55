/* The receive ring: single producer (the UART/USB interrupt) and single
 * consumer (daran_poll in the main loop), lock-free, and a leaf: it holds
 * bytes and knows nothing of what its reader makes of them. The producer
 * writes the bytes, then publishes them with a release store of `head`; the
 * consumer reads `head` with acquire, takes the bytes as runs, then frees
 * them with a release store of `tail`, which the producer reads with acquire
 * before reusing the slots. Each byte belongs to one side at a time, and
 * nothing else is shared but `dropped`, a counter only the producer writes.
 * The consumer's side is three inline functions in rx_ring.h.
 *
 * When the ring is full the producer loses the byte, and with it the line
 * it belonged to: it discards the rest of that line and stores the '\n' that
 * ends it as DARAN_RX_DAMAGED_END, so the framer rejects the line instead of
 * executing a line with a hole in it. */
#include "rx_ring.h"

#include <stdbool.h>
#include <string.h>

#include "atomics.h"
#include "compiler.h"

#define MASK DARAN_RX_MASK

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
        DARAN_COUNT_DROPPED(&ring->dropped, 1u);
        return head;
    }
    uint8_t value = stored(byte);
    if (ring->producer_dropping) {
        if (byte != '\n') {
            DARAN_COUNT_DROPPED(&ring->dropped, 1u);
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

/* Copy count bytes into consecutive slots, the marker value replaced:
 * eight bytes a step while none of them has its top bit set (one test for
 * all eight; the marker is such a byte, and text never has one), then four,
 * then one at a time. */
static void store_run(uint8_t *slots, const uint8_t *bytes, size_t count)
{
    for (; count >= 8u; count -= 8u) {
        uint32_t low;
        uint32_t high;
        memcpy(&low, bytes, sizeof low);
        memcpy(&high, bytes + 4, sizeof high);
        if (((low | high) & 0x80808080u) != 0u) {
            break;
        }
        memcpy(slots, &low, sizeof low);
        memcpy(slots + 4, &high, sizeof high);
        slots += 8;
        bytes += 8;
    }
    if (count >= 4u) {
        uint32_t word;
        memcpy(&word, bytes, sizeof word);
        if ((word & 0x80808080u) == 0u) {
            memcpy(slots, &word, sizeof word);
            slots += 4;
            bytes += 4;
            count -= 4u;
        }
    }
    for (size_t i = 0; i < count; i++) {
        slots[i] = stored(bytes[i]);
    }
}

/* Any number of bytes: as many as fit are copied with one release for all
 * of them; past a full ring, or while a line is being discarded, the bytes
 * take put_slow() one at a time. */
static DARAN_NOINLINE size_t write_bytes(daran_rx_ring_t *ring, const uint8_t *bytes, size_t len)
{
    uint16_t head = DARAN_LOAD_OWN(&ring->head);
    uint16_t tail = DARAN_LOAD_ACQUIRE(&ring->tail);
    size_t room = DARAN_RX_RING_SIZE - (uint16_t)(head - tail);
    size_t i = 0;
    if (!ring->producer_dropping) {
        size_t fast = len < room ? len : room;
        size_t slot = head & MASK;
        size_t to_end = DARAN_RX_RING_SIZE - slot;
        if (fast <= to_end) {
            store_run(&ring->bytes[slot], bytes, fast);
        } else {
            store_run(&ring->bytes[slot], bytes, to_end);
            store_run(ring->bytes, bytes + to_end, fast - to_end);
        }
        head = (uint16_t)(head + fast);
        i = fast;
    }
    size_t queued = i;
    for (; i < len; i++) {
        bool one;
        head = put_slow(ring, head, tail, bytes[i], &one);
        queued += one ? 1u : 0u;
    }
    DARAN_STORE_RELEASE(&ring->head, head);
    return queued;
}

size_t daran_rx_write(daran_drive_t *drive, const void *data, size_t len)
{
    daran_rx_ring_t *ring = &drive->rx;
    const uint8_t *bytes = (const uint8_t *)data;
    if (len == 1u && !ring->producer_dropping) {
        /* One byte, as a UART interrupt hands them over (daran_rx_byte):
         * no loop, no call, when there is room for it. */
        uint16_t head = DARAN_LOAD_OWN(&ring->head);
        if ((uint16_t)(head - DARAN_LOAD_ACQUIRE(&ring->tail)) < DARAN_RX_RING_SIZE) {
            ring->bytes[head & MASK] = stored(*bytes);
            DARAN_STORE_RELEASE(&ring->head, (uint16_t)(head + 1u));
            return 1;
        }
    }
    return write_bytes(ring, bytes, len);
}

uint32_t daran_rx_dropped(const daran_drive_t *drive)
{
    return DARAN_LOAD_COUNTER(&drive->rx.dropped);
}

size_t daran_rx_free(const daran_drive_t *drive)
{
    const daran_rx_ring_t *ring = &drive->rx;
    uint16_t used = (uint16_t)(DARAN_LOAD_ACQUIRE(&ring->head) - DARAN_LOAD_ACQUIRE(&ring->tail));
    return DARAN_RX_RING_SIZE - used;
}
