/* The CAN receive ring's consumer side (can.c), inline; the producer side
 * is the public daran_can_receive() (can_ring.c). The same discipline as
 * the byte ring (rx_ring.h): the producer fills a slot, then publishes it
 * with a release store of `head`; the consumer reads `head` with acquire and
 * frees a slot with a release store of `tail`. */
#ifndef DARAN_CAN_RING_H
#define DARAN_CAN_RING_H

#include <stddef.h>
#include <stdint.h>

#include "atomics.h"
#include "daran_can.h"

#define DARAN_CAN_RX_MASK ((uint16_t)(DARAN_CAN_RX_FRAMES - 1u))

/* How many frames are queued now. */
static inline size_t daran_can_queued(daran_can_t *can)
{
    return (uint16_t)(DARAN_LOAD_ACQUIRE(&can->head) - DARAN_LOAD_OWN(&can->tail));
}

/* The oldest queued frame (there must be one). */
static inline const daran_can_slot_t *daran_can_oldest(daran_can_t *can)
{
    return &can->slots[DARAN_LOAD_OWN(&can->tail) & DARAN_CAN_RX_MASK];
}

/* Hand the oldest frame's slot back to the producer. */
static inline void daran_can_release(daran_can_t *can)
{
    DARAN_STORE_RELEASE(&can->tail, (uint16_t)(DARAN_LOAD_OWN(&can->tail) + 1u));
}

#endif /* DARAN_CAN_RING_H */
