/* The ACME X1's CAN glue (acme_can.h). */
#include "acme_can.h"

#include "acme_hal.h"

#define NODE_MASK 0x7E0u /* bits 10..5 of a standard id: the node */

void acme_can_filter_set(acme_can_filter_t *filter, uint32_t node)
{
    filter->id[0] = (uint16_t)(node << 5 & NODE_MASK);
    filter->mask[0] = NODE_MASK;
    filter->id[1] = 0;
    filter->mask[1] = NODE_MASK;
}

bool acme_can_filter_passes(const acme_can_filter_t *filter, const daran_can_frame_t *frame)
{
    if ((frame->flags & DARAN_CAN_FRAME_EXTENDED) != 0u) {
        return false; /* the banks are set for standard ids */
    }
    for (unsigned bank = 0; bank < 2u; bank++) {
        if (((frame->id ^ filter->id[bank]) & filter->mask[bank]) == 0u) {
            return true;
        }
    }
    return false;
}

/* A frame waits in a mailbox until the bus took it (acme_drive_run()). */
bool acme_can_send(void *ctx, const daran_can_frame_t *frame)
{
    acme_drive_t *drive = ctx;
    (void)frame;
    if (drive->can_mailboxes_busy >= ACME_CAN_MAILBOXES) {
        return false;
    }
    drive->can_mailboxes_busy++;
    drive->can_frames_sent++;
    return true;
}

uint32_t acme_can_now_ms(void *ctx)
{
    const acme_drive_t *drive = ctx;
    return drive->time_ms;
}

void acme_can_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame)
{
    const acme_drive_t *drive = ctx;
    if (acme_can_filter_passes(&drive->can_filter, frame)) {
        (void)daran_can_receive(can, frame);
    }
}
