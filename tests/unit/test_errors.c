/* Unit tests of error answers: every phrase of spec section 8 reached with
 * no HAL setter/move/action, the check order of section 8 (a line with
 * several faults answers the first), and HAL fault injection (D26). */
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
    {"invalid value", {NULL}, 0, 0, "w axis1.motor.config.direction -1.5"},
    {"value out of range", {NULL}, 0, 0, "t 1 10 0 -1"},
    {"value out of range", {NULL}, 0, 0, "q 1 10 0 5"},
    {"value out of range", {NULL}, 0, 0, "w axis1.error 1"},
    {"value out of range", {NULL}, 0, 0, "w axis1.motor.config.direction 0"},
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
    /* 10.5: 100 deg in 0.03 s peaks at 1,111 r/min, beyond the 600 of vel_limit */
    {"trajectory infeasible", {"ms 1 100 0.03 1", NULL}, 0, 0, "mq 1 0"},
    {"trajectory infeasible", {"ms 1 100 0 10", NULL}, 0, 0, "mq 1 0"},
    {"trajectory infeasible", {"ms 1 100 2 0", NULL}, 0, 0, "mq 1 1"},
#if DARAN_ENABLE_S_CURVE
    /* 10.5: 90 deg in 0.04 s peaks at 750 r/min, beyond the 600 of vel_limit */
    {"trajectory infeasible", {"w axis1.trap_traj.config.traj_mode 2", "ms 1 90 0.04 60", NULL},
     0, 0, "mq 1 0"},
#endif
    {"estop active", {"st 1", NULL}, 0, 0, "t 1 10"},
    {"estop active", {NULL}, DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, "v 1 10"},
    {"motor fault", {NULL}, DARAN_FLAG_OVERTEMP, DARAN_STATE_IDLE, "c 1 1"},
    {"motor fault", {NULL}, 1u << 0, DARAN_STATE_CLOSED_LOOP, "t 1 10"},
    {"motor idle", {"w axis1.requested_state 1", NULL}, 0, 0, "t 1 10"},
    {"motor idle", {NULL}, 0, DARAN_STATE_IDLE, "q 1 10"},
};

static void phrase_case_run(const void *row_arg)
{
    const phrase_case_t *c = row_arg;
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

static void test_checksum_mismatch_has_no_effect(void)
{
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "t 1 10 *1");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

static void test_error_phrases_contain_no_digits(void)
{
    for (int r = 1; r < DARAN_RESULT_COUNT; r++) {
        const char *p = daran_result_phrase((daran_result_t)r);
        TEST_ASSERT_NOT_NULL(p);
        for (const char *q = p; *q; q++) {
            TEST_ASSERT_FALSE(*q >= '0' && *q <= '9');
        }
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
    {"axis_id_before_property", "r axis99.nope", "invalid motor", 0, 0, false},
    {"axis_id_before_format", "w axis99.nope", "invalid motor", 0, 0, false},
    {"format_before_unknown_property", "w axis1.nope", "invalid command format", 0, 0, false},
    {"axis_trailing_id_is_a_format_error", "r axis1.output_shaft.input_pos 1", "invalid command format", 0, 0, false},
    {"format_before_values", "t 1 abc 1 2 3", "invalid command format", 0, 0, false},
    {"format_before_property", "r nope 1 2", "invalid command format", 0, 0, false},
    {"property_before_value", "w axis1.nope abc", "invalid property", 0, 0, false},
    {"read_only_before_value", "w vbus_voltage abc 1", "read only property", 0, 0, false},
    {"invalid_value_before_range", "t 1 abc 0 0", "invalid value", 0, 0, false},
    {"first_value_first", "t 1 1e39 0 x", "value out of range", 0, 0, false},
    {"value_before_mode", "v 1 x 0 7", "invalid value", 0, 0, false},
    {"mode_before_its_ramp_range", "v 1 20 0 7", "invalid mode", 0, 0, false},
    {"ramp_range_after_mode", "v 1 20 -1 2", "value out of range", 0, 0, false},
    {"torque_ramp_range_after_mode", "c 1 5 -1 6", "value out of range", 0, 0, false},
    {"param_value_before_mode", "v 1 20 x 7", "invalid value", 0, 0, false},
    {"values_before_estop", "t 1 abc", "invalid value", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"range_before_estop", "t 1 10 0 -1", "value out of range", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"estop_before_motor_fault", "t 1 10", "estop active",
     DARAN_FLAG_ESTOP | DARAN_FLAG_OVERTEMP, DARAN_STATE_IDLE, false},
    {"zero_rate_still_waits_for_the_state", "t 1 10 0 0", "estop active", DARAN_FLAG_ESTOP,
     DARAN_STATE_IDLE, false},
    {"read_only_before_s32_value", "w axis1.encoder.pos_abs --1", "read only property", 0, 0, false},
    {"s32_value_before_range", "w axis1.motor.config.pole_pairs -1.5", "invalid value", 0, 0, false},
    {"motor_fault_before_idle", "t 1 10", "motor fault", DARAN_FLAG_WATCHDOG, DARAN_STATE_IDLE, false},
    {"estop_before_no_preset", "mq 1 1", "estop active", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, false},
    {"fault_before_no_preset", "mt 1 0", "motor fault", DARAN_FLAG_UNDERVOLTAGE, DARAN_STATE_IDLE, false},
    {"idle_before_no_preset", "mp 1 0", "motor idle", 0, DARAN_STATE_IDLE, false},
    {"idle_before_infeasible", "mq 1 0", "motor idle", 0, DARAN_STATE_IDLE, true},
    {"estop_before_infeasible", "mq 1 0", "estop active", DARAN_FLAG_ESTOP, DARAN_STATE_IDLE, true},
};

static void order_case_run(const void *row_arg)
{
    const order_case_t *c = row_arg;
    SKIP_LINE_IF_NO_MULTI(c->line);
    mock_t *m = mock_new();
    if (c->preset) {
        mock_send_line(m, "ms 1 100 0.03 1"); /* an infeasible mq (10.5) */
        ASSERT_REPLY(m, "");
    }
    if (c->flags)
        m->props[DARAN_PROP_AXIS_ERROR].u32 = c->flags;
    if (c->state)
        m->props[DARAN_PROP_CURRENT_STATE].u32 = c->state;
    if (c->phrase) {
        ASSERT_ERROR(m, c->line, c->phrase);
    }
    else {
        ASSERT_SILENT(m, c->line);
    }
}

static void test_checksum_mismatch_before_unknown_command(void)
{
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
    if (r <= DARAN_OK || r >= DARAN_ERR_NO_REPLY)
        return "motor fault";
    return daran_result_phrase(r);
}

static const daran_result_t injected[] = {
    DARAN_ERR_UNKNOWN_COMMAND,   DARAN_ERR_INVALID_FORMAT,        DARAN_ERR_INVALID_MOTOR,
    DARAN_ERR_INVALID_VALUE,     DARAN_ERR_OUT_OF_RANGE,          DARAN_ERR_INVALID_MODE,
    DARAN_ERR_INVALID_PROPERTY,  DARAN_ERR_READ_ONLY,             DARAN_ERR_INVALID_CHECKSUM,
    DARAN_ERR_CHECKSUM_MISMATCH, DARAN_ERR_LINE_TOO_LONG,         DARAN_ERR_INVALID_CHARACTER,
    DARAN_ERR_NO_PRESET,         DARAN_ERR_TRAJECTORY_INFEASIBLE, DARAN_ERR_ESTOP_ACTIVE,
    DARAN_ERR_MOTOR_FAULT,       DARAN_ERR_MOTOR_IDLE,            DARAN_ERR_NO_REPLY,
    DARAN_ERR_BUS_ERROR,         DARAN_ERR_NOT_BRIDGED,           DARAN_ERR_BAD_ARGUMENT,
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

static void hal_fault_case(const void *row_arg)
{
    daran_result_t r = *(const daran_result_t *)row_arg;
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
    TEST_ASSERT_EQUAL_STRING("24\n", ASSERT_QUERY(m, "r vbus_voltage 1"));
}

static void test_failed_getter_of_a_query_answers_that_error(void)
{
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_POS_ESTIMATE);
    ASSERT_ERROR(m, "f 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_IQ_MEASURED);
    ASSERT_ERROR(m, "g 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_AXIS_ERROR);
    ASSERT_ERROR(m, "e 1", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_SERIAL_NUMBER);
    ASSERT_ERROR(m, "i 1", "motor fault");
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 1"));
}

static void test_failed_state_getter_refuses_motion(void)
{
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_AXIS_ERROR);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_CURRENT_STATE);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    ASSERT_MOVE(m, "t 1 10");
}

static void test_failed_node_id_getter_is_answered_as_that_error(void)
{
    mock_t *m = mock_new();
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_CAN_NODE_ID);
    ASSERT_ERROR(m, "t 1 10", "motor fault");
    ASSERT_MOVE(m, "t 1 10");
}

static void test_relative_target_beyond_float_range_is_refused(void)
{
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

static void test_failed_setpoint_getter_refuses_a_relative_start(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_POS_SETPOINT);
    ASSERT_ERROR(m, "mt 1 1", "motor fault");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 1");
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
}

static void test_refused_start_after_hal_failure_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mock_fail(m, MOCK_FAIL_MOVE, 1, DARAN_ERR_MOTOR_FAULT, -1);
    mock_send_line(m, "mt 1 0");
    ASSERT_REPLY(m, "error: motor fault\n");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
}

/* ---- random lines: invariants that hold for every line ---- */

static uint32_t lcg = 2026u;
static uint32_t pick(uint32_t n)
{
    lcg = lcg * 1103515245u + 12345u;
    return (lcg >> 16) % n;
}

static const char *const phrases[] = {
    "unknown command", "invalid command format", "invalid motor", "invalid value",
    "value out of range", "invalid mode", "invalid property", "read only property",
    "invalid checksum", "checksum mismatch", "line too long", "invalid character", "no preset",
    "trajectory infeasible", "estop active", "motor fault", "motor idle",
    "updating", "not idle", "no update", "bad image",
    "no reply", "bus error", "not bridged",
};

static bool known_phrase(const char *p, size_t len)
{
    for (size_t i = 0; i < sizeof phrases / sizeof phrases[0]; i++)
        if (strlen(phrases[i]) == len && memcmp(p, phrases[i], len) == 0)
            return true;
    return false;
}

typedef struct rword { const char *word; int min, max; } rword_t;

static void random_line(char *line, size_t size, int *cks)
{
    /* words with their value counts after the id (r/w: after the path) */
    static const rword_t words[] = {
        {"t", 1, 3}, {"q", 1, 3}, {"p", 1, 3}, {"v", 1, 3}, {"c", 1, 3}, {"d", 5, 5},
        {"ms", 3, 3}, {"mt", 1, 1}, {"mq", 1, 1}, {"mp", 1, 1}, {"mv", 0, 0}, {"mc", 0, 0},
        {"r", 0, 1}, {"w", 1, 2}, {"ss", 0, 0}, {"se", 0, 0}, {"sr", 0, 0}, {"sc", 0, 0},
        {"sz", 0, 0}, {"st", 0, 0}, {"h", 0, 0}, {"f", 0, 0}, {"g", 0, 0}, {"i", 0, 0},
        {"e", 0, 0}, {"u", 0, 0}, {"T", 1, 3}, {"MQ", 1, 1}, {"x", 0, 2}, {"m", 0, 1}};
    static const char *const ids[] = {"1", "1", "1", "0", "0", "2", "63", "64", "-1",
                                      "1.5", "x", "01", "1.0"};
    static const char *const good[] = {"0", "1", "2", "6", "10", "0.5", "25", "5.0", "120",
                                       "-100", "0.02", "1", "8"};
    static const char *const bad[] = {"-1", "-0", "1e39", "1e-45", "abc", ".", "3.5", "nan",
                                      "115200", "9600", "7", "0"};
    static const char *const paths[] = {
        "axis1.output_shaft.input_pos", "axis0.config.can_node_id", "config.uart_baudrate",
        "vbus_voltage", "axis1.requested_state", "axis1.controller.config.pos_gain",
        "axis2.error", "axis1.nope", "axis64.x", "serial_number",
        "axis1.controller.trajectory_done", "axis1.config.enable_watchdog"};
    char payload[160];
    size_t k = 0;
    const rword_t *w = &words[pick(sizeof words / sizeof words[0])];
    k += (size_t)snprintf(payload + k, sizeof payload - k, "%s%s", pick(4) ? "" : " ", w->word);
    bool rw = (w->word[0] == 'r' || w->word[0] == 'w') && w->word[1] == '\0';
    if (pick(12) != 0) /* the id or the path */
        k += (size_t)snprintf(payload + k, sizeof payload - k, " %s",
                              rw ? paths[pick(sizeof paths / sizeof paths[0])]
                                 : ids[pick(sizeof ids / sizeof ids[0])]);
    int nf = w->min + (int)pick((uint32_t)(w->max - w->min + 1));
    if (pick(8) == 0)
        nf += pick(2) ? 1 : -1;
    for (int i = 0; i < nf; i++) {
        const char *f = pick(5) ? good[pick(sizeof good / sizeof good[0])]
                                : bad[pick(sizeof bad / sizeof bad[0])];
        k += (size_t)snprintf(payload + k, sizeof payload - k, "%s%s", pick(6) ? " " : "\t ", f);
    }
    if (pick(3) == 0)
        k += (size_t)snprintf(payload + k, sizeof payload - k, " ");
    *cks = (int)pick(4); /* 0, 1: none; 2: right; 3: wrong or malformed */
    if (*cks == 2) {
        char tmp[200];
        snprintf(tmp, sizeof tmp, "%s", payload);
        snprintf(line, size, "%s*%u", tmp, mock_xor(tmp));
    } else if (*cks == 3) {
        static const char *const fields[] = {"*0", "*255", "*x", "*1234", "*", "*256"};
        snprintf(line, size, "%s%s", payload, fields[pick(6)]);
    } else {
        snprintf(line, size, "%s", payload);
    }
}

/* D4: 1 to 3 digits after the first '*', value <= 255, then only blanks. */
static bool well_formed_checksum(const char *line)
{
    const char *star = strchr(line, '*');
    if (star == NULL)
        return false;
    const char *d = star + 1;
    unsigned v = 0, n = 0;
    while (*d >= '0' && *d <= '9') {
        v = v * 10u + (unsigned)(*d - '0');
        d++;
        n++;
    }
    while (*d == ' ' || *d == '\t' || *d == '\r')
        d++;
    return n >= 1 && n <= 3 && v <= 255 && *d == '\0';
}

static void test_random_lines_keep_every_invariant(void)
{
    mock_t *m = mock_new();
    mock_enable_forward(m);
    unsigned errors = 0, effects = 0, answers = 0, silent = 0;
    for (int n = 0; n < 20000; n++) {
        if (n % 500 == 0) {
            m = mock_new();
            mock_enable_forward(m);
        }
        /* state changes now and then: faults, idle, a preset */
        switch (pick(40)) {
        case 0: m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP; break;
        case 1: m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_UNDERVOLTAGE; break;
        case 2: m->props[DARAN_PROP_AXIS_ERROR].u32 = 0; break;
        case 3: m->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE; break;
        case 4: m->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP; break;
        default: break;
        }
        if (m->props[DARAN_PROP_CAN_NODE_ID].u32 != 1)
            m->props[DARAN_PROP_CAN_NODE_ID].u32 = 1;
        char line[220];
        int cks;
        random_line(line, sizeof line, &cks);
        (void)cks;
        if (strlen(line) > DARAN_LINE_MAX)
            continue;
        mock_send_line(m, line);
        bool is_error = strncmp(m->out, "error: ", 7) == 0;
        /* an error is one line, a known phrase, and has no effect at all */
        if (is_error) {
            mock_check(m->n_writes == 1, m, __FILE__, __LINE__, "one error line");
            mock_check(m->n_calls == 0, m, __FILE__, __LINE__, "an error has no effect");
            const char *ph = m->out + 7;
            const char *end = strchr(ph, '\n');
            const char *star = strstr(ph, " *");
            size_t plen = (size_t)((star && star < end ? star : end) - ph);
            mock_check(known_phrase(ph, plen), m, __FILE__, __LINE__, "unknown phrase");
        }
        /* every reply line carries a correct checksum iff the request had a well-formed one */
        bool framing = is_error && (strstr(m->out, "line too long") || strstr(m->out, "invalid character") ||
                                    strstr(m->out, "invalid checksum"));
        const char *l = m->out;
        while (*l) {
            const char *end = strchr(l, '\n');
            char one[DARAN_REPLY_MAX + 1];
            size_t len = (size_t)(end - l);
            memcpy(one, l, len);
            one[len] = '\0';
            char *star = strrchr(one, '*');
            bool want = well_formed_checksum(line) && !framing;
            mock_check((star != NULL) == want, m, __FILE__, __LINE__, "reply checksum presence");
            if (star) {
                unsigned sum = (unsigned)strtoul(star + 1, NULL, 10);
                *star = '\0';
                mock_check(star > one && star[-1] == ' ' && mock_xor(one) == sum, m, __FILE__,
                           __LINE__, "reply checksum value");
            }
            l = end + 1;
        }
        /* what an accepted line may do: one set, one action, or a move then a feed */
        if (!is_error && m->n_calls > 0) {
            bool one_set = m->n_calls == 1 && m->calls[0].kind == MOCK_CALL_SET;
            bool one_action = m->n_calls == 1 && m->calls[0].kind == MOCK_CALL_ACTION;
            bool move_feed = m->n_calls == 2 && m->calls[0].kind == MOCK_CALL_MOVE &&
                             m->calls[1].kind == MOCK_CALL_ACTION &&
                             m->calls[1].action == DARAN_ACTION_FEED_WATCHDOG;
            mock_check(one_set || one_action || move_feed, m, __FILE__, __LINE__,
                       "unexpected HAL call sequence");
            mock_check(m->out_len == 0, m, __FILE__, __LINE__, "a line with an effect is silent");
        }
        /* forwarded lines are the line as sent, for another id or a broadcast */
        for (size_t i = 0; i < m->n_fwd; i++) {
            mock_check(m->fwd[i].id != 1 && m->fwd[i].id <= DARAN_MOTOR_ID_MAX, m, __FILE__,
                       __LINE__, "forwarded id");
            mock_check(strcmp(m->fwd[i].line, line) == 0, m, __FILE__, __LINE__,
                       "forwarded as received");
        }
        mock_check(m->n_fwd <= 1, m, __FILE__, __LINE__, "forwarded once");
        if (is_error)
            errors++;
        else if (m->n_calls > 0)
            effects++;
        else if (m->out_len > 0)
            answers++;
        else
            silent++;
    }
    mock_message("random lines: %u errors, %u with an effect, %u answered, %u silent\n", errors,
                  effects, answers, silent);
    /* the generator must reach every outcome, or the invariants prove little */
    TEST_ASSERT_TRUE(errors > 1000 && effects > 500 && answers > 200 && silent > 500);
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
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
    ADD(test_random_lines_keep_every_invariant);
    ADD(test_relative_target_beyond_float_range_is_refused);
    ADD(test_failed_setpoint_getter_refuses_a_relative_start);
    ADD(test_refused_start_after_hal_failure_keeps_the_preset);
    mock_suite_run(&s);
    return UNITY_END();
}
