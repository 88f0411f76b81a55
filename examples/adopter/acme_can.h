/* The ACME X1's CAN glue (docs/can.md, "What a port does"): the transmit
 * and clock daran_can_init() takes, the acceptance filter set for the
 * drive's node id, and the receive path that hands the frames the filter
 * passes to daran_can_receive(). On the X1 the controller has two id/mask
 * filter banks and three transmit mailboxes; this host build keeps their
 * registers in the drive (acme_hal.h) so the conformance suite and the CAN
 * fuzz target run the very same code. */
#ifndef ACME_CAN_H
#define ACME_CAN_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_ascii.h"

#define ACME_CAN_MAILBOXES 3u

/* Two banks of (id, mask) over standard ids: a frame passes when one bank
 * matches every bit its mask sets. */
typedef struct acme_can_filter {
    uint16_t id[2];
    uint16_t mask[2];
} acme_can_filter_t;

/* Bank 0: the drive's node (every code, status frames included, which the
 * duplicate-id check needs); bank 1: node 0, the broadcast. */
void acme_can_filter_set(acme_can_filter_t *filter, uint32_t node);

bool acme_can_filter_passes(const acme_can_filter_t *filter, const daran_can_frame_t *frame);

/* The port description's CAN transmit (into a free mailbox) and clock (the
 * drive's); the context is the acme_drive_t. */
bool acme_can_send(void *ctx, const daran_can_frame_t *frame);
uint32_t acme_can_now_ms(void *ctx);

/* The receive interrupt's body: @p frame through the filter into @p can.
 * @p ctx is the acme_drive_t. */
void acme_can_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame);

#endif /* ACME_CAN_H */
