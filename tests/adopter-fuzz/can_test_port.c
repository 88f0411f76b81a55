/* port/minimal's HAL with the CAN glue of a firmware
 * (tests/conformance/firmware_can_glue.h), for the CAN fuzz target
 * (daran_ascii_add_can_fuzz_target): a clock that advance() moves, a
 * transmit that takes every frame, and a receive path whose acceptance
 * filter passes standard ids at the drive's current id and node 0.
 *
 * Compiled with BROKEN_CAN, the environment variable BROKEN_CAN chooses a
 * mistake the harness must catch on its built-in seeds (unset: none;
 * tests/adopter-fuzz/CMakeLists.txt):
 *   1  a receive path that takes an extended id for a standard one
 *   2  a clock in tenths of a millisecond */
#include <stdlib.h>

#include "daran_test_port.h"
#include "firmware_can_glue.h"
#include "minimal_hal.h"

static uint32_t node_id(void *drive)
{
    daran_value_t own;
    (void)minimal_hal.get(drive, DARAN_PROP_CAN_NODE_ID, &own);
    return own.u32;
}

static struct can_port_state {
    minimal_drive_t axis;
    firmware_can_glue_t glue;
} state = {.glue = {.node_id = node_id, .drive = &state.axis}};

/* The firmware's CAN glue, found in the port's context. */
static bool glue_send(void *ctx, const daran_can_frame_t *frame)
{
    return firmware_can_glue_send(&((struct can_port_state *)ctx)->glue, frame);
}

static uint32_t glue_now_ms(void *ctx)
{
    return firmware_can_glue_now_ms(&((struct can_port_state *)ctx)->glue);
}

static void glue_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame)
{
    firmware_can_glue_deliver(&((struct can_port_state *)ctx)->glue, can, frame);
}

/* The context is the state, whose first member is the drive minimal's
 * functions take. */
static const daran_hal_t can_port_hal = {MINIMAL_HAL_FUNCTIONS, .now_ms = glue_now_ms,
                                         .can_send = glue_send};

static bool factory_reset(void *ctx)
{
    struct can_port_state *s = ctx;
    minimal_drive_init(&s->axis);
    firmware_can_glue_reset(&s->glue);
    return true;
}

static void advance(void *ctx, uint32_t ms)
{
    struct can_port_state *s = ctx;
    firmware_can_glue_advance(&s->glue, ms);
}

const daran_test_port_t *daran_test_port(void)
{
#ifdef BROKEN_CAN
    static const firmware_can_mistake_t mistakes[] = {
        FIRMWARE_CAN_NO_MISTAKE,
        FIRMWARE_CAN_EXTENDED_ID_TAKEN_AS_STANDARD,
        FIRMWARE_CAN_CLOCK_IN_TENTHS,
    };
    const char *chosen = getenv("BROKEN_CAN");
    int breach = chosen != NULL ? atoi(chosen) : 0;
    bool known = breach > 0 && (size_t)breach < sizeof mistakes / sizeof mistakes[0];
    state.glue.mistake = known ? mistakes[breach] : FIRMWARE_CAN_NO_MISTAKE;
#endif
    static const daran_test_port_t port = {
        .name = "port/minimal with CAN glue",
        .hal = &can_port_hal,
        .ctx = &state,
        .reset = factory_reset,
        .advance = advance,
        .can_deliver = glue_deliver,
    };
    return &port;
}
