/* The bridge (can_bridge.c): a line for another drive -> CAN frames, and
 * the answer of a bridged query back as the line that drive would print.
 * drive.c hands it lines it validated; the CAN front end hands it frames
 * from other nodes through the listener it registers (daran_can_t). */
#ifndef DARAN_BRIDGE_H
#define DARAN_BRIDGE_H

#include <stdbool.h>

#include "command.h"
#include "daran_can.h"

#if DARAN_ENABLE_CAN_BRIDGE
/* Whether the drive bridges now: a bridge attached, CAN on (C31). */
bool daran_bridge_active(const daran_drive_t *drive);

/* Send @p request (checked by the dispatcher up to its values) as frames to
 * its drive, or to node 0 when @p broadcast. DARAN_OK when it went out (a
 * query then answers later), else the error the line answers, with nothing
 * sent. A broadcast line that must not go out (a node id write, C34)
 * returns DARAN_OK without sending. */
daran_result_t daran_bridge_line(daran_can_bridge_t *bridge, const daran_request_t *request,
                                 bool broadcast);

/* Advance a pending query (its timeout): true while it still waits, and
 * the drive reads no further line. */
bool daran_bridge_waiting(daran_can_bridge_t *bridge);

#endif

#endif /* DARAN_BRIDGE_H */
