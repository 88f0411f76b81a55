/* Unit tests of the commands themselves: every worked example of spec
 * section 9 with the exact HAL call it must make, omitted optional values,
 * zero rates (spec 10.1, D30), the multi-motor preset/start commands with the
 * timed trapezoid of spec section 6 and the S-curve of 10.3 (D16-D19, D31),
 * system commands, and every vendor recording on a bus of three drives. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}
#include "recordings_data.h"

#define F DARAN_MOVE_FILTERED_POSITION
#define Q DARAN_MOVE_TRAPEZOID
#define P DARAN_MOVE_PASSTHROUGH
#define V DARAN_MOVE_VELOCITY
#define VR DARAN_MOVE_VELOCITY_RAMP
#define C DARAN_MOVE_TORQUE
#define CR DARAN_MOVE_TORQUE_RAMP
#define D DARAN_MOVE_IMPEDANCE
#define GV DARAN_GIVEN_VEL
#define GR DARAN_GIVEN_RATE

/* ---- section 9, one case per example ---- */

typedef enum ex_type { EX_MOVE, EX_SET_F32, EX_SET_U32, EX_ACTION, EX_SILENT, EX_REPLY } ex_type_t;

typedef struct example {
    uint32_t id;
    const char *line;
    ex_type_t type;
    mock_move_expect_t move;
    daran_prop_t prop;
    float f;
    uint32_t u;
    daran_action_t action;
    const char *reply; /* payload, without line end */
    bool checksum;
} example_t;

static const example_t examples[] = {
    {1, "t 1 10 0 25", EX_MOVE, {F, GR, 10, 0, 0, 25, 0, 0}, 0, 0, 0, 0, NULL, false},
    {2, "q 2 160 30 10", EX_MOVE, {Q, GV | GR, 160, 30, 0, 10, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "p 0 10 5 3", EX_MOVE, {P, 0, 10, 5, 3, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "v 0 20 3 1", EX_MOVE, {V, 0, 0, 20, 3, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {2, "v 2 15 3 2", EX_MOVE, {VR, 0, 0, 15, 0, 3, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "c 0 5 0 1", EX_MOVE, {C, 0, 0, 0, 5, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {2, "c 2 5 3 6", EX_MOVE, {CR, 0, 0, 0, 5, 3, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "t 1 12.5", EX_MOVE, {F, 0, 12.5f, 0, 0, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "q 1 50.0 7.5 2.5", EX_MOVE, {Q, GV | GR, 50, 7.5f, 0, 2.5f, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "v 1 12.5 0.0 1", EX_MOVE, {V, 0, 0, 12.5f, 0, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "v 1 12.5 2.5 2", EX_MOVE, {VR, 0, 0, 12.5f, 0, 2.5f, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "c 1 0.1 0 1", EX_MOVE, {C, 0, 0, 0, 0.1f, 0, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "c 1 0.1 0.02 6", EX_MOVE, {CR, 0, 0, 0, 0.1f, 0.02f, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "ms 1 120 5 10", EX_SILENT, {0}, 0, 0, 0, 0, NULL, false},
    {2, "ms 2 -100 5 10", EX_SILENT, {0}, 0, 0, 0, 0, NULL, false},
    {1, "mq 0 1", EX_SILENT, {0}, 0, 0, 0, 0, NULL, false},
    {1, "r axis1.output_shaft.pos_setpoint", EX_REPLY, {0}, 0, 0, 0, 0, "42.25", false},
    {5, "r axis5.motor.current_control.Iq_measured", EX_REPLY, {0}, 0, 0, 0, 0, "1.5", false},
    {1, "r axis0.config.can_node_id", EX_REPLY, {0}, 0, 0, 0, 0, "1", false},
    {1, "r config.uart_baudrate 1", EX_REPLY, {0}, 0, 0, 0, 0, "115200", false},
    {1, "w axis1.output_shaft.pos_setpoint 150", EX_SET_F32, {0}, DARAN_PROP_POS_SETPOINT, 150, 0, 0, NULL, false},
    {1, "w axis0.config.can_node_id 5", EX_SET_U32, {0}, DARAN_PROP_CAN_NODE_ID, 0, 5, 0, NULL, false},
    {1, "w config.uart_baudrate 9600 1", EX_SET_U32, {0}, DARAN_PROP_UART_BAUDRATE, 0, 9600, 0, NULL, false},
    {1, "w config.uart_baudrate 115200 1", EX_SET_U32, {0}, DARAN_PROP_UART_BAUDRATE, 0, 115200, 0, NULL, false},
    {1, "f 1", EX_REPLY, {0}, 0, 0, 0, 0, "100.5 0.02", false},
    {1, "g 1", EX_REPLY, {0}, 0, 0, 0, 0, "24 1.5", false},
    {1, "ss 1", EX_ACTION, {0}, 0, 0, 0, DARAN_ACTION_SAVE_CONFIG, NULL, false},
    {1, "d 1 10 0 0.5 0.1 0.01", EX_MOVE, {D, 0, 10, 0, 0.5f, 0, 0.1f, 0.01f}, 0, 0, 0, 0, NULL, false},
    {1, "t 1 10 0 25 *83", EX_MOVE, {F, GR, 10, 0, 0, 25, 0, 0}, 0, 0, 0, 0, NULL, false},
    {1, "f 1 *87", EX_REPLY, {0}, 0, 0, 0, 0, "100.5 0.02", true},
    {1, "w axis0.config.can_node_id 5 *58", EX_SET_U32, {0}, DARAN_PROP_CAN_NODE_ID, 0, 5, 0, NULL, false},
    /* the vendor client's trailing space */
    {1, "f 1 ", EX_REPLY, {0}, 0, 0, 0, 0, "100.5 0.02", false},
    {1, "t 1 10 0 25 ", EX_MOVE, {F, GR, 10, 0, 0, 25, 0, 0}, 0, 0, 0, 0, NULL, false},
};

static void example_case(const void *row_arg)
{
    const example_t *e = row_arg;
    SKIP_LINE_IF_NO_MULTI(e->line);
    mock_t *m = mock_new_id(e->id);
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 42.25f;
    m->props[DARAN_PROP_IQ_MEASURED].f32 = 1.5f;
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 100.5f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = 0.02f;
    switch (e->type) {
    case EX_MOVE: {
        const daran_move_t *mv = ASSERT_MOVE(m, e->line);
        mock_assert_move_equals(m, mv, &e->move, __FILE__, __LINE__);
        break;
    }
    case EX_SET_F32: {
        daran_value_t v = ASSERT_SET(m, e->line, e->prop);
        TEST_ASSERT_TRUE(v.f32 == e->f);
        break;
    }
    case EX_SET_U32: {
        daran_value_t v = ASSERT_SET(m, e->line, e->prop);
        TEST_ASSERT_EQUAL_INT64(e->u, v.u32);
        break;
    }
    case EX_ACTION: ASSERT_ACTION(m, e->line, e->action); break;
    case EX_SILENT: ASSERT_SILENT(m, e->line); break;
    case EX_REPLY: {
        char want[96];
        mock_reply_line(want, sizeof want, e->reply, e->checksum);
        TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, e->line));
        break;
    }
    }
}

/* ---- omitted optional values ---- */

static void test_omitted_optional_values_are_not_given(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "q 1 10");
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 10, 0, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "q 1 10 30");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GV, 10, 30, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "t 1 10 99");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 10, 0, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "p 1 10");
    ASSERT_MOVE_EQUALS(m, mv, {P, 0, 10, 0, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "p 1 10 5");
    ASSERT_MOVE_EQUALS(m, mv, {P, 0, 10, 5, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "v 1 20");
    ASSERT_MOVE_EQUALS(m, mv, {V, 0, 0, 20, 0, 0, 0, 0});
    mv = ASSERT_MOVE(m, "v 1 20 0.5");
    ASSERT_MOVE_EQUALS(m, mv, {V, 0, 0, 20, 0.5f, 0, 0, 0});
    mv = ASSERT_MOVE(m, "c 1 -2");
    ASSERT_MOVE_EQUALS(m, mv, {C, 0, 0, 0, -2, 0, 0, 0});
    mv = ASSERT_MOVE(m, "c 1 -2 7");
    ASSERT_MOVE_EQUALS(m, mv, {C, 0, 0, 0, -2, 0, 0, 0});
}

static void test_torque_mode_2_is_taken_as_a_ramp(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "c 1 0.100000 0.020000 2 ");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.1f, 0.02f, 0, 0});
}

static void test_motion_ranges_are_checked(void)
{
    mock_t *m = mock_new();
    /* zero rates are accepted (spec 10.1): see the zero-rate tests below */
    ASSERT_ERROR(m, "t 1 10 0 -1", "value out of range");
    ASSERT_ERROR(m, "t 1 10 0 -1e-45", "value out of range");
    ASSERT_ERROR(m, "q 1 10 0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 -0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 -5", "value out of range");
    ASSERT_ERROR(m, "q 1 10 5 -1", "value out of range");
    ASSERT_ERROR(m, "q 1 10 5 -1e-45", "value out of range");
    ASSERT_ERROR(m, "d 1 10 0 0.5 -0.1 0.01", "value out of range");
    ASSERT_ERROR(m, "d 1 10 0 0.5 0.1 -0.01", "value out of range");
    ASSERT_ERROR(m, "v 1 20 -1 2", "value out of range");
    ASSERT_ERROR(m, "c 1 5 -1 6", "value out of range");
    /* kp = kd = 0 is allowed (>= 0), negative targets too */
    const daran_move_t *mv = ASSERT_MOVE(m, "d 1 -10 -5 -0.5 0 0");
    ASSERT_MOVE_EQUALS(m, mv, {D, 0, -10, -5, -0.5f, 0, 0, 0});
    mv = ASSERT_MOVE(m, "t 1 10 0 1e-30");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 10, 0, 0, 1e-30f, 0, 0});
}

/* ---- zero rates (spec 10.1, D30) ---- */

/* A rate of 0 reaches the HAL as +0: it becomes a property that reads back
 * "0", never "-0". */
static void assert_positive_zero(const mock_t *m, float rate, int line)
{
    mock_check(rate == 0.0f && !signbit(rate), m, __FILE__, line, "rate: expected +0, got %a",
               (double)rate);
}

static void test_t_with_bandwidth_0_is_accepted_and_keeps_the_bandwidth(void)
{
    mock_t *m = mock_new();
    /* the vendor's set_angle(1, 30) */
    const daran_move_t *mv = ASSERT_MOVE(m, "t 1 30 0 0 ");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 30, 0, 0, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("20\n", ASSERT_QUERY(m, "r axis1.controller.config.input_filter_bandwidth"));
    mv = ASSERT_MOVE(m, "t 1 -30 5 -0");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, -30, 0, 0, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    mv = ASSERT_MOVE(m, "t 1 30 0 0 *102");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 30, 0, 0, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("20\n", ASSERT_QUERY(m, "r axis1.controller.config.input_filter_bandwidth"));
    /* the same as omitting it */
    mv = ASSERT_MOVE(m, "t 1 30 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 30, 0, 0, 0, 0, 0});
    /* a positive bandwidth is still given and stored */
    mv = ASSERT_MOVE(m, "t 1 30 0 25");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 30, 0, 0, 25, 0, 0});
    TEST_ASSERT_EQUAL_STRING("25\n", ASSERT_QUERY(m, "r axis1.controller.config.input_filter_bandwidth"));
    ASSERT_ERROR(m, "t 1 30 0 -1", "value out of range");
}

static void test_q_with_acceleration_0_is_accepted_as_a_step_without_cruise(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = 120.0f;
    m->props[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = 30.0f;
    m->props[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = 30.0f;
    /* rate 0 given, cruise not given and 0: "as fast as the drive can" */
    const daran_move_t *mv = ASSERT_MOVE(m, "q 1 10 30 0 ");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GR, 10, 0, 0, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("120\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_vel_limit"));
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_accel_limit"));
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_decel_limit"));
    mv = ASSERT_MOVE(m, "q 1 -10 30 -0");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GR, -10, 0, 0, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_accel_limit"));
    mv = ASSERT_MOVE(m, "q 1 10 30 0 *82");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GR, 10, 0, 0, 0, 0, 0});
    /* a cruise of 0 stays refused, with or without an acceleration */
    ASSERT_ERROR(m, "q 1 10 0 0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 0 5", "value out of range");
    ASSERT_ERROR(m, "q 1 10 -30 0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 30 -1", "value out of range");
}

static void test_v_mode_2_with_ramp_0_is_accepted_with_rate_0(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "v 1 60 0 2 ");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 60, 0, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.vel_ramp_rate"));
    m->props[DARAN_PROP_VEL_RAMP_RATE].f32 = 60.0f;
    mv = ASSERT_MOVE(m, "v 1 -60 -0 2");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, -60, 0, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.vel_ramp_rate"));
    mv = ASSERT_MOVE(m, "v 1 60 0 2 *99");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 60, 0, 0, 0, 0});
    ASSERT_ERROR(m, "v 1 60 -1 2", "value out of range");
    ASSERT_ERROR(m, "v 1 60 -1e-45 2", "value out of range");
    /* mode 1: the parameter is a feed-forward torque and may be anything */
    mv = ASSERT_MOVE(m, "v 1 60 -1 1");
    ASSERT_MOVE_EQUALS(m, mv, {V, 0, 0, 60, -1, 0, 0, 0});
}

static void test_c_ramp_0_is_accepted_with_rate_0_in_modes_6_and_2(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "c 1 0.05 0 6 ");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.05f, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.torque_ramp_rate"));
    m->props[DARAN_PROP_TORQUE_RAMP_RATE].f32 = 1.0f;
    mv = ASSERT_MOVE(m, "c 1 0.05 0 2");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.05f, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.torque_ramp_rate"));
    mv = ASSERT_MOVE(m, "c 1 -0.05 -0 6");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, -0.05f, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    mv = ASSERT_MOVE(m, "c 1 0.05 -0 2");
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.torque_ramp_rate"));
    mv = ASSERT_MOVE(m, "c 1 0.05 0 6 *111");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.05f, 0, 0, 0});
    ASSERT_ERROR(m, "c 1 0.05 -1 6", "value out of range");
    ASSERT_ERROR(m, "c 1 0.05 -1 2", "value out of range");
    ASSERT_ERROR(m, "c 1 0.05 -1e-45 6", "value out of range");
}

/* ---- multi-motor: ms + mt/mq/mp/mv/mc ---- */

/* Expected cruise of a timed trapezoid, in double, from the float inputs. */
typedef struct timed { bool feasible; double vel_rpm, rate; } timed_t;

/* The mock's output_shaft.vel_limit, r/min (mock_hal.c). */
#define MOCK_SHAFT_VEL_LIMIT 600.0

static timed_t timed_expect_shape(float dist, float duration, float acc, bool s_curve)
{
    /* trapezoid: T = D/V + V/A; S-curve: T = D/V + 2V/A (spec 10.3), so
     * s V^2 - A T V + A D = 0 with s = 1 or 2 */
    timed_t t = {false, 0, 0};
    double s = s_curve ? 2.0 : 1.0;
    double d = fabs((double)dist), tt = duration, a = 6.0 * (double)acc;
    double disc = a * a * tt * tt - 4.0 * s * a * d;
    if (disc >= 0) {
        t.feasible = true;
        t.vel_rpm = (a * tt - sqrt(disc)) / (2.0 * s) / 6.0;
        t.rate = acc;
    } else if (-disc <= 1e-4 * a * a * tt * tt || 2.0 * d / tt / 6.0 <= MOCK_SHAFT_VEL_LIMIT) {
        /* 10.5: the move that lands exactly at T, within the velocity limit
         * unless T is the least duration float32 pushed a hair short */
        t.feasible = true;
        t.vel_rpm = 2.0 * d / tt / 6.0;
        t.rate = 4.0 * s * d / (tt * tt) / 6.0;
    }
    return t;
}

static timed_t timed_expect(float dist, float duration, float acc)
{
    return timed_expect_shape(dist, duration, acc, false);
}

static void assert_close(const mock_t *m, double got, double want, const char *what, int line)
{
    double tol = 1e-4 * fabs(want) + 1e-12;
    mock_check(fabs(got - want) <= tol, m, __FILE__, line, "%s: expected %.9g (+-1e-4 rel), got %.9g",
               what, want, got);
}

static void check_timed_move(const mock_t *m, const daran_move_t *mv, float target, float dist,
                             float duration, float acc, int line)
{
    timed_t t = timed_expect(dist, duration, acc);
    TEST_ASSERT_TRUE(t.feasible);
    mock_check(mv->kind == Q, m, __FILE__, line, "expected a trapezoid, got kind %d", (int)mv->kind);
    mock_check(mv->given == (GV | GR), m, __FILE__, line, "expected VEL|RATE given, got %u",
               (unsigned)mv->given);
    assert_close(m, mv->pos_deg, target, "pos_deg", line);
    assert_close(m, mv->vel_rpm, t.vel_rpm, "vel_rpm", line);
    assert_close(m, mv->rate, t.rate, "rate", line);
}

static void test_spec_mq_example_moves_each_drive_to_arrive_together(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *a = mock_new_slot(0, 1), *b = mock_new_slot(1, 2);
    a->props[DARAN_PROP_POS_SETPOINT].f32 = 30.0f;
    b->props[DARAN_PROP_POS_SETPOINT].f32 = -20.0f;
    static const char *const lines[] = {"ms 1 120 5 10", "ms 2 -100 5 10"};
    for (size_t i = 0; i < 2; i++) {
        ASSERT_SILENT(a, lines[i]);
        ASSERT_SILENT(b, lines[i]);
    }
    const daran_move_t *mv = ASSERT_MOVE(a, "mq 0 1");
    check_timed_move(a, mv, 150.0f, 120.0f, 5.0f, 10.0f, __LINE__);
    mv = ASSERT_MOVE(b, "mq 0 1");
    check_timed_move(b, mv, -120.0f, -100.0f, 5.0f, 10.0f, __LINE__);
    /* v = (A*T - sqrt(A^2 T^2 - 4AD)) / 2 by hand for drive 1: A = 60, T = 5, D = 120 */
    double v = (300.0 - sqrt(90000.0 - 28800.0)) / 2.0;
    assert_close(a, a->calls[0].move.vel_rpm, v / 6.0, "vel_rpm by hand", __LINE__);
}

static void test_mq_absolute_uses_the_distance_from_the_setpoint(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 10.0f;
    ASSERT_SILENT(m, "ms 1 40 2.5 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 0");
    check_timed_move(m, mv, 40.0f, 30.0f, 2.5f, 10.0f, __LINE__);
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 100.0f;
    ASSERT_SILENT(m, "ms 1 40 2.5 10");
    mv = ASSERT_MOVE(m, "mq 1 0");
    check_timed_move(m, mv, 40.0f, -60.0f, 2.5f, 10.0f, __LINE__);
}

/* A subnormal distance: the plan's cruise velocity and acceleration
 * underflow to 0, and the move goes as a step with nothing given, never as
 * a trapezoid with a cruise of 0 (found by fuzz_bridge). */
static void test_mq_of_a_subnormal_distance_is_a_step_with_nothing_given(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 1.5e-45 81.92 325.61"); /* the least subnormal */
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_TRAPEZOID, mv->kind);
    TEST_ASSERT_EQUAL_UINT8(0, mv->given);
    TEST_ASSERT_TRUE(mv->pos_deg > 0.0f && mv->pos_deg < 1e-44f);
    TEST_ASSERT_TRUE(mv->vel_rpm == 0.0f && mv->rate == 0.0f);
}

/* 10.5 (D42): a duration the preset's acceleration cannot cover is kept:
 * the cruise-less move landing at T, peak 2D/T, acceleration 4D/T^2. */
static void test_mq_short_of_its_acceleration_keeps_the_time(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* 100 deg in 1 s, where 1 (r/min)/s = 6 deg/s^2 needs 8.2 s */
    ASSERT_SILENT(m, "ms 1 100 1 1");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GV | GR, 100, 200.0f / 6.0f, 0, 400.0f / 6.0f, 0, 0});
    check_timed_move(m, mv, 100, 100, 1, 1, __LINE__);
    /* the recorded vendor case: 2.30 s for 80 deg at 10 (r/min)/s, least 2.3094 s */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 90.0f;
    ASSERT_SILENT(m, "ms 1 10 2.3 10");
    mv = ASSERT_MOVE(m, "mq 1 0");
    check_timed_move(m, mv, 10, 80, 2.3f, 10, __LINE__);
}

/* A port without a velocity limit keeps any time: a duration whose square
 * overflows leaves the triangle's acceleration 0, and the move goes as a
 * step with nothing given, never as a trapezoid with a rate of 0. */
static void test_mq_whose_triangle_acceleration_underflows_is_a_step(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 1e30 1e20 1e-11");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, DARAN_PROP_SHAFT_VEL_LIMIT);
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 1e30f, 0, 0, 0, 0, 0});
}

/* Only a peak beyond output_shaft.vel_limit is refused, with no motion and
 * the preset kept (D16); a peak at the limit runs. */
static void test_mq_beyond_the_velocity_limit_is_refused_at_it_runs(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* 150 deg in 0.5 s peaks at 600 deg/s = 100 r/min */
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 99.99f;
    ASSERT_SILENT(m, "ms 1 150 0.5 1");
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    TEST_ASSERT_EQUAL_UINT(0, mock_count(m, MOCK_CALL_MOVE));
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 100.0f;
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GV | GR, 150, 100, 0, 400, 0, 0});
    /* consumed: the next start has no preset */
    ASSERT_ERROR(m, "mq 1 0", "no preset");
    /* a far-off one at the default 600 r/min */
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 600.0f;
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 100 0.03 1");
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    mv = ASSERT_MOVE(m, "mp 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 100.0f);
}

/* The limit is read through the HAL only for a move the acceleration cannot
 * cover: a port without the property has no limit, a failing read is
 * answered and keeps the preset. */
static void test_mq_velocity_limit_read_through_the_hal(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 100 0.03 1");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, DARAN_PROP_SHAFT_VEL_LIMIT);
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 100.0f && mv->given == (GV | GR));
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 100 1 1");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_SHAFT_VEL_LIMIT);
    ASSERT_ERROR(m, "mq 1 0", "motor fault");
    TEST_ASSERT_EQUAL_UINT(0, mock_count(m, MOCK_CALL_MOVE));
    mv = ASSERT_MOVE(m, "mq 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 100.0f);
    /* a covered duration never asks */
    ASSERT_SILENT(m, "ms 1 40 2.5 10");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_SHAFT_VEL_LIMIT);
    mv = ASSERT_MOVE(m, "mq 1 1");
    TEST_ASSERT_TRUE(mv->pos_deg == 140.0f);
}

static void test_mq_within_the_1e4_shortfall_runs_the_exact_triangle(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* A = 60, D = 30: the minimum duration is sqrt(2); 1.4142 falls short by 2e-5 relative */
    ASSERT_SILENT(m, "ms 1 30 1.4142 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 1");
    float T = 1.4142f;
    assert_close(m, mv->pos_deg, 30.0, "pos_deg", __LINE__);
    assert_close(m, mv->vel_rpm, 2.0 * 30.0 / T / 6.0, "vel_rpm = 2D/T/6", __LINE__);
    assert_close(m, mv->rate, 4.0 * 30.0 / ((double)T * T) / 6.0, "rate = 4D/T^2/6", __LINE__);
}

static void test_mq_with_the_vendor_17_digit_minimum_duration_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 30 1.4142135623730951 10 ");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 1");
    /* peak A*T/2 = 42.43 deg/s = 7.07 r/min, acceleration 10 (r/min)/s */
    assert_close(m, mv->vel_rpm, 60.0 * 1.4142135623730951 / 2.0 / 6.0, "vel_rpm", __LINE__);
    assert_close(m, mv->rate, 10.0, "rate", __LINE__);
    assert_close(m, mv->pos_deg, 30.0, "pos_deg", __LINE__);
}

static void test_mq_with_zero_distance_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 5.0f;
    ASSERT_SILENT(m, "ms 1 0 2 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 1");
    TEST_ASSERT_EQUAL_INT64(Q, mv->kind);
    TEST_ASSERT_TRUE(mv->pos_deg == 5.0f);
    /* daran_hal.h: a given cruise and accel are > 0, even for a move that is already done */
    if (mv->given & GV) {
        TEST_ASSERT_TRUE(mv->vel_rpm > 0.0f);
    }
    if (mv->given & GR) {
        TEST_ASSERT_TRUE(mv->rate > 0.0f);
    }
    /* D31: nothing to plan, the drive keeps its settings */
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 5, 0, 0, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 5 2 10");
    mv = ASSERT_MOVE(m, "mq 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 5.0f);
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 5, 0, 0, 0, 0, 0});
}

static void test_mq_negative_duration_or_accel_is_out_of_range(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const presets[] = {"ms 1 10 -1 10", "ms 1 10 2 -3", "ms 1 10 -1e-45 10",
                                          "ms 1 10 2 -1e-45", "ms 1 0 -1 10", "ms 1 0 2 -3",
                                          "ms 1 10 -1 0"};
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        ASSERT_SILENT(m, presets[i]);
        ASSERT_ERROR(m, "mq 1 1", "value out of range");
        ASSERT_ERROR(m, "mq 1 0", "value out of range");
    }
}

/* Spec 10.1: the vendor library computes duration 0 when every drive already
 * stands at its target; a drive that must move cannot do it in no time. */
static void test_mq_zero_duration_or_accel_with_a_distance_is_infeasible(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 20.0f;
    static const char *const presets[] = {"ms 1 30 0 10", "ms 1 30 2 0", "ms 1 30 0 0",
                                          "ms 1 30 -0 10", "ms 1 30 2 -0", "ms 1 30 0.0 10 "};
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        ASSERT_SILENT(m, presets[i]);
        ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
        ASSERT_ERROR(m, "mq 0 1", "trajectory infeasible");
    }
    /* a refused start keeps its preset (D16): it still runs as another kind */
    const daran_move_t *mv = ASSERT_MOVE(m, "mp 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 30.0f);
}

static void test_mq_zero_duration_or_accel_at_zero_distance_is_a_trapezoid_in_place(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 20.0f;
    /* the vendor recording: ms 1 20 0.0 10 + mq 0 0 when the drive stands at 20 */
    static const char *const absolute[] = {"ms 1 20 0.0 10 ", "ms 1 20 2 0", "ms 1 20 0 0",
                                           "ms 1 20 -0 -0"};
    for (size_t i = 0; i < sizeof absolute / sizeof absolute[0]; i++) {
        ASSERT_SILENT(m, absolute[i]);
        const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 0");
        ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 20, 0, 0, 0, 0, 0});
    }
    static const char *const relative[] = {"ms 1 0 0 10", "ms 1 0 2 0", "ms 1 -0 0 0"};
    for (size_t i = 0; i < sizeof relative / sizeof relative[0]; i++) {
        ASSERT_SILENT(m, relative[i]);
        const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 1");
        ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 20, 0, 0, 0, 0, 0});
    }
    /* the trajectory settings are untouched */
    m->props[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = 90.0f;
    m->props[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = 10.0f;
    ASSERT_SILENT(m, "ms 1 20 0 0");
    (void)ASSERT_MOVE(m, "mq 1 0");
    TEST_ASSERT_EQUAL_STRING("90\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_vel_limit"));
    TEST_ASSERT_EQUAL_STRING("10\n", ASSERT_QUERY(m, "r axis1.output_shaft.trap_traj_accel_limit"));
}

/* ---- D41: mq measures from where the drive is heading ----
 *
 * The vendor's Python and STM32 libraries call set_angles() twice with the
 * same targets without waiting: the second call computes duration 0 from the
 * targets it sent last and sends `ms id pos 0 acc` + `mq 0 0` while the first
 * synchronised move still runs. The distance of spec 10.1 is the one from
 * the running move's end (input_pos while trajectory_done reads 0), else from
 * the position setpoint. */

/* The mock as a drive on its way to @p end, its setpoint passing
 * @p setpoint: trajectory_done 0. */
static void mock_moving(mock_t *m, float setpoint, float end)
{
    m->props[DARAN_PROP_POS_SETPOINT].f32 = setpoint;
    m->props[DARAN_PROP_INPUT_POS].f32 = end;
    m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 0;
}

static void test_mq_duration_or_accel_0_to_the_running_moves_end_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* absolute, by the vendor's broadcast start: duration 0, acceleration 0,
     * both, and a duration that is not 0: the distance is 0 all the same */
    static const char *const absolute[] = {"ms 1 30 0 10", "ms 1 30 0.0 10 ", "ms 1 30 2 0",
                                           "ms 1 30 0 0", "ms 1 30 -0 -0", "ms 1 30 2 10"};
    for (size_t i = 0; i < sizeof absolute / sizeof absolute[0]; i++) {
        mock_moving(m, 12.0f, 30.0f);
        ASSERT_SILENT(m, absolute[i]);
        const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 0");
        /* nothing given: the drive keeps its settings and its running move */
        ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 30, 0, 0, 0, 0, 0});
    }
    /* relative to the setpoint, landing on the running move's end */
    mock_moving(m, 12.0f, 30.0f);
    ASSERT_SILENT(m, "ms 1 18 0 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 1");
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 30, 0, 0, 0, 0, 0});
}

static void test_mq_duration_or_accel_0_to_another_target_while_moving_is_infeasible(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* the setpoint the shaft is passing is not where the drive is heading */
    static const char *const presets[] = {"ms 1 12 0 10", "ms 1 12 2 0", "ms 1 31 0 10",
                                          "ms 1 29.5 2 0", "ms 1 0 0 0"};
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        mock_moving(m, 12.0f, 30.0f);
        ASSERT_SILENT(m, presets[i]);
        ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
        ASSERT_ERROR(m, "mq 0 0", "trajectory infeasible");
    }
    /* relative: 0 from the setpoint is 18 from the running move's end */
    mock_moving(m, 12.0f, 30.0f);
    ASSERT_SILENT(m, "ms 1 0 0 10");
    ASSERT_ERROR(m, "mq 1 1", "trajectory infeasible");
}

static void test_mq_with_no_move_running_measures_from_the_setpoint(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* trajectory_done 1 (the mock's default): input_pos is only the last
     * target, which the drive reached or left (a `v`, a written setpoint) */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 20.0f;
    m->props[DARAN_PROP_INPUT_POS].f32 = 99.0f;
    ASSERT_SILENT(m, "ms 1 20 0 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 0");
    ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 20, 0, 0, 0, 0, 0});
    m->props[DARAN_PROP_INPUT_POS].f32 = 99.0f;
    ASSERT_SILENT(m, "ms 1 99 0 10");
    ASSERT_ERROR(m, "mq 0 0", "trajectory infeasible");
    ASSERT_SILENT(m, "ms 1 99 2 0");
    ASSERT_ERROR(m, "mq 0 0", "trajectory infeasible");
}

static void test_timed_mq_while_moving_times_the_distance_from_the_running_moves_end(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* what the host computed its duration for: 30 -> 90, not 12 -> 90 */
    mock_moving(m, 12.0f, 30.0f);
    ASSERT_SILENT(m, "ms 1 90 2 60");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 0");
    check_timed_move(m, mv, 90.0f, 60.0f, 2.0f, 60.0f, __LINE__);
    /* relative starts still add to the setpoint */
    mock_moving(m, 12.0f, 30.0f);
    ASSERT_SILENT(m, "ms 1 78 2 60");
    mv = ASSERT_MOVE(m, "mq 1 1");
    check_timed_move(m, mv, 90.0f, 60.0f, 2.0f, 60.0f, __LINE__);
}

/* A port without trajectory_done or input_pos (get answers
 * DARAN_ERR_INVALID_PROPERTY) measures from the setpoint; any other failing
 * read is answered, and the preset kept (D16, D26). */
static void test_mq_heading_reads_missing_or_failing(void)
{
    SKIP_IF_NO_MULTI();
    static const daran_prop_t props[] = {DARAN_PROP_TRAJECTORY_DONE, DARAN_PROP_INPUT_POS};
    for (size_t i = 0; i < 2; i++) {
        mock_t *m = mock_new();
        mock_moving(m, 20.0f, 30.0f);
        ASSERT_SILENT(m, "ms 1 20 0 10");
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, (int)props[i]);
        const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
        ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 20, 0, 0, 0, 0, 0});
        mock_moving(m, 20.0f, 30.0f);
        ASSERT_SILENT(m, "ms 1 30 0 10");
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, (int)props[i]);
        ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, (int)props[i]);
        ASSERT_ERROR(m, "mq 1 0", "motor fault");
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_BAD_ARGUMENT, (int)props[i]);
        ASSERT_ERROR(m, "mq 1 0", "motor fault");
        mv = ASSERT_MOVE(m, "mq 1 0");
        ASSERT_MOVE_EQUALS(m, mv, {Q, 0, 30, 0, 0, 0, 0, 0});
    }
}

/* ---- mq under traj_mode 1 (trapezoid) and 2 (S-curve), spec 10.3 ----
 *
 * D = 90 deg, T = 2 s, a = 60 (r/min)/s, so A = 6a = 360 deg/s^2, A T = 720,
 * A^2 T^2 = 518400.
 * Trapezoid: 4AD = 129600, sqrt(518400 - 129600) = sqrt(388800) = 360 sqrt(3)
 *   = 623.53829; V = 2AD / (AT + sqrt) = 64800 / 1343.53829 = 48.2308546 deg/s
 *   (= 360 - 180 sqrt(3)), so vel_rpm = V/6 = 60 - 30 sqrt(3) = 8.03847577 r/min;
 *   check: D/V + V/A = 1.8660254 + 0.1339746 = 2 s.
 * S-curve: 8AD = 259200, sqrt(518400 - 259200) = sqrt(259200) = 360 sqrt(2)
 *   = 509.11688; V = 64800 / 1229.11688 = 52.7207794 deg/s (= 180 - 90 sqrt(2)),
 *   so vel_rpm = 30 - 15 sqrt(2) = 8.78679656 r/min; check in the vendor's
 *   units: D/(6v) + 2v/a = 90/52.7207794 + 17.5735931/60 = 1.7071068 + 0.2928932
 *   = 2 s (and D = 90 > 12 v^2/a = 15.44, so the cruise is reached).
 * Both keep the acceleration: rate = a = 60 (r/min)/s. */
#define HAND_TRAPEZOID_RPM 8.0384757729336805 /* 60 - 30 sqrt(3) */
#define HAND_S_CURVE_RPM 8.7867965644035753   /* 30 - 15 sqrt(2) */

static void assert_hand_worked(const mock_t *m, const daran_move_t *mv, float target, double rpm,
                               double rate, unsigned given, int line)
{
    mock_check(mv->kind == Q && mv->given == given, m, __FILE__, line,
               "expected a trapezoid with given %u, got kind %d given %u", given, (int)mv->kind,
               (unsigned)mv->given);
    mock_check(mv->pos_deg == target, m, __FILE__, line, "pos_deg %.9g", (double)mv->pos_deg);
    /* float32 arithmetic: a few units in the last place */
    mock_check(fabs(mv->vel_rpm - rpm) <= 4e-6 * rpm, m, __FILE__, line,
               "vel_rpm: expected %.9g, got %.9g", rpm, (double)mv->vel_rpm);
    mock_check(fabs(mv->rate - rate) <= 4e-6 * rate, m, __FILE__, line,
               "rate: expected %.9g, got %.9g", rate, (double)mv->rate);
}

static void test_mq_trapezoid_cruise_is_the_hand_worked_value(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT64(1, m->props[DARAN_PROP_TRAJ_MODE].u32); /* the mock's default */
    ASSERT_SILENT(m, "ms 1 90 2 60");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    assert_hand_worked(m, mv, 90, HAND_TRAPEZOID_RPM, 60, GV | GR, __LINE__);
    check_timed_move(m, mv, 90, 90, 2, 60, __LINE__);
    /* explicitly 1 is the same */
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 1", DARAN_PROP_TRAJ_MODE);
    ASSERT_SILENT(m, "ms 1 -90 2 60");
    mv = ASSERT_MOVE(m, "mq 1 1");
    assert_hand_worked(m, mv, 0, HAND_TRAPEZOID_RPM, 60, GV | GR, __LINE__);
}

#if DARAN_ENABLE_S_CURVE
static void test_mq_s_curve_cruise_is_the_hand_worked_value(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 2", DARAN_PROP_TRAJ_MODE);
    ASSERT_SILENT(m, "ms 1 90 2 60");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    assert_hand_worked(m, mv, 90, HAND_S_CURVE_RPM, 60, GV | GR, __LINE__);
    /* relative and backwards: the distance is what counts */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 100.0f;
    ASSERT_SILENT(m, "ms 1 -90 2 60");
    mv = ASSERT_MOVE(m, "mq 0 1");
    assert_hand_worked(m, mv, 10, HAND_S_CURVE_RPM, 60, GV | GR, __LINE__);
    /* the S-curve needs the faster cruise for the same arrival */
    TEST_ASSERT_TRUE(HAND_S_CURVE_RPM > HAND_TRAPEZOID_RPM);
    /* other numbers against the model in double */
    static const float cases[][3] = {{120, 5, 10}, {30, 3, 10}, {1, 0.5f, 100}, {720, 10, 30}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
        char line[64];
        snprintf(line, sizeof line, "ms 1 %g %g %g", (double)cases[i][0], (double)cases[i][1],
                 (double)cases[i][2]);
        ASSERT_SILENT(m, line);
        mv = ASSERT_MOVE(m, "mq 1 0");
        timed_t t = timed_expect_shape(cases[i][0], cases[i][1], cases[i][2], true);
        TEST_ASSERT_TRUE(t.feasible);
        assert_close(m, mv->vel_rpm, t.vel_rpm, "S-curve vel_rpm", __LINE__);
        assert_close(m, mv->rate, t.rate, "S-curve rate", __LINE__);
    }
}

static void test_mq_s_curve_within_the_1e4_shortfall_runs_the_exact_triangle(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 2", DARAN_PROP_TRAJ_MODE);
    /* D = 90, A = 360: the S-curve minimum is sqrt(8D/A) = sqrt(2) s; 1.4142
     * falls short by 8AD/(AT)^2 - 1 = 1.9e-5 relative. Triangle: peak 2D/T,
     * acceleration 8D/T^2 (the S-curve's mean acceleration is a/2). */
    ASSERT_SILENT(m, "ms 1 90 1.4142 60");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    double T = 1.4142f;
    assert_hand_worked(m, mv, 90, 2.0 * 90.0 / T / 6.0, 8.0 * 90.0 / (T * T) / 6.0, GV | GR,
                       __LINE__);
    /* the vendor's 17-digit minimum */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 90 1.4142135623730951 60 ");
    mv = ASSERT_MOVE(m, "mq 1 0");
    assert_close(m, mv->vel_rpm, 2.0 * 90.0 / 1.4142135623730951 / 6.0, "vel_rpm", __LINE__);
    assert_close(m, mv->rate, 60.0, "rate", __LINE__);
}

static void test_mq_short_as_an_s_curve_keeps_the_time_at_8d_over_t2(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    /* D = 90, A = 360, T = 1.4 s: A^2 T^2 = 254016 >= 4AD = 129600 (trapezoid)
     * but < 8AD = 259200 by 2% (S-curve) */
    ASSERT_SILENT(m, "ms 1 90 1.4 60");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    timed_t t = timed_expect(90, 1.4f, 60);
    assert_close(m, mv->vel_rpm, t.vel_rpm, "trapezoid vel_rpm", __LINE__);
    assert_close(m, mv->rate, 60.0, "trapezoid rate", __LINE__);
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 2", DARAN_PROP_TRAJ_MODE);
    ASSERT_SILENT(m, "ms 1 90 1.4 60");
    mv = ASSERT_MOVE(m, "mq 1 0");
    double T = 1.4f;
    assert_hand_worked(m, mv, 90, 2.0 * 90.0 / T / 6.0, 8.0 * 90.0 / (T * T) / 6.0, GV | GR,
                       __LINE__);
    /* the vendor's trapezoid minimum 2 sqrt(D/A) is far too short for the S-curve: kept too */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 20 1.1547005383792515 10");
    mv = ASSERT_MOVE(m, "mq 0 0");
    T = 1.1547005383792515;
    assert_close(m, mv->vel_rpm, 2.0 * 20.0 / T / 6.0, "S-curve vel_rpm", __LINE__);
    assert_close(m, mv->rate, 8.0 * 20.0 / (T * T) / 6.0, "S-curve rate", __LINE__);
    /* beyond the velocity limit it is refused as a trapezoid is */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 90 0.04 60");
    ASSERT_ERROR(m, "mq 0 0", "trajectory infeasible");
}

/* The planner reads traj_mode through the HAL (D31). */
static void test_mq_traj_mode_read_failure_answers_motor_fault_and_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 90 2 60");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_TRAJ_MODE);
    ASSERT_ERROR(m, "mq 1 0", "motor fault");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    assert_hand_worked(m, mv, 90, HAND_TRAPEZOID_RPM, 60, GV | GR, __LINE__);
}
#endif /* DARAN_ENABLE_S_CURVE */

static void test_mq_on_a_port_without_traj_mode_plans_a_trapezoid(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_TRAJ_MODE].u32 = 2;
    ASSERT_SILENT(m, "ms 1 90 2 60");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, DARAN_PROP_TRAJ_MODE);
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 0");
    assert_hand_worked(m, mv, 90, HAND_TRAPEZOID_RPM, 60, GV | GR, __LINE__);
}

static void test_q_and_mq_are_planned_by_the_drive_not_the_core(void)
{
    mock_t *m = mock_new();
    /* q passes its values on whatever traj_mode says: the HAL shapes the profile */
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 2", DARAN_PROP_TRAJ_MODE);
    const daran_move_t *mv = ASSERT_MOVE(m, "q 1 90 30 60");
    ASSERT_MOVE_EQUALS(m, mv, {Q, GV | GR, 90, 30, 0, 60, 0, 0});
}

static void test_mt_starts_a_filtered_move_with_the_preset_bandwidth(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 7.0f;
    ASSERT_SILENT(m, "ms 1 10 99 5");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 10, 0, 0, 5, 0, 0});
    ASSERT_SILENT(m, "ms 1 10 99 5");
    mv = ASSERT_MOVE(m, "mt 0 1");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 20, 0, 0, 5, 0, 0});
    /* spec 10.1: bandwidth 0 keeps the current one, as `t` does */
    ASSERT_SILENT(m, "ms 1 10 99 0");
    mv = ASSERT_MOVE(m, "mt 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 10, 0, 0, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("5\n", ASSERT_QUERY(m, "r axis1.controller.config.input_filter_bandwidth"));
    ASSERT_SILENT(m, "ms 1 10 0 -0");
    mv = ASSERT_MOVE(m, "mt 0 1");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 20, 0, 0, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 10 99 -1");
    ASSERT_ERROR(m, "mt 1 0", "value out of range");
}

static void test_mt_with_preset_bandwidth_0_is_the_vendor_set_angles_default(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 30.0f;
    /* the vendor recording: ms 1 10 0 0 + mt 0 1 */
    ASSERT_SILENT(m, "ms 1 10 0 0 ");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 0 1");
    ASSERT_MOVE_EQUALS(m, mv, {F, 0, 40, 0, 0, 0, 0, 0});
    TEST_ASSERT_EQUAL_STRING("20\n", ASSERT_QUERY(m, "r axis1.controller.config.input_filter_bandwidth"));
}

static void test_mp_starts_passthrough_with_the_preset_feed_forwards(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = -4.0f;
    ASSERT_SILENT(m, "ms 1 10 5 3");
    const daran_move_t *mv = ASSERT_MOVE(m, "mp 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {P, 0, 10, 5, 3, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 10 5 3");
    mv = ASSERT_MOVE(m, "mp 1 1");
    ASSERT_MOVE_EQUALS(m, mv, {P, 0, 20, 5, 3, 0, 0, 0});
}

static void test_mv_starts_velocity_by_the_preset_mode(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 20 3 1");
    const daran_move_t *mv = ASSERT_MOVE(m, "mv 1");
    ASSERT_MOVE_EQUALS(m, mv, {V, 0, 0, 20, 3, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 20 3 2");
    mv = ASSERT_MOVE(m, "mv 0");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 20, 0, 3, 0, 0});
    /* spec 10.1: ramp 0 holds the velocity setpoint */
    ASSERT_SILENT(m, "ms 1 20 0 2");
    mv = ASSERT_MOVE(m, "mv 1");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 20, 0, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 60 -0 2");
    mv = ASSERT_MOVE(m, "mv 0");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 60, 0, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.vel_ramp_rate"));
    ASSERT_SILENT(m, "ms 1 20 -1 2");
    ASSERT_ERROR(m, "mv 1", "value out of range");
    ASSERT_SILENT(m, "ms 1 20 0 7");
    ASSERT_ERROR(m, "mv 1", "invalid mode");
}

static void test_mc_starts_torque_by_the_preset_mode(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 0.5 0 1");
    const daran_move_t *mv = ASSERT_MOVE(m, "mc 1");
    ASSERT_MOVE_EQUALS(m, mv, {C, 0, 0, 0, 0.5f, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 0.5 2 6");
    mv = ASSERT_MOVE(m, "mc 0");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.5f, 2, 0, 0});
    ASSERT_SILENT(m, "ms 1 0.5 2 2");
    mv = ASSERT_MOVE(m, "mc 1");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.5f, 2, 0, 0});
    /* spec 10.1: ramp 0 holds the torque setpoint */
    ASSERT_SILENT(m, "ms 1 0.5 0 6");
    mv = ASSERT_MOVE(m, "mc 1");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.5f, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 0.05 -0 2");
    mv = ASSERT_MOVE(m, "mc 0");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.05f, 0, 0, 0});
    assert_positive_zero(m, mv->rate, __LINE__);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.output_shaft.torque_ramp_rate"));
    ASSERT_SILENT(m, "ms 1 0.5 -2 6");
    ASSERT_ERROR(m, "mc 1", "value out of range");
    ASSERT_SILENT(m, "ms 1 0.5 0 5");
    ASSERT_ERROR(m, "mc 1", "invalid mode");
}

static void test_ms_stores_only_finite_values_and_makes_no_hal_call(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 1 2 3");
    ASSERT_SILENT(m, "ms 0 1 2 3");
    ASSERT_ERROR(m, "ms 1 1e39 2 3", "value out of range");
    ASSERT_ERROR(m, "ms 1 1 nan 3", "invalid value");
    ASSERT_ERROR(m, "ms 1 1 2", "invalid command format");
}

static void test_a_later_ms_replaces_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_SILENT(m, "ms 1 20 0 6");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 20, 0, 0, 6, 0, 0});
}

static void test_a_preset_for_another_drive_is_not_stored(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 2 10 0 5");
    ASSERT_ERROR(m, "mt 1 0", "no preset");
    ASSERT_SILENT(m, "mt 0 0");
}

/* ---- system commands ---- */

static void test_system_commands_make_their_action(void)
{
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "ss 1", DARAN_ACTION_SAVE_CONFIG);
    ASSERT_ACTION(m, "se 1", DARAN_ACTION_ERASE_CONFIG);
    ASSERT_ACTION(m, "sz 1", DARAN_ACTION_SET_ZERO);
    ASSERT_ACTION(m, "sc 1", DARAN_ACTION_CLEAR_ERRORS);
    ASSERT_ACTION(m, "u 1", DARAN_ACTION_FEED_WATCHDOG);
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ACTION(m, "sr 1", DARAN_ACTION_REBOOT);
    ASSERT_ACTION(m, "ss 0", DARAN_ACTION_SAVE_CONFIG);
    ASSERT_SILENT(m, "ss 2");
}

static void test_reboot_clears_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_ACTION(m, "sr 1", DARAN_ACTION_REBOOT);
    ASSERT_ERROR(m, "mt 1 0", "no preset");
}

/* ---- vendor recordings: every line accepted on a bus of three drives ---- */

#define BUS_DRIVES 3

/* The id a recording line addresses (D8, D9): field 1, the N of an axisN.
 * path, or a system path's trailing id (0 when omitted). */
static int line_motor_id(const char *line, char *word, size_t word_size)
{
    char text[DARAN_LINE_MAX + 1];
    snprintf(text, sizeof text, "%s", line);
    char *star = strchr(text, '*');
    if (star != NULL)
        *star = '\0';
    char *fields[8];
    int n = 0;
    for (char *f = strtok(text, " \t\r"); f != NULL && n < 8; f = strtok(NULL, " \t\r"))
        fields[n++] = f;
    if (n < 2)
        return -1;
    snprintf(word, word_size, "%s", fields[0]);
    for (char *c = word; *c; c++)
        *c = (char)(*c | 0x20);
    bool rw = (word[0] == 'r' || word[0] == 'w') && word[1] == '\0';
    if (!rw)
        return atoi(fields[1]);
    if (strncmp(fields[1], "axis", 4) == 0)
        return atoi(fields[1] + 4);
    return n == (word[0] == 'r' ? 3 : 4) ? atoi(fields[n - 1]) : 0;
}

static void replay(const char *name, const char *const *lines, size_t n)
{
    mock_t *bus[BUS_DRIVES];
    for (int k = 0; k < BUS_DRIVES; k++) {
        bus[k] = mock_new_slot(k, (uint32_t)(k + 1));
        bus[k]->props[DARAN_PROP_POS_ESTIMATE].f32 = 1.25f * (float)(k + 1);
    }
    for (size_t i = 0; i < n; i++) {
        char word[8] = "";
        int id = line_motor_id(lines[i], word, sizeof word);
        mock_check(id >= 0 && id <= BUS_DRIVES, bus[0], __FILE__, __LINE__,
                   "%s line %zu: no id of the bus", name, i);
        bool query = strchr("rfgie", word[0]) != NULL && word[1] == '\0';
        /* the same line reaches every drive of the bus */
        for (int k = 0; k < BUS_DRIVES; k++) {
            mock_t *m = bus[k];
            mock_send_line(m, lines[i]);
            mock_check(strstr(m->out, "error") == NULL, m, __FILE__, __LINE__,
                       "%s line %zu on drive %d answered an error", name, i, k + 1);
            bool mine = id == 0 || id == k + 1;
            if (!mine) {
                mock_check(m->out_len == 0 && m->n_calls == 0, m, __FILE__, __LINE__,
                           "%s line %zu: a line for drive %d must be silent and have no effect "
                           "on drive %d", name, i, id, k + 1);
            } else if (query) {
                size_t want = word[0] == 'e' ? 7u : 1u;
                mock_check(m->n_writes == want && m->n_calls == 0, m, __FILE__, __LINE__,
                           "%s line %zu: a read answers %zu line(s) on drive %d", name, i, want,
                           k + 1);
            } else {
                mock_check(m->out_len == 0, m, __FILE__, __LINE__,
                           "%s line %zu: a command is silent on success", name, i);
            }
        }
    }
}

static void test_every_line_of_the_vendor_python_recording_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    replay("vendor-python-client", recording_python,
           sizeof recording_python / sizeof recording_python[0]);
}

static void test_every_line_of_the_vendor_stm32_recording_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    replay("vendor-stm32-client", recording_stm32,
           sizeof recording_stm32 / sizeof recording_stm32[0]);
}

static void test_every_line_of_the_vendor_python_defaults_recording_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    replay("vendor-python-defaults", recording_python_defaults,
           sizeof recording_python_defaults / sizeof recording_python_defaults[0]);
}

static void test_the_three_recordings_run_back_to_back_on_one_bus(void)
{
    SKIP_IF_NO_MULTI();
    /* one bus for all three: state left by one recording must not trip the next */
    static const char *all[sizeof recording_python / sizeof recording_python[0] +
                           sizeof recording_stm32 / sizeof recording_stm32[0] +
                           sizeof recording_python_defaults / sizeof recording_python_defaults[0]];
    size_t n = 0;
    for (size_t i = 0; i < sizeof recording_python / sizeof recording_python[0]; i++)
        all[n++] = recording_python[i];
    for (size_t i = 0; i < sizeof recording_stm32 / sizeof recording_stm32[0]; i++)
        all[n++] = recording_stm32[i];
    for (size_t i = 0; i < sizeof recording_python_defaults / sizeof recording_python_defaults[0]; i++)
        all[n++] = recording_python_defaults[i];
    replay("all recordings", all, n);
}

static void test_each_read_of_the_defaults_recording_answers_one_number(void)
{
    /* every `r` line of vendor-python-defaults (each path of the vendor's
     * table) answers one number, never an error: what the vendor's client
     * parses with float() or int() */
    mock_t *m = mock_new();
    size_t reads = 0;
    for (size_t i = 0; i < sizeof recording_python_defaults / sizeof recording_python_defaults[0]; i++) {
        const char *line = recording_python_defaults[i];
        if (strncmp(line, "r ", 2) != 0)
            continue;
        const char *reply = ASSERT_QUERY(m, line);
        size_t value_len = strcspn(reply, " \n");
        bool checksummed = strchr(line, '*') != NULL;
        mock_check(value_len > 0 && strspn(reply, "-0123456789.e+") == value_len &&
                       (checksummed ? reply[value_len] == ' ' : reply[value_len] == '\n'),
                   m, __FILE__, __LINE__, "one number");
        reads++;
    }
    /* 159 vendor paths, trajectory_done also read by the default-argument calls */
    TEST_ASSERT_TRUE(reads >= 159);
}

static void test_vendor_python_id_discovery_read_answers_the_id(void)
{
    mock_t *m = mock_new_id(7);
    TEST_ASSERT_EQUAL_STRING("7\n", ASSERT_QUERY(m, "r axis0.config.can_node_id "));
    char want[32];
    mock_reply_line(want, sizeof want, "7", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "r axis0.config.can_node_id *42"));
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    for (size_t i = 0; i < sizeof examples / sizeof examples[0]; i++)
        mock_suite_add(&s, example_case, (void *)(uintptr_t)&examples[i],
                       "test_worked_example_\"%s\"_on_drive_%u_is_accepted", examples[i].line,
                       (unsigned)examples[i].id);
    ADD(test_omitted_optional_values_are_not_given);
    ADD(test_torque_mode_2_is_taken_as_a_ramp);
    ADD(test_motion_ranges_are_checked);
    ADD(test_t_with_bandwidth_0_is_accepted_and_keeps_the_bandwidth);
    ADD(test_q_with_acceleration_0_is_accepted_as_a_step_without_cruise);
    ADD(test_v_mode_2_with_ramp_0_is_accepted_with_rate_0);
    ADD(test_c_ramp_0_is_accepted_with_rate_0_in_modes_6_and_2);
    ADD(test_spec_mq_example_moves_each_drive_to_arrive_together);
    ADD(test_mq_absolute_uses_the_distance_from_the_setpoint);
    ADD(test_mq_of_a_subnormal_distance_is_a_step_with_nothing_given);
    ADD(test_mq_short_of_its_acceleration_keeps_the_time);
    ADD(test_mq_beyond_the_velocity_limit_is_refused_at_it_runs);
    ADD(test_mq_velocity_limit_read_through_the_hal);
    ADD(test_mq_whose_triangle_acceleration_underflows_is_a_step);
    ADD(test_mq_within_the_1e4_shortfall_runs_the_exact_triangle);
    ADD(test_mq_with_the_vendor_17_digit_minimum_duration_is_accepted);
    ADD(test_mq_with_zero_distance_is_accepted);
    ADD(test_mq_negative_duration_or_accel_is_out_of_range);
    ADD(test_mq_zero_duration_or_accel_with_a_distance_is_infeasible);
    ADD(test_mq_zero_duration_or_accel_at_zero_distance_is_a_trapezoid_in_place);
    ADD(test_mq_duration_or_accel_0_to_the_running_moves_end_is_accepted);
    ADD(test_mq_duration_or_accel_0_to_another_target_while_moving_is_infeasible);
    ADD(test_mq_with_no_move_running_measures_from_the_setpoint);
    ADD(test_timed_mq_while_moving_times_the_distance_from_the_running_moves_end);
    ADD(test_mq_heading_reads_missing_or_failing);
    ADD(test_mq_trapezoid_cruise_is_the_hand_worked_value);
#if DARAN_ENABLE_S_CURVE
    ADD(test_mq_s_curve_cruise_is_the_hand_worked_value);
    ADD(test_mq_s_curve_within_the_1e4_shortfall_runs_the_exact_triangle);
    ADD(test_mq_short_as_an_s_curve_keeps_the_time_at_8d_over_t2);
    ADD(test_mq_traj_mode_read_failure_answers_motor_fault_and_keeps_the_preset);
#endif
    ADD(test_mq_on_a_port_without_traj_mode_plans_a_trapezoid);
    ADD(test_q_and_mq_are_planned_by_the_drive_not_the_core);
    ADD(test_mt_starts_a_filtered_move_with_the_preset_bandwidth);
    ADD(test_mt_with_preset_bandwidth_0_is_the_vendor_set_angles_default);
    ADD(test_mp_starts_passthrough_with_the_preset_feed_forwards);
    ADD(test_mv_starts_velocity_by_the_preset_mode);
    ADD(test_mc_starts_torque_by_the_preset_mode);
    ADD(test_ms_stores_only_finite_values_and_makes_no_hal_call);
    ADD(test_a_later_ms_replaces_the_preset);
    ADD(test_a_preset_for_another_drive_is_not_stored);
    ADD(test_system_commands_make_their_action);
    ADD(test_reboot_clears_the_preset);
    ADD(test_every_line_of_the_vendor_python_recording_is_accepted);
    ADD(test_every_line_of_the_vendor_stm32_recording_is_accepted);
    ADD(test_every_line_of_the_vendor_python_defaults_recording_is_accepted);
    ADD(test_the_three_recordings_run_back_to_back_on_one_bus);
    ADD(test_each_read_of_the_defaults_recording_answers_one_number);
    ADD(test_vendor_python_id_discovery_read_answers_the_id);
    mock_suite_run(&s);
    return UNITY_END();
}
