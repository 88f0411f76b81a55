/* The recording HAL and the reply checks the fuzz harnesses share.
 *
 * The HAL behaves like a small drive (property store, state, flags) so that
 * fuzzed sessions reach deep into the handlers, logs every call into a hash
 * (so two runs can be compared for invariant 6), and checks on the way in
 * what the core promises the HAL: only writable properties are written, every
 * written value is in its documented range, every move is finite and valid.
 * It can also fail its Nth mutating call (fault injection).
 *
 * Every violated invariant ends in fuzz_fail(): a message on stderr, then
 * abort(), which libFuzzer and the standalone replay both report. */
#ifndef FUZZ_HAL_H
#define FUZZ_HAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

#if defined(__GNUC__) || defined(__clang__)
#define FUZZ_NORETURN __attribute__((noreturn))
#define FUZZ_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define FUZZ_NORETURN
#define FUZZ_PRINTF(a, b)
#endif

typedef struct fuzz_hal {
    daran_value_t props[DARAN_PROP_COUNT];

    /* counts since the last fuzz_hal_clear() */
    size_t n_get;
    size_t n_get_other; /* getters other than axis0.config.can_node_id */
    size_t n_set;
    size_t n_move;
    size_t n_action;
    size_t n_port;      /* calls of a port's own hardware (fuzz_hal_port_call) */
    daran_prop_t last_set_prop;
    daran_value_t last_set_value;
    daran_action_t last_action;
    char last_call; /* 's'et, 'm'ove, 'a'ction or 'p'ort: the last mutating call; 0 none */
    uint32_t period_writes; /* accepted sets of axis0.telemetry.period, ever (not cleared) */

    /* fault injection: the fail_nth-th mutating call (set/move/action/port,
     * counted since fuzz_hal_arm()) returns fail_result; 0 = off */
    uint32_t fail_nth;
    uint32_t mutating_seen;
    int fail_result;
    uint32_t fail_get_nth; /* the same for getters, counted separately */
    uint32_t gets_seen;
    bool failed;          /* a mutating call returned an error since the last clear */
    bool failed_was_last; /* ... and no mutating call followed it */
    daran_result_t fail_answer; /* the reply the core owes for it (D26) */
    bool get_failed;            /* an injected getter failure happened */
    daran_prop_t get_failed_prop; /* ... on this property */

    uint64_t hash; /* every mutating call and reply, in order */

    /* called at every HAL call and reply, e.g. to play an interrupt that
     * pushes bytes while the core runs a line; NULL: none */
    void (*on_call)(void *ctx);
    void *on_call_ctx;

    /* replies since the last clear */
    char out[4096];
    size_t out_len;
    size_t n_replies;
    size_t n_error_replies;

    /* forwarded lines since the last clear */
    size_t n_forward;
    uint8_t forward_id;
    size_t forward_len;
    char forward_line[DARAN_LINE_MAX + 8];
} fuzz_hal_t;

/* The HAL's four functions, their context a fuzz_hal_t. */
daran_result_t fuzz_hal_get(void *ctx, daran_prop_t prop, daran_value_t *out);
daran_result_t fuzz_hal_set(void *ctx, daran_prop_t prop, daran_value_t value);
daran_result_t fuzz_hal_move(void *ctx, const daran_move_t *move);
daran_result_t fuzz_hal_action(void *ctx, daran_action_t action);
#define FUZZ_HAL_FUNCTIONS \
    .get = fuzz_hal_get, .set = fuzz_hal_set, .move = fuzz_hal_move, .action = fuzz_hal_action
/* The four with fuzz_write, and with fuzz_forward too. */
extern const daran_hal_t fuzz_hal_fns;
extern const daran_hal_t fuzz_hal_forwarding;

/* Defaults like a fresh drive: id @p id, closed loop, no flags. */
void fuzz_hal_init(fuzz_hal_t *h, uint32_t id);
/* Forget counts, replies and forwards (not the store or the hash). */
void fuzz_hal_clear(fuzz_hal_t *h);
/* Fail the @p nth mutating call from now on with @p result (0: off). */
void fuzz_hal_arm(fuzz_hal_t *h, uint32_t nth, int result);
/* Fail the @p nth getter call from now on with @p result (0: off). */
void fuzz_hal_arm_get(fuzz_hal_t *h, uint32_t nth, int result);
size_t fuzz_hal_mutations(const fuzz_hal_t *h);

/* A call of a port's own hardware (fuzz_port.c's brake chopper), made by a
 * port command's handler: counted and hashed (with @p tag and @p data) as a
 * mutating call, so invariants 2 and 3 and fault injection cover it.
 * Returns DARAN_OK, or the injected failure. */
daran_result_t fuzz_hal_port_call(fuzz_hal_t *h, uint32_t tag, const void *data, size_t len);

/* daran_write_fn / daran_forward_fn with a fuzz_hal_t context. Each reply
 * line is checked against invariant 4 as it arrives. */
void fuzz_write(void *ctx, const char *line, size_t len);
void fuzz_forward(void *ctx, uint8_t id, const char *line, size_t len);

/* Bind @p drive to @p h (HAL, reply sink and, if asked, the forward hook). */
void fuzz_bind(daran_drive_t *drive, fuzz_hal_t *h, bool forward);

/* Invariant 4 for one reply line: 1..DARAN_REPLY_MAX bytes, printable ASCII,
 * exactly one line end at its end (CR LF with DARAN_REPLY_CRLF), a " *N"
 * tail with the right N, an error phrase from the protocol's list; the only
 * other replies with a ':' are `e`'s "register: u32" lines. */
void fuzz_check_reply_line(const char *line, size_t len);

void fuzz_fail(const char *fmt, ...) FUZZ_NORETURN FUZZ_PRINTF(1, 2);
#define FUZZ_CHECK(cond, ...)       \
    do {                            \
        if (!(cond)) {              \
            fuzz_fail(__VA_ARGS__); \
        }                           \
    } while (0)

/* C-escaped copy for messages (static buffer). */
const char *fuzz_escape(const char *s, size_t len);

/* 64-bit FNV-1a step. */
uint64_t fuzz_hash(uint64_t h, const void *data, size_t len);

/* The libFuzzer entry point every harness defines. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif /* FUZZ_HAL_H */
