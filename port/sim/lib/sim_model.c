/* The simulated drive's physics and controller: one call per control tick,
 * and every property of the protocol's table. Equations, defaults and the
 * meaning given to each property are explained in docs/simulator.md. */
#include "sim_model.h"

#include <math.h>
#include <string.h>

#define DEG_PER_TURN 360.0f
#define RPM_PER_TURN_S 60.0f
#define DEG_S_PER_RPM 6.0f /* 1 r/min = 6 deg/s */
#define TWO_PI 6.28318530718f
#define MAX_KICK_RPM 1.0e5f

/* ---- configuration: defaults, views, classification ---- */

static const struct {
    daran_prop_t prop;
    daran_value_t value;
} config_defaults[] = {
    /* axis: calibration (no physics; ODrive's defaults) */
    {DARAN_PROP_CALIBRATION_LOCKIN_ACCEL, {.f32 = 20.0f}},
    {DARAN_PROP_CALIBRATION_LOCKIN_CURRENT, {.f32 = 10.0f}},
    {DARAN_PROP_CALIBRATION_LOCKIN_RAMP_DISTANCE, {.f32 = 3.14159265f}},
    {DARAN_PROP_CALIBRATION_LOCKIN_RAMP_TIME, {.f32 = 0.4f}},
    {DARAN_PROP_CALIBRATION_LOCKIN_VEL, {.f32 = 40.0f}},
    {DARAN_PROP_STARTUP_CLOSED_LOOP_CONTROL, {.u32 = 1u}},
    {DARAN_PROP_STARTUP_ENCODER_INDEX_SEARCH, {.u32 = 0u}},
    {DARAN_PROP_STARTUP_ENCODER_OFFSET_CALIBRATION, {.u32 = 0u}},
    {DARAN_PROP_STARTUP_MOTOR_CALIBRATION, {.u32 = 0u}},
    /* axis: link, watchdog, pins */
    {DARAN_PROP_CAN_NODE_ID, {.u32 = 1u}},
    {DARAN_PROP_ENABLE_STEP_DIR, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_WATCHDOG, {.u32 = 0u}},
    {DARAN_PROP_WATCHDOG_TIMEOUT, {.f32 = 0.5f}},
    /* axis: the vendor's extra settings */
    {DARAN_PROP_ENABLE_120R, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_ADAPTIVE_GAIN, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_DAMP_IDLE, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_MULTI_CIRCLE, {.u32 = 1u}},
    {DARAN_PROP_ENABLE_REPLY_STATE, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_STALL_LIMIT, {.u32 = 0u}},
    {DARAN_PROP_ENCODER_OFFSET_CALIBRATED, {.u32 = 1u}},
    {DARAN_PROP_GEAR_RATIO, {.f32 = 1.0f}},
    /* telemetry (protocol.md 11.2): off, position and velocity when on */
    {DARAN_PROP_TELEMETRY_PERIOD, {.f32 = 0.0f}},
    {DARAN_PROP_TELEMETRY_FIELDS, {.u32 = 3u}},
    {DARAN_PROP_STALL_CURRENT_LIMIT, {.f32 = 20.0f}},
    {DARAN_PROP_STALL_TIME_LIMIT, {.f32 = 2.0f}},
    {DARAN_PROP_STORED_TURNS_COUNTS, {.s32 = 0}},
    /* axis: controller */
    {DARAN_PROP_CIRCULAR_SETPOINT_RANGE, {.f32 = 1.0f}},
    {DARAN_PROP_CIRCULAR_SETPOINTS, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, {.u32 = 1u}},
    {DARAN_PROP_ENABLE_GAIN_SCHEDULING, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_OVERSPEED_ERROR, {.u32 = 0u}},
    {DARAN_PROP_ENABLE_VEL_LIMIT, {.u32 = 1u}},
    {DARAN_PROP_GAIN_SCHEDULING_WIDTH, {.f32 = 10.0f}},
    {DARAN_PROP_INPUT_FILTER_BANDWIDTH, {.f32 = 20.0f}},
    {DARAN_PROP_POS_GAIN, {.f32 = 20.0f}},
    {DARAN_PROP_VEL_GAIN, {.f32 = 0.16f}},
    {DARAN_PROP_VEL_INTEGRATOR_GAIN, {.f32 = 0.8f}},
    {DARAN_PROP_CONTROLLER_VEL_LIMIT, {.f32 = 10.0f}},
    {DARAN_PROP_VEL_LIMIT_TOLERANCE, {.f32 = 1.2f}},
    {DARAN_PROP_TRAJ_MODE, {.u32 = 1u}},
    /* axis: encoder */
    {DARAN_PROP_ENCODER_ABS_SPI_CS_GPIO_PIN, {.u32 = 1u}},
    {DARAN_PROP_ENCODER_BANDWIDTH, {.f32 = 1000.0f}},
    {DARAN_PROP_ENCODER_CPR, {.s32 = 16384}},
    {DARAN_PROP_ENCODER_MODE, {.u32 = 0u}},
    {DARAN_PROP_ENCODER_PRE_CALIBRATED, {.u32 = 1u}},
    {DARAN_PROP_ENCODER_USE_INDEX, {.u32 = 0u}},
    /* axis: thermistors */
    {DARAN_PROP_FET_THERMISTOR_ENABLED, {.u32 = 1u}},
    {DARAN_PROP_FET_TEMP_LIMIT_LOWER, {.f32 = 80.0f}},
    {DARAN_PROP_FET_TEMP_LIMIT_UPPER, {.f32 = 100.0f}},
    {DARAN_PROP_MOTOR_THERMISTOR_ENABLED, {.u32 = 1u}},
    {DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER, {.f32 = 90.0f}},
    {DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER, {.f32 = 120.0f}},
    /* axis: motor */
    {DARAN_PROP_CALIBRATION_CURRENT, {.f32 = 10.0f}},
    {DARAN_PROP_CURRENT_CONTROL_BANDWIDTH, {.f32 = 1000.0f}},
    {DARAN_PROP_CURRENT_LIM, {.f32 = 25.0f}},
    {DARAN_PROP_CURRENT_LIM_MARGIN, {.f32 = 8.0f}},
    {DARAN_PROP_MOTOR_DIRECTION, {.s32 = 1}},
    {DARAN_PROP_MOTOR_TYPE, {.u32 = 0u}},
    {DARAN_PROP_PHASE_INDUCTANCE, {.f32 = 2.0e-4f}},
    {DARAN_PROP_PHASE_RESISTANCE, {.f32 = 0.3f}},
    {DARAN_PROP_POLE_PAIRS, {.s32 = 7}},
    {DARAN_PROP_MOTOR_PRE_CALIBRATED, {.u32 = 1u}},
    {DARAN_PROP_REQUESTED_CURRENT_RANGE, {.f32 = 60.0f}},
    {DARAN_PROP_RESISTANCE_CALIB_MAX_VOLTAGE, {.f32 = 2.0f}},
    {DARAN_PROP_MOTOR_TORQUE_LIM, {.f32 = 3.0f}},
    /* axis: output shaft */
    {DARAN_PROP_CIRCULAR_SETPOINT_MAX, {.f32 = 360.0f}},
    {DARAN_PROP_CIRCULAR_SETPOINT_MIN, {.f32 = -360.0f}},
    {DARAN_PROP_HOMING_MOVE_RANGE, {.f32 = 360.0f}},
    {DARAN_PROP_HOMING_POS_SETPOINT, {.f32 = 0.0f}},
    {DARAN_PROP_HOMING_TORQUE_LIM, {.f32 = 0.5f}},
    {DARAN_PROP_HOMING_VEL_LIMIT, {.f32 = 30.0f}},
    {DARAN_PROP_LOAD_INERTIA, {.f32 = 0.0f}},
    {DARAN_PROP_STEPS_PER_TURN, {.f32 = 16384.0f}},
    {DARAN_PROP_TORQUE_CONSTANT, {.f32 = 0.1f}},
    {DARAN_PROP_SHAFT_TORQUE_LIM, {.f32 = 2.0f}},
    {DARAN_PROP_TORQUE_RAMP_RATE, {.f32 = 1.0f}},
    {DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, {.f32 = 60.0f}},
    {DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, {.f32 = 60.0f}},
    {DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, {.f32 = 600.0f}},
    {DARAN_PROP_SHAFT_VEL_LIMIT, {.f32 = 600.0f}},
    {DARAN_PROP_VEL_RAMP_RATE, {.f32 = 60.0f}},
    /* system */
    {DARAN_PROP_CAN_BAUD_RATE, {.u32 = 1000000u}},
    {DARAN_PROP_CAN_HEARTBEAT_MS, {.u32 = 0u}},
    {DARAN_PROP_CAN_PROTOCOL, {.u32 = 1u}},
    {DARAN_PROP_CAN_TIMEOUT_MS, {.u32 = 0u}},
    {DARAN_PROP_BRAKE_RESISTANCE, {.f32 = 2.0f}},
    {DARAN_PROP_DC_BUS_OVERVOLTAGE_TRIP_LEVEL, {.f32 = 56.0f}},
    {DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL, {.f32 = 8.0f}},
    {DARAN_PROP_DC_MAX_NEGATIVE_CURRENT, {.f32 = -1.0f}},
    {DARAN_PROP_DC_MAX_POSITIVE_CURRENT, {.f32 = 20.0f}},
    {DARAN_PROP_ENABLE_UART, {.u32 = 1u}},
    {DARAN_PROP_MAX_REGEN_CURRENT, {.f32 = 0.0f}},
    {DARAN_PROP_UART_BAUDRATE, {.u32 = 115200u}},
};

/* A rotor-side property that is another view of a stored output-shaft value
 * (output = rotor / gear_ratio). */
typedef enum view_kind {
    VIEW_NONE,
    VIEW_POS,      /* deg <-> turn:          x / 360 * g */
    VIEW_VEL,      /* r/min <-> turn/s, and (r/min)/s <-> (turn/s)/s: x / 60 * g */
    VIEW_TORQUE,   /* Nm <-> Nm, Nm/A, Nm/s: x / g */
    VIEW_INERTIA,  /* load inertia at the shaft <-> at the rotor: x / g^2 */
    VIEW_PER_STEP  /* steps per output turn <-> rotor turns per step: g / x */
} view_kind_t;

static const struct {
    daran_prop_t view;
    daran_prop_t base;
    view_kind_t kind;
} views[] = {
    {DARAN_PROP_CONTROLLER_INPUT_POS, DARAN_PROP_INPUT_POS, VIEW_POS},
    {DARAN_PROP_CONTROLLER_POS_SETPOINT, DARAN_PROP_POS_SETPOINT, VIEW_POS},
    {DARAN_PROP_ENCODER_POS_ESTIMATE, DARAN_PROP_POS_ESTIMATE, VIEW_POS},
    {DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MIN, DARAN_PROP_CIRCULAR_SETPOINT_MIN, VIEW_POS},
    {DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MAX, DARAN_PROP_CIRCULAR_SETPOINT_MAX, VIEW_POS},
    {DARAN_PROP_CONTROLLER_INPUT_VEL, DARAN_PROP_INPUT_VEL, VIEW_VEL},
    {DARAN_PROP_CONTROLLER_VEL_SETPOINT, DARAN_PROP_VEL_SETPOINT, VIEW_VEL},
    {DARAN_PROP_ENCODER_VEL_ESTIMATE, DARAN_PROP_VEL_ESTIMATE, VIEW_VEL},
    {DARAN_PROP_CONTROLLER_VEL_RAMP_RATE, DARAN_PROP_VEL_RAMP_RATE, VIEW_VEL},
    {DARAN_PROP_TRAP_VEL_LIMIT, DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, VIEW_VEL},
    {DARAN_PROP_TRAP_ACCEL_LIMIT, DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, VIEW_VEL},
    {DARAN_PROP_TRAP_DECEL_LIMIT, DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, VIEW_VEL},
    {DARAN_PROP_CONTROLLER_INPUT_TORQUE, DARAN_PROP_INPUT_TORQUE, VIEW_TORQUE},
    {DARAN_PROP_CONTROLLER_TORQUE_SETPOINT, DARAN_PROP_TORQUE_SETPOINT, VIEW_TORQUE},
    {DARAN_PROP_CONTROLLER_TORQUE_RAMP_RATE, DARAN_PROP_TORQUE_RAMP_RATE, VIEW_TORQUE},
    {DARAN_PROP_MOTOR_TORQUE_CONSTANT, DARAN_PROP_TORQUE_CONSTANT, VIEW_TORQUE},
    {DARAN_PROP_CONTROLLER_INERTIA, DARAN_PROP_LOAD_INERTIA, VIEW_INERTIA},
    {DARAN_PROP_TURNS_PER_STEP, DARAN_PROP_STEPS_PER_TURN, VIEW_PER_STEP},
};

static view_kind_t view_of(daran_prop_t prop, daran_prop_t *base)
{
    size_t i;
    for (i = 0; i < sizeof views / sizeof views[0]; i++) {
        if (views[i].view == prop) {
            *base = views[i].base;
            return views[i].kind;
        }
    }
    return VIEW_NONE;
}

static float to_view(view_kind_t kind, float g, float x)
{
    switch (kind) {
    case VIEW_POS: return x / DEG_PER_TURN * g;
    case VIEW_VEL: return x / RPM_PER_TURN_S * g;
    case VIEW_TORQUE: return x / g;
    case VIEW_INERTIA: return x / (g * g);
    case VIEW_PER_STEP: return g / x;
    default: return x;
    }
}

static float from_view(view_kind_t kind, float g, float x)
{
    switch (kind) {
    case VIEW_POS: return x / g * DEG_PER_TURN;
    case VIEW_VEL: return x / g * RPM_PER_TURN_S;
    case VIEW_TORQUE: return x * g;
    case VIEW_INERTIA: return x * (g * g);
    case VIEW_PER_STEP: return g / x;
    default: return x;
    }
}

/* The port's own rows (DARAN_PORT_PROPERTY_LIST of its options header)
 * follow the vendor's: the model keeps a plain store for them. */
#ifdef DARAN_PORT_PROPERTY_LIST
#define DARAN_SIM_PORT_ROWS_(X) DARAN_PORT_PROPERTY_LIST(X)
#else
#define DARAN_SIM_PORT_ROWS_(X)
#endif

enum {
#define DARAN_SIM_COUNT_(id, path, scope, type, access, range, unit, can) +1
    VENDOR_PROP_COUNT = 0 DARAN_PROPERTY_LIST(DARAN_SIM_COUNT_)
#undef DARAN_SIM_COUNT_
};

#define DARAN_SIM_ACCESS_RW 1u
#define DARAN_SIM_ACCESS_RO 0u
static const uint8_t prop_is_rw[DARAN_PROP_COUNT] = {
#define DARAN_SIM_RW_(id, path, scope, type, access, range, unit, can) \
    (uint8_t)DARAN_SIM_ACCESS_##access,
    DARAN_PROPERTY_LIST(DARAN_SIM_RW_)
    DARAN_SIM_PORT_ROWS_(DARAN_SIM_RW_)
#undef DARAN_SIM_RW_
};

static const daran_prop_type_t prop_type[DARAN_PROP_COUNT] = {
#define DARAN_SIM_TYPE_(id, path, scope, type, access, range, unit, can) DARAN_TYPE_##type,
    DARAN_PROPERTY_LIST(DARAN_SIM_TYPE_)
    DARAN_SIM_PORT_ROWS_(DARAN_SIM_TYPE_)
#undef DARAN_SIM_TYPE_
};

daran_prop_type_t daran_sim_prop_type(daran_prop_t prop)
{
    return (unsigned)prop < (unsigned)DARAN_PROP_COUNT ? prop_type[prop] : DARAN_TYPE_U32;
}

bool daran_sim_is_port_prop(daran_prop_t prop)
{
    return (unsigned)prop >= (unsigned)VENDOR_PROP_COUNT &&
           (unsigned)prop < (unsigned)DARAN_PROP_COUNT;
}

bool daran_sim_is_config_prop(daran_prop_t prop)
{
    daran_prop_t base;
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT || !prop_is_rw[prop] ||
        view_of(prop, &base) != VIEW_NONE) {
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
    case DARAN_PROP_CONTROL_MODE:
    case DARAN_PROP_INPUT_MODE:
    case DARAN_PROP_ZERO_OFFSET_COUNTS: /* stored as zero_offset_deg */
    case DARAN_PROP_AXIS_ERROR:
    case DARAN_PROP_MOTOR_ERROR:
    case DARAN_PROP_CONTROLLER_ERROR:
    case DARAN_PROP_ENCODER_ERROR:
    case DARAN_PROP_FET_THERMISTOR_ERROR:
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR:
    case DARAN_PROP_CAN_ERROR:
    case DARAN_PROP_CONFIG_WARNINGS:
        return false;
    default:
        return true;
    }
}

bool daran_sim_model_config_ok(const daran_value_t cfg[DARAN_PROP_COUNT])
{
    int p;
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        if (daran_sim_is_config_prop((daran_prop_t)p) && prop_type[p] == DARAN_TYPE_F32 &&
            !isfinite(cfg[p].f32)) {
            return false;
        }
    }
    return cfg[DARAN_PROP_GEAR_RATIO].f32 > 0.0f && cfg[DARAN_PROP_ENCODER_CPR].s32 > 0 &&
           cfg[DARAN_PROP_STEPS_PER_TURN].f32 > 0.0f &&
           cfg[DARAN_PROP_TORQUE_CONSTANT].f32 > 0.0f;
}

/* ---- helpers ---- */

static float cfgf(const daran_sim_model_t *m, daran_prop_t prop)
{
    return m->cfg[prop].f32;
}

static bool cfgb(const daran_sim_model_t *m, daran_prop_t prop)
{
    return m->cfg[prop].u32 != 0u;
}

static float gear(const daran_sim_model_t *m)
{
    return cfgf(m, DARAN_PROP_GEAR_RATIO);
}

/* A rotor-side gain (Nm/(turn/s), Nm/(turn/s^2)) as it acts on the output
 * shaft: the rotor turns g times faster and its torque is g times smaller. */
static float shaft_gain(const daran_sim_model_t *m, daran_prop_t prop)
{
    float g = gear(m);
    return cfgf(m, prop) * g * g;
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

/* x - floor(x), in [0, 1). */
static float fracf(float x)
{
    float f = x - floorf(x);
    return f < 1.0f ? f : 0.0f;
}

static int32_t to_s32(float x)
{
    if (!(x > -2147483648.0f)) {
        return x == x ? INT32_MIN : 0;
    }
    return x < 2147483648.0f ? (int32_t)x : INT32_MAX;
}

float daran_sim_model_pos_deg(const daran_sim_model_t *m)
{
    return m->raw_pos_deg - m->zero_offset_deg;
}

float daran_sim_model_inertia(const daran_sim_model_t *m)
{
    float g = gear(m);
    return m->par.rotor_inertia * g * g + cfgf(m, DARAN_PROP_LOAD_INERTIA);
}

float daran_sim_model_vel_limit_rpm(const daran_sim_model_t *m)
{
    return minf(cfgf(m, DARAN_PROP_SHAFT_VEL_LIMIT),
                cfgf(m, DARAN_PROP_CONTROLLER_VEL_LIMIT) * RPM_PER_TURN_S / gear(m));
}

/* 1 below temp_limit_lower, falling linearly to 0 at temp_limit_upper. */
static float derating(float temp, bool enabled, float lower, float upper)
{
    if (!enabled || !(upper > lower) || temp <= lower) {
        return 1.0f;
    }
    return clampf((upper - temp) / (upper - lower), 0.0f, 1.0f);
}

static float fet_derating(const daran_sim_model_t *m)
{
    return derating(m->fet_temp_c, cfgb(m, DARAN_PROP_FET_THERMISTOR_ENABLED),
                    cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_LOWER),
                    cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_UPPER));
}

static float motor_derating(const daran_sim_model_t *m)
{
    return derating(m->motor_temp_c, cfgb(m, DARAN_PROP_MOTOR_THERMISTOR_ENABLED),
                    cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER),
                    cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER));
}

/* The current the inverter allows before derating: current_lim, but no more
 * than the current sense range (with ODrive's 2 % margin). */
static float current_limit(const daran_sim_model_t *m)
{
    return minf(cfgf(m, DARAN_PROP_CURRENT_LIM),
                0.98f * cfgf(m, DARAN_PROP_REQUESTED_CURRENT_RANGE));
}

float daran_sim_model_torque_limit(const daran_sim_model_t *m)
{
    float lim = minf(cfgf(m, DARAN_PROP_SHAFT_TORQUE_LIM),
                     cfgf(m, DARAN_PROP_MOTOR_TORQUE_LIM) * gear(m));
    lim = minf(lim, current_limit(m) * cfgf(m, DARAN_PROP_TORQUE_CONSTANT));
    lim *= fet_derating(m);
    lim *= motor_derating(m);
    return lim;
}

static bool limits_on(const daran_sim_model_t *m)
{
    return cfgb(m, DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT) &&
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

/* ---- power-up, states, faults ---- */

void daran_sim_model_default_config(daran_sim_model_t *m)
{
    size_t i;
    int p;
    for (i = 0; i < sizeof config_defaults / sizeof config_defaults[0]; i++) {
        m->cfg[config_defaults[i].prop] = config_defaults[i].value;
    }
    /* a port's settings default to 0; its readings are state and stay */
    for (p = (int)VENDOR_PROP_COUNT; p < (int)DARAN_PROP_COUNT; p++) {
        if (daran_sim_is_config_prop((daran_prop_t)p)) {
            m->cfg[p].u64 = 0u;
        }
    }
    m->zero_offset_deg = 0.0f;
}

static void params_default(daran_sim_params_t *p)
{
    p->rotor_inertia = 8.0e-4f;
    p->viscous_friction = 5.0e-4f;
    p->coulomb_friction = 1.0e-3f;
    p->vbus_nominal = 24.0f;
    p->source_resistance = 0.02f;
    p->sag_below_trip = 2.0f;
    p->sag_duration = 0.1f;
    p->ambient_temp = 25.0f;
    p->motor_heat = 0.3f;
    p->motor_time_const = 30.0f;
    p->fet_heat = 0.1f;
    p->fet_time_const = 5.0f;
    p->overtemp_jump = 5.0f;
    p->stall_speed = 1.0f;
    p->overspeed_kick = 1.5f;
    p->encoder_battery_v = 3.6f;
    p->encoder_supply_v = 3.3f;
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
    m->acc_sp = 0.0f;
    m->torque_ff = 0.0f;
    m->integrator = 0.0f;
    m->trajectory_done = true;
    m->watchdog_s = 0.0f;
}

static void clear_registers(daran_sim_model_t *m)
{
    m->error = 0u;
    m->motor_error = 0u;
    m->controller_error = 0u;
    m->encoder_error = 0u;
    m->fet_thermistor_error = 0u;
    m->motor_thermistor_error = 0u;
    m->can_error = 0u;
    m->config_warnings = 0u;
    m->stall_s = 0.0f;
    m->stall_injected = false;
}

void daran_sim_model_boot(daran_sim_model_t *m)
{
    m->vbus_v = m->par.vbus_nominal;
    m->ibus_a = 0.0f;
    m->sag_left_s = 0.0f;
    m->torque_nm = 0.0f;
    m->torque_cmd = 0.0f;
    clear_registers(m);
    hold_here(m);
    if (cfgb(m, DARAN_PROP_STARTUP_CLOSED_LOOP_CONTROL)) {
        m->state = DARAN_STATE_CLOSED_LOOP;
        m->requested_state = DARAN_STATE_CLOSED_LOOP;
    } else {
        m->state = DARAN_STATE_IDLE;
        m->requested_state = DARAN_STATE_IDLE;
    }
}

void daran_sim_model_trip(daran_sim_model_t *m, uint32_t flags)
{
    m->error |= flags;
    m->state = DARAN_STATE_IDLE;
    m->requested_state = DARAN_STATE_IDLE;
    m->torque_cmd = 0.0f;
    m->integrator = 0.0f;
}

void daran_sim_model_clear_errors(daran_sim_model_t *m)
{
    clear_registers(m);
}

/* What blocks closed loop: axis0.error, and the sub-registers whose summary
 * bit a host may have cleared alone with `w axis0.error 0`. */
static uint32_t blocking_flags(const daran_sim_model_t *m)
{
    uint32_t flags = m->error;
    if (m->motor_error != 0u) {
        flags |= DARAN_FLAG_MOTOR_FAILED;
    }
    if (m->controller_error != 0u) {
        flags |= DARAN_FLAG_CONTROLLER_FAILED;
    }
    if (m->fet_thermistor_error != 0u || m->motor_thermistor_error != 0u) {
        flags |= DARAN_FLAG_OVERTEMP;
    }
    if (m->encoder_error != 0u) {
        flags |= DARAN_FLAG_ENCODER_FAILED;
    }
    return flags;
}

static daran_result_t refusal(const daran_sim_model_t *m)
{
    uint32_t flags = blocking_flags(m);
    if ((flags & DARAN_FLAG_ESTOP) != 0u) {
        return DARAN_ERR_ESTOP_ACTIVE;
    }
    return flags != 0u ? DARAN_ERR_MOTOR_FAULT : DARAN_OK;
}

daran_result_t daran_sim_model_closed_loop(daran_sim_model_t *m)
{
    daran_result_t r = refusal(m);
    if (r != DARAN_OK) {
        return r;
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

/* The zero offset becomes @p raw_zero: the position reading jumps, and
 * every setpoint and target jumps with it, so nothing moves. */
static void move_zero(daran_sim_model_t *m, float raw_zero)
{
    float shift = raw_zero - m->zero_offset_deg;
    m->zero_offset_deg = raw_zero;
    m->input_pos -= shift;
    m->pos_sp -= shift;
    m->filt_ref -= shift;
    m->trap_start -= shift;
    m->trap_target -= shift;
}

void daran_sim_model_set_zero(daran_sim_model_t *m)
{
    move_zero(m, m->raw_pos_deg);
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
    case DARAN_SIM_FAULT_STALL:
        m->stall_injected = true;
        break;
    case DARAN_SIM_FAULT_OVERSPEED: {
        /* something back-drives the shaft beyond the over-speed limit */
        float kick = m->par.overspeed_kick * daran_sim_model_vel_limit_rpm(m) *
                     cfgf(m, DARAN_PROP_VEL_LIMIT_TOLERANCE);
        m->vel_rpm = signf(m->vel_rpm) * minf(kick, MAX_KICK_RPM);
        break;
    }
    default:
        break;
    }
}

/* ---- motion commands and modes ---- */

/* ODrive's numbers for each mode: controller.config.control_mode and
 * input_mode. */
static const struct {
    uint8_t control;
    uint8_t input;
} mode_numbers[] = {
    [DARAN_SIM_MODE_PASSTHROUGH] = {3u, 1u},
    [DARAN_SIM_MODE_FILTER] = {3u, 3u},
    [DARAN_SIM_MODE_TRAPEZOID] = {3u, 5u},
    [DARAN_SIM_MODE_VELOCITY] = {2u, 1u},
    [DARAN_SIM_MODE_VELOCITY_RAMP] = {2u, 2u},
    [DARAN_SIM_MODE_TORQUE] = {1u, 1u},
    [DARAN_SIM_MODE_TORQUE_RAMP] = {1u, 6u},
    [DARAN_SIM_MODE_IMPEDANCE] = {3u, 9u},
};

/* The plan from trap_start (at rest) to @p target with the stored limits:
 * output_shaft.trap_traj_vel_limit (capped by the velocity limit),
 * trap_traj_accel_limit for the rising phase and trap_traj_decel_limit for
 * the falling one. A trapezoid's phase reaching v takes v/a; an S-curve's
 * (traj_mode 2) takes 2v/a, its acceleration rising linearly to a and back
 * to 0, and covers v^2/a. Too short to reach the cruise: the triangle
 * (peak sqrt(2 D a1 a2/(a1+a2)), or sqrt(D a1 a2/(a1+a2)) for the S-curve).
 * An acceleration or deceleration limit of 0 (protocol.md 10.1) steps the
 * setpoint to the target at once. */
static void trap_plan(daran_sim_model_t *m, float target)
{
    float dist = fabsf(target - m->trap_start);
    float vmax = minf(cfgf(m, DARAN_PROP_TRAP_TRAJ_VEL_LIMIT), daran_sim_model_vel_limit_rpm(m)) *
                 DEG_S_PER_RPM;
    float a1 = cfgf(m, DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT) * DEG_S_PER_RPM;
    float a2 = cfgf(m, DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT) * DEG_S_PER_RPM;
    bool scurve = m->cfg[DARAN_PROP_TRAJ_MODE].u32 == 2u;
    float h; /* the triangle's peak is sqrt(dist * h) */
    bool triangle;
    m->trap_target = target;
    m->trap_acc = a1;
    m->trap_dec = a2;
    m->trap_scurve = scurve;
    m->trap_ticks = 0u;
    if (dist == 0.0f || !(a1 > 0.0f) || !(a2 > 0.0f) || !(vmax > 0.0f)) {
        m->trap_vmax = 0.0f;
        m->trap_ta = m->trap_tc = m->trap_td = m->trap_pa = m->trap_total = 0.0f;
        m->trap_end_tick = 0u;
        m->trajectory_done = true;
        return;
    }
    if (scurve) {
        h = a1 == a2 ? 0.5f * a1 : a1 * a2 / (a1 + a2);
    } else {
        h = a1 == a2 ? a1 : 2.0f * a1 * a2 / (a1 + a2);
    }
    triangle = dist * h < vmax * vmax;
    if (triangle) {
        vmax = sqrtf(dist * h); /* too short to reach the cruise velocity */
    }
    m->trap_ta = (scurve ? 2.0f : 1.0f) * vmax / a1;
    m->trap_td = (scurve ? 2.0f : 1.0f) * vmax / a2;
    if (triangle) {
        m->trap_tc = 0.0f;
    } else {
        /* each phase covers its duration times its mean velocity v/2 */
        float ramps = 0.5f * vmax * m->trap_ta + 0.5f * vmax * m->trap_td;
        m->trap_tc = (dist - ramps) / vmax;
    }
    m->trap_pa = scurve ? 0.5f * vmax * m->trap_ta : 0.5f * a1 * m->trap_ta * m->trap_ta;
    m->trap_vmax = vmax;
    m->trap_total = m->trap_ta + m->trap_td + m->trap_tc;
    /* A plan a float rounding longer than a whole number of ticks (an `mq`
     * of exactly 2 s computes to 2.0000002 s) still ends on that tick. */
    {
        float n = ceilf(m->trap_total * (float)m->tick_hz - 1e-3f);
        m->trap_end_tick = n >= 0.0f && n < 4.0e9f ? (uint32_t)n : UINT32_MAX;
    }
    m->trajectory_done = false;
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

/* Switch to @p mode from the current inputs (input_pos/vel/torque, kp, kd):
 * what a motion command does after storing its targets, and what a write of
 * control_mode / input_mode does (ODrive style). */
static void enter_mode(daran_sim_model_t *m, daran_sim_mode_t mode)
{
    switch (mode) {
    case DARAN_SIM_MODE_PASSTHROUGH:
    case DARAN_SIM_MODE_FILTER:
        enter_position_mode(m, mode);
        m->trajectory_done = true;
        break;
    case DARAN_SIM_MODE_TRAPEZOID:
        enter_position_mode(m, mode);
        m->trap_start = m->pos_sp;
        trap_plan(m, limit_pos(m, m->input_pos));
        break;
    case DARAN_SIM_MODE_VELOCITY_RAMP:
        if (m->mode != DARAN_SIM_MODE_VELOCITY && m->mode != DARAN_SIM_MODE_VELOCITY_RAMP) {
            m->vel_sp = m->vel_rpm; /* ramp from where the shaft is */
        }
        m->torque_ff = 0.0f;
        m->mode = mode;
        m->trajectory_done = true;
        break;
    case DARAN_SIM_MODE_TORQUE_RAMP:
        if (m->mode != DARAN_SIM_MODE_TORQUE && m->mode != DARAN_SIM_MODE_TORQUE_RAMP) {
            m->torque_cmd = m->torque_nm;
        }
        m->integrator = 0.0f;
        m->mode = mode;
        m->trajectory_done = true;
        break;
    case DARAN_SIM_MODE_TORQUE:
    case DARAN_SIM_MODE_IMPEDANCE:
        m->integrator = 0.0f;
        m->mode = mode;
        m->trajectory_done = true;
        break;
    case DARAN_SIM_MODE_VELOCITY:
    default:
        m->mode = mode;
        m->trajectory_done = true;
        break;
    }
}

daran_result_t daran_sim_model_move(daran_sim_model_t *m, const daran_move_t *mv)
{
    daran_sim_mode_t mode;
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        daran_result_t r = refusal(m);
        return r != DARAN_OK ? r : DARAN_ERR_MOTOR_IDLE;
    }
    switch (mv->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
        if ((mv->given & DARAN_GIVEN_RATE) != 0u) {
            m->cfg[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = mv->rate;
        }
        m->input_pos = mv->pos_deg;
        mode = DARAN_SIM_MODE_FILTER;
        break;
    case DARAN_MOVE_TRAPEZOID:
        if (mv->given == 0u && m->mode == DARAN_SIM_MODE_TRAPEZOID && !m->trajectory_done &&
            limit_pos(m, mv->pos_deg) == m->trap_target) {
            /* The running plan's own target with nothing new (a `q` without
             * vel/acc, an `mq` whose distance from that target is 0, D41):
             * the plan runs on and ends on its planned tick; a new plan
             * would start from rest where the setpoint is now. */
            m->input_pos = mv->pos_deg;
            return DARAN_OK;
        }
        if ((mv->given & DARAN_GIVEN_VEL) != 0u) {
            m->cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = mv->vel_rpm;
        }
        if ((mv->given & DARAN_GIVEN_RATE) != 0u) {
            m->cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = mv->rate;
            m->cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = mv->rate;
        }
        m->input_pos = mv->pos_deg;
        mode = DARAN_SIM_MODE_TRAPEZOID;
        break;
    case DARAN_MOVE_PASSTHROUGH:
        m->input_pos = mv->pos_deg;
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        mode = DARAN_SIM_MODE_PASSTHROUGH;
        break;
    case DARAN_MOVE_VELOCITY:
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        mode = DARAN_SIM_MODE_VELOCITY;
        break;
    case DARAN_MOVE_VELOCITY_RAMP:
        m->cfg[DARAN_PROP_VEL_RAMP_RATE].f32 = mv->rate;
        m->input_vel = mv->vel_rpm;
        m->input_torque = 0.0f;
        mode = DARAN_SIM_MODE_VELOCITY_RAMP;
        break;
    case DARAN_MOVE_TORQUE:
        m->input_torque = mv->torque_nm;
        mode = DARAN_SIM_MODE_TORQUE;
        break;
    case DARAN_MOVE_TORQUE_RAMP:
        m->cfg[DARAN_PROP_TORQUE_RAMP_RATE].f32 = mv->rate;
        m->input_torque = mv->torque_nm;
        mode = DARAN_SIM_MODE_TORQUE_RAMP;
        break;
    case DARAN_MOVE_IMPEDANCE:
        m->input_pos = mv->pos_deg;
        m->input_vel = mv->vel_rpm;
        m->input_torque = mv->torque_nm;
        m->kp = mv->kp;
        m->kd = mv->kd;
        mode = DARAN_SIM_MODE_IMPEDANCE;
        break;
    default:
        return DARAN_ERR_INVALID_MODE;
    }
    enter_mode(m, mode);
    return DARAN_OK;
}

/* `w controller.config.input_mode N`: the mode that input mode selects,
 * with the control mode it needs (passthrough keeps the current one). */
static daran_sim_mode_t mode_for_input(const daran_sim_model_t *m, uint32_t input)
{
    switch (input) {
    case 2u: return DARAN_SIM_MODE_VELOCITY_RAMP;
    case 3u: return DARAN_SIM_MODE_FILTER;
    case 5u: return DARAN_SIM_MODE_TRAPEZOID;
    case 6u: return DARAN_SIM_MODE_TORQUE_RAMP;
    case 9u: return DARAN_SIM_MODE_IMPEDANCE;
    default:
        switch (mode_numbers[m->mode].control) {
        case 1u: return DARAN_SIM_MODE_TORQUE;
        case 2u: return DARAN_SIM_MODE_VELOCITY;
        default: return DARAN_SIM_MODE_PASSTHROUGH;
        }
    }
}

/* `w controller.config.control_mode N`: the same mode when it already is
 * that control mode, else that control mode's passthrough. */
static daran_sim_mode_t mode_for_control(const daran_sim_model_t *m, uint32_t control)
{
    if (mode_numbers[m->mode].control == control) {
        return m->mode;
    }
    switch (control) {
    case 1u: return DARAN_SIM_MODE_TORQUE;
    case 2u: return DARAN_SIM_MODE_VELOCITY;
    default: return DARAN_SIM_MODE_PASSTHROUGH;
    }
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
 * last bit instead of stalling a few ulps short. A bandwidth of 0 holds the
 * setpoint where it is. */
static void filter_step(daran_sim_model_t *m, float target, float *acc_out)
{
    float w = cfgf(m, DARAN_PROP_INPUT_FILTER_BANDWIDTH);
    float t = m->dt;
    float e0 = clampf(m->filt_err + (m->filt_ref - target), -FILTER_ERROR_MAX, FILTER_ERROR_MAX);
    if (!(w > 0.0f)) {
        m->filt_ref = target;
        m->filt_err = e0;
        m->filt_vel = 0.0f;
        *acc_out = 0.0f;
        return;
    }
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

/* A phase reaching the velocity from rest, @p tau into it: distance,
 * velocity (deg, deg/s) and acceleration. Trapezoid: constant acceleration
 * @p a. S-curve: the phase lasts @p dur = 2 v / a, the acceleration rising
 * with jerk a / (dur/2) to a at mid-phase and back to 0. */
static void ramp_profile(const daran_sim_model_t *m, float tau, float a, float dur, float *p,
                         float *v, float *acc)
{
    if (!m->trap_scurve) {
        *p = 0.5f * a * tau * tau;
        *v = a * tau;
        *acc = a;
        return;
    }
    {
        float half = 0.5f * dur;
        float jerk = a / half;
        if (tau <= half) {
            *p = jerk * tau * tau * tau / 6.0f;
            *v = 0.5f * jerk * tau * tau;
            *acc = jerk * tau;
        } else {
            float u = dur - tau > 0.0f ? dur - tau : 0.0f;
            float vmax = m->trap_vmax;
            *p = 0.5f * vmax * dur - (vmax * u - jerk * u * u * u / 6.0f);
            *v = vmax - 0.5f * jerk * u * u;
            *acc = jerk * u;
        }
    }
}

/* The setpoint at the end of this tick: after N ticks of a plan of N * dt
 * seconds the move is done, on time. */
static void trap_eval(daran_sim_model_t *m, float *acc_out)
{
    float t;
    float p;
    float v;
    float a;
    if (m->trap_ticks < UINT32_MAX) {
        m->trap_ticks++;
    }
    t = (float)m->trap_ticks * m->dt;
    float s = signf(m->trap_target - m->trap_start);
    float ta = m->trap_ta;
    if (m->trap_ticks >= m->trap_end_tick || m->trajectory_done) {
        m->pos_sp = m->trap_target;
        m->vel_sp = 0.0f;
        *acc_out = 0.0f;
        m->trajectory_done = true;
        return;
    }
    if (t < ta) {
        ramp_profile(m, t, m->trap_acc, ta, &p, &v, &a);
        m->pos_sp = m->trap_start + s * p;
        m->vel_sp = s * v / DEG_S_PER_RPM;
        *acc_out = s * a;
    } else if (t < ta + m->trap_tc) {
        m->pos_sp = m->trap_start + s * (m->trap_pa + m->trap_vmax * (t - ta));
        m->vel_sp = s * m->trap_vmax / DEG_S_PER_RPM;
        *acc_out = 0.0f;
    } else {
        ramp_profile(m, m->trap_total - t, m->trap_dec, m->trap_td, &p, &v, &a);
        m->pos_sp = m->trap_target - s * p;
        m->vel_sp = s * v / DEG_S_PER_RPM;
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
 * torque is saturated in the direction of the error). Gains are rotor-side
 * (ODrive units) and act on the shaft through the gear ratio. */
static float velocity_loop(daran_sim_model_t *m, float vel_des_turn_s, float lim)
{
    float vel_err = vel_des_turn_s - m->vel_rpm / RPM_PER_TURN_S;
    float ki = shaft_gain(m, DARAN_PROP_VEL_INTEGRATOR_GAIN);
    float torque = m->torque_ff + shaft_gain(m, DARAN_PROP_VEL_GAIN) * vel_err + m->integrator;
    if (torque > lim) {
        torque = lim;
        if (vel_err < 0.0f) {
            m->integrator += ki * m->dt * vel_err;
        }
    } else if (torque < -lim) {
        torque = -lim;
        if (vel_err > 0.0f) {
            m->integrator += ki * m->dt * vel_err;
        }
    } else {
        m->integrator += ki * m->dt * vel_err;
    }
    return torque;
}

/* The velocity modes; false when the shaft met a circular setpoint limit and
 * is held there (passthrough: the position loop takes it). */
static bool control_velocity(daran_sim_model_t *m, float pos, float lim, float vlim,
                             bool vel_limited)
{
    if (m->mode == DARAN_SIM_MODE_VELOCITY) {
        m->vel_sp = m->input_vel;
        m->torque_ff = m->input_torque;
    } else {
        m->vel_sp = approach(m->vel_sp, m->input_vel,
                             cfgf(m, DARAN_PROP_VEL_RAMP_RATE) * m->dt);
        m->torque_ff = 0.0f;
    }
    if (vel_limited) {
        m->vel_sp = clampf(m->vel_sp, -vlim, vlim);
    }
    guard_limits(m, pos, m->vel_sp);
    if (m->mode == DARAN_SIM_MODE_PASSTHROUGH) {
        return false;
    }
    m->torque_cmd = velocity_loop(m, m->vel_sp / RPM_PER_TURN_S, lim);
    return true;
}

/* The torque modes; false as control_velocity() at a setpoint limit. */
static bool control_torque(daran_sim_model_t *m, float pos, float lim, float vlim)
{
    float torque;
    if (m->mode == DARAN_SIM_MODE_TORQUE) {
        torque = m->input_torque;
    } else {
        torque = approach(m->torque_cmd, m->input_torque,
                          cfgf(m, DARAN_PROP_TORQUE_RAMP_RATE) * m->dt);
    }
    m->vel_sp = 0.0f;
    guard_limits(m, pos, torque);
    if (m->mode == DARAN_SIM_MODE_PASSTHROUGH) {
        return false;
    }
    if (cfgb(m, DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT)) {
        /* Fade the torque out as the speed passes the limit, as the
         * velocity loop would. */
        float gain = shaft_gain(m, DARAN_PROP_VEL_GAIN);
        float hi = (vlim - m->vel_rpm) / RPM_PER_TURN_S * gain;
        float lo = (-vlim - m->vel_rpm) / RPM_PER_TURN_S * gain;
        torque = clampf(torque, lo < 0.0f ? lo : 0.0f, hi > 0.0f ? hi : 0.0f);
    }
    m->torque_cmd = clampf(torque, -lim, lim);
    return true;
}

/* The position modes (and passthrough): the setpoint of the mode, then the
 * position and velocity loops. */
static void control_position(daran_sim_model_t *m, float pos, float lim, float vlim,
                             bool vel_limited)
{
    float inertia = daran_sim_model_inertia(m);
    float acc = 0.0f;
    float vel_des;
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
    m->acc_sp = acc;
    m->torque_ff = (m->mode == DARAN_SIM_MODE_PASSTHROUGH ? m->input_torque : 0.0f) +
                   inertia * acc / DEG_PER_TURN;
    vel_des = m->vel_sp / RPM_PER_TURN_S +
              cfgf(m, DARAN_PROP_POS_GAIN) * (m->pos_sp - pos) / DEG_PER_TURN;
    if (vel_limited) {
        vel_des = clampf(vel_des, -vlim / RPM_PER_TURN_S, vlim / RPM_PER_TURN_S);
    }
    m->torque_cmd = velocity_loop(m, vel_des, lim);
}

static void control(daran_sim_model_t *m)
{
    float pos = daran_sim_model_pos_deg(m);
    float lim = daran_sim_model_torque_limit(m);
    float vlim = daran_sim_model_vel_limit_rpm(m);
    bool vel_limited = cfgb(m, DARAN_PROP_ENABLE_VEL_LIMIT);
    float torque;

    m->acc_sp = 0.0f;
    switch (m->mode) {
    case DARAN_SIM_MODE_VELOCITY:
    case DARAN_SIM_MODE_VELOCITY_RAMP:
        if (control_velocity(m, pos, lim, vlim, vel_limited)) {
            return;
        }
        break;
    case DARAN_SIM_MODE_TORQUE:
    case DARAN_SIM_MODE_TORQUE_RAMP:
        if (control_torque(m, pos, lim, vlim)) {
            return;
        }
        break;
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
    control_position(m, pos, lim, vlim, vel_limited);
}

/* The stall limiter of config.extra_setting: the current at or above
 * stall_current_limit while the shaft stands (below par.stall_speed) for
 * stall_time_limit seconds. */
static bool stalled(daran_sim_model_t *m)
{
    if (m->stall_injected) {
        m->stall_injected = false;
        return true;
    }
    if (m->state != DARAN_STATE_CLOSED_LOOP || !cfgb(m, DARAN_PROP_ENABLE_STALL_LIMIT)) {
        m->stall_s = 0.0f;
        return false;
    }
    if (fabsf(m->torque_nm / cfgf(m, DARAN_PROP_TORQUE_CONSTANT)) >=
            cfgf(m, DARAN_PROP_STALL_CURRENT_LIMIT) &&
        fabsf(m->vel_rpm) < m->par.stall_speed) {
        m->stall_s += m->dt;
        return m->stall_s >= cfgf(m, DARAN_PROP_STALL_TIME_LIMIT);
    }
    m->stall_s = 0.0f;
    return false;
}

static void protections(daran_sim_model_t *m)
{
    uint32_t flags = 0u;
    if (m->vbus_v < cfgf(m, DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL)) {
        flags |= DARAN_FLAG_UNDERVOLTAGE;
    }
    if (cfgb(m, DARAN_PROP_FET_THERMISTOR_ENABLED) &&
        m->fet_temp_c > cfgf(m, DARAN_PROP_FET_TEMP_LIMIT_UPPER)) {
        m->fet_thermistor_error |= DARAN_THERMISTOR_ERROR_OVERTEMP;
        flags |= DARAN_FLAG_OVERTEMP;
    }
    if (cfgb(m, DARAN_PROP_MOTOR_THERMISTOR_ENABLED) &&
        m->motor_temp_c > cfgf(m, DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER)) {
        m->motor_thermistor_error |= DARAN_THERMISTOR_ERROR_OVERTEMP;
        flags |= DARAN_FLAG_OVERTEMP;
    }
    if (stalled(m)) {
        m->stall_s = 0.0f;
        m->motor_error |= DARAN_MOTOR_ERROR_STALL;
        flags |= DARAN_FLAG_MOTOR_FAILED;
    }
    if (m->state == DARAN_STATE_CLOSED_LOOP && cfgb(m, DARAN_PROP_ENABLE_OVERSPEED_ERROR) &&
        fabsf(m->vel_rpm) >
            daran_sim_model_vel_limit_rpm(m) * cfgf(m, DARAN_PROP_VEL_LIMIT_TOLERANCE)) {
        m->controller_error |= DARAN_CONTROLLER_ERROR_OVERSPEED;
        flags |= DARAN_FLAG_CONTROLLER_FAILED;
    }
    if (m->state == DARAN_STATE_CLOSED_LOOP && cfgb(m, DARAN_PROP_ENABLE_WATCHDOG)) {
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
    float r = cfgf(m, DARAN_PROP_PHASE_RESISTANCE);
    float iq;
    float power;
    float stick;

    /* the current loop is a first-order lag of its bandwidth */
    m->torque_nm += (m->torque_cmd - m->torque_nm) * (1.0f - expf(-bw * dt));
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        m->torque_nm = 0.0f;
        if (cfgb(m, DARAN_PROP_ENABLE_DAMP_IDLE)) {
            /* windings shorted: the back-EMF drives kt w / R through them,
             * braking with kt^2 / R (Nm per rad/s), stepped exactly */
            float damping = r > 0.0f ? kt * kt * TWO_PI / r : 1.0e30f;
            w *= expf(-clampf(damping / inertia * dt, 0.0f, 80.0f));
        }
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
    power = m->torque_nm * w * TWO_PI + iq * iq * r;
    m->ibus_a = m->vbus_v > 0.1f ? power / m->vbus_v : 0.0f; /* no bus, no current */
    if (m->sag_left_s > 0.0f) {
        float sag = cfgf(m, DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL) - p->sag_below_trip;
        m->sag_left_s -= dt;
        m->vbus_v = sag > 0.0f ? sag : 0.0f;
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
        m->acc_sp = 0.0f;
    }
    plant(m);
    m->ticks++;
}

/* ---- properties ---- */

/* Rotor turns of the physical shaft angle (the absolute encoder's reading). */
static float rotor_turns_abs(const daran_sim_model_t *m)
{
    return m->raw_pos_deg / DEG_PER_TURN * gear(m);
}

/* The voltage the current controller puts out, in the stator frame: R Iq
 * plus the back-EMF on q, the inductive cross-coupling -w_e L Iq on d,
 * rotated by the electrical angle (pole_pairs x the rotor angle). 0 while
 * the bridge is off (idle). */
static void final_voltage(const daran_sim_model_t *m, float *alpha, float *beta)
{
    float kt = cfgf(m, DARAN_PROP_TORQUE_CONSTANT);
    float pairs = (float)m->cfg[DARAN_PROP_POLE_PAIRS].s32;
    float iq = m->torque_nm / kt;
    float w_shaft = m->vel_rpm / RPM_PER_TURN_S * TWO_PI;       /* rad/s */
    float w_elec = w_shaft * gear(m) * pairs;
    float theta = TWO_PI * fracf(rotor_turns_abs(m)) * pairs;
    float vq = cfgf(m, DARAN_PROP_PHASE_RESISTANCE) * iq + (2.0f / 3.0f) * kt * w_shaft;
    float vd = -w_elec * cfgf(m, DARAN_PROP_PHASE_INDUCTANCE) * iq;
    if (m->state != DARAN_STATE_CLOSED_LOOP) {
        *alpha = 0.0f;
        *beta = 0.0f;
        return;
    }
    *alpha = vd * cosf(theta) - vq * sinf(theta);
    *beta = vd * sinf(theta) + vq * cosf(theta);
}

/* Measured values, states and error registers: true with the value in *v
 * (zeroed by the caller), false for another property. */
static bool get_state(const daran_sim_model_t *m, daran_prop_t prop, daran_value_t *v)
{
    float alpha;
    float beta;
    switch (prop) {
    case DARAN_PROP_VBUS_VOLTAGE: v->f32 = m->vbus_v; break;
    case DARAN_PROP_IBUS:
    case DARAN_PROP_IBUS_MEASURED: v->f32 = m->ibus_a; break;
    case DARAN_PROP_TRAJECTORY_DONE: v->u32 = m->trajectory_done ? 1u : 0u; break;
    case DARAN_PROP_CURRENT_STATE: v->u32 = m->state; break;
    case DARAN_PROP_REQUESTED_STATE: v->u32 = m->requested_state; break;
    case DARAN_PROP_CONTROL_MODE: v->u32 = mode_numbers[m->mode].control; break;
    case DARAN_PROP_INPUT_MODE: v->u32 = mode_numbers[m->mode].input; break;
    case DARAN_PROP_AXIS_ERROR: v->u32 = m->error; break;
    case DARAN_PROP_MOTOR_ERROR: v->u32 = m->motor_error; break;
    case DARAN_PROP_CONTROLLER_ERROR: v->u32 = m->controller_error; break;
    case DARAN_PROP_ENCODER_ERROR: v->u32 = m->encoder_error; break;
    case DARAN_PROP_FET_THERMISTOR_ERROR: v->u32 = m->fet_thermistor_error; break;
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR: v->u32 = m->motor_thermistor_error; break;
    case DARAN_PROP_CAN_ERROR: v->u32 = m->can_error; break;
    case DARAN_PROP_CONFIG_WARNINGS: v->u32 = m->config_warnings; break;
    case DARAN_PROP_FET_TEMPERATURE: v->f32 = m->fet_temp_c; break;
    case DARAN_PROP_MOTOR_TEMPERATURE: v->f32 = m->motor_temp_c; break;
    case DARAN_PROP_IQ_MEASURED:
        v->f32 = m->torque_nm / cfgf(m, DARAN_PROP_TORQUE_CONSTANT);
        break;
    case DARAN_PROP_IQ_SETPOINT:
        v->f32 = m->torque_cmd / cfgf(m, DARAN_PROP_TORQUE_CONSTANT);
        break;
    case DARAN_PROP_ID_MEASURED:
    case DARAN_PROP_ID_SETPOINT:
        v->f32 = 0.0f; /* field-oriented control without field weakening */
        break;
    case DARAN_PROP_FINAL_V_ALPHA:
    case DARAN_PROP_FINAL_V_BETA:
        final_voltage(m, &alpha, &beta);
        v->f32 = prop == DARAN_PROP_FINAL_V_ALPHA ? alpha : beta;
        break;
    case DARAN_PROP_EFFECTIVE_CURRENT_LIM:
        v->f32 = current_limit(m) * fet_derating(m) * motor_derating(m);
        break;
    case DARAN_PROP_MOTOR_IS_CALIBRATED:
    case DARAN_PROP_ENCODER_IS_READY:
    case DARAN_PROP_ENCODER_INDEX_FOUND:
        v->u32 = 1u;
        break;
    default:
        return false;
    }
    return true;
}

/* Everything but the views: measured values, runtime state, registers,
 * stored configuration. */
static daran_result_t get_direct(const daran_sim_model_t *m, daran_prop_t prop,
                                 daran_value_t *out)
{
    daran_value_t v;
    v.u64 = 0u;
    if (get_state(m, prop, &v)) {
        *out = v;
        return DARAN_OK;
    }
    switch (prop) {
    case DARAN_PROP_INPUT_POS: v.f32 = m->input_pos; break;
    case DARAN_PROP_INPUT_VEL: v.f32 = m->input_vel; break;
    case DARAN_PROP_INPUT_TORQUE: v.f32 = m->input_torque; break;
    case DARAN_PROP_POS_SETPOINT: v.f32 = m->pos_sp; break;
    case DARAN_PROP_VEL_SETPOINT: v.f32 = m->vel_sp; break;
    case DARAN_PROP_TORQUE_SETPOINT: v.f32 = m->torque_cmd; break;
    case DARAN_PROP_POS_ESTIMATE: v.f32 = daran_sim_model_pos_deg(m); break;
    case DARAN_PROP_VEL_ESTIMATE: v.f32 = m->vel_rpm; break;
    case DARAN_PROP_TORQUE_ESTIMATE: v.f32 = m->torque_nm; break;
    case DARAN_PROP_ZERO_OFFSET_COUNTS:
        v.f32 = m->zero_offset_deg / DEG_PER_TURN * gear(m) *
                (float)m->cfg[DARAN_PROP_ENCODER_CPR].s32;
        break;
    case DARAN_PROP_ENCODER_POS_CIRCULAR:
        v.f32 = fracf(daran_sim_model_pos_deg(m) / DEG_PER_TURN * gear(m));
        break;
    case DARAN_PROP_ENCODER_POS_ABS: {
        int32_t cpr = m->cfg[DARAN_PROP_ENCODER_CPR].s32;
        int32_t counts = to_s32(floorf(fracf(rotor_turns_abs(m)) * (float)cpr));
        v.s32 = counts >= 0 && counts < cpr ? counts : 0;
        break;
    }
    case DARAN_PROP_ENCODER_TURN_ABS:
        v.s32 = to_s32(floorf(rotor_turns_abs(m)));
        break;
    case DARAN_PROP_ENCODER_BATTERY_VOLTAGE: v.f32 = m->par.encoder_battery_v; break;
    case DARAN_PROP_ENCODER_VOLTAGE: v.f32 = m->par.encoder_supply_v; break;
    case DARAN_PROP_ENCODER_CHARGE_STATE:
    case DARAN_PROP_ENCODER_SPI_BUFF_0:
    case DARAN_PROP_ENCODER_SPI_BUFF_1:
    case DARAN_PROP_ENCODER_SPI_BUFF_2:
        v.u32 = 0u; /* no SPI encoder, no charger */
        break;
    case DARAN_PROP_ENCODER_SPI_ERROR_RATE: v.f32 = 0.0f; break;
    case DARAN_PROP_FW_VERSION:
    case DARAN_PROP_HW_VERSION:
    case DARAN_PROP_SERIAL_NUMBER:
    case DARAN_PROP_SERIAL_NUMBER_H:
    case DARAN_PROP_SERIAL_NUMBER_L:
        return DARAN_ERR_INVALID_PROPERTY; /* the drive (sim_drive.c) knows these */
    default:
        if (!daran_sim_is_config_prop(prop) && !daran_sim_is_port_prop(prop)) {
            return DARAN_ERR_INVALID_PROPERTY;
        }
        v = m->cfg[prop];
        break;
    }
    *out = v;
    return DARAN_OK;
}

daran_result_t daran_sim_model_get(const daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t *out)
{
    daran_prop_t base;
    view_kind_t kind;
    daran_value_t v;
    daran_result_t r;
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT) {
        return DARAN_ERR_INVALID_PROPERTY;
    }
    kind = view_of(prop, &base);
    if (kind == VIEW_NONE) {
        return get_direct(m, prop, out);
    }
    r = get_direct(m, base, &v);
    if (r == DARAN_OK) {
        v.f32 = to_view(kind, gear(m), v.f32);
        *out = v;
    }
    return r;
}

static bool valid_value(daran_prop_t prop, daran_value_t value)
{
    if (prop_type[prop] == DARAN_TYPE_F32) {
        return isfinite(value.f32) != 0;
    }
    return true;
}

/* An error register: only 0 goes in, and clears that register alone; the
 * one exception is bit 0 of can.error, which the CAN front end sets when
 * another node sends status frames with this drive's id (C22). */
static uint32_t *error_register(daran_sim_model_t *m, daran_prop_t prop)
{
    switch (prop) {
    case DARAN_PROP_AXIS_ERROR: return &m->error;
    case DARAN_PROP_MOTOR_ERROR: return &m->motor_error;
    case DARAN_PROP_CONTROLLER_ERROR: return &m->controller_error;
    case DARAN_PROP_ENCODER_ERROR: return &m->encoder_error;
    case DARAN_PROP_FET_THERMISTOR_ERROR: return &m->fet_thermistor_error;
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR: return &m->motor_thermistor_error;
    case DARAN_PROP_CAN_ERROR: return &m->can_error;
    case DARAN_PROP_CONFIG_WARNINGS: return &m->config_warnings;
    default: return NULL;
    }
}

/* The requested state and the modes: true with the write's result in
 * *result, false for another property. */
static bool set_state_or_mode(daran_sim_model_t *m, daran_prop_t prop, daran_value_t value,
                              daran_result_t *result)
{
    switch (prop) {
    case DARAN_PROP_REQUESTED_STATE:
        if (value.u32 == DARAN_STATE_CLOSED_LOOP) {
            *result = daran_sim_model_closed_loop(m);
            return true;
        }
        if (value.u32 == DARAN_STATE_IDLE) {
            daran_sim_model_trip(m, 0u);
            *result = DARAN_OK;
            return true;
        }
        *result = DARAN_ERR_OUT_OF_RANGE;
        return true;
    case DARAN_PROP_CONTROL_MODE:
        if (value.u32 < 1u || value.u32 > 3u) {
            *result = DARAN_ERR_OUT_OF_RANGE;
            return true;
        }
        if (mode_for_control(m, value.u32) != m->mode) {
            enter_mode(m, mode_for_control(m, value.u32));
        }
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_INPUT_MODE:
        if (value.u32 < 1u || value.u32 > 9u || value.u32 == 4u || value.u32 == 7u ||
            value.u32 == 8u) {
            *result = DARAN_ERR_OUT_OF_RANGE;
            return true;
        }
        if (mode_for_input(m, value.u32) != m->mode) {
            enter_mode(m, mode_for_input(m, value.u32));
        }
        *result = DARAN_OK;
        return true;
    default:
        return false;
    }
}

/* The inputs, the setpoints and the zero, which act at once: true with the
 * write's result in *result, false for another property. */
static bool set_input(daran_sim_model_t *m, daran_prop_t prop, daran_value_t value,
                      daran_result_t *result)
{
    switch (prop) {
    case DARAN_PROP_INPUT_POS:
        m->input_pos = value.f32;
        if (m->mode == DARAN_SIM_MODE_TRAPEZOID) {
            m->trap_start = m->pos_sp;
            trap_plan(m, limit_pos(m, value.f32));
        }
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_INPUT_VEL:
        m->input_vel = value.f32;
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_INPUT_TORQUE:
        m->input_torque = value.f32;
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_POS_SETPOINT:
        enter_position_mode(m, DARAN_SIM_MODE_PASSTHROUGH);
        m->input_pos = value.f32;
        m->pos_sp = value.f32;
        m->input_vel = 0.0f;
        m->input_torque = 0.0f;
        m->trajectory_done = true;
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_VEL_SETPOINT:
        m->mode = DARAN_SIM_MODE_VELOCITY;
        m->input_vel = value.f32;
        m->vel_sp = value.f32;
        m->input_torque = 0.0f;
        m->trajectory_done = true;
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_TORQUE_SETPOINT:
        m->mode = DARAN_SIM_MODE_TORQUE;
        m->input_torque = value.f32;
        m->torque_cmd = m->state == DARAN_STATE_CLOSED_LOOP ? value.f32 : 0.0f;
        m->trajectory_done = true;
        *result = DARAN_OK;
        return true;
    case DARAN_PROP_ZERO_OFFSET_COUNTS: {
        float raw = value.f32 / (float)m->cfg[DARAN_PROP_ENCODER_CPR].s32 / gear(m) *
                    DEG_PER_TURN;
        if (!isfinite(raw)) {
            *result = DARAN_ERR_OUT_OF_RANGE;
            return true;
        }
        move_zero(m, raw);
        *result = DARAN_OK;
        return true;
    }
    default:
        return false;
    }
}

/* A stored setting (the few the model divides by or times with are checked
 * first); READ_ONLY for a property that is none. */
static daran_result_t set_config(daran_sim_model_t *m, daran_prop_t prop, daran_value_t value)
{
    switch (prop) {
    case DARAN_PROP_GEAR_RATIO:
    case DARAN_PROP_STEPS_PER_TURN:
    case DARAN_PROP_TORQUE_CONSTANT:
        if (!(value.f32 > 0.0f)) {
            return DARAN_ERR_OUT_OF_RANGE; /* the model divides by these */
        }
        break;
    case DARAN_PROP_ENCODER_CPR:
        if (value.s32 <= 0) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        break;
    case DARAN_PROP_ENABLE_WATCHDOG:
        m->watchdog_s = 0.0f;
        break;
    default:
        break;
    }
    if (!daran_sim_is_config_prop(prop)) {
        return DARAN_ERR_READ_ONLY;
    }
    m->cfg[prop] = value;
    return DARAN_OK;
}

static daran_result_t set_direct(daran_sim_model_t *m, daran_prop_t prop, daran_value_t value)
{
    daran_result_t result;
    uint32_t *reg = error_register(m, prop);
    if (reg != NULL) {
        uint32_t may_set = prop == DARAN_PROP_CAN_ERROR ? *reg | DARAN_SIM_CAN_ERROR_DUPLICATE_ID : 0u;
        if ((value.u32 & ~may_set) != 0u) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        *reg = value.u32;
        return DARAN_OK;
    }
    if (set_state_or_mode(m, prop, value, &result) || set_input(m, prop, value, &result)) {
        return result;
    }
    return set_config(m, prop, value);
}

daran_result_t daran_sim_model_set(daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t value)
{
    daran_prop_t base;
    view_kind_t kind;
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT || !prop_is_rw[prop]) {
        return DARAN_ERR_READ_ONLY;
    }
    if (!valid_value(prop, value)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    kind = view_of(prop, &base);
    if (kind != VIEW_NONE) {
        /* one stored value, two views: write it in the stored one's units */
        float stored = from_view(kind, gear(m), value.f32);
        if (!isfinite(stored) || ((stored == 0.0f) != (value.f32 == 0.0f))) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        value.f32 = stored;
        prop = base;
    }
    return set_direct(m, prop, value);
}
