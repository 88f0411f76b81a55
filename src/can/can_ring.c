/* The CAN receive ring's producer side: one interrupt (or thread) hands
 * frames to daran_can_receive(); daran_can_poll() takes them (can_ring.h).
 * Only 8-byte standard data frames are stored: every other shape is not
 * part of the protocol and is dropped here, before it costs a slot (C21). */
#include "can_ring.h"

#include <string.h>

#if DARAN_ENABLE_CAN

bool daran_can_receive(daran_can_t *can, const daran_can_frame_t *frame)
{
    if (frame->dlc != 8u || frame->flags != 0u || frame->id > 0x7FFu) {
        return false;
    }
    uint16_t head = DARAN_LOAD_OWN(&can->head);
    if ((uint16_t)(head - DARAN_LOAD_ACQUIRE(&can->tail)) >= DARAN_CAN_RX_FRAMES) {
        DARAN_COUNT_DROPPED(&can->dropped, 1u);
        return false;
    }
    daran_can_slot_t *slot = &can->slots[head & DARAN_CAN_RX_MASK];
    slot->id = (uint16_t)frame->id;
    memcpy(slot->data, frame->data, sizeof slot->data);
    DARAN_STORE_RELEASE(&can->head, (uint16_t)(head + 1u));
    return true;
}

uint32_t daran_can_dropped(const daran_can_t *can)
{
    return DARAN_LOAD_COUNTER(&can->dropped);
}

#endif /* DARAN_ENABLE_CAN */
