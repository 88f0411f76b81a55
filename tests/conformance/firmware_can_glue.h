/* The CAN glue a firmware gives the front end, for the in-tree test ports
 * that have one (sim_test_port.c here, tests/adopter-fuzz/can_test_port.c):
 * a clock that is the drive time advance() passes, a transmit that takes
 * every frame (a host has no mailbox to fill), and a receive path whose
 * acceptance filter passes standard ids at the drive's current id and at
 * node 0. One of its mistakes can be chosen, for the kit to catch.
 *
 * A test port's hal gives the glue's transmit and clock (can_send and
 * now_ms) and its can_deliver the glue's receive path, each through a
 * wrapper that finds the glue in the port's context, and calls
 * firmware_can_glue_reset() and firmware_can_glue_advance() from its
 * reset() and advance(). */
#ifndef FIRMWARE_CAN_GLUE_H
#define FIRMWARE_CAN_GLUE_H

#include <stdint.h>

#include "daran_ascii.h"

typedef enum firmware_can_mistake {
    FIRMWARE_CAN_NO_MISTAKE,
    FIRMWARE_CAN_FILTER_KEPT_AT_RESET_ID,       /* set for the id at reset, never for a new one */
    FIRMWARE_CAN_HEARS_ITS_OWN_FRAMES,          /* a controller in loopback */
    FIRMWARE_CAN_EXTENDED_ID_TAKEN_AS_STANDARD, /* the filter drops the IDE bit */
    FIRMWARE_CAN_CLOCK_IN_TENTHS,               /* now_ms() counts tenths of a millisecond */
} firmware_can_mistake_t;

typedef struct firmware_can_glue {
    firmware_can_mistake_t mistake;
    uint32_t (*node_id)(void *drive); /* the drive's CAN id now, as the filter is set */
    void *drive;
    uint32_t now_ms;      /* the drive time advance() passed since reset */
    uint32_t filter_node; /* the id the filter was set for at reset */
    daran_can_t *heard;   /* the front end the last frame was delivered to */
} firmware_can_glue_t;

/** The transmit and the clock. */
bool firmware_can_glue_send(firmware_can_glue_t *glue, const daran_can_frame_t *frame);
uint32_t firmware_can_glue_now_ms(const firmware_can_glue_t *glue);

/** The receive path (for daran_test_port_t.can_deliver): @p frame into
 * daran_can_receive(@p can) when the filter passes it. */
void firmware_can_glue_deliver(firmware_can_glue_t *glue, daran_can_t *can,
                               const daran_can_frame_t *frame);

/** The port's reset: the clock at 0, the filter set for the drive's id. The
 * chosen mistake stays. */
void firmware_can_glue_reset(firmware_can_glue_t *glue);

/** The port's advance(): @p ms of drive time. */
void firmware_can_glue_advance(firmware_can_glue_t *glue, uint32_t ms);

#endif /* FIRMWARE_CAN_GLUE_H */
