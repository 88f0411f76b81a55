/* port/minimal with one deliberate breach of the HAL contract, chosen by
 * BROKEN_HAL when it is compiled: the conformance suite must fail each
 * (tests/conformance/CMakeLists.txt names the requirement each must fail).
 *
 *   1  a setter that ignores its value (controller.config.pos_gain)
 *   2  a getter that answers "unsupported" for a property the build lists
 *      (controller.config.vel_gain: invalid property)
 *   3  an ss that reports success without saving
 *   4  an st that reports success and keeps the motor running
 *   5  a velocity move that never reaches input_vel
 *   6  a node id that is stored but never answered to (the getter keeps 1)
 *   7  a trapezoid that overwrites the cruise velocity the line did not give
 *      (found by a first adopter's trial: `given` ignored) */
#include "daran_test_port.h"

#include "minimal_hal.h"

#ifndef BROKEN_HAL
#error "BROKEN_HAL selects the breach (1..7)"
#endif

static minimal_drive_t axis;

static daran_result_t broken_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    if (BROKEN_HAL == 2 && prop == DARAN_PROP_VEL_GAIN) {
        return DARAN_ERR_INVALID_PROPERTY;
    }
    daran_result_t result = minimal_hal.get(ctx, prop, out);
    if (BROKEN_HAL == 6 && prop == DARAN_PROP_CAN_NODE_ID) {
        out->u32 = 1;
    }
    return result;
}

static daran_result_t broken_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    if (BROKEN_HAL == 1 && prop == DARAN_PROP_POS_GAIN) {
        return DARAN_OK;
    }
    return minimal_hal.set(ctx, prop, value);
}

static daran_result_t broken_move(void *ctx, const daran_move_t *move)
{
    if (BROKEN_HAL == 5 && (move->kind == DARAN_MOVE_VELOCITY || move->kind == DARAN_MOVE_VELOCITY_RAMP)) {
        return DARAN_OK;
    }
    if (BROKEN_HAL == 7 && move->kind == DARAN_MOVE_TRAPEZOID) {
        ((minimal_drive_t *)ctx)->props[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = move->vel_rpm;
    }
    return minimal_hal.move(ctx, move);
}

static daran_result_t broken_action(void *ctx, daran_action_t action)
{
    if ((BROKEN_HAL == 3 && action == DARAN_ACTION_SAVE_CONFIG) ||
        (BROKEN_HAL == 4 && action == DARAN_ACTION_ESTOP)) {
        return DARAN_OK;
    }
    return minimal_hal.action(ctx, action);
}

static const daran_hal_t broken_hal = {.get = broken_get, .set = broken_set, .move = broken_move, .action = broken_action};

static bool factory_reset(void *ctx)
{
    minimal_drive_init(ctx);
    return true;
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "port/minimal, broken on purpose",
        .hal = &broken_hal,
        .ctx = &axis,
        .reset = factory_reset,
    };
    return &port;
}
