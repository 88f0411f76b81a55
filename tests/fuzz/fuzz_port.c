/* Harness 5: the line harness (fuzz_line.c, every invariant of it) on a
 * drive with the example port's tables: the core compiled with
 * examples/port-brake/brake_options.h (two properties of the port's own,
 * five vendor rows left out) and the port's command table
 * (examples/port-brake/brake_port.c, `sb id hz`) whose chopper driver here
 * is a recording one (fuzz_hal_port_call: a mutating call for invariants 2
 * and 3 and for fault injection). Input: as fuzz_line. On top of fuzz_line's
 * checks it asserts:
 *  - every call of the chopper comes from a well-formed line, on this
 *    harness's own reading: printable, checksum right if any, word `sb` in
 *    any case, the id this drive's or 0, exactly one value that is a decimal
 *    in the protocol's grammar within 0..50000 Hz, whose correctly rounded
 *    float32 (strtof, -0 as +0) is the frequency the driver gets;
 *  - conversely every such line calls the chopper exactly once and answers
 *    nothing (or the injected failure's error); an `sb` line for this drive
 *    with a bad value answers `invalid value` / `value out of range` and a
 *    wrong count `invalid command format`, with no call;
 *  - the omitted rows never reach the HAL (fuzz_hal.c checks every get and
 *    set) and their paths appear in no reply (discovery included);
 *  - after the input, `r axis0.encoder.pos_abs` answers `invalid property`
 *    and the port's rows read back. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "brake_port.h"
#include "fuzz_hal.h"

static void port_setup(daran_drive_t *drive, fuzz_hal_t *hal, const uint8_t *data);
static void port_before(const char *line, size_t len);
static void port_after(const char *line, size_t len, daran_result_t result, int motor);
static void port_end(daran_drive_t *drive, fuzz_hal_t *hal);
static int read_sb(const char *line, size_t len, float *hz);

#define FUZZ_LINE_EXTRA_WORDS "sb"
#define FUZZ_LINE_SETUP(drive, hal, data) port_setup((drive), (hal), (data))
#define FUZZ_LINE_BEFORE(line, len) port_before((line), (len))
#define FUZZ_LINE_AFTER(line, len, result, motor) port_after((line), (len), (result), (motor))
#define FUZZ_LINE_END(drive, hal) port_end((drive), (hal))
#include "fuzz_line.c"

static struct {
    fuzz_hal_t *hal;
    const char *line; /* the line being run */
    size_t len;
    size_t calls;     /* chopper calls during it */
    float hz;
} port;

static daran_result_t chopper_set(void *ctx, float hz)
{
    (void)ctx;
    float want = 0.0f;
    FUZZ_CHECK(port.line != NULL, "chopper called outside a line");
    /* the line must be one this harness reads as a good `sb` for this drive */
    int kind = read_sb(port.line, port.len, &want);
    FUZZ_CHECK(kind == 1, "chopper called (%g Hz) for \"%s\", not a good sb line (%d)",
               (double)hz, fuzz_escape(port.line, port.len), kind);
    FUZZ_CHECK(memcmp(&hz, &want, sizeof hz) == 0,
               "chopper got %a Hz, the line says %a: \"%s\"", (double)hz, (double)want,
               fuzz_escape(port.line, port.len));
    port.calls++;
    port.hz = hz;
    return fuzz_hal_port_call(port.hal, 1u, &hz, sizeof hz);
}

static brake_chopper_t chopper = {chopper_set, NULL};

brake_chopper_t *brake_chopper_of(void *ctx)
{
    (void)ctx;
    return &chopper;
}

/* The protocol's number grammar (spec 5): [+-]?(d+(.d*)?|.d+)([eE][+-]?d+)?,
 * written out here rather than taken from the core. */
static bool number_grammar(const char *p, size_t n)
{
    size_t i = 0, digits = 0;
    if (i < n && (p[i] == '+' || p[i] == '-')) {
        i++;
    }
    while (i < n && p[i] >= '0' && p[i] <= '9') {
        i++;
        digits++;
    }
    if (i < n && p[i] == '.') {
        i++;
        while (i < n && p[i] >= '0' && p[i] <= '9') {
            i++;
            digits++;
        }
    }
    if (digits == 0u) {
        return false;
    }
    if (i < n && (p[i] == 'e' || p[i] == 'E')) {
        i++;
        if (i < n && (p[i] == '+' || p[i] == '-')) {
            i++;
        }
        size_t e = 0;
        while (i < n && p[i] >= '0' && p[i] <= '9') {
            i++;
            e++;
        }
        if (e == 0u) {
            return false;
        }
    }
    return i == n;
}

/* This harness's reading of an `sb` line addressed to this drive (or to
 * every drive): 0 not such a line (another word, another drive, refused
 * before the address); 1 good, *hz the value; 2 wrong field count;
 * 3 invalid value; 4 out of range. */
static int read_sb(const char *line, size_t len, float *hz)
{
    int motor = addressed_motor(line, len); /* fuzz_line.c: printable, checksum, id */
    uint32_t own = port.hal->props[DARAN_PROP_CAN_NODE_ID].u32;
    if (motor < 0 || (motor != 0 && (uint32_t)motor != own)) {
        return 0;
    }
    const char *star = memchr(line, '*', len);
    size_t payload = star != NULL ? (size_t)(star - line) : len;
    view_t f[8];
    size_t count = split(line, payload, f, 8);
    if (count < 2u || !word_is(f[0], "sb")) {
        return 0;
    }
    if (count != 3u) {
        return 2;
    }
    if (!number_grammar(f[2].p, f[2].n)) {
        return 3;
    }
    char text[DARAN_LINE_MAX + 1];
    memcpy(text, f[2].p, f[2].n);
    text[f[2].n] = '\0';
    float v = strtof(text, NULL); /* glibc: correctly rounded, inf beyond FLT_MAX */
    if (isinf(v) || !(v >= 0.0f && v <= 50000.0f)) {
        return 4;
    }
    *hz = v + 0.0f;
    return 1;
}

/* Replies must not name a row the port left out. */
static void port_write(void *ctx, const char *line, size_t len)
{
    static const char *const gone[] = {"encoder.spi_buff_", "encoder.pos_abs", "encoder.turn_abs"};
    for (size_t i = 0; i < sizeof gone / sizeof gone[0]; i++) {
        size_t n = strlen(gone[i]);
        for (size_t k = 0; k + n <= len; k++) {
            FUZZ_CHECK(memcmp(line + k, gone[i], n) != 0, "a reply names an omitted row: \"%s\"",
                       fuzz_escape(line, len));
        }
    }
    fuzz_write(ctx, line, len);
}

static void port_setup(daran_drive_t *drive, fuzz_hal_t *hal, const uint8_t *data)
{
    /* bound again with the checking reply sink, then the port's table */
    static const daran_hal_t checked = {FUZZ_HAL_FUNCTIONS, .write = port_write};
    static const daran_hal_t checked_forwarding = {FUZZ_HAL_FUNCTIONS, .write = port_write,
                                                   .forward = fuzz_forward};
    if (daran_init(drive, (data[1] & 4u) != 0u ? &checked_forwarding : &checked, hal) != DARAN_OK) {
        fuzz_fail("daran_init refused a complete HAL");
    }
    if (brake_port_attach(drive) != DARAN_OK) {
        fuzz_fail("the example's command table was refused");
    }
    hal->props[DARAN_PROP_BRAKE_TEMPERATURE].f32 = 41.5f;
    port.hal = hal;
    port.line = NULL;
}

static void port_before(const char *line, size_t len)
{
    port.line = line;
    port.len = len;
    port.calls = 0;
}

static void port_after(const char *line, size_t len, daran_result_t result, int motor)
{
    (void)motor;
    fuzz_hal_t *h = port.hal;
    float hz = 0.0f;
    int kind = read_sb(line, len, &hz);
    const char *what = fuzz_escape(line, len);
    switch (kind) {
    case 1:
        FUZZ_CHECK(port.calls == 1u, "good sb line made %zu chopper calls: \"%s\"", port.calls,
                   what);
        if (h->failed) {
            FUZZ_CHECK(result == h->fail_answer, "chopper refused, answered %d: \"%s\"",
                       (int)result, what);
        } else {
            FUZZ_CHECK(result == DARAN_OK && h->n_replies == 0u,
                       "good sb line answered %d (%zu lines): \"%s\"", (int)result, h->n_replies,
                       what);
        }
        break;
    case 2:
        FUZZ_CHECK(result == DARAN_ERR_INVALID_FORMAT && port.calls == 0u,
                   "sb with a wrong count answered %d: \"%s\"", (int)result, what);
        break;
    case 3:
        FUZZ_CHECK(result == DARAN_ERR_INVALID_VALUE && port.calls == 0u,
                   "sb with a bad number answered %d: \"%s\"", (int)result, what);
        break;
    case 4:
        FUZZ_CHECK(result == DARAN_ERR_OUT_OF_RANGE && port.calls == 0u,
                   "sb out of range answered %d: \"%s\"", (int)result, what);
        break;
    default:
        FUZZ_CHECK(port.calls == 0u, "chopper called for a line that is no sb: \"%s\"", what);
        break;
    }
    port.line = NULL;
}

/* After the input: the omitted rows answer `invalid property`, the port's
 * rows read back, `h` lists `sb` last. */
static void port_end(daran_drive_t *drive, fuzz_hal_t *hal)
{
    static const char omitted_line[] = "r axis0.encoder.pos_abs";
    static const char temperature_line[] = "r axis0.brake.temperature";
    fuzz_hal_arm(hal, 0, 0);
    fuzz_hal_clear(hal);
    FUZZ_CHECK(daran_process_line(drive, omitted_line, sizeof omitted_line - 1u) ==
                       DARAN_ERR_INVALID_PROPERTY &&
                   hal->n_replies == 1u && hal->n_get_other == 0u,
               "an omitted row read: \"%s\"", fuzz_escape(hal->out, hal->out_len));
    fuzz_hal_clear(hal);
    char want[DARAN_FLOAT_TEXT_MAX + 1];
    size_t n = daran_format_float(hal->props[DARAN_PROP_BRAKE_TEMPERATURE].f32, want,
                                  sizeof want);
    FUZZ_CHECK(daran_process_line(drive, temperature_line, sizeof temperature_line - 1u) ==
                       DARAN_OK &&
                   hal->n_replies == 1u && hal->out_len > n && memcmp(hal->out, want, n) == 0,
               "the port's row read \"%s\"", fuzz_escape(hal->out, hal->out_len));
}
