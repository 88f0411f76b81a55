/* A firmware's CAN glue, with its mistakes (firmware_can_glue.h). */
#include "firmware_can_glue.h"

void firmware_can_glue_reset(firmware_can_glue_t *glue)
{
    glue->now_ms = 0;
    glue->filter_node = glue->node_id(glue->drive);
    glue->heard = NULL;
}

void firmware_can_glue_advance(firmware_can_glue_t *glue, uint32_t ms)
{
    glue->now_ms += ms;
}

bool firmware_can_glue_send(firmware_can_glue_t *glue, const daran_can_frame_t *frame)
{
    if (glue->mistake == FIRMWARE_CAN_HEARS_ITS_OWN_FRAMES && glue->heard != NULL) {
        (void)daran_can_receive(glue->heard, frame);
    }
    return true;
}

uint32_t firmware_can_glue_now_ms(const firmware_can_glue_t *glue)
{
    return glue->mistake == FIRMWARE_CAN_CLOCK_IN_TENTHS ? glue->now_ms * 10u : glue->now_ms;
}

/* Status frames at the own id pass too (the duplicate check needs them);
 * other shapes pass to the front end, which drops them itself (C21). */
void firmware_can_glue_deliver(firmware_can_glue_t *glue, daran_can_t *can,
                               const daran_can_frame_t *frame)
{
    daran_can_frame_t taken = *frame;
    if (glue->mistake == FIRMWARE_CAN_EXTENDED_ID_TAKEN_AS_STANDARD) {
        taken.flags &= (uint8_t)~DARAN_CAN_FRAME_EXTENDED;
        taken.id &= 0x7FFu;
    }
    glue->heard = can;
    uint32_t node = glue->mistake == FIRMWARE_CAN_FILTER_KEPT_AT_RESET_ID ? glue->filter_node
                                                                          : glue->node_id(glue->drive);
    bool standard = (taken.flags & DARAN_CAN_FRAME_EXTENDED) == 0u;
    uint32_t frame_node = taken.id >> 5;
    if (!standard || frame_node == node || frame_node == 0u) {
        (void)daran_can_receive(can, &taken);
    }
}
