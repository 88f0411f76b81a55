/* The simulated drive (daran_sim.h) handed to the conformance suite: a HAL
 * over a physical model, with time (advance() runs its 1 kHz control
 * ticks) and non-volatile memory. Its reset is a new drive: id 1, empty
 * storage, closed loop.
 *
 * Its CAN glue is the one a firmware has (firmware_can_glue.h): a clock
 * that is the drive time advance() passes, a transmit that takes every
 * frame, and a receive path whose acceptance filter passes standard ids at
 * the drive's current id and at node 0.
 *
 * Compiled with BROKEN_CAN, the environment variable BROKEN_CAN chooses one
 * deliberate breach of the CAN glue or the HAL that the suite must catch
 * (tests/conformance/CMakeLists.txt names the requirement each fails):
 *   1  can.config.protocol reads 0 after reset (the front end stays silent)
 *   2  a setter that drops enable_reply_state
 *   3  a filter set for the id at reset, never for a new one
 *   4  a setter that drops the core's write of can.error
 *   5  a NODE_GUARD action that answers ok and keeps running
 *   6  a controller that hears its own frames (loopback)
 *   7  a receive path that takes an extended id for a standard one
 *   8  a clock in tenths of a millisecond */
#include <stdlib.h>

#include "daran_test_port.h"

#include "daran_sim.h"
#include "firmware_can_glue.h"

#define SIM_TICK_HZ 1000u

static uint32_t node_id(void *drive)
{
    return daran_sim_drive_id(drive);
}

static struct sim_port {
    daran_sim_drive_t sim;
    firmware_can_glue_t glue;
} port_state = {.glue = {.node_id = node_id, .drive = &port_state.sim}};

#ifdef BROKEN_CAN
static int breach;
/* the breaches of the CAN glue, by number */
static const firmware_can_mistake_t glue_mistakes[] = {
    [3] = FIRMWARE_CAN_FILTER_KEPT_AT_RESET_ID,
    [6] = FIRMWARE_CAN_HEARS_ITS_OWN_FRAMES,
    [7] = FIRMWARE_CAN_EXTENDED_ID_TAKEN_AS_STANDARD,
    [8] = FIRMWARE_CAN_CLOCK_IN_TENTHS,
};
#else
enum { breach = 0 };
#endif

static daran_result_t sim_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    daran_result_t result = daran_sim_hal.get(ctx, prop, out);
    if (breach == 1 && prop == DARAN_PROP_CAN_PROTOCOL) {
        out->u32 = 0;
    }
    return result;
}

static daran_result_t sim_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    if ((breach == 2 && prop == DARAN_PROP_ENABLE_REPLY_STATE) ||
        (breach == 4 && prop == DARAN_PROP_CAN_ERROR && value.u32 != 0u)) {
        return DARAN_OK;
    }
    return daran_sim_hal.set(ctx, prop, value);
}

static daran_result_t sim_action(void *ctx, daran_action_t action)
{
    if (breach == 5 && action == DARAN_ACTION_NODE_GUARD) {
        return DARAN_OK;
    }
    return daran_sim_hal.action(ctx, action);
}

static daran_result_t sim_move(void *ctx, const daran_move_t *move)
{
    return daran_sim_hal.move(ctx, move);
}

/* The firmware's CAN glue, found in the port's context. */
static bool glue_send(void *ctx, const daran_can_frame_t *frame)
{
    return firmware_can_glue_send(&((struct sim_port *)ctx)->glue, frame);
}

static uint32_t glue_now_ms(void *ctx)
{
    return firmware_can_glue_now_ms(&((struct sim_port *)ctx)->glue);
}

static void glue_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame)
{
    firmware_can_glue_deliver(&((struct sim_port *)ctx)->glue, can, frame);
}

/* The context is the port's state, whose first member is the drive the
 * simulator's functions take. */
static const daran_hal_t sim_hal = {.get = sim_get,
                                    .set = sim_set,
                                    .move = sim_move,
                                    .action = sim_action,
                                    .now_ms = glue_now_ms,
                                    .can_send = glue_send};

static bool factory_reset(void *ctx)
{
    struct sim_port *p = ctx;
    daran_sim_drive_init(&p->sim, 0u, SIM_TICK_HZ);
    firmware_can_glue_reset(&p->glue);
    return true;
}

static void advance(void *ctx, uint32_t ms)
{
    struct sim_port *p = ctx;
    for (uint32_t tick = 0; tick < ms * (SIM_TICK_HZ / 1000u); tick++) {
        daran_sim_drive_tick(&p->sim);
    }
    firmware_can_glue_advance(&p->glue, ms);
}

const daran_test_port_t *daran_test_port(void)
{
#ifdef BROKEN_CAN
    const char *chosen = getenv("BROKEN_CAN");
    breach = chosen != NULL ? atoi(chosen) : 0;
    bool of_the_glue = breach > 0 && (size_t)breach < sizeof glue_mistakes / sizeof glue_mistakes[0];
    port_state.glue.mistake = of_the_glue ? glue_mistakes[breach] : FIRMWARE_CAN_NO_MISTAKE;
#endif
    static const daran_test_port_t port = {
        .name = "port/sim (the simulated drive)",
        .hal = &sim_hal,
        .ctx = &port_state,
        .reset = factory_reset,
        .advance = advance,
        .can_deliver = glue_deliver,
    };
    return &port;
}
