/* Unit tests of the commands themselves: every worked example of spec
 * section 9 with the exact HAL call it must make, omitted optional values,
 * the multi-motor preset/start commands with the timed trapezoid of spec
 * section 6 (D16-D19), system commands, and both vendor recordings. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"
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

static void example_case(void **state)
{
    const example_t *e = *state;
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
        assert_true(v.f32 == e->f);
        break;
    }
    case EX_SET_U32: {
        daran_value_t v = ASSERT_SET(m, e->line, e->prop);
        assert_int_equal(v.u32, e->u);
        break;
    }
    case EX_ACTION: ASSERT_ACTION(m, e->line, e->action); break;
    case EX_SILENT: ASSERT_SILENT(m, e->line); break;
    case EX_REPLY: {
        char want[96];
        mock_reply_line(want, sizeof want, e->reply, e->checksum);
        assert_string_equal(ASSERT_QUERY(m, e->line), want);
        break;
    }
    }
}

/* ---- omitted optional values ---- */

static void test_omitted_optional_values_are_not_given(void **state)
{
    (void)state;
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

static void test_torque_mode_2_is_taken_as_a_ramp(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "c 1 0.100000 0.020000 2 ");
    ASSERT_MOVE_EQUALS(m, mv, {CR, 0, 0, 0, 0.1f, 0.02f, 0, 0});
}

static void test_motion_ranges_are_checked(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "t 1 10 0 0", "value out of range");
    ASSERT_ERROR(m, "t 1 10 0 -1", "value out of range");
    ASSERT_ERROR(m, "q 1 10 0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 -5", "value out of range");
    ASSERT_ERROR(m, "q 1 10 5 0", "value out of range");
    ASSERT_ERROR(m, "q 1 10 5 -1", "value out of range");
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

/* ---- multi-motor: ms + mt/mq/mp/mv/mc ---- */

/* Expected cruise of a timed trapezoid, in double, from the float inputs. */
typedef struct timed { bool feasible; double vel_rpm, rate; } timed_t;

static timed_t timed_expect(float dist, float duration, float acc)
{
    timed_t t = {false, 0, 0};
    double d = fabs((double)dist), tt = duration, a = 6.0 * (double)acc;
    double disc = a * a * tt * tt - 4.0 * a * d;
    if (disc >= 0) {
        t.feasible = true;
        t.vel_rpm = (a * tt - sqrt(disc)) / 2.0 / 6.0;
        t.rate = acc;
    } else if (-disc <= 1e-4 * a * a * tt * tt) {
        t.feasible = true;
        t.vel_rpm = 2.0 * d / tt / 6.0;
        t.rate = 4.0 * d / (tt * tt) / 6.0;
    }
    return t;
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
    assert_true(t.feasible);
    mock_check(mv->kind == Q, m, __FILE__, line, "expected a trapezoid, got kind %d", (int)mv->kind);
    mock_check(mv->given == (GV | GR), m, __FILE__, line, "expected VEL|RATE given, got %u",
               (unsigned)mv->given);
    assert_close(m, mv->pos_deg, target, "pos_deg", line);
    assert_close(m, mv->vel_rpm, t.vel_rpm, "vel_rpm", line);
    assert_close(m, mv->rate, t.rate, "rate", line);
}

static void test_spec_mq_example_moves_each_drive_to_arrive_together(void **state)
{
    (void)state;
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

static void test_mq_absolute_uses_the_distance_from_the_setpoint(void **state)
{
    (void)state;
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

static void test_infeasible_mq_is_refused_with_no_motion(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 100 1 1");
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    ASSERT_SILENT(m, "ms 1 30 1.41 10");
    ASSERT_ERROR(m, "mq 1 1", "trajectory infeasible");
}

static void test_mq_within_the_1e4_shortfall_runs_the_exact_triangle(void **state)
{
    (void)state;
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

static void test_mq_with_the_vendor_17_digit_minimum_duration_is_accepted(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 30 1.4142135623730951 10 ");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 1");
    /* peak A*T/2 = 42.43 deg/s = 7.07 r/min, acceleration 10 (r/min)/s */
    assert_close(m, mv->vel_rpm, 60.0 * 1.4142135623730951 / 2.0 / 6.0, "vel_rpm", __LINE__);
    assert_close(m, mv->rate, 10.0, "rate", __LINE__);
    assert_close(m, mv->pos_deg, 30.0, "pos_deg", __LINE__);
}

static void test_mq_with_zero_distance_is_accepted(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 5.0f;
    ASSERT_SILENT(m, "ms 1 0 2 10");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 1 1");
    assert_int_equal(mv->kind, Q);
    assert_true(mv->pos_deg == 5.0f);
    /* daran_hal.h: a given cruise and accel are > 0, even for a move that is already done */
    if (mv->given & GV)
        assert_true(mv->vel_rpm > 0.0f);
    if (mv->given & GR)
        assert_true(mv->rate > 0.0f);
    ASSERT_SILENT(m, "ms 1 5 2 10");
    mv = ASSERT_MOVE(m, "mq 1 0");
    assert_true(mv->pos_deg == 5.0f);
}

static void test_mq_duration_and_accel_must_be_positive(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const presets[] = {"ms 1 10 0 10", "ms 1 10 -1 10", "ms 1 10 2 0",
                                          "ms 1 10 2 -3"};
    for (size_t i = 0; i < 4; i++) {
        ASSERT_SILENT(m, presets[i]);
        ASSERT_ERROR(m, "mq 1 1", "value out of range");
    }
}

static void test_mt_starts_a_filtered_move_with_the_preset_bandwidth(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 7.0f;
    ASSERT_SILENT(m, "ms 1 10 99 5");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 10, 0, 0, 5, 0, 0});
    ASSERT_SILENT(m, "ms 1 10 99 5");
    mv = ASSERT_MOVE(m, "mt 0 1");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 20, 0, 0, 5, 0, 0});
    ASSERT_SILENT(m, "ms 1 10 99 0");
    ASSERT_ERROR(m, "mt 1 0", "value out of range");
}

static void test_mp_starts_passthrough_with_the_preset_feed_forwards(void **state)
{
    (void)state;
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

static void test_mv_starts_velocity_by_the_preset_mode(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 20 3 1");
    const daran_move_t *mv = ASSERT_MOVE(m, "mv 1");
    ASSERT_MOVE_EQUALS(m, mv, {V, 0, 0, 20, 3, 0, 0, 0});
    ASSERT_SILENT(m, "ms 1 20 3 2");
    mv = ASSERT_MOVE(m, "mv 0");
    ASSERT_MOVE_EQUALS(m, mv, {VR, 0, 0, 20, 0, 3, 0, 0});
    ASSERT_SILENT(m, "ms 1 20 0 2");
    ASSERT_ERROR(m, "mv 1", "value out of range");
    ASSERT_SILENT(m, "ms 1 20 0 7");
    ASSERT_ERROR(m, "mv 1", "invalid mode");
}

static void test_mc_starts_torque_by_the_preset_mode(void **state)
{
    (void)state;
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
    ASSERT_SILENT(m, "ms 1 0.5 0 6");
    ASSERT_ERROR(m, "mc 1", "value out of range");
    ASSERT_SILENT(m, "ms 1 0.5 0 5");
    ASSERT_ERROR(m, "mc 1", "invalid mode");
}

static void test_ms_stores_only_finite_values_and_makes_no_hal_call(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 1 2 3");
    ASSERT_SILENT(m, "ms 0 1 2 3");
    ASSERT_ERROR(m, "ms 1 1e39 2 3", "value out of range");
    ASSERT_ERROR(m, "ms 1 1 nan 3", "invalid value");
    ASSERT_ERROR(m, "ms 1 1 2", "invalid command format");
}

static void test_a_later_ms_replaces_the_preset(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_SILENT(m, "ms 1 20 0 6");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    ASSERT_MOVE_EQUALS(m, mv, {F, GR, 20, 0, 0, 6, 0, 0});
}

static void test_a_preset_for_another_drive_is_not_stored(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 2 10 0 5");
    ASSERT_ERROR(m, "mt 1 0", "no preset");
    ASSERT_SILENT(m, "mt 0 0");
}

/* ---- system commands ---- */

static void test_system_commands_make_their_action(void **state)
{
    (void)state;
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

static void test_reboot_clears_the_preset(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_ACTION(m, "sr 1", DARAN_ACTION_REBOOT);
    ASSERT_ERROR(m, "mt 1 0", "no preset");
}

/* ---- vendor recordings ---- */

static int line_motor_id(const char *line)
{
    char word[8] = "", second[80] = "";
    if (sscanf(line, "%7s %79s", word, second) < 2)
        return -1;
    if (word[0] == 'r' || word[0] == 'w') {
        if (strncmp(second, "axis", 4) == 0)
            return second[4] - '0';
        return 1; /* the recordings send their system reads with id 1 */
    }
    int id = -1;
    sscanf(second, "%d", &id);
    return id;
}

static void replay(const char *const *lines, size_t n)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 1.25f;
    for (size_t i = 0; i < n; i++) {
        mock_send_line(m, lines[i]);
        mock_check(strstr(m->out, "error") == NULL, m, __FILE__, __LINE__,
                   "recording line %zu answered an error", i);
        int id = line_motor_id(lines[i]);
        if (id == 2 || id == 3) {
            mock_check(m->out_len == 0 && m->n_calls == 0, m, __FILE__, __LINE__,
                       "a line for drive %d must be silent and have no effect here", id);
        }
        char word[8] = "";
        sscanf(lines[i], "%7s", word);
        bool query = strchr("rfgie", word[0]) != NULL && word[1] == '\0';
        if (query && id != 2 && id != 3)
            mock_check(m->n_writes == 1, m, __FILE__, __LINE__, "a read answers one line");
        if (!query)
            mock_check(m->out_len == 0, m, __FILE__, __LINE__, "a command is silent on success");
    }
}

static void test_every_line_of_the_vendor_python_recording_is_accepted(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    replay(recording_python, sizeof recording_python / sizeof recording_python[0]);
}

static void test_every_line_of_the_vendor_stm32_recording_is_accepted(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    replay(recording_stm32, sizeof recording_stm32 / sizeof recording_stm32[0]);
}

static void test_vendor_python_id_discovery_read_answers_the_id(void **state)
{
    (void)state;
    mock_t *m = mock_new_id(7);
    assert_string_equal(ASSERT_QUERY(m, "r axis0.config.can_node_id "), "7\n");
    char want[32];
    mock_reply_line(want, sizeof want, "7", true);
    assert_string_equal(ASSERT_QUERY(m, "r axis0.config.can_node_id *42"), want);
}

int main(void)
{
    static mock_suite_t s;
#define ADD(fn) mock_suite_add(&s, fn, NULL, #fn)
    for (size_t i = 0; i < sizeof examples / sizeof examples[0]; i++)
        mock_suite_add(&s, example_case, (void *)(uintptr_t)&examples[i],
                       "test_worked_example_\"%s\"_on_drive_%u_is_accepted", examples[i].line,
                       (unsigned)examples[i].id);
    ADD(test_omitted_optional_values_are_not_given);
    ADD(test_torque_mode_2_is_taken_as_a_ramp);
    ADD(test_motion_ranges_are_checked);
    ADD(test_spec_mq_example_moves_each_drive_to_arrive_together);
    ADD(test_mq_absolute_uses_the_distance_from_the_setpoint);
    ADD(test_infeasible_mq_is_refused_with_no_motion);
    ADD(test_mq_within_the_1e4_shortfall_runs_the_exact_triangle);
    ADD(test_mq_with_the_vendor_17_digit_minimum_duration_is_accepted);
    ADD(test_mq_with_zero_distance_is_accepted);
    ADD(test_mq_duration_and_accel_must_be_positive);
    ADD(test_mt_starts_a_filtered_move_with_the_preset_bandwidth);
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
    ADD(test_vendor_python_id_discovery_read_answers_the_id);
    return mock_suite_run(&s, "commands");
}
