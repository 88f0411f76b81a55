/* The simulated drive (daran_sim.h) handed to the conformance suite: a HAL
 * over a physical model, with time (advance() runs its 1 kHz control
 * ticks) and non-volatile memory. Its reset is a new drive: id 1, empty
 * storage, closed loop.
 *
 * Its CAN glue is the one a firmware has: a clock that is the drive time
 * advance() passes, a transmit that takes every frame (a host has no
 * mailbox to fill), and a receive path whose acceptance filter passes
 * standard data frames at the drive's current id and at node 0.
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

#define SIM_TICK_HZ 1000u

static struct sim_port {
    daran_sim_drive_t sim;
    uint32_t now_ms;
    uint32_t filter_node; /* breach 3: the id the filter was set for at reset */
    daran_can_t *heard;   /* breach 6: the front end its own frames come back to */
} port_state;

#ifdef BROKEN_CAN
static int breach;
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

static const daran_hal_t sim_hal = {sim_get, sim_set, sim_move, sim_action};

static bool factory_reset(void *ctx)
{
    struct sim_port *p = ctx;
    daran_sim_drive_init(&p->sim, 0u, SIM_TICK_HZ);
    p->now_ms = 0;
    p->filter_node = daran_sim_drive_id(&p->sim);
    p->heard = NULL;
    return true;
}

static void advance(void *ctx, uint32_t ms)
{
    struct sim_port *p = ctx;
    for (uint32_t tick = 0; tick < ms * (SIM_TICK_HZ / 1000u); tick++) {
        daran_sim_drive_tick(&p->sim);
    }
    p->now_ms += ms;
}

static bool can_send(void *ctx, const daran_can_frame_t *frame)
{
    struct sim_port *p = ctx;
    if (breach == 6 && p->heard != NULL) {
        (void)daran_can_receive(p->heard, frame);
    }
    return true;
}

static uint32_t can_now_ms(void *ctx)
{
    const struct sim_port *p = ctx;
    return breach == 8 ? p->now_ms * 10u : p->now_ms;
}

static const daran_can_port_t can_port = {can_send, can_now_ms, NULL};

/* The acceptance filter: standard ids at the drive's id or node 0 (status
 * frames at the own id included: the duplicate check needs them). */
static void can_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame)
{
    struct sim_port *p = ctx;
    daran_can_frame_t taken = *frame;
    if (breach == 7) {
        taken.flags &= (uint8_t)~DARAN_CAN_FRAME_EXTENDED;
        taken.id &= 0x7FFu;
    }
    p->heard = can;
    uint32_t node = breach == 3 ? p->filter_node : daran_sim_drive_id(&p->sim);
    bool standard = (taken.flags & DARAN_CAN_FRAME_EXTENDED) == 0u;
    uint32_t frame_node = taken.id >> 5;
    if (!standard || frame_node == node || frame_node == 0u) {
        (void)daran_can_receive(can, &taken); /* it refuses other shapes itself */
    }
}

const daran_test_port_t *daran_test_port(void)
{
#ifdef BROKEN_CAN
    const char *chosen = getenv("BROKEN_CAN");
    breach = chosen != NULL ? atoi(chosen) : 0;
#endif
    static const daran_test_port_t port = {
        .name = "port/sim (the simulated drive)",
        .hal = &sim_hal,
        .ctx = &port_state,
        .reset = factory_reset,
        .advance = advance,
        .can_port = &can_port,
        .can_ctx = &port_state,
        .can_deliver = can_deliver,
    };
    return &port;
}
