/* port/minimal's HAL with the CAN glue of a firmware, for the CAN fuzz
 * target (daran_ascii_add_can_fuzz_target): a clock that advance() moves,
 * a transmit that takes every frame, and a receive path whose acceptance
 * filter passes standard ids at the drive's current id and node 0.
 *
 * Compiled with BROKEN_CAN, the environment variable BROKEN_CAN chooses a
 * mistake the harness must catch on its built-in seeds (unset: none;
 * tests/adopter-fuzz/CMakeLists.txt):
 *   1  a receive path that takes an extended id for a standard one
 *   2  a clock in tenths of a millisecond */
#include <stdlib.h>

#include "daran_test_port.h"
#include "minimal_hal.h"

static struct can_port_state {
    minimal_drive_t axis;
    uint32_t now_ms;
} state;

#ifdef BROKEN_CAN
static int breach;
#else
enum { breach = 0 };
#endif

static bool factory_reset(void *ctx)
{
    struct can_port_state *s = ctx;
    minimal_drive_init(&s->axis);
    s->now_ms = 0;
    return true;
}

static void advance(void *ctx, uint32_t ms)
{
    struct can_port_state *s = ctx;
    s->now_ms += ms;
}

static bool can_send(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    (void)frame;
    return true;
}

static uint32_t can_now_ms(void *ctx)
{
    const struct can_port_state *s = ctx;
    return breach == 2 ? s->now_ms * 10u : s->now_ms;
}

static const daran_can_port_t can_port = {can_send, can_now_ms, NULL};

static void can_deliver(void *ctx, daran_can_t *can, const daran_can_frame_t *frame)
{
    struct can_port_state *s = ctx;
    daran_can_frame_t taken = *frame;
    if (breach == 1) {
        taken.flags &= (uint8_t)~DARAN_CAN_FRAME_EXTENDED;
        taken.id &= 0x7FFu;
    }
    daran_value_t own;
    (void)minimal_hal.get(&s->axis, DARAN_PROP_CAN_NODE_ID, &own);
    uint32_t node = taken.id >> 5;
    if ((taken.flags & DARAN_CAN_FRAME_EXTENDED) == 0u && (node == own.u32 || node == 0u)) {
        (void)daran_can_receive(can, &taken);
    }
}

const daran_test_port_t *daran_test_port(void)
{
#ifdef BROKEN_CAN
    const char *chosen = getenv("BROKEN_CAN");
    breach = chosen != NULL ? atoi(chosen) : 0;
#endif
    static const daran_test_port_t port = {
        .name = "port/minimal with CAN glue",
        .hal = &minimal_hal,
        .ctx = &state, /* its first member is the drive minimal_hal takes */
        .reset = factory_reset,
        .advance = advance,
        .can_port = &can_port,
        .can_ctx = &state,
        .can_deliver = can_deliver,
    };
    return &port;
}
