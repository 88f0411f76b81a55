/* A recording mock HAL and reply sink shared by the core's unit tests.
 *
 * The mock keeps a property store, logs every set/move/action call (getters
 * are only counted: the core may read while it validates), captures the
 * replies and forwarded lines, reacts to actions and writes the way a drive
 * does (st -> idle + estop flag, sc clears, requested_state -> current_state)
 * and can make the Nth call of chosen kinds fail (fault injection).
 *
 * The logging and the fault injection are the installed recording HAL's
 * (testkit/include/daran_recorder.h): each mock embeds a daran_recorder_t
 * whose inner HAL is the mock's store, and its observer keeps the calls
 * below, so the double an adopter installs runs under every unit suite.
 *
 * The UPPER-CASE helpers are macros so that a failure points at the test's
 * line, not at this file. */
#ifndef MOCK_HAL_H
#define MOCK_HAL_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "unity.h"

#include "daran_ascii.h"
#include "daran_recorder.h"

#define MOCK_CALLS_MAX (DARAN_RX_RING_SIZE / 4 + 128) /* a ring full of "u 1" lines */
#define MOCK_OUT_MAX 16384
#define MOCK_FWD_MAX 32
#define MOCK_INSTANCES 3

/* A logged call: the recorder's record (kind, prop and value for SET, move
 * for MOVE, action for ACTION, and what the call returned). */
typedef daran_call_kind_t mock_call_kind_t;
typedef daran_call_t mock_call_t;
#define MOCK_CALL_SET DARAN_CALL_SET
#define MOCK_CALL_MOVE DARAN_CALL_MOVE
#define MOCK_CALL_ACTION DARAN_CALL_ACTION

/* Kinds a fault injection may target. */
#define MOCK_FAIL_GET DARAN_RECORDER_FAIL_GET
#define MOCK_FAIL_SET DARAN_RECORDER_FAIL_SET
#define MOCK_FAIL_MOVE DARAN_RECORDER_FAIL_MOVE
#define MOCK_FAIL_ACTION DARAN_RECORDER_FAIL_ACTION

typedef struct mock_forward {
    uint8_t id;
    size_t len;
    char line[DARAN_LINE_MAX + 16];
} mock_forward_t;

typedef struct mock {
    daran_drive_t drive;
    /* The drive's port description: mock_hal_fns at first; a test changes a
     * member (the forward hook, the CAN functions) in place. */
    daran_hal_t hal;
    daran_value_t props[DARAN_PROP_COUNT];
    bool react; /* model state changes on actions/sets (default true) */

    /* Every HAL call goes through it (logging, fault injection), then to
     * the store above. */
    daran_recorder_t rec;
    mock_call_t calls[MOCK_CALLS_MAX]; /* set/move/action, as the recorder saw them */
    size_t n_calls;
    size_t n_gets;

    char out[MOCK_OUT_MAX + 1];
    size_t out_len;
    size_t n_writes;

    mock_forward_t fwd[MOCK_FWD_MAX];
    size_t n_fwd;

    char last[DARAN_LINE_MAX * 4 + 64]; /* last line sent, for messages */
} mock_t;

/* Instance @p slot (0..MOCK_INSTANCES-1) reset to defaults with node id
 * @p id and bound to a fresh daran_drive_t. */
mock_t *mock_new_slot(int slot, uint32_t id);
/* Slot 0 with node id 1. */
mock_t *mock_new(void);
/* Slot 0 with node id @p id. */
mock_t *mock_new_id(uint32_t id);

extern const daran_hal_t mock_hal_fns;
void mock_write(void *ctx, const char *line, size_t len);
void mock_forward(void *ctx, uint8_t id, const char *line, size_t len);

/* Register the recording forward hook (m->hal.forward). */
void mock_enable_forward(mock_t *m);

/* Forget replies, calls, getter count and forwards. */
void mock_clear(mock_t *m);

/* Feed bytes through daran_rx_write() in chunks of @p chunk (0: 32) with a
 * daran_poll() after each, so the ring never overruns. */
void mock_send_bytes(mock_t *m, const void *data, size_t len, size_t chunk);
/* Send @p text as is (it must hold its own '\n'). */
void mock_send_raw(mock_t *m, const char *text);
/* Clear, then send @p line followed by '\n'. */
void mock_send_line(mock_t *m, const char *line);

/* Fault injection: the @p nth (1-based) call among the kinds in @p mask
 * returns @p result instead of doing anything. prop >= 0 restricts the
 * count to get/set of that property. */
void mock_fail(mock_t *m, unsigned mask, unsigned nth, daran_result_t result, int prop);

/* Count of logged calls of a kind. */
size_t mock_count(const mock_t *m, mock_call_kind_t kind);
size_t mock_count_action(const mock_t *m, daran_action_t action);

/* XOR of the bytes of a NUL-terminated string. */
unsigned mock_xor(const char *s);
/* "<payload> *N" into buf (N = XOR of "<payload> "); returns buf. */
char *mock_with_checksum(char *buf, size_t size, const char *payload);
/* A reply line as the core must write it: payload, optional checksum, '\n'. */
char *mock_reply_line(char *buf, size_t size, const char *payload, bool checksum);

/* C-escaped copy of s for messages (static buffer; two rotating slots). */
const char *mock_escape(const char *s, size_t len);

/* Location-carrying checks behind the macros below. */
void mock_check(bool ok, const mock_t *m, const char *file, int line, const char *fmt, ...);
void mock_assert_reply(mock_t *m, const char *expected, const char *file, int line);
void mock_assert_no_effect(const mock_t *m, const char *file, int line);
void mock_assert_error(mock_t *m, const char *line_text, const char *phrase, const char *file,
                       int line);
void mock_assert_silent_no_effect(mock_t *m, const char *line_text, const char *file, int line);
const daran_move_t *mock_assert_move(mock_t *m, const char *line_text, const char *file,
                                     int line);
daran_value_t mock_assert_set(mock_t *m, const char *line_text, daran_prop_t prop,
                              const char *file, int line);
void mock_assert_action(mock_t *m, const char *line_text, daran_action_t action,
                        const char *file, int line);
const char *mock_assert_query(mock_t *m, const char *line_text, const char *file, int line);

typedef struct mock_move_expect {
    daran_move_kind_t kind;
    unsigned given;
    float pos, vel, torque, rate, kp, kd;
} mock_move_expect_t;
void mock_assert_move_equals(const mock_t *m, const daran_move_t *got,
                             const mock_move_expect_t *want, const char *file, int line);

/* Send a line; assert the reply (exactly @p expected, '\n' included). */
#define ASSERT_REPLY(m, expected) mock_assert_reply((m), (expected), __FILE__, __LINE__)
/* No HAL setter, move or action was called since the last clear. */
#define ASSERT_NO_EFFECT(m) mock_assert_no_effect((m), __FILE__, __LINE__)
/* Send line; assert "error: <phrase>\n" and no HAL setter/move/action. */
#define ASSERT_ERROR(m, line, phrase) mock_assert_error((m), (line), (phrase), __FILE__, __LINE__)
/* Send line; assert no reply and no HAL setter/move/action. */
#define ASSERT_SILENT(m, line) mock_assert_silent_no_effect((m), (line), __FILE__, __LINE__)
/* Send line; assert no reply, exactly one move then one FEED_WATCHDOG (D22). */
#define ASSERT_MOVE(m, line) mock_assert_move((m), (line), __FILE__, __LINE__)
/* Send line; assert no reply and exactly one set of prop; returns the value. */
#define ASSERT_SET(m, line, prop) mock_assert_set((m), (line), (prop), __FILE__, __LINE__)
/* Send line; assert no reply and exactly one action call of that kind. */
#define ASSERT_ACTION(m, line, action) mock_assert_action((m), (line), (action), __FILE__, __LINE__)
/* Send line; assert no setter/move/action and one reply line; returns it. */
#define ASSERT_QUERY(m, line) mock_assert_query((m), (line), __FILE__, __LINE__)
#define ASSERT_MOVE_EQUALS(m, got, ...)                                    \
    do {                                                                   \
        const mock_move_expect_t want_ = __VA_ARGS__;                      \
        mock_assert_move_equals((m), (got), &want_, __FILE__, __LINE__);   \
    } while (0)

/* True when the line's command word is a multi-motor one (ms mt mq mp mv mc). */
bool mock_uses_multi(const char *line);
/* Tests of the multi-motor commands skip themselves in a build without them. */
#define SKIP_IF_NO_MULTI()                \
    do {                                  \
        if (!DARAN_ENABLE_MULTI_MOTOR)    \
            TEST_IGNORE();                \
    } while (0)
#define SKIP_LINE_IF_NO_MULTI(line)                                \
    do {                                                           \
        if (!DARAN_ENABLE_MULTI_MOTOR && mock_uses_multi(line))    \
            TEST_IGNORE();                                         \
    } while (0)

/* Tests generated from tables: each row is its own Unity case, with a
 * name built at run time; the case gets its row back as its argument. */
typedef void (*mock_row_fn)(const void *row);
typedef void (*mock_test_fn)(void);
typedef struct mock_suite_case {
    mock_row_fn fn;     /* a table row's case, or */
    mock_test_fn test;  /* a plain test function */
    const void *row;
    int line;
} mock_suite_case_t;
typedef struct mock_suite {
    mock_suite_case_t cases[1200];
    char names[1200][112];
    size_t count;
} mock_suite_t;
/* Add a case; @p line is where the table lives (reports point there). */
void mock_suite_add_at(mock_suite_t *s, mock_row_fn fn, const void *row, int line,
                       const char *fmt, ...);
#define mock_suite_add(s, fn, row, ...) mock_suite_add_at((s), (fn), (row), __LINE__, __VA_ARGS__)
/* Add a plain test function under its own name. */
void mock_suite_add_test_at(mock_suite_t *s, mock_test_fn fn, int line, const char *name);
#define mock_suite_add_test(s, fn) mock_suite_add_test_at((s), (fn), __LINE__, #fn)
/* Run every case added, inside the current UNITY_BEGIN()/UNITY_END(). */
void mock_suite_run(mock_suite_t *s);

/* A printf-style note in the test output (Unity 2.4.3 has no TEST_MESSAGE). */
void mock_message(const char *fmt, ...);
/* Fail the current test with a printf-style message, at the caller's line. */
void mock_fail_at(int line, const char *fmt, ...);
#define TEST_FAIL_MESSAGE_F(...) mock_fail_at(__LINE__, __VA_ARGS__)

#endif /* MOCK_HAL_H */
