/* The simulated drive's physics and controller: one call per control tick.
 * Equations and defaults are explained in docs/simulator.md. */
#include "sim_model.h"

#include <math.h>
#include <string.h>

#define DEG_PER_TURN 360.0f
#define RPM_PER_TURN_S 60.0f
#define DEG_S_PER_RPM 6.0f /* 1 r/min = 6 deg/s */
#define TWO_PI 6.28318530718f

static const struct {
    daran_prop_t prop;
    daran_value_t value;
} config_defaults[] = {
    {DARAN_PROP_CAN_BAUD_RATE, {.u32 = 1000000u}},
    {DARAN_PROP_UART_BAUDRATE, {.u32 = 115200u}},
    {DARAN_PROP_CAN_NODE_ID, {.u32 = 1u}},
    {DARAN_PROP_ENABLE_WATCHDOG, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, {.u32 = 0u}},
    {DARAN_PROP_WATCHDOG_TIMEOUT, {.f32 = 0.5f}},
    {DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, {.u32 = 1u}},
    {DARAN_PROP_INPUT_FILTER_BANDWIDTH, {.f32 = 20.0f}},
    {DARAN_PROP_POS_GAIN, {.f32 = 20.0f}},
    {DARAN_PROP_VEL_GAIN, {.f32 = 0.16f}},
    {DARAN_PROP_VEL_INTEGRATOR_GAIN, {.f32 = 0.8f}},
    {DARAN_PROP_CONTROLLER_VEL_LIMIT, {.f32 = 10.0f}},
    {DARAN_PROP_FET_THERMISTOR_ENABLED, {.u32 = 1u}},
    {DARAN_PROP_FET_TEMP_LIMIT_LOWER, {.f32 = 80.0f}},
    {DARAN_PROP_FET_TEMP_LIMIT_UPPER, {.f32 = 100.0f}},
    {DARAN_PROP_CURRENT_CONTROL_BANDWIDTH, {.f32 = 1000.0f}},
    {DARAN_PROP_CURRENT_LIM, {.f32 = 25.0f}},
    {DARAN_PROP_MOTOR_TORQUE_LIM, {.f32 = 3.0f}},
    {DARAN_PROP_MOTOR_THERMISTOR_ENABLED, {.u32 = 1u}},
    {DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER, {.f32 = 90.0f}},
    {DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER, {.f32 = 120.0f}},
    {DARAN_PROP_CIRCULAR_SETPOINT_MAX, {.f32 = 360.0f}},
    {DARAN_PROP_CIRCULAR_SETPOINT_MIN, {.f32 = -360.0f}},
    {DARAN_PROP_LOAD_INERTIA, {.f32 = 0.0f}},
    {DARAN_PROP_STEPS_PER_TURN, {.f32 = 16384.0f}},
    {DARAN_PROP_TORQUE_CONSTANT, {.f32 = 0.1f}},
    {DARAN_PROP_SHAFT_TORQUE_LIM, {.f32 = 2.0f}},
    {DARAN_PROP_TORQUE_RAMP_RATE, {.f32 = 1.0f}},
    {DARAN_PROP_SHAFT_VEL_LIMIT, {.f32 = 600.0f}},
    {DARAN_PROP_VEL_RAMP_RATE, {.f32 = 60.0f}},
};

#define DARAN_SIM_ACCESS_RW 1u
#define DARAN_SIM_ACCESS_RO 0u
static const uint8_t prop_is_rw[DARAN_PROP_COUNT] = {
#define DARAN_SIM_RW_(id, path, scope, type, access, range, unit) \
    (uint8_t)DARAN_SIM_ACCESS_##access,
    DARAN_PROPERTY_LIST(DARAN_SIM_RW_)
#undef DARAN_SIM_RW_
};

static const daran_prop_type_t prop_type[DARAN_PROP_COUNT] = {
#define DARAN_SIM_TYPE_(id, path, scope, type, access, range, unit) DARAN_TYPE_##type,
    DARAN_PROPERTY_LIST(DARAN_SIM_TYPE_)
#undef DARAN_SIM_TYPE_
};

bool daran_sim_is_config_prop(daran_prop_t prop)
{
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT || !prop_is_rw[prop]) {
        return false;
    }
    switch (prop) {
    case DARAN_PROP_INPUT_POS:
    case DARAN_PROP_INPUT_VEL:
    case DARAN_PROP_INPUT_TORQUE:
    case DARAN_PROP_POS_SETPOINT:
    case DARAN_PROP_VEL_SETPOINT:
    case DARAN_PROP_TORQUE_SETPOINT:
    case DARAN_PROP_REQUESTED_STATE:
        return false;
    default:
        return true;
    }
}

static float cfgf(const daran_sim_model_t *m, daran_prop_t prop)
{
    return m->cfg[prop].f32;
}

static float minf(float a, float b)
{
    return a < b ? a : b;
}

static float clampf(float x, float lo, float hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

static float signf(float x)
{
    return x < 0.0f ? -1.0f : 1.0f;
}

float daran_sim_model_pos_deg(const daran_sim_model_t *m)
{
    return m->raw_pos_deg - m->zero_offset_deg;
}

float daran_sim_model_inertia(const daran_sim_model_t *m)
{
    return m->par.rotor_inertia + cfgf(m, DARAN_PROP_LOAD_INERTIA);
}

float daran_sim_model_vel_limit_rpm(const daran_sim_model_t *m)
{
    return minf(cfgf(m, DARAN_PROP_SHAFT_VEL_LIMIT),
                cfgf(m, DARAN_PROP_CONTROLLER_VEL_LIMIT) * RPM_PER_TURN_S);
}

/* 1 below temp_limit_lower, falling linearly to 0 at temp_limit_upper. */
static float derating(float temp, uint32_t enabled, float lower, float upper)
{
    if (!enabled || !(upper > lower) || temp <= lower) {
        return 1.0f;
    }
    return clampf((upper - temp) / (upper - lower), 0.0f, 1.0f);
}

float daran_sim_model_torque_limit(const daran_sim_model_t *m)
{
    float lim = minf(cfgf(m, DARAN_PROP_SHAFT_TORQUE_LIM), cfgf(m, DARAN_PROP_MOTOR_TORQUE_LIM));
    lim = minf(lim, cfgf(m, DARAN_PROP_CURRENT_LIM) * cfgf(m, DARAN_PROP_TORQUE_CONSTANT));
    lim *= derating(m->fet_temp_c, m->cfg[DARAN_PROP_FET_THERMISTOR_ENABLED].u32,
                    cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_LOWER), cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_UPPER));
    lim *= derating(m->motor_temp_c, m->cfg[DARAN_PROP_MOTOR_THERMISTOR_ENABLED].u32,
                    cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER),
                    cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER));
    return lim;
}

static bool limits_on(const daran_sim_model_t *m)
{
    return m->cfg[DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT].u32 != 0u &&
           cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MIN) <= cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MAX);
}

static float limit_pos(const daran_sim_model_t *m, float pos)
{
    if (!limits_on(m)) {
        return pos;
    }
    return clampf(pos, cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MIN),
                  cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MAX));
}

void daran_sim_model_default_config(daran_sim_model_t *m)
{
    size_t i;
    for (i = 0; i < sizeof config_defaults / sizeof config_defaults[0]; i++) {
        m->cfg[config_defaults[i].prop] = config_defaults[i].value;
    }
    m->zero_offset_deg = 0.0f;
}

static void params_default(daran_sim_params_t *p)
{
    p->rotor_inertia = 8.0e-4f;
    p->viscous_friction = 5.0e-4f;
    p->coulomb_friction = 1.0e-3f;
    p->phase_resistance = 0.3f;
    p->vbus_nominal = 24.0f;
    p->source_resistance = 0.02f;
    p->undervoltage_trip = 10.0f;
    p->sag_voltage = 8.0f;
    p->sag_duration = 0.1f;
    p->ambient_temp = 25.0f;
    p->motor_heat = 0.3f;
    p->motor_time_const = 30.0f;
    p->fet_heat = 0.1f;
    p->fet_time_const = 5.0f;
    p->overtemp_jump = 5.0f;
}

void daran_sim_model_init(daran_sim_model_t *m, uint32_t tick_hz)
{
    memset(m, 0, sizeof *m);
    params_default(&m->par);
    daran_sim_model_default_config(m);
    m->tick_hz = tick_hz == 0u ? 1u : tick_hz;
    m->dt = 1.0f / (float)m->tick_hz;
    m->motor_temp_c = m->par.ambient_temp;
    m->fet_temp_c = m->par.ambient_temp;
    daran_sim_model_boot(m);
}

/* Closed loop holding where the shaft is, as after power-up. */
static void hold_here(daran_sim_model_t *m)
{
    float pos = daran_sim_model_pos_deg(m);
    m->mode = DARAN_SIM_MODE_PASSTHROUGH;
    m->input_pos = pos;
    m->input_vel = 0.0f;
    m->input_torque = 0.0f;
    m->pos_sp = pos;
    m->vel_sp = 0.0f;
    m->torque_ff = 0.0f;
    m->integrator = 0.0f;
    m->trajectory_done = true;
    m->watchdog_s = 0.0f;
}

void daran_sim_model_boot(daran_sim_model_t *m)
{
    m->vbus_v = m->par.vbus_nominal;
    m->ibus_a = 0.0f;
    m->sag_left_s = 0.0f;
    m->torque_nm = 0.0f;
    m->torque_cmd = 0.0f;
    m->error = 0u;
    m->fet_error = 0u;
    m->motor_error = 0u;
    m->trap_vel_rpm = daran_sim_model_vel_limit_rpm(m);
    m->trap_acc_rpms = 60.0f;
    m->state = DARAN_STATE_CLOSED_LOOP;
    m->requested_state = DARAN_STATE_CLOSED_LOOP;
    hold_here(m);
}

void daran_sim_model_trip(daran_sim_model_t *m, uint32_t flags)
{
    m->error |= flags;
    if ((flags & ~(uint32_t)DARAN_FLAG_WARNING_MASK) != 0u || flags == 0u) {
        m->state = DARAN_STATE_IDLE;
        m->requested_state = DARAN_STATE_IDLE;
        m->torque_cmd = 0.0f;
        m->integrator = 0.0f;
    }
}

void daran_sim_model_clear_errors(daran_sim_model_t *m)
{
    m->error = 0u;
    m->fet_error = 0u;
    m->motor_error = 0u;
}

daran_result_t daran_sim_model_closed_loop(daran_sim_model_t *m)
{
    uint32_t blocking = m->error & ~(uint32_t)DARAN_FLAG_WARNING_MASK;
    if ((blocking & DARAN_FLAG_ESTOP) != 0u) {
        return DARAN_ERR_ESTOP_ACTIVE;
    }
    if (blocking != 0u) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        m->state = DARAN_STATE_CLOSED_LOOP;
        hold_here(m);
    }
    m->requested_state = DARAN_STATE_CLOSED_LOOP;
    return DARAN_OK;
}

void daran_sim_model_feed_watchdog(daran_sim_model_t *m)
{
    m->watchdog_s = 0.0f;
}

void daran_sim_model_set_zero(daran_sim_model_t *m)
{
    float shift = daran_sim_model_pos_deg(m);
    m->zero_offset_deg = m->raw_pos_deg;
    m->input_pos -= shift;
    m->pos_sp -= shift;
    m->filt_ref -= shift;
    m->trap_start -= shift;
    m->trap_target -= shift;
}

void daran_sim_model_fault(daran_sim_model_t *m, daran_sim_fault_t fault)
{
    switch (fault) {
    case DARAN_SIM_FAULT_OVERTEMP:
        m->fet_temp_c = cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_UPPER) + m->par.overtemp_jump;
        m->motor_temp_c = cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER) + m->par.overtemp_jump;
        break;
    case DARAN_SIM_FAULT_UNDERVOLTAGE:
        m->sag_left_s = m->par.sag_duration;
        break;
    default:
        break;
    }
}

/* ---- motion commands ---- */

static void trap_plan(daran_sim_model_t *m, float target)
{
    float dist = fabsf(target - m->trap_start);
    float vmax = minf(m->trap_vel_rpm, daran_sim_model_vel_limit_rpm(m)) * DEG_S_PER_RPM;
    float acc = m->trap_acc_rpms * DEG_S_PER_RPM;
    m->trap_target = target;
    m->trap_acc = acc;
    if (dist * acc < vmax * vmax) {
        /* too short to reach the cruise velocity: triangle */
        vmax = sqrtf(dist * acc);
        m->trap_ta = vmax / acc;
        m->trap_tc = 0.0f;
    } else {
        m->trap_ta = vmax / acc;
        m->trap_tc = (dist - vmax * m->trap_ta) / vmax;
    }
    m->trap_vmax = vmax;
    m->trap_total = 2.0f * m->trap_ta + m->trap_tc;
    /* A plan a float rounding longer than a whole number of ticks (an `mq`
     * of exactly 2 s computes to 2.0000002 s) still ends on that tick. */
    {
        float n = ceilf(m->trap_total * (float)m->tick_hz - 1e-3f);
        m->trap_end_tick = n >= 0.0f && n < 4.0e9f ? (uint32_t)n : UINT32_MAX;
    }
    m->trap_ticks = 0u;
    m->trajectory_done = dist == 0.0f;
}

static bool is_position_mode(daran_sim_mode_t mode)
{
    return mode == DARAN_SIM_MODE_PASSTHROUGH || mode == DARAN_SIM_MODE_FILTER ||
           mode == DARAN_SIM_MODE_TRAPEZOID;
}

/* The position setpoint belongs to the position modes: velocity and torque
 * control leave it where it was, and a position mode continues from it (as
 * on the ODrive-derived firmware: a drive that was spun by hand or by `c`
 * goes back to it). The filter starts at rest unless it continues a
 * position move. */
static void enter_position_mode(daran_sim_model_t *m, daran_sim_mode_t mode)
{
    if (mode == DARAN_SIM_MODE_FILTER && m->mode != DARAN_SIM_MODE_FILTER) {
        m->filt_ref = m->pos_sp;
        m->filt_err = 0.0f;
        m->filt_vel = is_position_mode(m->mode) ? m->vel_sp * DEG_S_PER_RPM : 0.0f;
    }
    if (m->mode == DARAN_SIM_MODE_TORQUE || m->mode == DARAN_SIM_MODE_TORQUE_RAMP ||
        m->mode == DARAN_SIM_MODE_IMPEDANCE) {
        m->integrator = 0.0f;
    }
    m->mode = mode;
}

daran_result_t daran_sim_model_move(daran_sim_model_t *m, const daran_move_t *mv)
{
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        if ((m->error & DARAN_FLAG_ESTOP) != 0u) {
            return DARAN_ERR_ESTOP_ACTIVE;
        }
        return (m->error & ~(uint32_t)DARAN_FLAG_WARNING_MASK) != 0u ? DARAN_ERR_MOTOR_FAULT
                                                                     : DARAN_ERR_MOTOR_IDLE;
    }
    switch (mv->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
        if ((mv->given & DARAN_GIVEN_RATE) != 0u) {
            m->cfg[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = mv->rate;
        }
        enter_position_mode(m, DARAN_SIM_MODE_FILTER);
        m->input_pos = mv->pos_deg;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_TRAPEZOID:
        if ((mv->given & DARAN_GIVEN_VEL) != 0u) {
            m->trap_vel_rpm = mv->vel_rpm;
        }
        if ((mv->given & DARAN_GIVEN_RATE) != 0u) {
            m->trap_acc_rpms = mv->rate;
        }
        enter_position_mode(m, DARAN_SIM_MODE_TRAPEZOID);
        m->input_pos = mv->pos_deg;
        m->trap_start = m->pos_sp;
        trap_plan(m, limit_pos(m, mv->pos_deg));
        break;
    case DARAN_MOVE_PASSTHROUGH:
        enter_position_mode(m, DARAN_SIM_MODE_PASSTHROUGH);
        m->input_pos = mv->pos_deg;
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_VELOCITY:
        m->mode = DARAN_SIM_MODE_VELOCITY;
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_VELOCITY_RAMP:
        m->cfg[DARAN_PROP_VEL_RAMP_RATE].f32 = mv->rate;
        if (m->mode != DARAN_SIM_MODE_VELOCITY && m->mode != DARAN_SIM_MODE_VELOCITY_RAMP) {
            m->vel_sp = m->vel_rpm; /* ramp from where the shaft is */
        }
        m->mode = DARAN_SIM_MODE_VELOCITY_RAMP;
        m->input_vel = mv->vel_rpm;
        m->input_torque = 0.0f;
        m->torque_ff = 0.0f;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_TORQUE:
        m->mode = DARAN_SIM_MODE_TORQUE;
        m->input_torque = mv->torque_nm;
        m->integrator = 0.0f;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_TORQUE_RAMP:
        m->cfg[DARAN_PROP_TORQUE_RAMP_RATE].f32 = mv->rate;
        if (m->mode != DARAN_SIM_MODE_TORQUE && m->mode != DARAN_SIM_MODE_TORQUE_RAMP) {
            m->torque_cmd = m->torque_nm;
        }
        m->mode = DARAN_SIM_MODE_TORQUE_RAMP;
        m->input_torque = mv->torque_nm;
        m->integrator = 0.0f;
        m->trajectory_done = true;
        break;
    case DARAN_MOVE_IMPEDANCE:
        m->mode = DARAN_SIM_MODE_IMPEDANCE;
        m->input_pos = mv->pos_deg;
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        m->kp = mv->kp;
        m->kd = mv->kd;
        m->integrator = 0.0f;
        m->trajectory_done = true;
        break;
    default:
        return DARAN_ERR_INVALID_MODE;
    }
    return DARAN_OK;
}

/* ---- one control tick ---- */

/* Far beyond any real drive, far enough below FLT_MAX that the filter's
 * products (w^2 e, w c t) stay finite: an absurd target (t 1 1e36) or
 * bandwidth (w ...input_filter_bandwidth 1e38) saturates, it does not turn
 * the state into inf or nan. At a bandwidth of 1e6/s and any tick the
 * filter already passes the target straight through. */
#define FILTER_ACC_MAX 1.0e30f
#define FILTER_ERROR_MAX 1.0e25f
#define FILTER_BANDWIDTH_MAX 1.0e6f

/* Exact step of the critically damped second-order filter x'' = w^2 (u - x)
 * - 2 w x' over dt: stable for any bandwidth and tick rate. The state is
 * kept as an offset from the target so that it settles on the target to the
 * last bit instead of stalling a few ulps short. */
static void filter_step(daran_sim_model_t *m, float target, float *acc_out)
{
    float w = cfgf(m, DARAN_PROP_INPUT_FILTER_BANDWIDTH);
    float t = m->dt;
    float e0 = clampf(m->filt_err + (m->filt_ref - target), -FILTER_ERROR_MAX, FILTER_ERROR_MAX);
    if (w > FILTER_BANDWIDTH_MAX) {
        w = FILTER_BANDWIDTH_MAX;
    }
    float v0 = m->filt_vel;
    float k = expf(-w * t);
    float c = v0 + w * e0;
    float e = (e0 + c * t) * k;
    float v = (v0 - w * c * t) * k;
    m->filt_ref = target;
    m->filt_err = e;
    m->filt_vel = v;
    /* A target near FLT_MAX makes w^2 e overflow. The acceleration only feeds
     * the torque feed-forward, which the torque limits cut long before: it
     * saturates here instead of carrying inf (or inf - inf) into the loops. */
    float acc = -w * w * e - 2.0f * w * v;
    if (!(acc - acc == 0.0f)) {
        acc = acc > 0.0f ? FILTER_ACC_MAX : (acc < 0.0f ? -FILTER_ACC_MAX : 0.0f);
    }
    *acc_out = acc;
}

/* The setpoint at the end of this tick: after N ticks of a plan of N * dt
 * seconds the move is done, on time. */
static void trap_eval(daran_sim_model_t *m, float *acc_out)
{
    float t;
    if (m->trap_ticks < UINT32_MAX) {
        m->trap_ticks++;
    }
    t = (float)m->trap_ticks * m->dt;
    float s = signf(m->trap_target - m->trap_start);
    float a = m->trap_acc;
    float ta = m->trap_ta;
    if (m->trap_ticks >= m->trap_end_tick || m->trajectory_done) {
        m->pos_sp = m->trap_target;
        m->vel_sp = 0.0f;
        *acc_out = 0.0f;
        m->trajectory_done = true;
        return;
    }
    if (t < ta) {
        m->pos_sp = m->trap_start + s * 0.5f * a * t * t;
        m->vel_sp = s * a * t / DEG_S_PER_RPM;
        *acc_out = s * a;
    } else if (t < ta + m->trap_tc) {
        m->pos_sp = m->trap_start + s * (0.5f * a * ta * ta + m->trap_vmax * (t - ta));
        m->vel_sp = s * m->trap_vmax / DEG_S_PER_RPM;
        *acc_out = 0.0f;
    } else {
        float td = m->trap_total - t;
        m->pos_sp = m->trap_target - s * 0.5f * a * td * td;
        m->vel_sp = s * a * td / DEG_S_PER_RPM;
        *acc_out = -s * a;
    }
}

/* Velocity and torque modes stop at a software limit and hold it. */
static void guard_limits(daran_sim_model_t *m, float pos, float push)
{
    float lo = cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MIN);
    float hi = cfgf(m, DARAN_PROP_CIRCULAR_SETPOINT_MAX);
    if (!limits_on(m)) {
        return;
    }
    if ((pos >= hi && push > 0.0f) || (pos <= lo && push < 0.0f)) {
        m->mode = DARAN_SIM_MODE_PASSTHROUGH;
        m->input_pos = pos >= hi ? hi : lo;
        m->input_vel = 0.0f;
        m->input_torque = 0.0f;
        m->vel_sp = 0.0f;
    }
}

static float approach(float from, float to, float step)
{
    if (from < to) {
        return from + step < to ? from + step : to;
    }
    return from - step > to ? from - step : to;
}

/* The velocity PI loop with conditional integration (no wind-up while the
 * torque is saturated in the direction of the error). */
static float velocity_loop(daran_sim_model_t *m, float vel_des_turn_s, float lim)
{
    float vel_err = vel_des_turn_s - m->vel_rpm / RPM_PER_TURN_S;
    float torque = m->torque_ff + cfgf(m, DARAN_PROP_VEL_GAIN) * vel_err + m->integrator;
    if (torque > lim) {
        torque = lim;
        if (vel_err < 0.0f) {
            m->integrator += cfgf(m, DARAN_PROP_VEL_INTEGRATOR_GAIN) * m->dt * vel_err;
        }
    } else if (torque < -lim) {
        torque = -lim;
        if (vel_err > 0.0f) {
            m->integrator += cfgf(m, DARAN_PROP_VEL_INTEGRATOR_GAIN) * m->dt * vel_err;
        }
    } else {
        m->integrator += cfgf(m, DARAN_PROP_VEL_INTEGRATOR_GAIN) * m->dt * vel_err;
    }
    return torque;
}

static void control(daran_sim_model_t *m)
{
    float pos = daran_sim_model_pos_deg(m);
    float lim = daran_sim_model_torque_limit(m);
    float vlim = daran_sim_model_vel_limit_rpm(m);
    float inertia = daran_sim_model_inertia(m);
    float acc = 0.0f;
    float torque;

    switch (m->mode) {
    case DARAN_SIM_MODE_VELOCITY:
    case DARAN_SIM_MODE_VELOCITY_RAMP:
        if (m->mode == DARAN_SIM_MODE_VELOCITY) {
            m->vel_sp = m->input_vel;
            m->torque_ff = m->input_torque;
        } else {
            m->vel_sp = approach(m->vel_sp, m->input_vel,
                                 cfgf(m, DARAN_PROP_VEL_RAMP_RATE) * m->dt);
            m->torque_ff = 0.0f;
        }
        m->vel_sp = clampf(m->vel_sp, -vlim, vlim);
        guard_limits(m, pos, m->vel_sp);
        if (m->mode == DARAN_SIM_MODE_PASSTHROUGH) {
            break;
        }
        m->torque_cmd = velocity_loop(m, m->vel_sp / RPM_PER_TURN_S, lim);
        return;
    case DARAN_SIM_MODE_TORQUE:
    case DARAN_SIM_MODE_TORQUE_RAMP:
        if (m->mode == DARAN_SIM_MODE_TORQUE) {
            torque = m->input_torque;
        } else {
            torque = approach(m->torque_cmd, m->input_torque,
                              cfgf(m, DARAN_PROP_TORQUE_RAMP_RATE) * m->dt);
        }
        m->vel_sp = 0.0f;
        guard_limits(m, pos, torque);
        if (m->mode == DARAN_SIM_MODE_PASSTHROUGH) {
            break;
        }
        if (m->cfg[DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT].u32 != 0u) {
            /* Fade the torque out as the speed passes the limit, as the
             * velocity loop would. */
            float gain = cfgf(m, DARAN_PROP_VEL_GAIN);
            float hi = (vlim - m->vel_rpm) / RPM_PER_TURN_S * gain;
            float lo = (-vlim - m->vel_rpm) / RPM_PER_TURN_S * gain;
            torque = clampf(torque, lo < 0.0f ? lo : 0.0f, hi > 0.0f ? hi : 0.0f);
        }
        m->torque_cmd = clampf(torque, -lim, lim);
        return;
    case DARAN_SIM_MODE_IMPEDANCE:
        m->pos_sp = m->input_pos;
        m->vel_sp = m->input_vel;
        torque = m->kp * (m->input_pos - pos) + m->input_torque +
                 m->kd * (m->input_vel - m->vel_rpm);
        m->torque_cmd = clampf(torque, -lim, lim);
        return;
    default:
        break;
    }

    /* position modes */
    switch (m->mode) {
    case DARAN_SIM_MODE_FILTER:
        filter_step(m, limit_pos(m, m->input_pos), &acc);
        m->pos_sp = m->filt_ref + m->filt_err;
        m->vel_sp = m->filt_vel / DEG_S_PER_RPM;
        break;
    case DARAN_SIM_MODE_TRAPEZOID:
        trap_eval(m, &acc);
        break;
    default:
        m->pos_sp = m->input_pos;
        m->vel_sp = m->input_vel;
        break;
    }
    m->pos_sp = limit_pos(m, m->pos_sp);
    m->torque_ff = (m->mode == DARAN_SIM_MODE_PASSTHROUGH ? m->input_torque : 0.0f) +
                   inertia * acc / DEG_PER_TURN;
    {
        float vel_des = m->vel_sp / RPM_PER_TURN_S +
                        cfgf(m, DARAN_PROP_POS_GAIN) * (m->pos_sp - pos) / DEG_PER_TURN;
        vel_des = clampf(vel_des, -vlim / RPM_PER_TURN_S, vlim / RPM_PER_TURN_S);
        m->torque_cmd = velocity_loop(m, vel_des, lim);
    }
}

static void protections(daran_sim_model_t *m)
{
    uint32_t flags = 0u;
    if (m->vbus_v < m->par.undervoltage_trip) {
        flags |= DARAN_FLAG_UNDERVOLTAGE;
    }
    if (m->cfg[DARAN_PROP_FET_THERMISTOR_ENABLED].u32 != 0u &&
        m->fet_temp_c > cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_UPPER)) {
        m->fet_error = 1u;
        flags |= DARAN_FLAG_FET_OVERTEMP;
    }
    if (m->cfg[DARAN_PROP_MOTOR_THERMISTOR_ENABLED].u32 != 0u &&
        m->motor_temp_c > cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER)) {
        m->motor_error = 1u;
        flags |= DARAN_FLAG_MOTOR_OVERTEMP;
    }
    if (m->state == DARAN_STATE_CLOSED_LOOP &&
        m->cfg[DARAN_PROP_ENABLE_WATCHDOG].u32 != 0u) {
        m->watchdog_s += m->dt;
        if (m->watchdog_s > cfgf(m, DARAN_PROP_WATCHDOG_TIMEOUT)) {
            flags |= DARAN_FLAG_WATCHDOG;
        }
    }
    if (flags != 0u) {
        daran_sim_model_trip(m, flags);
    }
}

/* First-order approach to the steady temperature. Absurd settings (a
 * torque constant of 1e-40 Nm/A) must not turn the state into inf/nan: a
 * burnt-out motor reads hot, not "nan". */
static float thermal_step(float temp, float steady, float alpha)
{
    if (!(steady < 1.0e4f)) {
        steady = 1.0e4f;
    }
    temp += (steady - temp) * alpha;
    return temp < 1.0e4f ? temp : 1.0e4f;
}

static void plant(daran_sim_model_t *m)
{
    const daran_sim_params_t *p = &m->par;
    float dt = m->dt;
    float inertia = daran_sim_model_inertia(m);
    float bw = cfgf(m, DARAN_PROP_CURRENT_CONTROL_BANDWIDTH);
    float w = m->vel_rpm / RPM_PER_TURN_S; /* turn/s */
    float kt = cfgf(m, DARAN_PROP_TORQUE_CONSTANT);
    float iq;
    float power;
    float stick;

    /* the current loop is a first-order lag of its bandwidth */
    m->torque_nm += (m->torque_cmd - m->torque_nm) * (1.0f - expf(-bw * dt));
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        m->torque_nm = 0.0f;
    }

    w += (m->torque_nm + m->ext_torque_nm - p->viscous_friction * w) / inertia * dt;
    /* Coulomb friction removes speed but never reverses it */
    stick = p->coulomb_friction / inertia * dt;
    if (fabsf(w) <= stick) {
        w = 0.0f;
    } else {
        w -= signf(w) * stick;
    }
    m->vel_rpm = w * RPM_PER_TURN_S;
    m->raw_pos_deg += w * DEG_PER_TURN * dt;

    iq = m->torque_nm / kt;
    power = m->torque_nm * w * TWO_PI + iq * iq * p->phase_resistance;
    m->ibus_a = power / m->vbus_v;
    if (m->sag_left_s > 0.0f) {
        m->sag_left_s -= dt;
        m->vbus_v = p->sag_voltage;
    } else {
        m->vbus_v = p->vbus_nominal - p->source_resistance * m->ibus_a;
    }

    m->motor_temp_c = thermal_step(m->motor_temp_c, p->ambient_temp + p->motor_heat * iq * iq,
                                   dt / p->motor_time_const);
    m->fet_temp_c = thermal_step(m->fet_temp_c, p->ambient_temp + p->fet_heat * iq * iq,
                                 dt / p->fet_time_const);
}

void daran_sim_model_tick(daran_sim_model_t *m)
{
    protections(m);
    if (m->state == DARAN_STATE_CLOSED_LOOP) {
        control(m);
    } else {
        m->torque_cmd = 0.0f;
        m->pos_sp = daran_sim_model_pos_deg(m);
        m->vel_sp = 0.0f;
    }
    plant(m);
    m->ticks++;
}

/* ---- properties ---- */

daran_result_t daran_sim_model_get(const daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t *out)
{
    daran_value_t v;
    v.u64 = 0u;
    switch (prop) {
    case DARAN_PROP_VBUS_VOLTAGE: v.f32 = m->vbus_v; break;
    case DARAN_PROP_IBUS: v.f32 = m->ibus_a; break;
    case DARAN_PROP_TRAJECTORY_DONE: v.u32 = m->trajectory_done ? 1u : 0u; break;
    case DARAN_PROP_CURRENT_STATE: v.u32 = m->state; break;
    case DARAN_PROP_REQUESTED_STATE: v.u32 = m->requested_state; break;
    case DARAN_PROP_AXIS_ERROR: v.u32 = m->error; break;
    case DARAN_PROP_FET_THERMISTOR_ERROR: v.u32 = m->fet_error; break;
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR: v.u32 = m->motor_error; break;
    case DARAN_PROP_FET_TEMPERATURE: v.f32 = m->fet_temp_c; break;
    case DARAN_PROP_MOTOR_TEMPERATURE: v.f32 = m->motor_temp_c; break;
    case DARAN_PROP_IQ_MEASURED:
        v.f32 = m->torque_nm / cfgf(m, DARAN_PROP_TORQUE_CONSTANT);
        break;
    case DARAN_PROP_INPUT_POS: v.f32 = m->input_pos; break;
    case DARAN_PROP_INPUT_VEL: v.f32 = m->input_vel; break;
    case DARAN_PROP_INPUT_TORQUE: v.f32 = m->input_torque; break;
    case DARAN_PROP_POS_SETPOINT: v.f32 = m->pos_sp; break;
    case DARAN_PROP_VEL_SETPOINT: v.f32 = m->vel_sp; break;
    case DARAN_PROP_TORQUE_SETPOINT: v.f32 = m->torque_cmd; break;
    case DARAN_PROP_POS_ESTIMATE: v.f32 = daran_sim_model_pos_deg(m); break;
    case DARAN_PROP_VEL_ESTIMATE: v.f32 = m->vel_rpm; break;
    case DARAN_PROP_TORQUE_ESTIMATE: v.f32 = m->torque_nm; break;
    case DARAN_PROP_FW_VERSION:
    case DARAN_PROP_HW_VERSION:
    case DARAN_PROP_SERIAL_NUMBER:
        return DARAN_ERR_INVALID_PROPERTY; /* the drive (sim_drive.c) knows these */
    default:
        if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT || !daran_sim_is_config_prop(prop)) {
            return DARAN_ERR_INVALID_PROPERTY;
        }
        v = m->cfg[prop];
        break;
    }
    *out = v;
    return DARAN_OK;
}

static bool valid_value(daran_prop_t prop, daran_value_t value)
{
    if (prop_type[prop] == DARAN_TYPE_F32) {
        return isfinite(value.f32) != 0;
    }
    return true;
}

daran_result_t daran_sim_model_set(daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t value)
{
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT || !prop_is_rw[prop]) {
        return DARAN_ERR_READ_ONLY;
    }
    if (!valid_value(prop, value)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    switch (prop) {
    case DARAN_PROP_REQUESTED_STATE:
        if (value.u32 == DARAN_STATE_CLOSED_LOOP) {
            return daran_sim_model_closed_loop(m);
        }
        if (value.u32 == DARAN_STATE_IDLE) {
            daran_sim_model_trip(m, 0u);
            return DARAN_OK;
        }
        return DARAN_ERR_OUT_OF_RANGE;
    case DARAN_PROP_INPUT_POS:
        m->input_pos = value.f32;
        if (m->mode == DARAN_SIM_MODE_TRAPEZOID) {
            m->trap_start = m->pos_sp;
            trap_plan(m, limit_pos(m, value.f32));
        }
        return DARAN_OK;
    case DARAN_PROP_INPUT_VEL:
        m->input_vel = value.f32;
        return DARAN_OK;
    case DARAN_PROP_INPUT_TORQUE:
        m->input_torque = value.f32;
        return DARAN_OK;
    case DARAN_PROP_POS_SETPOINT:
        enter_position_mode(m, DARAN_SIM_MODE_PASSTHROUGH);
        m->input_pos = value.f32;
        m->pos_sp = value.f32;
        m->input_vel = 0.0f;
        m->input_torque = 0.0f;
        m->trajectory_done = true;
        return DARAN_OK;
    case DARAN_PROP_VEL_SETPOINT:
        m->mode = DARAN_SIM_MODE_VELOCITY;
        m->input_vel = value.f32;
        m->vel_sp = value.f32;
        m->input_torque = 0.0f;
        m->trajectory_done = true;
        return DARAN_OK;
    case DARAN_PROP_TORQUE_SETPOINT:
        m->mode = DARAN_SIM_MODE_TORQUE;
        m->input_torque = value.f32;
        m->torque_cmd = m->state == DARAN_STATE_CLOSED_LOOP ? value.f32 : 0.0f;
        m->trajectory_done = true;
        return DARAN_OK;
    case DARAN_PROP_ENABLE_WATCHDOG:
        m->watchdog_s = 0.0f;
        break;
    default:
        break;
    }
    m->cfg[prop] = value;
    return DARAN_OK;
}
