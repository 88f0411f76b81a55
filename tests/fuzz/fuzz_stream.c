/* Harness 1: the byte path (daran_rx_byte / daran_rx_write -> ring -> framer
 * -> daran_poll) under arbitrary bytes, chunking and producer/consumer
 * interleaving, with overruns.
 *
 * Input: 4 seed bytes, 1 pattern byte, then the data. Two lanes run
 * interleaved, each a drive instance fed by a simulated interrupt: lane A
 * gets the data, lane B the data reversed, with different chunking. The
 * pattern picks chunk sizes, how often the main loop polls (so the ring
 * overruns), byte-wise or block pushes, and whether the "interrupt" also
 * fires while the core is running a line (from inside HAL calls and replies).
 *
 * Oracle: each lane keeps a reference instance fed through
 * daran_process_line() with the lines the accepted bytes form, a line that
 * lost any byte being answered `line too long` (D3). The stream instance's
 * replies and HAL calls (hashed in order) must equal the reference's. This
 * proves invariants 1 (with the sanitizers), 4 (every reply is checked on
 * the way out), 6 (two interleaved instances, each equal to its reference,
 * even when one runs inside the other's HAL call) and that no damaged line
 * runs. Then invariant 5: after the garbage, a '\n' and one valid line, the
 * line executes exactly once. */
#include <string.h>

#include "fuzz_hal.h"

typedef struct lane {
    daran_drive_t drive;
    fuzz_hal_t hal;
    daran_drive_t ref;
    fuzz_hal_t ref_hal;

    const uint8_t *data;
    size_t len;
    size_t pos;
    bool reversed;
    uint32_t rng;
    uint8_t pattern;
    uint32_t lost;
    size_t newlines_queued;
    unsigned nesting;

    /* the reference framer */
    char line[DARAN_LINE_MAX + 1];
    size_t line_len;
    bool damaged;
} lane_t;

static lane_t lanes[2];

static uint32_t next(lane_t *l)
{
    l->rng ^= l->rng << 13;
    l->rng ^= l->rng >> 17;
    l->rng ^= l->rng << 5;
    return l->rng;
}

static uint8_t byte_at(const lane_t *l, size_t i)
{
    return l->reversed ? l->data[l->len - 1u - i] : l->data[i];
}

/* The reference sees exactly the bytes the ring accepted. */
static void ref_byte(lane_t *l, uint8_t b, bool accepted)
{
    if (!accepted) {
        l->damaged = true; /* even a lost '\n': its line runs on into the next */
        return;
    }
    if (b != '\n') {
        if (l->line_len <= DARAN_LINE_MAX) {
            l->line[l->line_len++] = (char)b;
        }
        return;
    }
    l->newlines_queued++;
    if (l->damaged) {
        /* Any line over DARAN_LINE_MAX answers exactly `line too long`. */
        static const char long_line[DARAN_LINE_MAX + 1] = {0};
        (void)daran_process_line(&l->ref, long_line, sizeof long_line);
    } else {
        (void)daran_process_line(&l->ref, l->line, l->line_len);
    }
    l->line_len = 0;
    l->damaged = false;
}

static void push(lane_t *l, size_t n)
{
    bool bytewise = (l->pattern & 0x10u) != 0u;
    while (n > 0u && l->pos < l->len) {
        uint8_t b = byte_at(l, l->pos);
        size_t run = 1;
        bool ok;
        if (bytewise || l->reversed) {
            ok = daran_rx_byte(&l->drive, b);
            ref_byte(l, b, ok);
        } else {
            /* a block: learn per byte what was accepted from the ring's
             * drop counter, which counts every byte refused */
            run = n < l->len - l->pos ? n : l->len - l->pos;
            for (size_t i = 0; i < run; i++) {
                uint32_t before = daran_rx_dropped(&l->drive);
                size_t q = daran_rx_write(&l->drive, &l->data[l->pos + i], 1);
                ok = q == 1u;
                FUZZ_CHECK(daran_rx_dropped(&l->drive) - before == (ok ? 0u : 1u),
                           "drop counter disagrees with daran_rx_write");
                ref_byte(l, l->data[l->pos + i], ok);
                if (!ok) {
                    l->lost++;
                }
            }
            l->pos += run;
            n -= run;
            continue;
        }
        if (!ok) {
            l->lost++;
        }
        l->pos++;
        n--;
    }
}

static size_t chunk(lane_t *l)
{
    static const uint32_t max[4] = {1, 7, 40, 300};
    return 1u + next(l) % max[l->pattern & 3u];
}

static bool want_poll(lane_t *l)
{
    switch ((l->pattern >> 2) & 3u) {
    case 0: return true;
    case 1: return (next(l) & 1u) != 0u;
    case 2: return (next(l) & 7u) == 0u;
    default: return (next(l) & 63u) == 0u;
    }
}

/* The interrupt firing while the main loop runs a line of this lane. */
static void interrupt(void *ctx)
{
    lane_t *l = ctx;
    if ((l->pattern & 0x20u) == 0u || l->nesting > 0u || (next(l) & 3u) != 0u) {
        return;
    }
    /* Pattern bit 7: the interrupt belongs to the other instance, so one
     * instance's bytes arrive while the other runs a line. */
    lane_t *target = (l->pattern & 0x80u) != 0u ? &lanes[l == &lanes[0] ? 1 : 0] : l;
    if (target->nesting > 0u) {
        return;
    }
    l->nesting++;
    target->nesting++;
    push(target, 1u + next(l) % 16u);
    target->nesting--;
    l->nesting--;
}

static void lane_init(lane_t *l, const uint8_t *data, size_t len, bool reversed, uint32_t seed,
                      uint8_t pattern, uint32_t id)
{
    memset(l, 0, sizeof *l);
    l->data = data;
    l->len = len;
    l->reversed = reversed;
    l->rng = seed != 0u ? seed : 0x9e3779b9u;
    l->pattern = pattern;
    fuzz_hal_init(&l->hal, id);
    fuzz_hal_init(&l->ref_hal, id);
    bool fwd = (pattern & 0x40u) != 0u;
    fuzz_bind(&l->drive, &l->hal, fwd);
    fuzz_bind(&l->ref, &l->ref_hal, fwd);
    l->hal.on_call = interrupt;
    l->hal.on_call_ctx = l;
}

static void lane_poll(lane_t *l)
{
    size_t lines = daran_poll(&l->drive);
    (void)lines;
}

static void lane_step(lane_t *l)
{
    push(l, chunk(l));
    if (want_poll(l)) {
        lane_poll(l);
    }
}

static void lane_check_equal(lane_t *l, const char *when)
{
    FUZZ_CHECK(daran_rx_dropped(&l->drive) == l->lost, "%s: %u bytes dropped, %u refused", when,
               (unsigned)daran_rx_dropped(&l->drive), (unsigned)l->lost);
    FUZZ_CHECK(l->hal.hash == l->ref_hal.hash,
               "%s: lane %s differs from its line-by-line reference (replies or HAL calls)",
               when, l->reversed ? "B" : "A");
}

/* Invariant 5: whatever came before, '\n' then a valid line runs it once. */
static void lane_sentinel(lane_t *l)
{
    static const char line[] = "w axis0.output_shaft.circular_setpoint_max 1234.5\n";
    lane_poll(l);
    l->pattern &= (uint8_t)~0x20u; /* no more interrupts: the ring must have room */
    FUZZ_CHECK(daran_rx_byte(&l->drive, '\n'), "an empty ring refused a byte");
    ref_byte(l, '\n', true);
    lane_poll(l);
    lane_check_equal(l, "after the data");

    fuzz_hal_clear(&l->hal);
    FUZZ_CHECK(daran_rx_write(&l->drive, line, sizeof line - 1u) == sizeof line - 1u,
               "an empty ring refused a line");
    FUZZ_CHECK(daran_poll(&l->drive) == 1u, "the sentinel line was not framed once");
    FUZZ_CHECK(l->hal.n_set == 1u && l->hal.n_move == 0u && l->hal.n_action == 0u &&
                   l->hal.n_replies == 0u &&
                   l->hal.last_set_prop == DARAN_PROP_CIRCULAR_SETPOINT_MAX &&
                   l->hal.last_set_value.f32 == 1234.5f,
               "invariant 5: the valid line after garbage made %zu sets, %zu moves, %zu "
               "actions, replies \"%s\"",
               l->hal.n_set, l->hal.n_move, l->hal.n_action,
               fuzz_escape(l->hal.out, l->hal.out_len));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 5u) {
        return 0;
    }
    uint32_t seed = (uint32_t)data[0] | (uint32_t)data[1] << 8 | (uint32_t)data[2] << 16 |
                    (uint32_t)data[3] << 24;
    uint8_t pattern = data[4];
    const uint8_t *text = data + 5;
    size_t len = size - 5u;

    lane_t *a = &lanes[0], *b = &lanes[1];
    lane_init(a, text, len, false, seed, pattern, 1u);
    lane_init(b, text, len, true, seed * 2654435761u + 1u, (uint8_t)(pattern ^ 0x15u), 2u);

    while (a->pos < a->len || b->pos < b->len) {
        unsigned order = next(a) & 3u;
        if (order != 1u) {
            lane_step(a);
        }
        if (order != 2u) {
            lane_step(b);
        }
    }
    lane_sentinel(a);
    lane_sentinel(b);
    return 0;
}
