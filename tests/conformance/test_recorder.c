/* The recording HAL (testkit/include/daran_recorder.h) and its Unity
 * assertions (daran_recorder_unity.h): the store double keeps the HAL
 * contract's bookkeeping, every call is logged with its arguments and
 * result, an inner HAL sees exactly the calls the core made, fault
 * injection hits the Nth call, replies are captured, descriptions read as
 * the conformance suite prints them, and each assertion fails when it
 * should. */
#include <string.h>

#include "unity.h"

#include "daran_recorder_unity.h"

/* Unity 2.4 has no size_t assertion */
#define ASSERT_SIZE(expected, actual) TEST_ASSERT_EQUAL_UINT64((uint64_t)(expected), (uint64_t)(actual))

static daran_recorder_t rec;
static daran_recorder_t inner;
static daran_drive_t drive;

void setUp(void)
{
    daran_recorder_init_store(&rec, 1);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive, &daran_recorder_hal, &rec));
}

void tearDown(void)
{
}

static void send(const char *line)
{
    daran_recorder_clear(&rec);
    (void)daran_process_line(&drive, line, strlen(line));
}

/* Run @p check, which must fail its assertion; Unity prints that failure
 * (announced first), and the test goes on. */
static void expect_assertion_failure(void (*check)(void), const char *what)
{
    UnityPrint("(an expected failure of ");
    UnityPrint(what);
    UnityPrint(" follows)");
    UNITY_PRINT_EOL();
    if (TEST_PROTECT()) {
        check();
    }
    bool failed = Unity.CurrentTestFailed != 0;
    Unity.CurrentTestFailed = 0;
    TEST_ASSERT_TRUE_MESSAGE(failed, what);
}

static void test_the_store_double_serves_node_id_and_closed_loop(void)
{
    daran_recorder_init_store(&rec, 7);
    TEST_ASSERT_EQUAL_UINT32(7, rec.store[DARAN_PROP_CAN_NODE_ID].u32);
    TEST_ASSERT_EQUAL_UINT32(DARAN_STATE_CLOSED_LOOP, rec.store[DARAN_PROP_CURRENT_STATE].u32);
    TEST_ASSERT_EQUAL_UINT32(DARAN_STATE_CLOSED_LOOP, rec.store[DARAN_PROP_REQUESTED_STATE].u32);
    TEST_ASSERT_NULL(rec.inner);
    TEST_ASSERT_EQUAL_INT(-1, rec.fail_prop);
}

static void test_a_write_is_one_logged_set_and_reads_back(void)
{
    send("w axis1.controller.config.pos_gain 20.5");
    TEST_ASSERT_DARAN_SET_F32(&rec, DARAN_PROP_POS_GAIN, 20.5f);
    TEST_ASSERT_DARAN_REPLY(&rec, "");
    ASSERT_SIZE(1, rec.n_mutations);
    send("r axis1.controller.config.pos_gain");
    TEST_ASSERT_DARAN_REPLY(&rec, "20.5\n");
    TEST_ASSERT_DARAN_NO_EFFECT(&rec);
    TEST_ASSERT_TRUE(rec.n_gets >= 2u); /* the id, then the value */
    ASSERT_SIZE(0, rec.n_calls); /* gets are counted, not logged, by default */
}

static void test_integer_writes_carry_their_type(void)
{
    send("w axis1.motor.config.direction -1");
    TEST_ASSERT_DARAN_SET_S32(&rec, DARAN_PROP_MOTOR_DIRECTION, -1);
    send("w config.uart_baudrate 9600 1");
    TEST_ASSERT_DARAN_SET_U32(&rec, DARAN_PROP_UART_BAUDRATE, 9600u);
    daran_value_t value = TEST_ASSERT_DARAN_SET(&rec, DARAN_PROP_UART_BAUDRATE);
    TEST_ASSERT_EQUAL_UINT32(9600u, value.u32);
}

static void test_the_store_keeps_the_move_targets_and_rates(void)
{
    send("q 1 90 120 60");
    const daran_move_t *move = TEST_ASSERT_DARAN_MOVE(&rec, DARAN_MOVE_TRAPEZOID);
    TEST_ASSERT_EQUAL_FLOAT(90.0f, move->pos_deg);
    TEST_ASSERT_EQUAL_UINT8(DARAN_GIVEN_VEL | DARAN_GIVEN_RATE, move->given);
    ASSERT_SIZE(1, daran_recorder_count(&rec, DARAN_CALL_ACTION, DARAN_ACTION_FEED_WATCHDOG));
    TEST_ASSERT_EQUAL_FLOAT(90.0f, rec.store[DARAN_PROP_INPUT_POS].f32);
    TEST_ASSERT_EQUAL_FLOAT(120.0f, rec.store[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32);
    TEST_ASSERT_EQUAL_FLOAT(60.0f, rec.store[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32);
    TEST_ASSERT_EQUAL_FLOAT(60.0f, rec.store[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32);
    send("v 1 30 5 2");
    (void)TEST_ASSERT_DARAN_MOVE(&rec, DARAN_MOVE_VELOCITY_RAMP);
    TEST_ASSERT_EQUAL_FLOAT(30.0f, rec.store[DARAN_PROP_INPUT_VEL].f32);
    TEST_ASSERT_EQUAL_FLOAT(5.0f, rec.store[DARAN_PROP_VEL_RAMP_RATE].f32);
}

static void test_estop_idles_the_store_and_clear_errors_clears_it(void)
{
    send("st 1");
    TEST_ASSERT_DARAN_ACTION(&rec, DARAN_ACTION_ESTOP);
    send("t 1 10");
    TEST_ASSERT_DARAN_ERROR(&rec, "estop active");
    send("sc 1");
    TEST_ASSERT_DARAN_ACTION(&rec, DARAN_ACTION_CLEAR_ERRORS);
    send("t 1 10");
    TEST_ASSERT_DARAN_ERROR(&rec, "motor idle");
    send("w axis1.requested_state 8");
    TEST_ASSERT_DARAN_SET_U32(&rec, DARAN_PROP_REQUESTED_STATE, 8u);
    TEST_ASSERT_EQUAL_UINT32(DARAN_STATE_CLOSED_LOOP, rec.store[DARAN_PROP_CURRENT_STATE].u32);
}

static void test_an_inner_hal_sees_each_call_the_core_made(void)
{
    daran_recorder_init_store(&inner, 1);
    daran_recorder_init(&rec, &daran_recorder_hal, &inner);
    rec.log_gets = true;
    send("w axis1.controller.config.vel_gain 0.25");
    TEST_ASSERT_DARAN_SET_F32(&rec, DARAN_PROP_VEL_GAIN, 0.25f);
    TEST_ASSERT_EQUAL_FLOAT(0.25f, inner.store[DARAN_PROP_VEL_GAIN].f32);
    ASSERT_SIZE(1, inner.n_mutations);
    /* the logged get of the id carries the value the inner HAL returned */
    const daran_call_t *get = daran_recorder_first(&rec, DARAN_CALL_GET);
    TEST_ASSERT_NOT_NULL(get);
    TEST_ASSERT_EQUAL_INT(DARAN_PROP_CAN_NODE_ID, get->prop);
    TEST_ASSERT_EQUAL_UINT32(1, get->value.u32);
    ASSERT_SIZE(1, daran_recorder_count_prop(&rec, DARAN_CALL_SET, DARAN_PROP_VEL_GAIN));
}

static void test_the_nth_call_of_a_kind_fails_and_reaches_nothing(void)
{
    daran_recorder_fail(&rec, DARAN_RECORDER_FAIL_SET, 2, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_POS_GAIN);
    send("w axis1.controller.config.vel_gain 3"); /* another property: not counted */
    TEST_ASSERT_DARAN_REPLY(&rec, "");
    send("w axis1.controller.config.pos_gain 3"); /* the first of pos_gain */
    TEST_ASSERT_DARAN_REPLY(&rec, "");
    send("w axis1.controller.config.pos_gain 4"); /* the second: refused */
    TEST_ASSERT_DARAN_REPLY(&rec, "error: motor fault\n");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_MOTOR_FAULT, rec.calls[0].result);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, rec.store[DARAN_PROP_POS_GAIN].f32);
    send("w axis1.controller.config.pos_gain 5"); /* one shot */
    TEST_ASSERT_DARAN_SET_F32(&rec, DARAN_PROP_POS_GAIN, 5.0f);
}

static void test_a_failing_get_answers_its_error(void)
{
    daran_recorder_fail(&rec, DARAN_RECORDER_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_VBUS_VOLTAGE);
    send("r vbus_voltage 1");
    TEST_ASSERT_DARAN_ERROR(&rec, "motor fault");
}

static void test_replies_beyond_the_buffer_are_counted_not_kept(void)
{
    daran_recorder_clear(&rec);
    char line[64];
    memset(line, 'x', sizeof line);
    for (size_t i = 0; i < DARAN_RECORDER_OUT_MAX / sizeof line + 2u; i++) {
        daran_recorder_write(&rec, line, sizeof line);
    }
    ASSERT_SIZE(DARAN_RECORDER_OUT_MAX, rec.out_len);
    ASSERT_SIZE(2u * sizeof line, rec.out_dropped);
    TEST_ASSERT_EQUAL_INT('\0', rec.out[rec.out_len]);
    TEST_ASSERT_FALSE(daran_recorder_reply_equals(&rec, ""));
}

static void test_calls_beyond_the_log_are_counted_not_kept(void)
{
    daran_recorder_clear(&rec);
    for (size_t i = 0; i < DARAN_RECORDER_CALLS_MAX + 3u; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_recorder_hal.action(&rec, DARAN_ACTION_FEED_WATCHDOG));
    }
    ASSERT_SIZE(DARAN_RECORDER_CALLS_MAX, rec.n_calls);
    ASSERT_SIZE(3, rec.n_dropped);
    ASSERT_SIZE(DARAN_RECORDER_CALLS_MAX + 3u, daran_recorder_mutations(&rec));
    char text[64];
    daran_recorder_clear(&rec);
    (void)daran_recorder_describe(&rec, text, sizeof text);
    TEST_ASSERT_EQUAL_STRING("none", text);
}

static void test_calls_read_as_the_report_prints_them(void)
{
    char text[256];
    send("w axis1.controller.config.pos_gain 20");
    (void)daran_call_describe(&rec.calls[0], text, sizeof text);
    TEST_ASSERT_EQUAL_STRING("set axis0.controller.config.pos_gain 20 -> ok", text);
    send("t 1 10 0 25");
    (void)daran_recorder_describe(&rec, text, sizeof text);
    TEST_ASSERT_EQUAL_STRING("move FILTERED_POSITION pos 10 rate 25 given rate -> ok\n"
                             "action FEED_WATCHDOG -> ok", text);
    rec.log_gets = true;
    send("r vbus_voltage 1");
    (void)daran_call_describe(&rec.calls[1], text, sizeof text);
    TEST_ASSERT_EQUAL_STRING("get vbus_voltage -> 0", text);
    /* cut to the buffer, the full length returned */
    size_t full = daran_call_describe(&rec.calls[1], text, 8);
    TEST_ASSERT_EQUAL_STRING("get vbu", text);
    ASSERT_SIZE(strlen("get vbus_voltage -> 0"), full);
    ASSERT_SIZE(11, daran_recorder_prop_path(DARAN_PROP_AXIS_ERROR, text, sizeof text));
    TEST_ASSERT_EQUAL_STRING("axis0.error", text);
    TEST_ASSERT_EQUAL_STRING("?", daran_recorder_action_name((daran_action_t)99));
}

static void check_no_effect_after_a_write(void)
{
    send("w axis1.controller.config.pos_gain 2");
    TEST_ASSERT_DARAN_NO_EFFECT(&rec);
}

static void check_wrong_value(void)
{
    send("w axis1.controller.config.pos_gain 2");
    TEST_ASSERT_DARAN_SET_F32(&rec, DARAN_PROP_POS_GAIN, 3.0f);
}

static void check_wrong_move_kind(void)
{
    send("t 1 10");
    (void)TEST_ASSERT_DARAN_MOVE(&rec, DARAN_MOVE_TRAPEZOID);
}

static void check_error_that_was_not(void)
{
    send("t 1 10");
    TEST_ASSERT_DARAN_ERROR(&rec, "motor idle");
}

static void check_wrong_reply(void)
{
    send("r vbus_voltage 1");
    TEST_ASSERT_DARAN_REPLY(&rec, "1\n");
}

static void test_each_assertion_fails_when_it_should(void)
{
    expect_assertion_failure(check_no_effect_after_a_write, "TEST_ASSERT_DARAN_NO_EFFECT");
    expect_assertion_failure(check_wrong_value, "TEST_ASSERT_DARAN_SET_F32");
    expect_assertion_failure(check_wrong_move_kind, "TEST_ASSERT_DARAN_MOVE");
    expect_assertion_failure(check_error_that_was_not, "TEST_ASSERT_DARAN_ERROR");
    expect_assertion_failure(check_wrong_reply, "TEST_ASSERT_DARAN_REPLY");
}

static void test_an_error_with_a_checksum_tail_is_that_error(void)
{
    send("t 1 10 *1");
    TEST_ASSERT_DARAN_ERROR(&rec, "checksum mismatch");
}

/* The one escaper of the test kit's reports (Unity assertions, conformance
 * and fuzz reports, the unit tests' mock). */
static void test_escape_writes_a_c_literal_body_and_marks_a_cut(void)
{
    char buf[64];
    TEST_ASSERT_EQUAL_STRING("t 1 \\\\\\\"x\\\" \\t\\r\\n\\x01\\xFF",
                             daran_recorder_escape("t 1 \\\"x\" \t\r\n\x01\xff", 14, buf, sizeof buf));
    TEST_ASSERT_EQUAL_STRING("", daran_recorder_escape("abc", 0, buf, sizeof buf));
    char small[10];
    TEST_ASSERT_EQUAL_STRING("abcdef...", daran_recorder_escape("abcdefghijklmnop", 16, small, sizeof small));
    TEST_ASSERT_EQUAL_STRING("abcdef", daran_recorder_escape("abcdef", 6, small, sizeof small));
    /* a cut never splits an escape */
    TEST_ASSERT_EQUAL_STRING("\\x01...", daran_recorder_escape("\x01\x02\x03", 3, small, sizeof small));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_store_double_serves_node_id_and_closed_loop);
    RUN_TEST(test_a_write_is_one_logged_set_and_reads_back);
    RUN_TEST(test_integer_writes_carry_their_type);
    RUN_TEST(test_the_store_keeps_the_move_targets_and_rates);
    RUN_TEST(test_estop_idles_the_store_and_clear_errors_clears_it);
    RUN_TEST(test_an_inner_hal_sees_each_call_the_core_made);
    RUN_TEST(test_the_nth_call_of_a_kind_fails_and_reaches_nothing);
    RUN_TEST(test_a_failing_get_answers_its_error);
    RUN_TEST(test_replies_beyond_the_buffer_are_counted_not_kept);
    RUN_TEST(test_calls_beyond_the_log_are_counted_not_kept);
    RUN_TEST(test_calls_read_as_the_report_prints_them);
    RUN_TEST(test_each_assertion_fails_when_it_should);
    RUN_TEST(test_an_error_with_a_checksum_tail_is_that_error);
    RUN_TEST(test_escape_writes_a_c_literal_body_and_marks_a_cut);
    return UNITY_END();
}
