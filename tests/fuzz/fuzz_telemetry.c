/* Harness 6: telemetry reports (daran_telemetry_tick) interleaved with
 * request bytes on the byte path, the period and fields set by the fuzzed
 * requests themselves (`w axis0.telemetry.period`, `.fields`).
 *
 * Input: 8 setup bytes, then the request bytes.
 *   [0]    own id, 1 + b % 63
 *   [1]    bits 0-2: the tick rate (1000, 8000, 100, 1, 0, 48000, 3, 1000000 Hz);
 *          bit 3: telemetry on from the start (period 0.002 s, every field);
 *          bit 4: odd values behind the fields' getters (NaN, inf, extremes);
 *          bit 5: a getter fails now and then inside a tick;
 *          bit 6: the forward hook; bit 7: bytes also arrive during ticks
 *          (the receive interrupt firing inside the tick's HAL reads)
 *   [2..5] the first tick (u32; below 2^30 when telemetry is on from the start)
 *   [6..7] seed of the schedule: chunk sizes, polls, ticks between them and
 *          their steps (mostly 1, sometimes up to 1000)
 * Two instances get the same bytes and polls: the drive under test, which
 * also ticks, and a reference that never ticks.
 *
 * Oracle, at every write callback and tick:
 *  - every write is exactly one whole line (fuzz_check_reply_line);
 *  - reports come only from daran_telemetry_tick(), replies only from
 *    daran_poll(); a tick writes at most one line;
 *  - a report is `@<id> <t> <values> *N`: the drive's id, t = tick / rate
 *    as a float32, one value per field bit in bit order equal to what the
 *    HAL holds (floats read back to the same float32), a right checksum;
 *  - a report comes when due: at once when telemetry goes on, then every
 *    period rounded to whole ticks (at least one), by this harness's own
 *    arithmetic in double (either answer allowed where float rounding can
 *    tip a half tick); none while the period is 0, NaN or negative, or the
 *    rate 0; none when a getter failed;
 *  - the replies and HAL calls of the drive under test, reports left out,
 *    equal the reference's after every poll: reports never split, corrupt
 *    or reorder a reply. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_hal.h"

static const uint32_t rates[8] = {1000u, 8000u, 100u, 1u, 0u, 48000u, 3u, 1000000u};

/* Bit b of axis0.telemetry.fields reports this property (protocol.md 11.2). */
static const daran_prop_t field_props[9] = {
    DARAN_PROP_POS_ESTIMATE,      DARAN_PROP_VEL_ESTIMATE,    DARAN_PROP_TORQUE_ESTIMATE,
    DARAN_PROP_IQ_MEASURED,       DARAN_PROP_VBUS_VOLTAGE,    DARAN_PROP_FET_TEMPERATURE,
    DARAN_PROP_MOTOR_TEMPERATURE, DARAN_PROP_AXIS_ERROR,      DARAN_PROP_TRAJECTORY_DONE};

static struct {
    daran_drive_t drive;
    fuzz_hal_t hal;
    daran_drive_t ref;
    fuzz_hal_t ref_hal;

    const uint8_t *data;
    size_t len;
    size_t pos;
    uint32_t rng;
    bool interrupts;

    bool in_tick;
    uint32_t tick;
    uint32_t rate;
    size_t reports; /* lines written during the current tick */

    /* the schedule as this harness reads protocol.md 11.2 */
    bool running;       /* a report went out (or was due) and the period stayed > 0 */
    uint32_t last;      /* tick of that report */
    float last_period;  /* the period then */
    uint32_t period_writes; /* the HAL's count of accepted period writes at the last tick */
} st;

static uint32_t next(void)
{
    st.rng ^= st.rng << 13;
    st.rng ^= st.rng >> 17;
    st.rng ^= st.rng << 5;
    return st.rng;
}

/* Same bytes to both rings (the fill levels are equal: both were polled
 * at the same points). */
static void push(size_t n)
{
    while (n > 0u && st.pos < st.len) {
        uint8_t b = st.data[st.pos++];
        bool a = daran_rx_byte(&st.drive, b);
        bool r = daran_rx_byte(&st.ref, b);
        FUZZ_CHECK(a == r, "the two rings disagree on a byte");
        n--;
    }
}

static void interrupt(void *ctx)
{
    (void)ctx;
    if (st.interrupts && st.in_tick && (next() & 3u) == 0u) {
        push(1u + next() % 8u);
    }
}

static bool same_float(float a, float b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* One space-separated token of a report: [*p, *p + n). */
static bool token(const char **p, const char *end, const char **start, size_t *n)
{
    if (*p >= end || **p != ' ') {
        return false;
    }
    (*p)++;
    *start = *p;
    while (*p < end && **p != ' ') {
        (*p)++;
    }
    *n = (size_t)(*p - *start);
    return *n > 0u;
}

static float parse_float(const char *s, size_t n)
{
    char text[40];
    FUZZ_CHECK(n < sizeof text, "report value of %zu characters", n);
    memcpy(text, s, n);
    text[n] = '\0';
    char *end;
    float v = strtof(text, &end);
    FUZZ_CHECK(end == text + n, "report value \"%s\" is no number", text);
    return v;
}

static uint64_t parse_uint(const char *s, size_t n)
{
    FUZZ_CHECK(n >= 1u && n <= 10u && (n == 1u || s[0] != '0'), "report integer malformed");
    uint64_t v = 0;
    for (size_t i = 0; i < n; i++) {
        FUZZ_CHECK(s[i] >= '0' && s[i] <= '9', "report integer malformed");
        v = v * 10u + (uint64_t)(s[i] - '0');
    }
    return v;
}

static void check_report(const char *line, size_t len)
{
    const fuzz_hal_t *h = &st.hal;
    const char *what = fuzz_escape(line, len);
    const char *end = line + len - (DARAN_REPLY_CRLF ? 2u : 1u);
    const char *star = memchr(line, '*', (size_t)(end - line));
    FUZZ_CHECK(star != NULL && star > line + 1 && star[-1] == ' ', "report without its checksum: \"%s\"",
               what);
    end = star - 1; /* the space before the '*' */
    const char *p = line + 1;
    const char *s = p;
    while (p < end && *p != ' ') {
        p++;
    }
    FUZZ_CHECK(parse_uint(s, (size_t)(p - s)) == h->props[DARAN_PROP_CAN_NODE_ID].u32,
               "report from another id: \"%s\"", what);
    size_t n;
    FUZZ_CHECK(token(&p, end, &s, &n), "report without a time: \"%s\"", what);
    float t = (float)st.tick / (float)st.rate;
    FUZZ_CHECK(same_float(parse_float(s, n), t), "report time is not tick/rate (%u/%u): \"%s\"",
               (unsigned)st.tick, (unsigned)st.rate, what);
    uint32_t fields = h->props[DARAN_PROP_TELEMETRY_FIELDS].u32;
    for (unsigned bit = 0; bit < 9u; bit++) {
        if (((fields >> bit) & 1u) == 0u) {
            continue;
        }
        FUZZ_CHECK(token(&p, end, &s, &n), "report lacks field %u: \"%s\"", bit, what);
        daran_value_t v = h->props[field_props[bit]];
        if (bit < 7u) {
            FUZZ_CHECK(same_float(parse_float(s, n), v.f32), "report field %u is not %a: \"%s\"",
                       bit, (double)v.f32, what);
        } else {
            FUZZ_CHECK(parse_uint(s, n) == v.u32, "report field %u is not %u: \"%s\"", bit,
                       (unsigned)v.u32, what);
        }
    }
    FUZZ_CHECK(p == end, "report has more than its fields: \"%s\"", what);
}

/* The drive under test's sink: reports checked here, replies hashed as the
 * reference's are. */
static void write_line(void *ctx, const char *line, size_t len)
{
    fuzz_check_reply_line(line, len);
    if (len > 0u && line[0] == '@') {
        FUZZ_CHECK(st.in_tick, "a report outside daran_telemetry_tick: \"%s\"",
                   fuzz_escape(line, len));
        st.reports++;
        FUZZ_CHECK(st.reports == 1u, "one tick wrote two lines");
        check_report(line, len);
        return;
    }
    FUZZ_CHECK(!st.in_tick, "daran_telemetry_tick wrote a line that is no report: \"%s\"",
               fuzz_escape(line, len));
    fuzz_write(ctx, line, len);
}

/* Whole ticks in a period, as a range [lo, hi] (float rounding of the
 * core's period x rate + 1/2 may tip a value near a half tick). */
static void period_ticks(float period, uint32_t rate, double *lo, double *hi)
{
    double exact = (double)period * (double)rate;
    double tol = exact * 1e-6 + 1e-9;
    *lo = ceil(exact - 0.5 - tol);
    *hi = floor(exact + 0.5 + tol);
    *lo = *lo < 1.0 ? 1.0 : (*lo > 2e9 ? 2e9 : *lo);
    *hi = *hi < 1.0 ? 1.0 : (*hi > 2e9 ? 2e9 : *hi);
}

static void one_tick(uint32_t step, bool getter_fault)
{
    fuzz_hal_t *h = &st.hal;
    st.tick += step;
    float period = h->props[DARAN_PROP_TELEMETRY_PERIOD].f32;
    uint32_t nth = 0;
    if (getter_fault) {
        nth = 1u + next() % 12u;
        fuzz_hal_arm_get(h, nth, 1 + (int)(next() % (DARAN_RESULT_COUNT + 2)));
    }
    size_t gets_before = h->n_get;
    st.in_tick = true;
    st.reports = 0;
    daran_result_t r = daran_telemetry_tick(&st.drive, st.tick, st.rate);
    st.in_tick = false;
    size_t gets = h->n_get - gets_before;
    /* an accepted write of the period restarts its schedule: the tick after
     * it reports at once (a new period never waits for the old one's report) */
    if (h->period_writes != st.period_writes) {
        st.period_writes = h->period_writes;
        st.running = false;
    }
    bool failed = getter_fault && nth <= gets;
    fuzz_hal_arm_get(h, 0, 0);
    FUZZ_CHECK(failed == (r != DARAN_OK), "tick answered %d, a getter %s", (int)r,
               failed ? "failed" : "did not fail");
    FUZZ_CHECK(!failed || st.reports == 0u, "a report although a getter failed");
    FUZZ_CHECK(gets >= 1u, "a tick that did not read the period");

    if (st.rate == 0u || !(period > 0.0f) || (failed && nth == 1u)) {
        /* off (or its period unreadable): only the period read, nothing
         * written, and on again it reports at once */
        FUZZ_CHECK(st.reports == 0u && gets == 1u, "a report (or %zu reads) with period %a at %u Hz",
                   gets, (double)period, (unsigned)st.rate);
        st.running = false;
        return;
    }
    /* The core reads past the period only when a report is due; then it
     * reports, unless a getter fails. */
    bool due = gets > 1u;
    FUZZ_CHECK(failed || st.reports == (due ? 1u : 0u), "%zu reports, %zu reads at tick %u",
               st.reports, gets, (unsigned)st.tick);
    bool must = true;
    bool may = true;
    if (st.running) {
        double lo, hi;
        period_ticks(st.last_period, st.rate, &lo, &hi);
        double since = (double)(uint32_t)(st.tick - st.last);
        must = since >= hi;
        may = since >= lo;
    }
    FUZZ_CHECK(!must || due, "no report at tick %u, the last at %u, period %a at %u Hz",
               (unsigned)st.tick, (unsigned)st.last, (double)st.last_period, (unsigned)st.rate);
    FUZZ_CHECK(may || !due, "a report at tick %u, the last at %u, period %a at %u Hz",
               (unsigned)st.tick, (unsigned)st.last, (double)st.last_period, (unsigned)st.rate);
    if (due) {
        st.running = true;
        st.last = st.tick;
        st.last_period = period;
    }
}

static void poll_both(void)
{
    (void)daran_poll(&st.drive);
    (void)daran_poll(&st.ref);
    FUZZ_CHECK(st.hal.hash == st.ref_hal.hash,
               "replies or HAL calls differ from the reference that never ticks");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 8u) {
        return 0;
    }
    uint32_t id = 1u + data[0] % DARAN_MOTOR_ID_MAX;
    uint8_t flags = data[1];
    memset(&st, 0, sizeof st);
    st.rate = rates[flags & 7u];
    st.tick = (uint32_t)data[2] | (uint32_t)data[3] << 8 | (uint32_t)data[4] << 16 |
              (uint32_t)data[5] << 24;
    if ((flags & 0x08u) != 0u) {
        st.tick &= 0x3fffffffu; /* on at the first tick: see below */
    }
    st.rng = 0x9e3779b9u ^ ((uint32_t)data[6] | (uint32_t)data[7] << 8);
    st.data = data + 8;
    st.len = size - 8u;
    st.interrupts = (flags & 0x80u) != 0u;

    fuzz_hal_t *hals[2] = {&st.hal, &st.ref_hal};
    for (int i = 0; i < 2; i++) {
        fuzz_hal_t *h = hals[i];
        fuzz_hal_init(h, id);
        h->props[DARAN_PROP_TELEMETRY_PERIOD].f32 = 0.0f; /* off, as a drive boots */
        h->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = 3u;
        h->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 1u;
        h->props[DARAN_PROP_IQ_MEASURED].f32 = 0.25f;
        if ((flags & 0x08u) != 0u) {
            h->props[DARAN_PROP_TELEMETRY_PERIOD].f32 = 0.002f;
            h->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = 511u;
        }
        if ((flags & 0x10u) != 0u) {
            static const float odd[] = {NAN, -INFINITY, 3.4028235e38f, -4.0e-45f,
                                        -0.0f, 1.17549435e-38f, 123456789.0f};
            for (unsigned bit = 0; bit < 7u; bit++) {
                h->props[field_props[bit]].f32 = odd[(bit + data[0]) % 7u];
            }
            h->props[DARAN_PROP_AXIS_ERROR].u32 = 0xffffffffu;
        }
    }
    static const daran_hal_t reporting = {FUZZ_HAL_FUNCTIONS, .write = write_line};
    static const daran_hal_t reporting_forwarding = {FUZZ_HAL_FUNCTIONS, .write = write_line,
                                                     .forward = fuzz_forward};
    if (daran_init(&st.drive, (flags & 0x40u) != 0u ? &reporting_forwarding : &reporting,
                   &st.hal) != DARAN_OK) {
        fuzz_fail("daran_init refused a complete HAL");
    }
    fuzz_bind(&st.ref, &st.ref_hal, (flags & 0x40u) != 0u);
    st.hal.on_call = interrupt;

    /* A drive's main loop: it ticks from boot, before any line arrives
     * (the schedule starts at tick 0 in daran_init: a first call past 2^31
     * ticks with telemetry on would wait for the counter to wrap); then
     * bytes arrive, it polls, control ticks go by. */
    one_tick(0u, false);
    while (st.pos < st.len) {
        uint32_t r = next();
        push(1u + r % ((r >> 8) % 4u == 0u ? 200u : 24u));
        if ((r >> 12) % 4u != 0u) {
            poll_both();
        }
        unsigned ticks = (unsigned)((r >> 16) % 6u);
        for (unsigned k = 0; k < ticks; k++) {
            uint32_t q = next();
            uint32_t step = (q & 15u) != 0u ? 1u : 1u + q % 1000u;
            one_tick(step, (flags & 0x20u) != 0u && ((q >> 10) & 7u) == 0u);
        }
    }
    poll_both();
    /* and the line in progress ends: the last reply must match too */
    (void)daran_rx_byte(&st.drive, '\n');
    (void)daran_rx_byte(&st.ref, '\n');
    poll_both();
    for (unsigned k = 0; k < 4u; k++) {
        one_tick(1u, false);
    }
    return 0;
}
