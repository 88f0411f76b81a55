/* Single-motor motion commands: t q p v c d. Each parses and checks every
 * value first, then the drive's state, then makes one HAL move. */
#include "internal.h"

static daran_result_t run(daran_drive_t *drive, daran_result_t parsed, const daran_move_t *move)
{
    if (parsed != DARAN_OK) {
        return parsed;
    }
    daran_result_t result = daran_check_motion_allowed(drive);
    return result != DARAN_OK ? result : daran_start_move(drive, move);
}

daran_result_t daran_velocity_move(float vel, float param, uint32_t mode, daran_move_t *move)
{
    move->vel_rpm = vel;
    if (mode == 2u) {
        move->kind = DARAN_MOVE_VELOCITY_RAMP;
        move->rate = param;
        return param > 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    }
    move->kind = DARAN_MOVE_VELOCITY;
    move->torque_nm = param;
    return DARAN_OK;
}

daran_result_t daran_torque_move(float torque, float param, uint32_t mode, daran_move_t *move)
{
    move->torque_nm = torque;
    if (mode == 1u) {
        move->kind = DARAN_MOVE_TORQUE;
        return DARAN_OK;
    }
    /* Mode 2 is the vendor's own C libraries' name for the ramp (6). */
    move->kind = DARAN_MOVE_TORQUE_RAMP;
    move->rate = param;
    return param > 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
}

daran_result_t daran_cmd_t(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_FILTERED_POSITION, 0, 0, 0, 0, 0, 0, 0};
    float ignored_vel;
    daran_result_t result = daran_field_f32(&fields->at[2], &move.pos_deg);
    if (result == DARAN_OK && fields->count > 3u) {
        result = daran_field_f32(&fields->at[3], &ignored_vel);
    }
    if (result == DARAN_OK && fields->count > 4u) {
        result = daran_field_positive(&fields->at[4], &move.rate);
        move.given = DARAN_GIVEN_RATE;
    }
    return run(drive, result, &move);
}

daran_result_t daran_cmd_q(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_TRAPEZOID, 0, 0, 0, 0, 0, 0, 0};
    daran_result_t result = daran_field_f32(&fields->at[2], &move.pos_deg);
    if (result == DARAN_OK && fields->count > 3u) {
        result = daran_field_positive(&fields->at[3], &move.vel_rpm);
        move.given |= DARAN_GIVEN_VEL;
    }
    if (result == DARAN_OK && fields->count > 4u) {
        result = daran_field_positive(&fields->at[4], &move.rate);
        move.given |= DARAN_GIVEN_RATE;
    }
    return run(drive, result, &move);
}

daran_result_t daran_cmd_p(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_PASSTHROUGH, 0, 0, 0, 0, 0, 0, 0};
    daran_result_t result = daran_field_f32(&fields->at[2], &move.pos_deg);
    if (result == DARAN_OK && fields->count > 3u) {
        result = daran_field_f32(&fields->at[3], &move.vel_rpm);
    }
    if (result == DARAN_OK && fields->count > 4u) {
        result = daran_field_f32(&fields->at[4], &move.torque_nm);
    }
    return run(drive, result, &move);
}

daran_result_t daran_cmd_v(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_VELOCITY, 0, 0, 0, 0, 0, 0, 0};
    float vel;
    float param = 0.0f;
    uint32_t mode = 1;
    daran_result_t result = daran_field_f32(&fields->at[2], &vel);
    if (result == DARAN_OK && fields->count > 3u) {
        result = daran_field_f32(&fields->at[3], &param);
    }
    if (result == DARAN_OK && fields->count > 4u) {
        result = daran_field_mode(&fields->at[4], DARAN_MODES_VELOCITY, &mode);
    }
    if (result == DARAN_OK) {
        result = daran_velocity_move(vel, param, mode, &move);
    }
    return run(drive, result, &move);
}

daran_result_t daran_cmd_c(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_TORQUE, 0, 0, 0, 0, 0, 0, 0};
    float torque;
    float param = 0.0f;
    uint32_t mode = 1;
    daran_result_t result = daran_field_f32(&fields->at[2], &torque);
    if (result == DARAN_OK && fields->count > 3u) {
        result = daran_field_f32(&fields->at[3], &param);
    }
    if (result == DARAN_OK && fields->count > 4u) {
        result = daran_field_mode(&fields->at[4], DARAN_MODES_TORQUE, &mode);
    }
    if (result == DARAN_OK) {
        result = daran_torque_move(torque, param, mode, &move);
    }
    return run(drive, result, &move);
}

daran_result_t daran_cmd_d(daran_drive_t *drive, const daran_request_t *request)
{
    const daran_fields_t *fields = request->fields;
    daran_move_t move = {DARAN_MOVE_IMPEDANCE, 0, 0, 0, 0, 0, 0, 0};
    daran_result_t result = daran_field_f32(&fields->at[2], &move.pos_deg);
    if (result == DARAN_OK) {
        result = daran_field_f32(&fields->at[3], &move.vel_rpm);
    }
    if (result == DARAN_OK) {
        result = daran_field_f32(&fields->at[4], &move.torque_nm);
    }
    if (result == DARAN_OK) {
        result = daran_field_non_negative(&fields->at[5], &move.kp);
    }
    if (result == DARAN_OK) {
        result = daran_field_non_negative(&fields->at[6], &move.kd);
    }
    return run(drive, result, &move);
}
