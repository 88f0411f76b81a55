/* Unit tests of error answers: every phrase of spec section 8 reached with
 * no HAL setter/move/action, the check order of section 8 (a line with
 * several faults answers the first), and HAL fault injection (D26). */
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"

/* ---- every phrase, one case each ---- */

typedef struct phrase_case {
    const char *phrase;
    const char *setup[3]; /* lines sent first (their effects are allowed) */
    uint32_t flags;       /* axis0.error before the line */
    uint32_t state;       /* current_state before the line (0: leave) */
    const char *line;
} phrase_case_t;

static char long_line[DARAN_LINE_MAX + 40];

static const phrase_case_t phrase_cases[] = {
    {"unknown command", {NULL}, 0, 0, "x 1"},
    {"invalid command format", {NULL}, 0, 0, "f"},
    {"invalid command format", {NULL}, 0, 0, "t 1 1 2 3 4"},
    {"invalid motor", {NULL}, 0, 0, "f 64"},
    {"invalid motor", {NULL}, 0, 0, "r axis99.output_shaft.input_pos"},
    {"invalid value", {NULL}, 0, 0, "t 1 abc"},
    {"value out of range", {NULL}, 0, 0, "t 1 10 0 0"},
    {"value out of range", {NULL}, 0, 0, "w axis1.output_shaft.vel_limit 0"},
    {"invalid mode", {NULL}, 0, 0, "v 1 20 0 7"},
    {"invalid mode", {NULL}, 0, 0, "mq 1 5"},
    {"invalid property", {NULL}, 0, 0, "r axis1.nope"},
    {"invalid property", {NULL}, 0, 0, "w nope 1 1"},
    {"read only property", {NULL}, 0, 0, "w vbus_voltage 5"},
    {"read only property", {NULL}, 0, 0, "w axis1.output_shaft.pos_estimate 5"},
    {"invalid checksum", {NULL}, 0, 0, "t 1 10 *x"},
    {"line too long", {NULL}, 0, 0, long_line},
    {"invalid character", {NULL}, 0, 0, "t 1 10\x01"},
    {"no preset", {NULL}, 0, 0, "mq 1 1"},
    {"trajectory infeasible", {"ms 1 100 1 1", NULL}, 0, 0, "mq 1 0"},
    {"estop active", {"st 1", NULL}, 0, 0, "t 1 10"},
    {"estop active", {NULL}, DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, "v 1 10"},
    {"motor fault", {NULL}, DARAN_FLAG_MOTOR_OVERTEMP, DARAN_STATE_IDLE, "c 1 1"},
    {"motor idle", {"w axis1.requested_state 1", NULL}, 0, 0, "t 1 10"},
    {"motor idle", {NULL}, 0, DARAN_STATE_IDLE, "q 1 10"},
};

static void phrase_case_run(void **state)
{
    const phrase_case_t *c = *state;
    SKIP_LINE_IF_NO_MULTI(c->line);
    if (c->setup[0])
        SKIP_LINE_IF_NO_MULTI(c->setup[0]);
    mock_t *m = mock_new();
    for (size_t i = 0; i < 3 && c->setup[i]; i++) {
        mock_send_line(m, c->setup[i]);
        ASSERT_REPLY(m, "");
    }
    if (c->flags)
        m->props[DARAN_PROP_AXIS_ERROR].u32 = c->flags;
    if (c->state)
        m->props[DARAN_PROP_CURRENT_STATE].u32 = c->state;
    ASSERT_ERROR(m, c->line, c->phrase);
    /* the drive still works afterwards */
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_checksum_mismatch_has_no_effect(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "t 1 10 *1");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

static void test_error_phrases_contain_no_digits(void **state)
{
    (void)state;
    for (int r = 1; r < DARAN_RESULT_COUNT; r++) {
        const char *p = daran_result_phrase((daran_result_t)r);
        assert_non_null(p);
        for (const char *q = p; *q; q++)
            assert_false(*q >= '0' && *q <= '9');
    }
}

/* ---- check order: the first fault answers ---- */

typedef struct order_case {
    const char *why;
    const char *line;
    const char *phrase; /* NULL: silence */
    uint32_t flags;
    uint32_t state;
    bool preset;
} order_case_t;

static char long_bad_line[DARAN_LINE_MAX + 40];

static const order_case_t order_cases[] = {
    {"too_long_before_invalid_character", long_bad_line, "line too long", 0, 0, false},
    {"invalid_character_before_checksum", "x\x02 1 *zz", "invalid character", 0, 0, false},
    {"invalid_checksum_before_unknown_command", "x 1 *zz", "invalid checksum", 0, 0, false},
    {"invalid_checksum_before_another_id", "t 9 10 *1000", "invalid checksum", 0, 0, false},
    {"unknown_command_before_invalid_motor", "x 99", "unknown command", 0, 0, false},
    {"unknown_command_before_format", "qq 1 2 3 4 5 6 7", "unknown command", 0, 0, false},
    {"missing_motor_is_a_format_error", "t", "invalid command format", 0, 0, false},
    {"invalid_motor_before_format", "f 99 1 2", "invalid motor", 0, 0, false},
    {"invalid_motor_before_values", "t 1.5 abc", "invalid motor", 0, 0, false},
    {"another_id_is_silent_before_format", "t 5 1 2 3 4 5 6", NULL, 0, 0, false},
    {"another_id_is_silent_before_values", "t 5 abc", NULL, 0, 0, false},
    {"another_id_is_silent_before_state", "t 5 10", NULL, DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"another_axis_id_is_silent_before_property", "r axis5.nope", NULL, 0, 0, false},
    {"another_axis_id_is_silent_before_trailing_id", "r axis5.output_shaft.input_pos 1", NULL, 0, 0, false},
    {"axis_trailing_id_is_a_format_error", "r axis1.output_shaft.input_pos 1", "invalid command format", 0, 0, false},
    {"format_before_values", "t 1 abc 1 2 3", "invalid command format", 0, 0, false},
    {"format_before_property", "r nope 1 2", "invalid command format", 0, 0, false},
    {"property_before_value", "w axis1.nope abc", "invalid property", 0, 0, false},
    {"read_only_before_value", "w vbus_voltage abc 1", "read only property", 0, 0, false},
    {"invalid_value_before_range", "t 1 abc 0 0", "invalid value", 0, 0, false},
    {"first_value_first", "t 1 1e39 0 x", "value out of range", 0, 0, false},
    {"value_before_mode", "v 1 x 0 7", "invalid value", 0, 0, false},
    {"mode_before_its_ramp_range", "v 1 20 0 7", "invalid mode", 0, 0, false},
    {"ramp_range_after_mode", "v 1 20 0 2", "value out of range", 0, 0, false},
    {"param_value_before_mode", "v 1 20 x 7", "invalid value", 0, 0, false},
    {"values_before_estop", "t 1 abc", "invalid value", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"range_before_estop", "t 1 10 0 0", "value out of range", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"estop_before_motor_fault", "t 1 10", "estop active",
     DARAN_FLAG_ESTOP | DARAN_FLAG_MOTOR_OVERTEMP, DARAN_STATE_IDLE, false},
    {"motor_fault_before_idle", "t 1 10", "motor fault", DARAN_FLAG_WATCHDOG, DARAN_STATE_IDLE, false},
    {"estop_before_no_preset", "mq 1 1", "estop active", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"fault_before_no_preset", "mt 1 0", "motor fault", DARAN_FLAG_UNDERVOLTAGE, DARAN_STATE_IDLE, false},
    {"idle_before_no_preset", "mp 1 0", "motor idle", 0, DARAN_STATE_IDLE, false},
    {"idle_before_infeasible", "mq 1 0", "motor idle", 0, DARAN_STATE_IDLE, true},
    {"estop_before_infeasible", "mq 1 0", "estop active", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, true},
};

static void order_case_run(void **state)
{
    const order_case_t *c = *state;
    SKIP_LINE_IF_NO_MULTI(c->line);
    mock_t *m = mock_new();
    if (c->preset) {
        mock_send_line(m, "ms 1 100 1 1"); /* an infeasible mq */
        ASSERT_REPLY(m, "");
    }
    if (c->flags)
        m->props[DARAN_PROP_AXIS_ERROR].u32 = c->flags;
    if (c->state)
        m->props[DARAN_PROP_CURRENT_STATE].u32 = c->state;
    if (c->phrase)
        ASSERT_ERROR(m, c->line, c->phrase);
    else
        ASSERT_SILENT(m, c->line);
}

static void test_checksum_mismatch_before_unknown_command(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "x 1 *0");
    ASSERT_REPLY(m, want);
    mock_send_line(m, "t 99 abc *0");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

/* ---- HAL fault injection (D26) ---- */

static const char *expected_phrase(daran_result_t r)
{
    /* a HAL result is answered as such; API misuse and unknown values are a motor fault */
    if (r <= DARAN_OK || r >= DARAN_ERR_BAD_ARGUMENT)
        return "motor fault";
    return daran_result_phrase(r);
}

static const daran_result_t injected[] = {
    DARAN_ERR_UNKNOWN_COMMAND,   DARAN_ERR_INVALID_FORMAT,        DARAN_ERR_INVALID_MOTOR,
    DARAN_ERR_INVALID_VALUE,     DARAN_ERR_OUT_OF_RANGE,          DARAN_ERR_INVALID_MODE,
    DARAN_ERR_INVALID_PROPERTY,  DARAN_ERR_READ_ONLY,             DARAN_ERR_INVALID_CHECKSUM,
    DARAN_ERR_CHECKSUM_MISMATCH, DARAN_ERR_LINE_TOO_LONG,         DARAN_ERR_INVALID_CHARACTER,
    DARAN_ERR_NO_PRESET,         DARAN_ERR_TRAJECTORY_INFEASIBLE, DARAN_ERR_ESTOP_ACTIVE,
    DARAN_ERR_MOTOR_FAULT,       DARAN_ERR_MOTOR_IDLE,            DARAN_ERR_BAD_ARGUMENT,
    (daran_result_t)DARAN_RESULT_COUNT, (daran_result_t)1000,
};

static void assert_hal_failure_answered(mock_t *m, const char *line, daran_result_t r)
{
    char want[80];
    snprintf(want, sizeof want, "error: %s\n", expected_phrase(r));
    mock_send_line(m, line);
    mock_check(strcmp(m->out, want) == 0, m, __FILE__, __LINE__,
               "HAL result %d: expected \"%s\"", (int)r, mock_escape(want, strlen(want)));
    /* the failing call was the only one: no watchdog feed for a refused move */
    mock_check(m->n_calls == 1, m, __FILE__, __LINE__, "expected only the failing call, got %zu",
               m->n_calls);
}

static void hal_fault_case(void **state)
{
    daran_result_t r = *(const daran_result_t *)*state;
    mock_t *m = mock_new();

    mock_fail(m, MOCK_FAIL_MOVE, 1, r, -1);
    assert_hal_failure_answered(m, "t 1 10 0 25", r);
    ASSERT_MOVE(m, "t 1 10 0 25");

    mock_fail(m, MOCK_FAIL_SET, 1, r, -1);
    assert_hal_failure_answered(m, "w axis1.controller.config.pos_gain 5", r);
    (void)ASSERT_SET(m, "w axis1.controller.config.pos_gain 5", DARAN_PROP_POS_GAIN);

    mock_fail(m, MOCK_FAIL_ACTION, 1, r, -1);
    assert_hal_failure_answered(m, "ss 1", r);
    ASSERT_ACTION(m, "ss 1", DARAN_ACTION_SAVE_CONFIG);

    mock_fail(m, MOCK_FAIL_GET, 1, r, DARAN_PROP_VBUS_VOLTAGE);
    char want[80];
    snprintf(want, sizeof want, "error: %s\n", expected_phrase(r));
    mock_send_line(m, "r vbus_voltage 1");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
    assert_string_equal(ASSERT_QUERY(m, "r vbus_voltage 1"), "24\n");
}

static void test_failed_getter_of_a_query_answers_that_error(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_POS_ESTIMATE);
    ASSERT_ERROR(m, "f 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_IQ_MEASURED);
    ASSERT_ERROR(m, "g 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_AXIS_ERROR);
    ASSERT_ERROR(m, "e 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_SERIAL_NUMBER);
    ASSERT_ERROR(m, "i 1", "motor fault");
    assert_string_equal(ASSERT_QUERY(m, "f 1"), "0 0\n");
}

static void test_failed_state_getter_refuses_motion(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_AXIS_ERROR);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_CURRENT_STATE);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    ASSERT_MOVE(m, "t 1 10");
}

static void test_failed_node_id_getter_is_answered_as_that_error(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_CAN_NODE_ID);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    ASSERT_MOVE(m, "t 1 10");
}

static void test_relative_target_beyond_float_range_is_refused(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 3e38f;
    ASSERT_SILENT(m, "ms 1 3e38 0 5");
    ASSERT_ERROR(m, "mt 1 1", "value out of range");
    ASSERT_SILENT(m, "ms 1 3e38 0 0");
    ASSERT_ERROR(m, "mp 1 1", "value out of range");
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_MOVE(m, "mp 1 1");
}

static void test_failed_setpoint_getter_refuses_a_relative_start(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_POS_SETPOINT);
    ASSERT_ERROR(m, "mt 1 1", "motor fault");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 1");
    assert_true(mv->pos_deg == 10.0f);
}

static void test_refused_start_after_hal_failure_keeps_the_preset(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mock_fail(m, MOCK_FAIL_MOVE, 1, DARAN_ERR_MOTOR_FAULT, -1);
    mock_send_line(m, "mt 1 0");
    ASSERT_REPLY(m, "error: motor fault\n");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    assert_true(mv->pos_deg == 10.0f);
}

int main(void)
{
    static mock_suite_t s;
#define ADD(fn) mock_suite_add(&s, fn, NULL, #fn)
    memset(long_line, ' ', DARAN_LINE_MAX + 10);
    memcpy(long_line, "t 1 10", 6);
    long_line[DARAN_LINE_MAX + 10] = '\0';
    memset(long_bad_line, ' ', DARAN_LINE_MAX + 10);
    memcpy(long_bad_line, "x\x01 1 *zz", 8);
    long_bad_line[DARAN_LINE_MAX + 10] = '\0';
    for (size_t i = 0; i < sizeof phrase_cases / sizeof phrase_cases[0]; i++)
        mock_suite_add(&s, phrase_case_run, (void *)(uintptr_t)&phrase_cases[i],
                       "test_error_%s_case_%zu_has_no_effect", phrase_cases[i].phrase, i);
    ADD(test_checksum_mismatch_has_no_effect);
    ADD(test_error_phrases_contain_no_digits);
    for (size_t i = 0; i < sizeof order_cases / sizeof order_cases[0]; i++)
        mock_suite_add(&s, order_case_run, (void *)(uintptr_t)&order_cases[i],
                       "test_check_order_%s", order_cases[i].why);
    ADD(test_checksum_mismatch_before_unknown_command);
    for (size_t i = 0; i < sizeof injected / sizeof injected[0]; i++)
        mock_suite_add(&s, hal_fault_case, (void *)(uintptr_t)&injected[i],
                       "test_hal_result_%d_is_answered_as_%s_and_the_next_line_works",
                       (int)injected[i], expected_phrase(injected[i]));
    ADD(test_failed_getter_of_a_query_answers_that_error);
    ADD(test_failed_state_getter_refuses_motion);
    ADD(test_failed_node_id_getter_is_answered_as_that_error);
    ADD(test_relative_target_beyond_float_range_is_refused);
    ADD(test_failed_setpoint_getter_refuses_a_relative_start);
    ADD(test_refused_start_after_hal_failure_keeps_the_preset);
    return mock_suite_run(&s, "errors");
}
