/* Unity assertions over the recording HAL (daran_recorder.h).
 *
 * Header only: include it in a Unity test file after unity.h; it needs
 * Unity's headers on the include path and links nothing but the recorder.
 * Every assertion is a macro, so a failure is reported at the test's line;
 * its message says what was expected and lists the HAL calls and replies
 * the recorder saw since its last daran_recorder_clear().
 *
 *   daran_recorder_clear(&rec);
 *   (void)daran_process_line(&drive, "w axis1.controller.config.pos_gain 20", 38);
 *   TEST_ASSERT_DARAN_SET_F32(&rec, DARAN_PROP_POS_GAIN, 20.0f);
 *   TEST_ASSERT_DARAN_REPLY(&rec, "");
 *
 * Expected replies are written with "\n" line ends; the assertion matches
 * them against the configured line end (DARAN_REPLY_CRLF). */
#ifndef DARAN_RECORDER_UNITY_H
#define DARAN_RECORDER_UNITY_H

#include <stdio.h>
#include <string.h>

#include "unity.h"

#include "daran_recorder.h"

/** No HAL set, move or action since the last clear. */
#define TEST_ASSERT_DARAN_NO_EFFECT(rec) daran_unity_no_effect((rec), __LINE__)
/** Exactly one mutating call, a set of @p prop; evaluates to the value set. */
#define TEST_ASSERT_DARAN_SET(rec, prop) daran_unity_set((rec), (prop), __LINE__)
/** Exactly one mutating call, a set of @p prop with that value. */
#define TEST_ASSERT_DARAN_SET_U32(rec, prop, expected) \
    daran_unity_set_u32((rec), (prop), (uint32_t)(expected), __LINE__)
#define TEST_ASSERT_DARAN_SET_U64(rec, prop, expected) \
    daran_unity_set_u64((rec), (prop), (uint64_t)(expected), __LINE__)
#define TEST_ASSERT_DARAN_SET_S32(rec, prop, expected) \
    daran_unity_set_s32((rec), (prop), (int32_t)(expected), __LINE__)
/** The float must be the very one (the core rounds correctly); nan matches nan. */
#define TEST_ASSERT_DARAN_SET_F32(rec, prop, expected) \
    daran_unity_set_f32((rec), (prop), (float)(expected), __LINE__)
/** Exactly one move, of @p kind, then at most the FEED_WATCHDOG action that
 * follows an accepted move (D22), nothing else; evaluates to the move. */
#define TEST_ASSERT_DARAN_MOVE(rec, kind) daran_unity_move((rec), (kind), __LINE__)
/** Exactly one mutating call, the action @p action. */
#define TEST_ASSERT_DARAN_ACTION(rec, action) daran_unity_action((rec), (action), __LINE__)
/** The replies are exactly @p expected ("" for none). */
#define TEST_ASSERT_DARAN_REPLY(rec, expected) daran_unity_reply((rec), (expected), __LINE__)
/** One reply line, `error: <phrase>` (with a right ` *N` tail or none), and
 * no HAL set, move or action. */
#define TEST_ASSERT_DARAN_ERROR(rec, phrase) daran_unity_error((rec), (phrase), __LINE__)

/* ---- what the macros call; not for direct use ---- */

/** @cond INTERNAL */
/* Fail at the test's line with the expectation and what the recorder saw. */
static inline void daran_unity_fail(const daran_recorder_t *rec, int line, const char *expected)
{
    static char calls[1024];
    static char replies[1024];
    static char message[2400];
    (void)daran_recorder_describe(rec, calls, sizeof calls);
    for (char *c = calls; *c != '\0'; c++) {
        if (*c == '\n') {
            *c = ';'; /* Unity prints one line per failure */
        }
    }
    (void)daran_recorder_escape(rec->out, rec->out_len, replies, sizeof replies);
    int len = snprintf(message, sizeof message, "expected %s; HAL calls: %s; replies: \"%s\"%s",
                       expected, calls, replies, rec->out_dropped > 0u ? " (cut)" : "");
    if (len < 0 || (size_t)len >= sizeof message) {
        /* a long expectation: say that the message was cut */
        (void)memcpy(message + sizeof message - 4u, "...", 4u);
    }
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, message);
}

static inline void daran_unity_no_effect(const daran_recorder_t *rec, int line)
{
    if (!daran_recorder_no_effect(rec)) {
        daran_unity_fail(rec, line, "no HAL set, move or action");
    }
}

static inline const daran_call_t *daran_unity_only_set(const daran_recorder_t *rec,
                                                       daran_prop_t prop, int line)
{
    const daran_call_t *set = daran_recorder_first(rec, DARAN_CALL_SET);
    if (daran_recorder_mutations(rec) != 1u || set == NULL || set->prop != prop) {
        char want[160];
        char path[96];
        (void)daran_recorder_prop_path(prop, path, sizeof path);
        (void)snprintf(want, sizeof want, "exactly one HAL call that changes something: set %s", path);
        daran_unity_fail(rec, line, want);
    }
    if (set == NULL) {
        /* Unity built without setjmp returns from a failure: stay defined */
        static const daran_call_t none;
        set = &none;
    }
    return set;
}

static inline daran_value_t daran_unity_set(const daran_recorder_t *rec, daran_prop_t prop, int line)
{
    return daran_unity_only_set(rec, prop, line)->value;
}

static inline void daran_unity_set_u32(const daran_recorder_t *rec, daran_prop_t prop,
                                       uint32_t expected, int line)
{
    if (daran_unity_only_set(rec, prop, line)->value.u32 != expected) {
        char want[64];
        (void)snprintf(want, sizeof want, "the value %lu", (unsigned long)expected);
        daran_unity_fail(rec, line, want);
    }
}

static inline void daran_unity_set_u64(const daran_recorder_t *rec, daran_prop_t prop,
                                       uint64_t expected, int line)
{
    if (daran_unity_only_set(rec, prop, line)->value.u64 != expected) {
        char want[64];
        (void)snprintf(want, sizeof want, "the value %llu", (unsigned long long)expected);
        daran_unity_fail(rec, line, want);
    }
}

static inline void daran_unity_set_s32(const daran_recorder_t *rec, daran_prop_t prop,
                                       int32_t expected, int line)
{
    if (daran_unity_only_set(rec, prop, line)->value.s32 != expected) {
        char want[64];
        (void)snprintf(want, sizeof want, "the value %ld", (long)expected);
        daran_unity_fail(rec, line, want);
    }
}

static inline void daran_unity_set_f32(const daran_recorder_t *rec, daran_prop_t prop,
                                       float expected, int line)
{
    float got = daran_unity_only_set(rec, prop, line)->value.f32;
    if (!(got == expected || (got != got && expected != expected))) {
        char want[64];
        (void)snprintf(want, sizeof want, "the value %.9g", (double)expected);
        daran_unity_fail(rec, line, want);
    }
}

static inline const daran_move_t *daran_unity_move(const daran_recorder_t *rec,
                                                   daran_move_kind_t kind, int line)
{
    const daran_call_t *move = daran_recorder_first(rec, DARAN_CALL_MOVE);
    size_t feeds = daran_recorder_count(rec, DARAN_CALL_ACTION, (int)DARAN_ACTION_FEED_WATCHDOG);
    if (move == NULL || move->move.kind != kind || daran_recorder_count(rec, DARAN_CALL_MOVE, -1) != 1u ||
        feeds > 1u || daran_recorder_mutations(rec) != 1u + feeds) {
        char want[96];
        (void)snprintf(want, sizeof want, "exactly one move %s (then FEED_WATCHDOG)",
                       daran_recorder_move_name(kind));
        daran_unity_fail(rec, line, want);
    }
    if (move == NULL) {
        static const daran_move_t none;
        return &none;
    }
    return &move->move;
}

static inline void daran_unity_action(const daran_recorder_t *rec, daran_action_t action, int line)
{
    const daran_call_t *call = daran_recorder_first(rec, DARAN_CALL_ACTION);
    if (daran_recorder_mutations(rec) != 1u || call == NULL || call->action != action) {
        char want[96];
        (void)snprintf(want, sizeof want, "exactly one HAL call that changes something: action %s",
                       daran_recorder_action_name(action));
        daran_unity_fail(rec, line, want);
    }
}

static inline void daran_unity_reply(const daran_recorder_t *rec, const char *expected, int line)
{
    if (!daran_recorder_reply_equals(rec, expected)) {
        static char want[1100];
        char text[1024];
        (void)snprintf(want, sizeof want, "the reply \"%s\"",
                       daran_recorder_escape(expected, strlen(expected), text, sizeof text));
        daran_unity_fail(rec, line, want);
    }
}

static inline void daran_unity_error(const daran_recorder_t *rec, const char *phrase, int line)
{
    char plain[128];
    char tailed[140];
    if (strlen(phrase) + 10u > sizeof plain) {
        daran_unity_fail(rec, line, "an error phrase shorter than 118 characters");
        return;
    }
    (void)snprintf(plain, sizeof plain, "error: %s", phrase);
    unsigned xor_sum = ' ';
    for (const char *c = plain; *c != '\0'; c++) {
        xor_sum ^= (unsigned char)*c;
    }
    (void)snprintf(tailed, sizeof tailed, "%s *%u\n", plain, xor_sum);
    size_t len = strlen(plain);
    plain[len] = '\n';
    plain[len + 1u] = '\0';
    if (!daran_recorder_reply_equals(rec, plain) && !daran_recorder_reply_equals(rec, tailed)) {
        char want[160];
        (void)snprintf(want, sizeof want, "the reply \"error: %s\"", phrase);
        daran_unity_fail(rec, line, want);
    }
    if (!daran_recorder_no_effect(rec)) {
        daran_unity_fail(rec, line, "no HAL set, move or action after an error");
    }
}
/** @endcond */

#endif /* DARAN_RECORDER_UNITY_H */
