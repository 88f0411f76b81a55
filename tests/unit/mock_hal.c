/* The recording mock HAL, reply sink and check helpers of the unit tests
 * (see mock_hal.h). */
#include "mock_hal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static mock_t mock_instances[MOCK_INSTANCES];

static void mock_defaults(mock_t *m, uint32_t id)
{
    daran_value_t *p = m->props;
    p[DARAN_PROP_CAN_NODE_ID].u32 = id;
    p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    p[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    p[DARAN_PROP_AXIS_ERROR].u32 = 0;
    p[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.0f;
    p[DARAN_PROP_IBUS].f32 = 0.25f;
    p[DARAN_PROP_UART_BAUDRATE].u32 = 115200;
    p[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000;
    p[DARAN_PROP_FW_VERSION].u32 = 10203;
    p[DARAN_PROP_HW_VERSION].u32 = 7;
    p[DARAN_PROP_SERIAL_NUMBER].u64 = 1234567890123ull;
    p[DARAN_PROP_TRAJECTORY_DONE].u32 = 1;
    p[DARAN_PROP_POS_GAIN].f32 = 20.0f;
    p[DARAN_PROP_VEL_GAIN].f32 = 0.16f;
    p[DARAN_PROP_VEL_INTEGRATOR_GAIN].f32 = 0.32f;
    p[DARAN_PROP_CONTROLLER_VEL_LIMIT].f32 = 10.0f;
    p[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = 20.0f;
    p[DARAN_PROP_CURRENT_LIM].f32 = 10.0f;
    p[DARAN_PROP_MOTOR_TORQUE_LIM].f32 = 5.0f;
    p[DARAN_PROP_CURRENT_CONTROL_BANDWIDTH].f32 = 1000.0f;
    p[DARAN_PROP_FET_TEMPERATURE].f32 = 30.0f;
    p[DARAN_PROP_MOTOR_TEMPERATURE].f32 = 31.0f;
    p[DARAN_PROP_FET_TEMP_LIMIT_LOWER].f32 = 80.0f;
    p[DARAN_PROP_FET_TEMP_LIMIT_UPPER].f32 = 100.0f;
    p[DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER].f32 = 80.0f;
    p[DARAN_PROP_MOTOR_TEMP_LIMIT_UPPER].f32 = 100.0f;
    p[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 600.0f;
    p[DARAN_PROP_SHAFT_TORQUE_LIM].f32 = 5.0f;
    p[DARAN_PROP_VEL_RAMP_RATE].f32 = 60.0f;
    p[DARAN_PROP_TORQUE_RAMP_RATE].f32 = 1.0f;
    p[DARAN_PROP_STEPS_PER_TURN].f32 = 360.0f;
    p[DARAN_PROP_TORQUE_CONSTANT].f32 = 0.1f;
    p[DARAN_PROP_WATCHDOG_TIMEOUT].f32 = 1.0f;
    /* spec 10.2: a trapezoid unless a host asks for the S-curve */
    p[DARAN_PROP_TRAJ_MODE].u32 = 1;
    /* rows whose range refuses 0 hold a value the range accepts */
    p[DARAN_PROP_MOTOR_DIRECTION].s32 = 1;
    p[DARAN_PROP_POLE_PAIRS].s32 = 7;
    p[DARAN_PROP_ENCODER_CPR].s32 = 16384;
    p[DARAN_PROP_GEAR_RATIO].f32 = 1.0f;
    p[DARAN_PROP_CONTROL_MODE].u32 = 3;
    p[DARAN_PROP_INPUT_MODE].u32 = 3;
}

static const daran_hal_t mock_store_fns;
static void mock_observe(void *ctx, const daran_call_t *call);

mock_t *mock_new_slot(int slot, uint32_t id)
{
    mock_t *m = &mock_instances[slot];
    memset(m, 0, sizeof *m);
    m->react = true;
    daran_recorder_init(&m->rec, &mock_store_fns, m);
    m->rec.observer = mock_observe;
    m->rec.observer_ctx = m;
    mock_defaults(m, id);
    m->hal = mock_hal_fns;
    daran_result_t r = daran_init(&m->drive, &m->hal, m);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, r);
    return m;
}

mock_t *mock_new(void) { return mock_new_slot(0, 1); }
mock_t *mock_new_id(uint32_t id) { return mock_new_slot(0, id); }

void mock_enable_forward(mock_t *m) { m->hal.forward = mock_forward; }

void mock_clear(mock_t *m)
{
    daran_recorder_clear(&m->rec);
    memset(m->calls, 0, sizeof m->calls);
    m->n_calls = 0;
    m->n_gets = 0;
    m->out_len = 0;
    m->out[0] = '\0';
    m->n_writes = 0;
    m->n_fwd = 0;
}

/* ---- fault injection and logging: the recorder's ---- */

void mock_fail(mock_t *m, unsigned mask, unsigned nth, daran_result_t result, int prop)
{
    daran_recorder_fail(&m->rec, mask, nth, result, prop);
}

/* The recorder's observer: every call as it completed, failed ones too. */
static void mock_observe(void *ctx, const daran_call_t *call)
{
    mock_t *m = ctx;
    if (call->kind == DARAN_CALL_GET) {
        m->n_gets++;
        return;
    }
    TEST_ASSERT_TRUE(m->n_calls < MOCK_CALLS_MAX);
    m->calls[m->n_calls++] = *call;
}

/* ---- the store: the recorder's inner HAL (reached unless a call is made to fail) ---- */

static daran_result_t mock_store_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    mock_t *m = ctx;
    TEST_ASSERT_TRUE((int)prop >= 0 && prop < DARAN_PROP_COUNT);
    TEST_ASSERT_NOT_NULL(out);
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT)
        return DARAN_ERR_BAD_ARGUMENT; /* a failed assertion that returned */
    *out = m->props[prop];
    return DARAN_OK;
}

static daran_result_t mock_store_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    mock_t *m = ctx;
    TEST_ASSERT_TRUE((int)prop >= 0 && prop < DARAN_PROP_COUNT);
    if ((unsigned)prop >= (unsigned)DARAN_PROP_COUNT)
        return DARAN_ERR_BAD_ARGUMENT; /* a failed assertion that returned */
    m->props[prop] = value;
    if (m->react) {
        daran_value_t *p = m->props;
        switch (prop) {
        case DARAN_PROP_REQUESTED_STATE: p[DARAN_PROP_CURRENT_STATE] = value; break;
        case DARAN_PROP_POS_SETPOINT: p[DARAN_PROP_INPUT_POS] = value; break;
        case DARAN_PROP_VEL_SETPOINT: p[DARAN_PROP_INPUT_VEL] = value; break;
        case DARAN_PROP_TORQUE_SETPOINT: p[DARAN_PROP_INPUT_TORQUE] = value; break;
        default: break;
        }
    }
    return DARAN_OK;
}

static daran_result_t mock_store_move(void *ctx, const daran_move_t *mv)
{
    mock_t *m = ctx;
    TEST_ASSERT_NOT_NULL(mv);
    if (!m->react)
        return DARAN_OK;
    if (daran_recorder_apply_move(m->props, mv) != DARAN_OK) {
        TEST_FAIL_MESSAGE_F("move kind %d outside the enum", (int)mv->kind);
    }
    if (mv->kind == DARAN_MOVE_FILTERED_POSITION || mv->kind == DARAN_MOVE_TRAPEZOID ||
        mv->kind == DARAN_MOVE_PASSTHROUGH) {
        /* The mock "arrives" at once so relative starts are predictable. */
        m->props[DARAN_PROP_POS_SETPOINT].f32 = mv->pos_deg;
    }
    return DARAN_OK;
}

static daran_result_t mock_store_action(void *ctx, daran_action_t action)
{
    mock_t *m = ctx;
    if (!m->react)
        return DARAN_OK;
    daran_value_t *p = m->props;
    switch (action) {
    case DARAN_ACTION_ESTOP:
    case DARAN_ACTION_NODE_GUARD:
        p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        p[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_IDLE;
        p[DARAN_PROP_AXIS_ERROR].u32 |=
            action == DARAN_ACTION_ESTOP ? DARAN_FLAG_ESTOP : DARAN_FLAG_WATCHDOG;
        break;
    case DARAN_ACTION_CLEAR_ERRORS:
        /* spec 10.4: sc clears every error register and the warnings */
        p[DARAN_PROP_AXIS_ERROR].u32 = 0;
        p[DARAN_PROP_MOTOR_ERROR].u32 = 0;
        p[DARAN_PROP_ENCODER_ERROR].u32 = 0;
        p[DARAN_PROP_CONTROLLER_ERROR].u32 = 0;
        p[DARAN_PROP_FET_THERMISTOR_ERROR].u32 = 0;
        p[DARAN_PROP_MOTOR_THERMISTOR_ERROR].u32 = 0;
        p[DARAN_PROP_CAN_ERROR].u32 = 0;
        p[DARAN_PROP_CONFIG_WARNINGS].u32 = 0;
        break;
    case DARAN_ACTION_REBOOT:
        p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
        p[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
        p[DARAN_PROP_AXIS_ERROR].u32 = 0;
        break;
    case DARAN_ACTION_SET_ZERO: {
        float shift = p[DARAN_PROP_POS_ESTIMATE].f32;
        p[DARAN_PROP_POS_ESTIMATE].f32 -= shift;
        p[DARAN_PROP_POS_SETPOINT].f32 -= shift;
        p[DARAN_PROP_INPUT_POS].f32 -= shift;
        break;
    }
    case DARAN_ACTION_SAVE_CONFIG:
    case DARAN_ACTION_ERASE_CONFIG:
    case DARAN_ACTION_FEED_WATCHDOG: break;
    default: TEST_FAIL_MESSAGE_F("action %d outside the enum", (int)action);
    }
    return DARAN_OK;
}

static const daran_hal_t mock_store_fns = {.get = mock_store_get, .set = mock_store_set, .move = mock_store_move, .action = mock_store_action};

/* ---- the HAL a drive is bound to: the mock's recorder ---- */

static daran_result_t mock_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    mock_t *m = ctx;
    return daran_recorder_hal.get(&m->rec, prop, out);
}

static daran_result_t mock_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    mock_t *m = ctx;
    return daran_recorder_hal.set(&m->rec, prop, value);
}

static daran_result_t mock_move(void *ctx, const daran_move_t *mv)
{
    mock_t *m = ctx;
    return daran_recorder_hal.move(&m->rec, mv);
}

static daran_result_t mock_action(void *ctx, daran_action_t action)
{
    mock_t *m = ctx;
    return daran_recorder_hal.action(&m->rec, action);
}

const daran_hal_t mock_hal_fns = {mock_get, mock_set, mock_move, mock_action, mock_write, NULL,
                                  NULL, NULL, NULL};

void mock_write(void *ctx, const char *line, size_t len)
{
    mock_t *m = ctx;
    TEST_ASSERT_NOT_NULL(line);
    /* Whole lines only, each ending in the configured line end, bounded. */
    TEST_ASSERT_TRUE(len >= 1 && len <= DARAN_REPLY_MAX);
    TEST_ASSERT_EQUAL_INT64('\n', line[len - 1]);
    TEST_ASSERT_NULL(memchr(line, '\n', len - 1));
#if DARAN_REPLY_CRLF
    /* checked here once, then stored as "\n" so every expectation reads the same */
    TEST_ASSERT_TRUE(len >= 2 && line[len - 2] == '\r');
    TEST_ASSERT_NULL(memchr(line, '\r', len - 2));
    len--;
    TEST_ASSERT_TRUE(m->out_len + len <= MOCK_OUT_MAX);
    memcpy(m->out + m->out_len, line, len - 1);
    m->out[m->out_len + len - 1] = '\n';
    m->out_len += len;
    m->out[m->out_len] = '\0';
    m->n_writes++;
    return;
#endif
    TEST_ASSERT_TRUE(m->out_len + len <= MOCK_OUT_MAX);
    memcpy(m->out + m->out_len, line, len);
    m->out_len += len;
    m->out[m->out_len] = '\0';
    m->n_writes++;
}

void mock_forward(void *ctx, uint8_t id, const char *line, size_t len)
{
    mock_t *m = ctx;
    TEST_ASSERT_TRUE(m->n_fwd < MOCK_FWD_MAX);
    TEST_ASSERT_TRUE(len < sizeof m->fwd[0].line);
    mock_forward_t *f = &m->fwd[m->n_fwd++];
    f->id = id;
    f->len = len;
    memcpy(f->line, line, len);
    f->line[len] = '\0';
}

/* ---- sending ---- */

static void mock_remember(mock_t *m, const void *data, size_t len)
{
    size_t n = len < sizeof m->last - 1 ? len : sizeof m->last - 1;
    memcpy(m->last, data, n);
    m->last[n] = '\0';
}

void mock_send_bytes(mock_t *m, const void *data, size_t len, size_t chunk)
{
    const uint8_t *b = data;
    /* never more than the ring holds between two polls */
    if (chunk == 0 || chunk > DARAN_RX_RING_SIZE / 2)
        chunk = DARAN_RX_RING_SIZE / 2 < 32 ? DARAN_RX_RING_SIZE / 2 : 32;
    mock_remember(m, data, len);
    while (len > 0) {
        size_t n = len < chunk ? len : chunk;
        size_t queued = daran_rx_write(&m->drive, b, n);
        TEST_ASSERT_EQUAL_INT64(n, queued);
        (void)daran_poll(&m->drive);
        b += n;
        len -= n;
    }
}

void mock_send_raw(mock_t *m, const char *text) { mock_send_bytes(m, text, strlen(text), 0); }

void mock_send_line(mock_t *m, const char *line)
{
    char buf[DARAN_LINE_MAX * 4 + 8];
    size_t n = strlen(line);
    TEST_ASSERT_TRUE(n + 1 < sizeof buf);
    memcpy(buf, line, n);
    buf[n] = '\n';
    mock_clear(m);
    mock_send_bytes(m, buf, n + 1, 0);
    mock_remember(m, line, n);
}

/* ---- counting and checksums ---- */

size_t mock_count(const mock_t *m, mock_call_kind_t kind)
{
    size_t n = 0;
    for (size_t i = 0; i < m->n_calls; i++)
        n += m->calls[i].kind == kind;
    return n;
}

size_t mock_count_action(const mock_t *m, daran_action_t action)
{
    size_t n = 0;
    for (size_t i = 0; i < m->n_calls; i++)
        n += m->calls[i].kind == MOCK_CALL_ACTION && m->calls[i].action == action;
    return n;
}

unsigned mock_xor(const char *s)
{
    unsigned x = 0;
    while (*s)
        x ^= (unsigned char)*s++;
    return x;
}

char *mock_with_checksum(char *buf, size_t size, const char *payload)
{
    size_t n = strlen(payload);
    TEST_ASSERT_TRUE(n + 6 <= size);
    memcpy(buf, payload, n);
    buf[n] = ' ';
    buf[n + 1] = '\0';
    unsigned x = mock_xor(buf);
    buf[n + 1] = '*';
    size_t k = n + 2;
    if (x >= 100)
        buf[k++] = (char)('0' + x / 100);
    if (x >= 10)
        buf[k++] = (char)('0' + x / 10 % 10);
    buf[k++] = (char)('0' + x % 10);
    buf[k] = '\0';
    return buf;
}

char *mock_reply_line(char *buf, size_t size, const char *payload, bool checksum)
{
    const char *end = "\n"; /* mock_write stores "\r\n" as "\n" */
    if (checksum) {
        char tmp[512];
        mock_with_checksum(tmp, sizeof tmp, payload);
        snprintf(buf, size, "%s%s", tmp, end);
    } else {
        snprintf(buf, size, "%s%s", payload, end);
    }
    return buf;
}

const char *mock_escape(const char *s, size_t len)
{
    static char slots[2][2048];
    static int turn;
    turn ^= 1;
    return daran_recorder_escape(s, len, slots[turn], sizeof slots[0]);
}

/* ---- checks ---- */

void mock_check(bool ok, const mock_t *m, const char *file, int line, const char *fmt, ...)
{
    if (ok)
        return;
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    static char report[sizeof msg + 2 * 2048 + 64];
    (void)file; /* Unity names the test file itself */
    snprintf(report, sizeof report, "%s\n  line sent: \"%s\"\n  replies:   \"%s\"", msg,
             mock_escape(m->last, strlen(m->last)), mock_escape(m->out, m->out_len));
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, report);
}

void mock_assert_reply(mock_t *m, const char *expected, const char *file, int line)
{
    mock_check(strcmp(m->out, expected) == 0, m, file, line, "expected reply \"%s\"",
               mock_escape(expected, strlen(expected)));
    m->out_len = 0;
    m->out[0] = '\0';
}

static const char *mock_call_name(const mock_call_t *c)
{
    static char buf[96];
    switch (c->kind) {
    case MOCK_CALL_SET: snprintf(buf, sizeof buf, "set(prop %d)", (int)c->prop); break;
    case MOCK_CALL_MOVE: snprintf(buf, sizeof buf, "move(kind %d)", (int)c->move.kind); break;
    default: snprintf(buf, sizeof buf, "action(%d)", (int)c->action); break;
    }
    return buf;
}

void mock_assert_no_effect(const mock_t *m, const char *file, int line)
{
    mock_check(m->n_calls == 0, m, file, line, "expected no HAL setter/move/action; got %zu, first %s",
               m->n_calls, m->n_calls ? mock_call_name(&m->calls[0]) : "");
}

void mock_assert_error(mock_t *m, const char *line_text, const char *phrase, const char *file,
                       int line)
{
    char want[160];
    snprintf(want, sizeof want, "error: %s", phrase);
    char want_line[200];
    mock_reply_line(want_line, sizeof want_line, want, false);
    mock_send_line(m, line_text);
    mock_check(strcmp(m->out, want_line) == 0, m, file, line, "expected reply \"%s\"",
               mock_escape(want_line, strlen(want_line)));
    mock_assert_no_effect(m, file, line);
}

void mock_assert_silent_no_effect(mock_t *m, const char *line_text, const char *file, int line)
{
    mock_send_line(m, line_text);
    mock_check(m->out_len == 0, m, file, line, "expected no reply");
    mock_assert_no_effect(m, file, line);
}

const daran_move_t *mock_assert_move(mock_t *m, const char *line_text, const char *file, int line)
{
    mock_send_line(m, line_text);
    mock_check(m->out_len == 0, m, file, line, "expected an accepted, silent motion command");
    mock_check(m->n_calls == 2 && m->calls[0].kind == MOCK_CALL_MOVE &&
                   m->calls[1].kind == MOCK_CALL_ACTION &&
                   m->calls[1].action == DARAN_ACTION_FEED_WATCHDOG,
               m, file, line, "expected exactly move + FEED_WATCHDOG (D22); got %zu calls, first %s",
               m->n_calls, m->n_calls ? mock_call_name(&m->calls[0]) : "");
    return &m->calls[0].move;
}

daran_value_t mock_assert_set(mock_t *m, const char *line_text, daran_prop_t prop,
                              const char *file, int line)
{
    mock_send_line(m, line_text);
    mock_check(m->out_len == 0, m, file, line, "expected an accepted, silent write");
    mock_check(m->n_calls == 1 && m->calls[0].kind == MOCK_CALL_SET && m->calls[0].prop == prop, m,
               file, line, "expected exactly one set(prop %d); got %zu calls, first %s", (int)prop,
               m->n_calls, m->n_calls ? mock_call_name(&m->calls[0]) : "");
    return m->calls[0].value;
}

void mock_assert_action(mock_t *m, const char *line_text, daran_action_t action, const char *file,
                        int line)
{
    mock_send_line(m, line_text);
    mock_check(m->out_len == 0, m, file, line, "expected an accepted, silent command");
    mock_check(m->n_calls == 1 && m->calls[0].kind == MOCK_CALL_ACTION &&
                   m->calls[0].action == action,
               m, file, line, "expected exactly action(%d); got %zu calls, first %s", (int)action,
               m->n_calls, m->n_calls ? mock_call_name(&m->calls[0]) : "");
}

const char *mock_assert_query(mock_t *m, const char *line_text, const char *file, int line)
{
    mock_send_line(m, line_text);
    mock_check(m->n_writes == 1, m, file, line, "expected one reply line, got %zu", m->n_writes);
    mock_check(strncmp(m->out, "error", 5) != 0, m, file, line, "expected a value reply");
    mock_assert_no_effect(m, file, line);
    return m->out;
}

static bool mock_same_float(float a, float b) { return a == b || (a != a && b != b); }

void mock_assert_move_equals(const mock_t *m, const daran_move_t *got,
                             const mock_move_expect_t *w, const char *file, int line)
{
    mock_check(got->kind == w->kind, m, file, line, "move kind: expected %d, got %d", (int)w->kind,
               (int)got->kind);
    /* The given bits are defined for these two kinds only (daran_hal.h). */
    if (w->kind == DARAN_MOVE_FILTERED_POSITION || w->kind == DARAN_MOVE_TRAPEZOID)
        mock_check(got->given == w->given, m, file, line, "move given: expected %u, got %u",
                   w->given, (unsigned)got->given);
    mock_check(mock_same_float(got->pos_deg, w->pos), m, file, line,
               "pos_deg: expected %.9g, got %.9g", (double)w->pos, (double)got->pos_deg);
    mock_check(mock_same_float(got->vel_rpm, w->vel), m, file, line,
               "vel_rpm: expected %.9g, got %.9g", (double)w->vel, (double)got->vel_rpm);
    mock_check(mock_same_float(got->torque_nm, w->torque), m, file, line,
               "torque_nm: expected %.9g, got %.9g", (double)w->torque, (double)got->torque_nm);
    mock_check(mock_same_float(got->rate, w->rate), m, file, line, "rate: expected %.9g, got %.9g",
               (double)w->rate, (double)got->rate);
    mock_check(mock_same_float(got->kp, w->kp), m, file, line, "kp: expected %.9g, got %.9g",
               (double)w->kp, (double)got->kp);
    mock_check(mock_same_float(got->kd, w->kd), m, file, line, "kd: expected %.9g, got %.9g",
               (double)w->kd, (double)got->kd);
}

bool mock_uses_multi(const char *line)
{
    while (*line == ' ' || *line == '\t')
        line++;
    if (line[0] != 'm' && line[0] != 'M')
        return false;
    char c = (char)(line[1] | 0x20);
    return strchr("stqpvc", c) != NULL && c != '\0' &&
           (line[2] == ' ' || line[2] == '\t' || line[2] == '*' || line[2] == '\0');
}

/* ---- table-generated suites ---- */

/* Outside any test case: a full table stops the program with a message. */
static mock_suite_case_t *mock_suite_next(mock_suite_t *s)
{
    if (s->count == sizeof s->cases / sizeof s->cases[0]) {
        UnityPrint("mock_suite: more cases than the table holds");
        UNITY_PRINT_EOL();
        UNITY_OUTPUT_FLUSH();
        exit(1);
    }
    mock_suite_case_t *t = &s->cases[s->count];
    t->fn = NULL;
    t->test = NULL;
    t->row = NULL;
    return t;
}

void mock_suite_add_test_at(mock_suite_t *s, mock_test_fn fn, int line, const char *name)
{
    mock_suite_case_t *t = mock_suite_next(s);
    snprintf(s->names[s->count], sizeof s->names[0], "%s", name);
    t->test = fn;
    t->line = line;
    s->count++;
}

void mock_suite_add_at(mock_suite_t *s, mock_row_fn fn, const void *row, int line,
                       const char *fmt, ...)
{
    (void)mock_suite_next(s);
    char *name = s->names[s->count];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(name, sizeof s->names[0], fmt, ap);
    va_end(ap);
    /* names read as one identifier-like sentence */
    for (char *c = name; *c; c++)
        if (*c == ' ')
            *c = '_';
    mock_suite_case_t *t = &s->cases[s->count++];
    t->fn = fn;
    t->row = row;
    t->line = line;
}

static const mock_suite_case_t *mock_running;

static void mock_suite_trampoline(void)
{
    mock_running->fn(mock_running->row);
}

void mock_suite_run(mock_suite_t *s)
{
    for (size_t i = 0; i < s->count; i++) {
        mock_running = &s->cases[i];
        UnityDefaultTestRun(s->cases[i].test != NULL ? s->cases[i].test : mock_suite_trampoline,
                            s->names[i], s->cases[i].line);
    }
}

void mock_message(const char *fmt, ...)
{
    char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    UnityPrint(text);
    UNITY_PRINT_EOL();
}

void mock_fail_at(int line, const char *fmt, ...)
{
    static char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, text);
}
