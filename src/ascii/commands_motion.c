/* Motion commands t q p v c d, and the shapes the multi-motor starts reuse.
 * A shape says where each value of the line goes in the move and how it is
 * checked; one function turns values into a move, so `mt` is exactly `t`,
 * `mv` exactly `v`, and so on. Every value is checked before the drive's
 * state, and the state before the one HAL move. */
#include "compiler.h"
#include "hal.h"
#include "handlers.h"
#include "number.h"

enum slot { SLOT_POS, SLOT_VEL, SLOT_TORQUE, SLOT_RATE, SLOT_KP, SLOT_KD, SLOT_PARAM, SLOT_MODE,
            SLOT_IGNORED, SLOT_COUNT };
enum check { CHECK_ANY, CHECK_POSITIVE, CHECK_NON_NEGATIVE, CHECK_MODE_VELOCITY, CHECK_MODE_TORQUE };

#define VALUE(slot, check) (uint8_t)(((slot) << 4) | (check))
#define SLOT_OF(value) ((value) >> 4)
#define CHECK_OF(value) ((value) & 0x0Fu)

typedef struct motion_shape {
    uint8_t kind;      /* daran_move_kind_t */
    uint8_t count;     /* values after the id */
    uint8_t value[DARAN_MOTION_VALUES_MAX]; /* VALUE(slot, check) */
} motion_shape_t;

static const motion_shape_t shapes[DARAN_SHAPE_COUNT] = {
    [DARAN_SHAPE_FILTERED] = {DARAN_MOVE_FILTERED_POSITION, 3,
                              {VALUE(SLOT_POS, CHECK_ANY), VALUE(SLOT_IGNORED, CHECK_ANY),
                               VALUE(SLOT_RATE, CHECK_NON_NEGATIVE)}},
    [DARAN_SHAPE_TRAPEZOID] = {DARAN_MOVE_TRAPEZOID, 3,
                               {VALUE(SLOT_POS, CHECK_ANY), VALUE(SLOT_VEL, CHECK_POSITIVE),
                                VALUE(SLOT_RATE, CHECK_NON_NEGATIVE)}},
    [DARAN_SHAPE_PASSTHROUGH] = {DARAN_MOVE_PASSTHROUGH, 3,
                                 {VALUE(SLOT_POS, CHECK_ANY), VALUE(SLOT_VEL, CHECK_ANY),
                                  VALUE(SLOT_TORQUE, CHECK_ANY)}},
    [DARAN_SHAPE_VELOCITY] = {DARAN_MOVE_VELOCITY, 3,
                              {VALUE(SLOT_VEL, CHECK_ANY), VALUE(SLOT_PARAM, CHECK_ANY),
                               VALUE(SLOT_MODE, CHECK_MODE_VELOCITY)}},
    [DARAN_SHAPE_TORQUE] = {DARAN_MOVE_TORQUE, 3,
                            {VALUE(SLOT_TORQUE, CHECK_ANY), VALUE(SLOT_PARAM, CHECK_ANY),
                             VALUE(SLOT_MODE, CHECK_MODE_TORQUE)}},
    [DARAN_SHAPE_IMPEDANCE] = {DARAN_MOVE_IMPEDANCE, 5,
                               {VALUE(SLOT_POS, CHECK_ANY), VALUE(SLOT_VEL, CHECK_ANY),
                                VALUE(SLOT_TORQUE, CHECK_ANY), VALUE(SLOT_KP, CHECK_NON_NEGATIVE),
                                VALUE(SLOT_KD, CHECK_NON_NEGATIVE)}},
};

/* Which optional value a slot gives the HAL (daran_move_t.given). */
static const uint8_t slot_given[SLOT_COUNT] = {
    [SLOT_VEL] = DARAN_GIVEN_VEL,
    [SLOT_RATE] = DARAN_GIVEN_RATE,
};

/* The modes of v and c (spec 5), carried as the float a value slot holds:
 * a preset's mode is one of ms's floats. */
#define MODE_DIRECT 1.0f        /* v: velocity, c: torque, each at once */
#define MODE_VELOCITY_RAMP 2.0f /* v: the parameter is the ramp rate */
/* What a well-formed integer past every mode becomes: no set holds it, so
 * check_value answers `invalid mode` for it like for any other. */
#define MODE_NONE -1.0f

/* Modes as bit sets: bit m set = mode m allowed. Mode 2 of `c` is the vendor's
 * own C libraries' name for the torque ramp (6). */
static const uint8_t mode_sets[] = {
    [CHECK_MODE_VELOCITY] = (1u << 1) | (1u << 2),
    [CHECK_MODE_TORQUE] = (1u << 1) | (1u << 2) | (1u << 6),
};

static daran_result_t check_value(uint8_t check, float value)
{
    switch (check) {
    case CHECK_POSITIVE:
        return value > 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    case CHECK_NON_NEGATIVE:
        return value >= 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    case CHECK_MODE_VELOCITY:
    case CHECK_MODE_TORQUE:
        for (uint8_t mode = 1; mode < 8u; mode++) {
            if ((((unsigned)mode_sets[check] >> mode) & 1u) != 0u && value == (float)mode) {
                return DARAN_OK;
            }
        }
        return DARAN_ERR_INVALID_MODE;
    default:
        return DARAN_OK;
    }
}

/* A mode field is an exact integer (D12): "1.5" is an invalid value, a
 * well-formed integer outside the set an invalid mode. */
static daran_result_t parse_motion_value(const daran_field_t *field, uint8_t check, float *out)
{
    if (check == CHECK_MODE_VELOCITY || check == CHECK_MODE_TORQUE) {
        uint64_t mode;
        daran_result_t result = daran_parse_u64(field->text, field->len, &mode);
        if (result == DARAN_ERR_INVALID_VALUE) {
            return result;
        }
        *out = (result == DARAN_OK && mode < 8u) ? (float)(uint8_t)mode : MODE_NONE;
    } else {
        daran_result_t result = daran_parse_f32(field->text, field->len, out);
        if (result != DARAN_OK) {
            return result;
        }
    }
    return check_value(check, *out);
}

daran_result_t daran_shape_check(daran_shape_t shape_id, const float *values, uint8_t count)
{
    const motion_shape_t *shape = &shapes[shape_id];
    for (uint8_t i = 0; i < count; i++) {
        daran_result_t result = check_value(CHECK_OF(shape->value[i]), values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    return DARAN_OK;
}

daran_result_t daran_shape_move(daran_shape_t shape_id, const float *values, uint8_t count,
                                daran_move_t *move)
{
    const motion_shape_t *shape = &shapes[shape_id];
    float slot[SLOT_COUNT];
    slot[SLOT_POS] = slot[SLOT_VEL] = slot[SLOT_TORQUE] = slot[SLOT_RATE] = 0.0f;
    slot[SLOT_KP] = slot[SLOT_KD] = slot[SLOT_PARAM] = slot[SLOT_IGNORED] = 0.0f;
    slot[SLOT_MODE] = MODE_DIRECT; /* the mode of v and c defaults to 1 */
    unsigned given = 0;
    for (uint8_t i = 0; i < count; i++) {
        unsigned to = SLOT_OF(shape->value[i]);
        slot[to] = values[i];
        given |= slot_given[to];
    }
    move->kind = (daran_move_kind_t)shape->kind;
    if (shape->kind != DARAN_MOVE_TRAPEZOID) {
        given &= ~DARAN_GIVEN_VEL; /* a cruise velocity is a trapezoid's alone */
    }
    move->given = (uint8_t)given;

    /* v and c: the mode says what the parameter is. A ramp needs a rate
     * >= 0; 0 holds the setpoint where it is (spec 10.1). */
    if (shape->kind == DARAN_MOVE_VELOCITY && slot[SLOT_MODE] == MODE_VELOCITY_RAMP) {
        move->kind = DARAN_MOVE_VELOCITY_RAMP;
        slot[SLOT_RATE] = slot[SLOT_PARAM];
    } else if (shape->kind == DARAN_MOVE_VELOCITY) {
        slot[SLOT_TORQUE] = slot[SLOT_PARAM];
    } else if (shape->kind == DARAN_MOVE_TORQUE && slot[SLOT_MODE] != MODE_DIRECT) {
        move->kind = DARAN_MOVE_TORQUE_RAMP;
        slot[SLOT_RATE] = slot[SLOT_PARAM];
    }
    if ((move->kind == DARAN_MOVE_VELOCITY_RAMP || move->kind == DARAN_MOVE_TORQUE_RAMP) &&
        !(slot[SLOT_RATE] >= 0.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (slot[SLOT_RATE] == 0.0f) {
        slot[SLOT_RATE] = 0.0f; /* -0 is 0: the rate becomes a property that reads back */
        if (move->kind == DARAN_MOVE_FILTERED_POSITION) {
            move->given &= (uint8_t)~DARAN_GIVEN_RATE; /* bandwidth 0: keep the current one */
        } else if (move->kind == DARAN_MOVE_TRAPEZOID && (move->given & DARAN_GIVEN_RATE) != 0u) {
            move->given &= (uint8_t)~DARAN_GIVEN_VEL; /* acceleration 0: a step, no cruise */
            slot[SLOT_VEL] = 0.0f;
        }
    }

    move->pos_deg = slot[SLOT_POS];
    move->vel_rpm = slot[SLOT_VEL];
    move->torque_nm = slot[SLOT_TORQUE];
    move->rate = slot[SLOT_RATE];
    move->kp = slot[SLOT_KP];
    move->kd = slot[SLOT_KD];
    return DARAN_OK;
}

/* Build the move and run it. Kept out of daran_cmd_motion() so the move is not
 * on the stack while the values are parsed: that chain is the core's deepest. */
DARAN_NOINLINE daran_result_t daran_run_motion(daran_drive_t *drive, daran_shape_t shape_id,
                                               const float *values, uint8_t count)
{
    daran_move_t move;
    daran_result_t result = daran_shape_move(shape_id, values, count, &move);
    if (result == DARAN_OK) {
        result = daran_check_motion_allowed(drive);
    }
    return result != DARAN_OK ? result : daran_start_move(drive, &move);
}

daran_result_t daran_parse_motion(const daran_request_t *request,
                                                      float *values, uint8_t *count)
{
    const motion_shape_t *shape = &shapes[request->command->arg];
    *count = (uint8_t)(request->fields->count - 2u);
    for (uint8_t i = 0; i < *count; i++) {
        daran_field_t field = daran_field_at(request, 2u + i);
        daran_result_t result = parse_motion_value(&field, CHECK_OF(shape->value[i]), &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    return DARAN_OK;
}

daran_result_t daran_cmd_motion(daran_drive_t *drive, const daran_request_t *request)
{
    float values[DARAN_MOTION_VALUES_MAX];
    uint8_t count;
    daran_result_t result = daran_parse_motion(request, values, &count);
    return result != DARAN_OK ? result
                              : daran_run_motion(drive, (daran_shape_t)request->command->arg,
                                                 values, count);
}
