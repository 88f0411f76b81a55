/* Every property of the protocol's table on the simulated drive
 * (protocol.md 10.2): each reads, each read-write one takes a new value and
 * gives it back; the rotor-side views agree with the output shaft through
 * config.extra_setting.gear_ratio (output = rotor / ratio) whichever side is
 * written; the encoder's absolute readings; measured motor values; the
 * serial number's halves. Driven through the drive's HAL, no protocol core. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_drive.h"

/* The drive under test (index 0: id 1, blank storage), fresh for every test
 * (setUp()); m is its model. */
static daran_sim_drive_t drive;
static daran_sim_model_t *const m = &drive.model;

static const daran_prop_type_t prop_type[DARAN_PROP_COUNT] = {
#define TYPE_(id, path, scope, type, access, range, unit, can) DARAN_TYPE_##type,
    DARAN_PROPERTY_LIST(TYPE_)
#undef TYPE_
};

static const daran_range_t prop_range[DARAN_PROP_COUNT] = {
#define RANGE_(id, path, scope, type, access, range, unit, can) DARAN_RANGE_##range,
    DARAN_PROPERTY_LIST(RANGE_)
#undef RANGE_
};

#define RW_1 1
#define RO_1 0
static const int prop_rw[DARAN_PROP_COUNT] = {
#define RW_(id, path, scope, type, access, range, unit, can) access##_1,
    DARAN_PROPERTY_LIST(RW_)
#undef RW_
};

static const char *const prop_path[DARAN_PROP_COUNT] = {
#define PATH_(id, path, scope, type, access, range, unit, can) path,
    DARAN_PROPERTY_LIST(PATH_)
#undef PATH_
};

void setUp(void)
{
    memset(&drive, 0, sizeof drive);
    daran_sim_drive_init(&drive, 0u, 1000u);
}

void tearDown(void)
{
}

/* The UPPER-CASE helpers are macros so that a failure points at the test's
 * line. */
static daran_value_t get_at(int line, daran_prop_t prop)
{
    daran_value_t v;
    v.u64 = 0u;
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_hal.get(&drive, prop, &v), line,
                                  "the drive refused the read");
    return v;
}
/* Read a property through the drive's HAL; the read must succeed. */
#define GET(prop) get_at(__LINE__, (prop))
#define GETF(prop) (get_at(__LINE__, (prop)).f32)

static void set_at(int line, daran_prop_t prop, daran_value_t v)
{
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_hal.set(&drive, prop, v), line,
                                  "the drive refused the value");
}

static daran_value_t f32_value(float x)
{
    daran_value_t v;
    v.u64 = 0u;
    v.f32 = x;
    return v;
}

static daran_value_t u32_value(uint32_t x)
{
    daran_value_t v;
    v.u64 = 0u;
    v.u32 = x;
    return v;
}
/* Write a property through the drive's HAL; the write must succeed. */
#define SETF(prop, x) set_at(__LINE__, (prop), f32_value(x))
#define SETU(prop, x) set_at(__LINE__, (prop), u32_value(x))

static void run(double seconds)
{
    long n = lround(seconds * (double)m->tick_hz);
    long k;
    for (k = 0; k < n; k++) {
        daran_sim_model_tick(m);
    }
}

static void assert_close_at(int line, float got, float want)
{
    float tol = 1e-5f * (fabsf(want) > 1.0f ? fabsf(want) : 1.0f);
    if (!(fabsf(got - want) <= tol)) {
        sim_fail_at(line, "got %.9g, want %.9g", (double)got, (double)want);
    }
}
/* Equal to float rounding (the views convert on the way in and out). */
#define ASSERT_CLOSE(got, want) assert_close_at(__LINE__, (got), (want))

/* A value the property's range accepts, different from @p now. */
static daran_value_t new_value(daran_prop_t prop, daran_value_t now)
{
    daran_value_t v;
    v.u64 = 0u;
    switch (prop_range[prop]) {
    case DARAN_RANGE_BOOL: v.u32 = 1u - now.u32; return v;
    case DARAN_RANGE_ZERO: v.u32 = 0u; return v;
    case DARAN_RANGE_NODE_ID: v.u32 = 5u; return v;
    case DARAN_RANGE_UART_BAUD: v.u32 = 9600u; return v;
    case DARAN_RANGE_CAN_BAUD: v.u32 = 500000u; return v;
    case DARAN_RANGE_CAN_PROTOCOL: v.u32 = 0u; return v;
    case DARAN_RANGE_AXIS_STATE: v.u32 = DARAN_STATE_IDLE; return v;
    case DARAN_RANGE_CONTROL_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_INPUT_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_TRAJ_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_DIRECTION: v.s32 = -1; return v;
    case DARAN_RANGE_MOTOR_TYPE: v.u32 = 2u; return v;
    case DARAN_RANGE_POLE_PAIRS: v.s32 = 14; return v;
    default:
        break;
    }
    switch (prop_type[prop]) {
    case DARAN_TYPE_F32: v.f32 = now.f32 == 0.0f ? 0.5f : now.f32 * 1.25f; break;
    case DARAN_TYPE_S32: v.s32 = now.s32 == 0 ? 7 : now.s32 / 2; break;
    default: v.u32 = now.u32 + 1u; break;
    }
    return v;
}

static void test_every_property_reads_and_every_writable_one_takes_a_new_value(void)
{
    int p;
    int rw = 0;
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        daran_prop_t prop = (daran_prop_t)p;
        daran_value_t now = GET(prop);
        daran_value_t want;
        daran_value_t back;
        if (prop_type[p] == DARAN_TYPE_F32 && !isfinite(now.f32)) {
            FAIL_F("%s reads %g", prop_path[p], (double)now.f32);
        }
        if (!prop_rw[p]) {
            TEST_ASSERT_EQUAL_INT64(DARAN_ERR_READ_ONLY, daran_sim_hal.set(&drive, prop, now));
            continue;
        }
        rw++;
        want = new_value(prop, now);
        if (daran_sim_hal.set(&drive, prop, want) != DARAN_OK) {
            FAIL_F("w %s refused", prop_path[p]);
        }
        back = GET(prop);
        if (prop_type[p] == DARAN_TYPE_F32) {
            ASSERT_CLOSE(back.f32, want.f32);
        } else if (back.u32 != want.u32) {
            FAIL_F("%s: wrote %u, read %u", prop_path[p], want.u32, back.u32);
        }
        if (prop == DARAN_PROP_REQUESTED_STATE) {
            SETU(prop, DARAN_STATE_CLOSED_LOOP);
            TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, GET(DARAN_PROP_CURRENT_STATE).u32);
        }
    }
    NOTE("%d properties read, %d of them written and read back", p, rw);
    /* the drive still runs */
    run(0.5);
    TEST_ASSERT_TRUE(isfinite(GETF(DARAN_PROP_POS_ESTIMATE)));
}

static void test_error_registers_take_only_zero(void)
{
    static const daran_prop_t regs[] = {
        DARAN_PROP_AXIS_ERROR,        DARAN_PROP_MOTOR_ERROR,          DARAN_PROP_CONTROLLER_ERROR,
        DARAN_PROP_ENCODER_ERROR,     DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CONFIG_WARNINGS,
    };
    size_t i;
    for (i = 0; i < sizeof regs / sizeof regs[0]; i++) {
        daran_value_t v;
        v.u64 = 0u;
        v.u32 = 1u;
        TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE, daran_sim_hal.set(&drive, regs[i], v));
        SETU(regs[i], 0u);
    }
}

/* can.error takes one more value: its bit 0, which the CAN front end sets
 * when another node claims the drive's id (C22); no other bit goes in. */
static void test_can_error_takes_the_duplicate_id_bit_and_zero_only(void)
{
    daran_value_t v;
    v.u64 = 0u;
    v.u32 = 2u;
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE, daran_sim_hal.set(&drive, DARAN_PROP_CAN_ERROR, v));
    SETU(DARAN_PROP_CAN_ERROR, DARAN_SIM_CAN_ERROR_DUPLICATE_ID);
    TEST_ASSERT_EQUAL_INT64(1u, GET(DARAN_PROP_CAN_ERROR).u32);
    v.u32 = 3u;
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE, daran_sim_hal.set(&drive, DARAN_PROP_CAN_ERROR, v));
    SETU(DARAN_PROP_CAN_ERROR, 0u);
    TEST_ASSERT_EQUAL_INT64(0u, GET(DARAN_PROP_CAN_ERROR).u32);
}

/* Gear ratio g: rotor = output x g. Position 36 deg = 0.1 g turn; 60 r/min =
 * g turn/s; 1 Nm at the shaft = 1/g Nm at the rotor; inertia / g^2; 16384
 * steps per output turn = g/16384 rotor turns per step. */
static void check_views(float g)
{
    SETF(DARAN_PROP_GEAR_RATIO, g);
    /* configuration: write the shaft side, read the rotor side */
    SETF(DARAN_PROP_TORQUE_CONSTANT, 0.2f);
    ASSERT_CLOSE(GETF(DARAN_PROP_MOTOR_TORQUE_CONSTANT), 0.2f / g);
    SETF(DARAN_PROP_STEPS_PER_TURN, 16384.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TURNS_PER_STEP), g / 16384.0f);
    SETF(DARAN_PROP_VEL_RAMP_RATE, 120.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_VEL_RAMP_RATE), 2.0f * g);
    SETF(DARAN_PROP_TORQUE_RAMP_RATE, 3.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_TORQUE_RAMP_RATE), 3.0f / g);
    SETF(DARAN_PROP_LOAD_INERTIA, 0.5f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_INERTIA), 0.5f / (g * g));
    SETF(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, 300.0f);
    SETF(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 30.0f);
    SETF(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 90.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_VEL_LIMIT), 5.0f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_ACCEL_LIMIT), 0.5f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_DECEL_LIMIT), 1.5f * g);
    SETF(DARAN_PROP_CIRCULAR_SETPOINT_MIN, -90.0f);
    SETF(DARAN_PROP_CIRCULAR_SETPOINT_MAX, 180.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MIN), -0.25f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MAX), 0.5f * g);
    /* and the other way round */
    SETF(DARAN_PROP_MOTOR_TORQUE_CONSTANT, 0.05f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TORQUE_CONSTANT), 0.05f * g);
    SETF(DARAN_PROP_TURNS_PER_STEP, g / 200.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_STEPS_PER_TURN), 200.0f);
    SETF(DARAN_PROP_CONTROLLER_VEL_RAMP_RATE, 4.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_VEL_RAMP_RATE), 240.0f / g);
    SETF(DARAN_PROP_CONTROLLER_TORQUE_RAMP_RATE, 0.25f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TORQUE_RAMP_RATE), 0.25f * g);
    SETF(DARAN_PROP_CONTROLLER_INERTIA, 1e-3f);
    ASSERT_CLOSE(GETF(DARAN_PROP_LOAD_INERTIA), 1e-3f * g * g);
    SETF(DARAN_PROP_TRAP_VEL_LIMIT, 8.0f);
    SETF(DARAN_PROP_TRAP_ACCEL_LIMIT, 2.0f);
    SETF(DARAN_PROP_TRAP_DECEL_LIMIT, 0.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT), 480.0f / g);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT), 120.0f / g);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT) == 0.0f);
    SETF(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MAX, 2.0f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_CIRCULAR_SETPOINT_MAX), 720.0f);
    SETF(DARAN_PROP_LOAD_INERTIA, 0.0f);
    SETF(DARAN_PROP_TORQUE_CONSTANT, 0.1f);
    SETF(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 60.0f);

    /* setpoints and inputs, both ways */
    SETF(DARAN_PROP_POS_SETPOINT, 36.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_POS_SETPOINT), 0.1f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_INPUT_POS), 0.1f * g);
    SETF(DARAN_PROP_CONTROLLER_INPUT_POS, 0.25f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_INPUT_POS), 90.0f);
    SETF(DARAN_PROP_CONTROLLER_POS_SETPOINT, -0.5f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_POS_SETPOINT), -180.0f);
    SETF(DARAN_PROP_VEL_SETPOINT, 30.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_VEL_SETPOINT), 0.5f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_INPUT_VEL), 0.5f * g);
    SETF(DARAN_PROP_CONTROLLER_INPUT_VEL, 2.0f * g);
    ASSERT_CLOSE(GETF(DARAN_PROP_INPUT_VEL), 120.0f);
    SETF(DARAN_PROP_CONTROLLER_VEL_SETPOINT, -g);
    ASSERT_CLOSE(GETF(DARAN_PROP_VEL_SETPOINT), -60.0f);
    SETF(DARAN_PROP_TORQUE_SETPOINT, 0.8f);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_TORQUE_SETPOINT), 0.8f / g);
    ASSERT_CLOSE(GETF(DARAN_PROP_CONTROLLER_INPUT_TORQUE), 0.8f / g);
    SETF(DARAN_PROP_CONTROLLER_INPUT_TORQUE, 0.1f / g);
    ASSERT_CLOSE(GETF(DARAN_PROP_INPUT_TORQUE), 0.1f);
    SETF(DARAN_PROP_CONTROLLER_TORQUE_SETPOINT, 0.05f / g);
    ASSERT_CLOSE(GETF(DARAN_PROP_TORQUE_SETPOINT), 0.05f);

    /* estimates, after a real move */
    SETF(DARAN_PROP_POS_SETPOINT, 45.0f);
    run(1.0);
    ASSERT_CLOSE(GETF(DARAN_PROP_ENCODER_POS_ESTIMATE),
                 GETF(DARAN_PROP_POS_ESTIMATE) / 360.0f * g);
    SETF(DARAN_PROP_VEL_SETPOINT, 6.0f);
    run(0.5);
    ASSERT_CLOSE(GETF(DARAN_PROP_ENCODER_VEL_ESTIMATE),
                 GETF(DARAN_PROP_VEL_ESTIMATE) / 60.0f * g);
    SETF(DARAN_PROP_POS_SETPOINT, 0.0f);
    run(1.0);
}

static void test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_1(void)
{
    check_views(1.0f);
}

static void test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_8(void)
{
    check_views(8.0f);
}

/* A rotor-side value that would not fit the stored one is refused, and
 * nothing changes. */
static void test_a_view_that_overflows_its_stored_value_is_refused(void)
{
    daran_value_t v;
    SETF(DARAN_PROP_GEAR_RATIO, 1e-30f);
    v.u64 = 0u;
    v.f32 = 3e38f;
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE,
                            daran_sim_hal.set(&drive, DARAN_PROP_TRAP_VEL_LIMIT, v));
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT) == 600.0f);
    v.f32 = 0.0f;
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE,
                            daran_sim_hal.set(&drive, DARAN_PROP_GEAR_RATIO, v));
}

/* Gear 8, cpr 16384, shaft angle 100 deg: the rotor has turned 100/360*8 =
 * 2.2222 turns: turn_abs 2, pos_abs 0.2222*16384 = 3640.9 -> 3640. At -100
 * deg: -2.2222 turns: turn_abs -3, pos_abs 0.7778*16384 -> 12743. */
static void test_encoder_absolute_readings_count_the_rotor_angle(void)
{
    SETF(DARAN_PROP_GEAR_RATIO, 8.0f);
    m->raw_pos_deg = 100.0f;
    TEST_ASSERT_EQUAL_INT64(2, GET(DARAN_PROP_ENCODER_TURN_ABS).s32);
    TEST_ASSERT_EQUAL_INT64(3640, GET(DARAN_PROP_ENCODER_POS_ABS).s32);
    ASSERT_CLOSE(GETF(DARAN_PROP_ENCODER_POS_CIRCULAR), 0.222222f);
    m->raw_pos_deg = -100.0f;
    TEST_ASSERT_EQUAL_INT64(-3, GET(DARAN_PROP_ENCODER_TURN_ABS).s32);
    TEST_ASSERT_EQUAL_INT64(12743, GET(DARAN_PROP_ENCODER_POS_ABS).s32);
    ASSERT_CLOSE(GETF(DARAN_PROP_ENCODER_POS_CIRCULAR), 0.777778f);
    ASSERT_CLOSE(GETF(DARAN_PROP_ENCODER_POS_ESTIMATE), -2.222222f);
    /* cpr 4096 */
    GET(DARAN_PROP_ENCODER_CPR);
    {
        daran_value_t v;
        v.u64 = 0u;
        v.s32 = 4096;
        TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_hal.set(&drive, DARAN_PROP_ENCODER_CPR, v));
    }
    TEST_ASSERT_EQUAL_INT64(3185, GET(DARAN_PROP_ENCODER_POS_ABS).s32);
}

/* sz at shaft angle 100 deg, gear 8: zero_offset_counts = 100/360*8*16384 =
 * 36408.9. Writing it moves the zero the same way: position jumps, the
 * setpoints jump with it, the shaft stays. */
static void test_zero_offset_counts_is_the_zero_offset_in_rotor_counts(void)
{
    SETF(DARAN_PROP_GEAR_RATIO, 8.0f);
    SETF(DARAN_PROP_POS_SETPOINT, 100.0f);
    run(1.0);
    daran_sim_hal.action(&drive, DARAN_ACTION_SET_ZERO);
    ASSERT_CLOSE(GETF(DARAN_PROP_ZERO_OFFSET_COUNTS), m->raw_pos_deg / 360.0f * 8.0f * 16384.0f);
    TEST_ASSERT_FLOAT_WITHIN(20.0f, 36408.9f, GETF(DARAN_PROP_ZERO_OFFSET_COUNTS));
    TEST_ASSERT_TRUE(fabsf(GETF(DARAN_PROP_POS_ESTIMATE)) < 1e-3f);
    SETF(DARAN_PROP_ZERO_OFFSET_COUNTS, 0.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_POS_ESTIMATE), m->raw_pos_deg);
    ASSERT_CLOSE(GETF(DARAN_PROP_POS_SETPOINT), 100.0f);
    run(1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 100.0f, m->raw_pos_deg);
}

/* motor.config.torque_lim is rotor Nm: 0.1 at gear 8 allows 0.8 Nm at the
 * shaft, below output_shaft.torque_lim 2; the lower applies. */
static void test_motor_torque_lim_acts_at_the_shaft_times_the_gear_ratio(void)
{
    SETF(DARAN_PROP_GEAR_RATIO, 8.0f);
    SETF(DARAN_PROP_MOTOR_TORQUE_LIM, 0.1f);
    ASSERT_CLOSE(daran_sim_model_torque_limit(m), 0.8f);
    SETF(DARAN_PROP_SHAFT_TORQUE_LIM, 0.5f);
    ASSERT_CLOSE(daran_sim_model_torque_limit(m), 0.5f);
    /* controller.config.vel_limit is rotor turn/s: 10 at gear 8 = 75 r/min */
    ASSERT_CLOSE(daran_sim_model_vel_limit_rpm(m), 75.0f);
}

/* The controller works rotor-side as ODrive's does: at gear 8 the rotor's
 * inertia counts 64 times at the shaft and so do the gains, so a small step
 * (no saturation) follows the same course as at gear 1 (with the plant's
 * friction scaled by g^2 as well). */
static void test_a_geared_drive_keeps_the_dynamics_of_its_rotor(void)
{
    static daran_sim_drive_t direct;
    int k;
    float worst = 0.0f;
    daran_sim_drive_init(&direct, 1u, 1000u);
    SETF(DARAN_PROP_GEAR_RATIO, 8.0f);
    m->par.viscous_friction *= 64.0f; /* the friction scaled alike */
    m->par.coulomb_friction *= 64.0f;
    SETF(DARAN_PROP_POS_SETPOINT, 0.5f);
    {
        daran_value_t v;
        v.u64 = 0u;
        v.f32 = 0.5f;
        TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_hal.set(&direct, DARAN_PROP_POS_SETPOINT, v));
    }
    for (k = 0; k < 500; k++) {
        daran_sim_model_tick(m);
        daran_sim_model_tick(&direct.model);
        if (fabsf(daran_sim_model_pos_deg(m) - daran_sim_model_pos_deg(&direct.model)) > worst) {
            worst = fabsf(daran_sim_model_pos_deg(m) - daran_sim_model_pos_deg(&direct.model));
        }
    }
    NOTE("0.5 deg step, gear 8 against gear 1: largest difference %.2g deg",
         (double)worst);
    TEST_ASSERT_TRUE(worst < 1e-3f);
    TEST_ASSERT_FLOAT_WITHIN(0.02f, 0.5f, daran_sim_model_pos_deg(m));
}

/* 0.5 Nm into a blocked shaft: Iq = Iq_setpoint = 5 A, Id = 0, the bridge
 * puts out R Iq = 1.5 V (the shaft stands: no back-EMF, no cross-coupling),
 * Ibus = ibus. */
static void test_motor_measurements_follow_the_model(void)
{
    float va;
    float vb;
    SETF(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    SETF(DARAN_PROP_TORQUE_SETPOINT, 0.5f);
    run(0.1);
    ASSERT_CLOSE(GETF(DARAN_PROP_IQ_SETPOINT), 5.0f);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 5.0f, GETF(DARAN_PROP_IQ_MEASURED));
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_ID_MEASURED) == 0.0f);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_ID_SETPOINT) == 0.0f);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_IBUS_MEASURED) == GETF(DARAN_PROP_IBUS));
    va = GETF(DARAN_PROP_FINAL_V_ALPHA);
    vb = GETF(DARAN_PROP_FINAL_V_BETA);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 1.5f, sqrtf(va * va + vb * vb));
    ASSERT_CLOSE(GETF(DARAN_PROP_EFFECTIVE_CURRENT_LIM), 25.0f);
    SETF(DARAN_PROP_REQUESTED_CURRENT_RANGE, 10.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_EFFECTIVE_CURRENT_LIM), 9.8f);
    ASSERT_CLOSE(daran_sim_model_torque_limit(m), 0.98f);
    TEST_ASSERT_EQUAL_INT64(1u, GET(DARAN_PROP_MOTOR_IS_CALIBRATED).u32);
    TEST_ASSERT_EQUAL_INT64(1u, GET(DARAN_PROP_ENCODER_IS_READY).u32);
    TEST_ASSERT_EQUAL_INT64(1u, GET(DARAN_PROP_ENCODER_INDEX_FOUND).u32);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_ENCODER_BATTERY_VOLTAGE) > 3.0f);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_ENCODER_VOLTAGE) > 3.0f);
    /* idle: the bridge is off */
    SETU(DARAN_PROP_REQUESTED_STATE, DARAN_STATE_IDLE);
    run(0.01);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_FINAL_V_ALPHA) == 0.0f);
    TEST_ASSERT_TRUE(GETF(DARAN_PROP_IQ_MEASURED) == 0.0f);
}

static void test_serial_number_halves_are_its_low_and_high_words(void)
{
    TEST_ASSERT_EQUAL_INT64(2026000001u, GET(DARAN_PROP_SERIAL_NUMBER_L).u32);
    TEST_ASSERT_EQUAL_INT64(0u, GET(DARAN_PROP_SERIAL_NUMBER_H).u32);
    drive.serial_number = 0x123456789ABCDEF0ull;
    TEST_ASSERT_EQUAL_INT64(0x9ABCDEF0u, GET(DARAN_PROP_SERIAL_NUMBER_L).u32);
    TEST_ASSERT_EQUAL_INT64(0x12345678u, GET(DARAN_PROP_SERIAL_NUMBER_H).u32);
}

/* A q's cruise and rate are the trap_traj properties: q 1 90 30 60 sets
 * vel_limit 30 r/min (0.5 turn/s rotor) and accel = decel 60 (r/min)/s
 * (1 (turn/s)/s). */
static void test_q_settings_are_the_trap_traj_properties(void)
{
    daran_move_t q = {DARAN_MOVE_TRAPEZOID, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE, 90.0f, 30.0f,
                      0.0f, 60.0f, 0.0f, 0.0f};
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_hal.move(&drive, &q));
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT), 30.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT), 60.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT), 60.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_VEL_LIMIT), 0.5f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_ACCEL_LIMIT), 1.0f);
    ASSERT_CLOSE(GETF(DARAN_PROP_TRAP_DECEL_LIMIT), 1.0f);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_property_reads_and_every_writable_one_takes_a_new_value);
    RUN_TEST(test_error_registers_take_only_zero);
    RUN_TEST(test_can_error_takes_the_duplicate_id_bit_and_zero_only);
    RUN_TEST(test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_1);
    RUN_TEST(test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_8);
    RUN_TEST(test_a_view_that_overflows_its_stored_value_is_refused);
    RUN_TEST(test_encoder_absolute_readings_count_the_rotor_angle);
    RUN_TEST(test_zero_offset_counts_is_the_zero_offset_in_rotor_counts);
    RUN_TEST(test_motor_torque_lim_acts_at_the_shaft_times_the_gear_ratio);
    RUN_TEST(test_a_geared_drive_keeps_the_dynamics_of_its_rotor);
    RUN_TEST(test_motor_measurements_follow_the_model);
    RUN_TEST(test_serial_number_halves_are_its_low_and_high_words);
    RUN_TEST(test_q_settings_are_the_trap_traj_properties);
    return UNITY_END();
}
