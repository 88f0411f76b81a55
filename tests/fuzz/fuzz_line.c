/* Harness 2: daran_process_line() with the recording HAL.
 *
 * Input: 4 setup bytes (own id, drive state or the NVM warning, forward
 * hook, fault injection, every bit of every error register, odd values
 * behind the read-only getters with S-curve timing),
 * then lines separated by '\n' (any bytes, '\r' and NUL included), each given
 * to daran_process_line() on one instance. After every line it asserts:
 *  - invariant 4: every reply line is well-formed (fuzz_check_reply_line);
 *  - the result and the reply agree: DARAN_OK answers no error; an error
 *    answers exactly one line "error: <its phrase>";
 *  - invariant 2: a line answered with an error made no HAL setter, move or
 *    action call, unless the HAL itself refused (D26), and then the refused
 *    call was the last one and the reply is the HAL's error;
 *  - invariant 3: a line this harness decides, on its own reading of the
 *    protocol, is addressed to another drive makes no HAL call other than
 *    reading axis0.config.can_node_id, no reply, and reaches the forward
 *    hook once, unchanged; and any line the core forwards to another id
 *    behaved the same way. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_hal.h"
#include "number.h"

/* fuzz_port.c includes this file with its own hooks: the port's command
 * words for this harness's reading of the address, a set-up after the
 * drive is bound, and checks around every line. */
#ifndef FUZZ_LINE_EXTRA_WORDS
#define FUZZ_LINE_EXTRA_WORDS
#endif
#ifndef FUZZ_LINE_SETUP
#define FUZZ_LINE_SETUP(drive, hal, data) ((void)0)
#endif
#ifndef FUZZ_LINE_BEFORE
#define FUZZ_LINE_BEFORE(line, len) ((void)0)
#endif
#ifndef FUZZ_LINE_AFTER
#define FUZZ_LINE_AFTER(line, len, result, motor) ((void)0)
#endif
#ifndef FUZZ_LINE_END
#define FUZZ_LINE_END(drive, hal) ((void)0)
#endif

static bool blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

typedef struct view {
    const char *p;
    size_t n;
} view_t;

/* Split on blanks; returns the count (at most max kept, the true count
 * returned). */
static size_t split(const char *s, size_t len, view_t *out, size_t max)
{
    size_t count = 0, i = 0;
    while (i < len) {
        while (i < len && blank(s[i])) {
            i++;
        }
        if (i == len) {
            break;
        }
        size_t start = i;
        while (i < len && !blank(s[i])) {
            i++;
        }
        if (count < max) {
            out[count].p = s + start;
            out[count].n = i - start;
        }
        count++;
    }
    return count;
}

static bool word_is(view_t w, const char *name)
{
    size_t n = strlen(name);
    if (w.n != n) {
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        char c = w.p[i];
        if (c >= 'A' && c <= 'Z') {
            c = (char)(c - 'A' + 'a');
        }
        if (c != name[i]) {
            return false;
        }
    }
    return true;
}

static const char *const words[] = {"t",  "q",  "p",  "v",  "c",  "d",  "ms", "mt", "mq",
                                    "mp", "mv", "mc", "r",  "w",  "ss", "se", "sr", "sc",
                                    "sz", "st", "h",  "f",  "g",  "i",  "e",  "u",
                                    FUZZ_LINE_EXTRA_WORDS};

/* A motor id under D7, or -1 when it is not one. */
static int motor_of(view_t f)
{
    uint64_t v;
    if (daran_parse_u64(f.p, f.n, &v) != DARAN_OK || v > DARAN_MOTOR_ID_MAX) {
        return -1;
    }
    return (int)v;
}

/* This harness's own reading of which motor a line is for (protocol.md
 * sections 1-3, D4, D7-D9): -1 when the line is refused before the address
 * is known (or its address is malformed), else the id. */
static int addressed_motor(const char *line, size_t len)
{
    if (len > DARAN_LINE_MAX) {
        return -1;
    }
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)line[i];
        if (!((c >= 0x20 && c <= 0x7e) || c == '\t' || c == '\r')) {
            return -1;
        }
    }
    size_t payload = len;
    const char *star = memchr(line, '*', len);
    if (star != NULL) {
        payload = (size_t)(star - line);
        size_t i = payload + 1u;
        unsigned n = 0, digits = 0;
        while (i < len && line[i] >= '0' && line[i] <= '9' && digits < 4u) {
            n = n * 10u + (unsigned)(line[i] - '0');
            digits++;
            i++;
        }
        while (i < len && blank(line[i])) {
            i++;
        }
        unsigned x = 0;
        for (size_t k = 0; k < payload; k++) {
            x ^= (unsigned char)line[k];
        }
        if (digits < 1u || digits > 3u || n > 255u || i != len || x != n) {
            return -1;
        }
    }
    view_t f[8];
    size_t count = split(line, payload, f, 8);
    if (count == 0u) {
        return -1;
    }
    bool known = false;
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++) {
        known = known || word_is(f[0], words[i]);
    }
    if (!known || count < 2u) {
        return -1;
    }
    bool is_r = word_is(f[0], "r"), is_w = word_is(f[0], "w");
    if (!is_r && !is_w) {
        return motor_of(f[1]);
    }
    view_t path = f[1];
    if (path.n >= 5u && memcmp(path.p, "axis", 4) == 0) {
        const char *dot = memchr(path.p + 4, '.', path.n - 4u);
        if (dot != NULL) {
            view_t n = {path.p + 4, (size_t)(dot - path.p) - 4u};
            return motor_of(n);
        }
    }
    size_t min = is_r ? 2u : 3u;
    if (count == min) {
        return 0;
    }
    if (count == min + 1u) {
        return motor_of(f[min]);
    }
    return -1;
}

typedef struct state {
    daran_drive_t drive;
    fuzz_hal_t hal;
} state_t;

static state_t st;

static void check_line(const char *line, size_t len)
{
    fuzz_hal_t *h = &st.hal;
    uint32_t own = h->props[DARAN_PROP_CAN_NODE_ID].u32;
    int motor = addressed_motor(line, len);

    fuzz_hal_clear(h);
    FUZZ_LINE_BEFORE(line, len);
    daran_result_t r = daran_process_line(&st.drive, line, len);
    const char *what = fuzz_escape(line, len);

    FUZZ_CHECK((int)r >= 0 && r < DARAN_ERR_BAD_ARGUMENT, "result %d for \"%s\"", (int)r, what);
    if (r == DARAN_OK) {
        FUZZ_CHECK(h->n_error_replies == 0u, "DARAN_OK but an error answered for \"%s\"", what);
        /* D22: a watchdog feed that fails after an accepted move cannot undo
         * the move and is not answered; any other refusal must be. */
        FUZZ_CHECK(!h->failed || (h->failed_was_last && h->n_move == 1u &&
                                  h->last_call == 'a' && h->last_action == DARAN_ACTION_FEED_WATCHDOG),
                   "HAL refused but DARAN_OK for \"%s\"", what);
    } else {
        char want[96];
        int n = snprintf(want, sizeof want, "error: %s", daran_result_phrase(r));
        FUZZ_CHECK(h->n_replies == 1u && h->out_len > (size_t)n &&
                       memcmp(h->out, want, (size_t)n) == 0 &&
                       (h->out[n] == '\n' || h->out[n] == ' ' || h->out[n] == '\r'),
                   "result %d answered \"%s\" for \"%s\"", (int)r,
                   fuzz_escape(h->out, h->out_len), fuzz_escape(line, len));
        if (h->failed) {
            FUZZ_CHECK(h->failed_was_last && r == h->fail_answer,
                       "HAL refused (%d), core answered %d or called on, for \"%s\"",
                       (int)h->fail_answer, (int)r, fuzz_escape(line, len));
        } else {
            FUZZ_CHECK(fuzz_hal_mutations(h) == 0u,
                       "invariant 2: error %d after %zu set, %zu move, %zu action for \"%s\"",
                       (int)r, h->n_set, h->n_move, h->n_action, fuzz_escape(line, len));
        }
    }

    bool other = motor > 0 && (uint32_t)motor != own;
    bool forwarded_other = h->n_forward > 0u && h->forward_id != 0u;
    if (other || forwarded_other) {
        FUZZ_CHECK(h->n_replies == 0u && fuzz_hal_mutations(h) == 0u && h->n_get_other == 0u &&
                       r == DARAN_OK,
                   "invariant 3: line for id %d (own %u) answered %zu lines, %zu mutations, "
                   "%zu other getters: \"%s\"",
                   motor, own, h->n_replies, fuzz_hal_mutations(h), h->n_get_other,
                   fuzz_escape(line, len));
    }
    if (other && st.drive.hal->forward != NULL) {
        FUZZ_CHECK(h->n_forward == 1u && h->forward_id == (uint8_t)motor &&
                       h->forward_len == len && memcmp(h->forward_line, line, len) == 0,
                   "line for id %d not forwarded once, unchanged: \"%s\"", motor,
                   fuzz_escape(line, len));
    }
    if (forwarded_other) {
        FUZZ_CHECK(motor == (int)h->forward_id,
                   "core forwarded to %u a line this harness reads as for %d: \"%s\"",
                   h->forward_id, motor, fuzz_escape(line, len));
    }
    FUZZ_LINE_AFTER(line, len, r, motor);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 4u) {
        return 0;
    }
    uint32_t id = 1u + data[0] % DARAN_MOTOR_ID_MAX;
    fuzz_hal_init(&st.hal, id);
    switch (data[1] & 3u) {
    case 1:
        st.hal.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        break;
    case 2:
        st.hal.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        st.hal.props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP;
        break;
    case 3:
        /* the NVM warning (never blocks motion), with or without a blocking
         * bit (0x40 is DARAN_FLAG_MOTOR_FAILED) and the register behind it */
        st.hal.props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
        st.hal.props[DARAN_PROP_AXIS_ERROR].u32 = data[1] & (uint32_t)DARAN_FLAG_MOTOR_FAILED;
        st.hal.props[DARAN_PROP_MOTOR_ERROR].u32 = (data[1] & 0x40u) != 0u ? DARAN_MOTOR_ERROR_STALL : 0u;
        break;
    default:
        break;
    }
    if ((data[2] & 0x40u) != 0u) {
        /* every bit of every error register: the longest `e` reply, seven
         * lines of up to "motor_thermistor: 4294967295" */
        static const daran_prop_t registers[] = {
            DARAN_PROP_AXIS_ERROR,           DARAN_PROP_MOTOR_ERROR,
            DARAN_PROP_ENCODER_ERROR,        DARAN_PROP_CONTROLLER_ERROR,
            DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
            DARAN_PROP_CAN_ERROR,            DARAN_PROP_CONFIG_WARNINGS};
        for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
            st.hal.props[registers[i]].u32 = 0xffffffffu;
        }
    }
    if ((data[2] & 0x20u) != 0u) {
        /* odd values behind the getters: replies must still fit and be ASCII */
        static const float odd[8] = {NAN, -INFINITY, 3.4028235e38f, -4.0e-45f,
                                     -0.0f, 1.17549435e-38f, 123456789.0f, -1.5e-7f};
        float v = odd[data[2] & 7u];
        static const daran_prop_t ro[] = {
            DARAN_PROP_VBUS_VOLTAGE,  DARAN_PROP_IBUS,          DARAN_PROP_IQ_MEASURED,
            DARAN_PROP_POS_ESTIMATE,  DARAN_PROP_VEL_ESTIMATE,  DARAN_PROP_TORQUE_ESTIMATE,
            DARAN_PROP_FET_TEMPERATURE, DARAN_PROP_MOTOR_TEMPERATURE};
        for (size_t i = 0; i < sizeof ro / sizeof ro[0]; i++) {
            st.hal.props[ro[i]].f32 = v;
        }
        st.hal.props[DARAN_PROP_FW_VERSION].u32 = 0xffffffffu;
        st.hal.props[DARAN_PROP_HW_VERSION].u32 = 0xffffffffu;
        st.hal.props[DARAN_PROP_SERIAL_NUMBER_L].u32 = 0xffffffffu;
        /* the widest s32 replies */
        st.hal.props[DARAN_PROP_ENCODER_POS_ABS].s32 = INT32_MIN;
        st.hal.props[DARAN_PROP_ENCODER_TURN_ABS].s32 = INT32_MIN + 1;
        st.hal.props[DARAN_PROP_STORED_TURNS_COUNTS].s32 = INT32_MAX;
        /* S-curve timing for mq */
        st.hal.props[DARAN_PROP_TRAJ_MODE].u32 = 2u;
    }
    fuzz_bind(&st.drive, &st.hal, (data[1] & 4u) != 0u);
    FUZZ_LINE_SETUP(&st.drive, &st.hal, data);
    if ((data[2] & 0x80u) != 0u) {
        /* Results outside the enum too: the core must answer motor fault. */
        int result = 1 + data[3] % (DARAN_RESULT_COUNT + 2);
        fuzz_hal_arm(&st.hal, 1u + (data[2] & 0x1fu), result);
    }
    const char *text = (const char *)data + 4;
    size_t len = size - 4u;
    size_t start = 0;
    for (size_t i = 0; i <= len; i++) {
        if (i == len || text[i] == '\n') {
            check_line(text + start, i - start);
            start = i + 1u;
        }
    }
    FUZZ_LINE_END(&st.drive, &st.hal);
    return 0;
}
