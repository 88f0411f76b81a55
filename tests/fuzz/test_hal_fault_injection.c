/* HAL fault injection: a port whose Nth call fails, for every N across a
 * realistic session, must make the core answer that failure (D26: a result
 * outside the protocol's errors answers `motor fault`) and leave it able to
 * run the next line: the failed line, sent again, works. Getters and
 * mutating calls (set, move, action) are failed separately. */
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"

#include "fuzz_hal.h"

/* Fail the current test at @p line with a formatted message (Unity 2.4.3
 * has no TEST_PRINTF). */
static void fail_at(int line, const char *fmt, ...)
{
    static char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, text);
}
#define FAIL_F(...) fail_at(__LINE__, __VA_ARGS__)

/* Every line succeeds on a fresh drive with id 1 when nothing fails. */
static const char *const session[] = {
    "t 1 10 0 25",
    "q 1 50.0 7.5 2.5",
    "p 0 10 5 3",
    "v 1 20 3 1",
    "v 1 12.5 2.5 2",
    "c 1 0.1 0 1",
    "c 1 0.1 0.02 6",
    "d 1 10 0 0.5 0.1 0.01",
    "ms 1 120 5 10",
    "mq 0 0",
    "ms 1 10 0 25",
    "mt 1 1",
    "w axis1.controller.config.pos_gain 25",
    "w config.uart_baudrate 9600 1",
    "w axis0.output_shaft.circular_setpoint_max 180 *5",
    "r axis1.output_shaft.pos_setpoint",
    "r serial_number 1",
    "f 1",
    "g 1",
    "i 1",
    "e 1",
    "u 1",
    "sz 1",
    "ss 1",
    "se 1",
    "st 1",
    "sc 1",
    "w axis1.requested_state 8",
    "t 1 12.5",
    /* zero rates, s32, error registers, S-curve timing (spec section 10) */
    "t 1 30 0 0",
    "q 1 20 30 0",
    "v 1 10 0 2",
    "c 1 1 0 6",
    "w axis1.motor.config.direction -1",
    "r axis1.encoder.pos_abs",
    "w axis1.error 0",
    "w axis1.trap_traj.config.traj_mode 2",
    "ms 1 120 5 10",
    "mq 0 0",
    /* the vendor library's repeated call: the running move's own target
     * again (this HAL's trajectory_done reads 0), duration 0 (D41) */
    "ms 1 120 0 0",
    "mq 0 0",
    "sr 1",
};
#define SESSION_LEN (sizeof session / sizeof session[0])

typedef struct run {
    daran_drive_t drive;
    fuzz_hal_t hal;
} run_t;

/* The drive and its recording HAL; start() makes them fresh for each
 * session, setUp() for each test. */
static run_t run;

void setUp(void)
{
    memset(&run, 0, sizeof run);
}

void tearDown(void)
{
}

static char *with_checksum_fixed(const char *line, char *buf, size_t size)
{
    /* "…*5" in the table means "add the right checksum here". */
    const char *star = strchr(line, '*');
    if (star == NULL) {
        snprintf(buf, size, "%s", line);
        return buf;
    }
    unsigned x = 0;
    for (const char *c = line; c < star; c++) {
        x ^= (unsigned char)*c;
    }
    snprintf(buf, size, "%.*s*%u", (int)(star - line), line, x);
    return buf;
}

static daran_result_t send(const char *text)
{
    char line[160];
    with_checksum_fixed(text, line, sizeof line);
    fuzz_hal_clear(&run.hal);
    return daran_process_line(&run.drive, line, strlen(line));
}

static void start(void)
{
    fuzz_hal_init(&run.hal, 1u);
    fuzz_bind(&run.drive, &run.hal, false);
}

/* Mutating calls (or getter calls) the whole session makes when nothing
 * fails; every line must succeed. */
static uint32_t calls_in_clean_session(bool getters)
{
    start();
    size_t total = 0;
    for (size_t i = 0; i < SESSION_LEN; i++) {
        daran_result_t r = send(session[i]);
        if (r != DARAN_OK) {
            FAIL_F("clean session: \"%s\" answered %d: %.*s", session[i], (int)r,
                   (int)run.hal.out_len, run.hal.out);
        }
        total += getters ? run.hal.n_get : fuzz_hal_mutations(&run.hal);
    }
    return (uint32_t)total;
}

static void check_session_with_failure(uint32_t nth, int result, bool getter)
{
    start();
    if (getter) {
        fuzz_hal_arm_get(&run.hal, nth, result);
    } else {
        fuzz_hal_arm(&run.hal, nth, result);
    }
    daran_result_t want = (result > 0 && result < (int)DARAN_ERR_NO_REPLY)
                              ? (daran_result_t)result
                              : DARAN_ERR_MOTOR_FAULT;
    bool seen = false;
    for (size_t i = 0; i < SESSION_LEN; i++) {
        daran_result_t r = send(session[i]);
        bool failed_here = getter ? run.hal.get_failed : run.hal.failed;
        if (!failed_here) {
            if (r != DARAN_OK) {
                FAIL_F("N=%u: \"%s\" failed (%d) without an injected failure", nth,
                       session[i], (int)r);
            }
            continue;
        }
        seen = true;
        /* D24: `e` reads a register other than axis0.error whose read fails
         * as 0 when axis0.error's summary bit for it is clear (the session's
         * drive has no error bit): a full report, no error line. */
        if (getter && strcmp(session[i], "e 1") == 0 &&
            run.hal.get_failed_prop != DARAN_PROP_AXIS_ERROR &&
            run.hal.get_failed_prop != DARAN_PROP_CAN_NODE_ID) {
            if (r != DARAN_OK || run.hal.n_replies != 7u) {
                FAIL_F("N=%u: \"e 1\" with a failed read of register %d answered %d in %u lines, "
                       "want the 7-line report", nth, (int)run.hal.get_failed_prop, (int)r,
                       (unsigned)run.hal.n_replies);
            }
            continue;
        }
        bool feed_only = !getter && run.hal.n_move == 1u &&
                         run.hal.last_call == 'a' && run.hal.last_action == DARAN_ACTION_FEED_WATCHDOG &&
                         run.hal.failed_was_last;
        if (feed_only) {
            /* D22: a failed watchdog feed after an accepted move is not answered. */
            TEST_ASSERT_EQUAL_INT64(DARAN_OK, r);
            TEST_ASSERT_EQUAL_INT64(0, run.hal.n_replies);
        } else {
            char expect[96];
            int n = snprintf(expect, sizeof expect, "error: %s", daran_result_phrase(want));
            if (r != want || run.hal.n_replies != 1u || run.hal.out_len < (size_t)n ||
                memcmp(run.hal.out, expect, (size_t)n) != 0) {
                FAIL_F("N=%u result %d: \"%s\" answered %d \"%.*s\", want \"%s\"", nth, result,
                       session[i], (int)r, (int)run.hal.out_len, run.hal.out, expect);
            }
            if (getter && fuzz_hal_mutations(&run.hal) != 0u) {
                FAIL_F("N=%u: a failed getter still let \"%s\" reach the HAL", nth, session[i]);
            }
            /* Recovery: the same line again works (the injection fired once). */
            r = send(session[i]);
            if (r != DARAN_OK) {
                FAIL_F("N=%u: \"%s\" failed again after recovery (%d)", nth, session[i],
                       (int)r);
            }
        }
    }
    if (!seen) {
        FAIL_F("N=%u: the injection never fired", nth);
    }
}

static void test_each_failing_hal_call_is_answered_and_the_line_works_again(void)
{
    uint32_t k = calls_in_clean_session(false);
    TEST_ASSERT_TRUE(k >= 20u);
    static const int results[] = {DARAN_ERR_MOTOR_FAULT, DARAN_ERR_OUT_OF_RANGE,
                                  DARAN_ERR_BAD_ARGUMENT, 99};
    for (size_t r = 0; r < sizeof results / sizeof results[0]; r++) {
        for (uint32_t n = 1; n <= k; n++) {
            check_session_with_failure(n, results[r], false);
        }
    }
}

static void test_each_failing_getter_is_answered_without_effect(void)
{
    uint32_t k = calls_in_clean_session(true);
    TEST_ASSERT_TRUE(k >= 20u);
    for (uint32_t n = 1; n <= k; n++) {
        check_session_with_failure(n, DARAN_ERR_MOTOR_FAULT, true);
        check_session_with_failure(n, 1234, true);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_each_failing_hal_call_is_answered_and_the_line_works_again);
    RUN_TEST(test_each_failing_getter_is_answered_without_effect);
    return UNITY_END();
}
