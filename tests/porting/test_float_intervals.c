/* Float rows with interval ranges (DARAN_PORT_RANGE_LIST, "lo..hi"): both
 * ends included, compared as the floats the ends parse to, the value as the
 * float the field parses to; outside answers `value out of range` and the
 * HAL is not called; discovery prints the range. Built against a core of
 * float_interval_options.h (CMakeLists.txt). */
#include <string.h>

#include "unity.h"

#include "daran_ascii.h"
#include "stub_hal.h"

static daran_drive_t drive;
static daran_stub_t stub;
static char reply[512];
static size_t reply_len;

static void collect(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (reply_len + len < sizeof reply) {
        memcpy(reply + reply_len, line, len);
        reply_len += len;
        reply[reply_len] = '\0';
    }
}

static const daran_hal_t collect_port = {DARAN_STUB_HAL_FUNCTIONS, .write = collect};

static const char *send(const char *line)
{
    reply_len = 0;
    reply[0] = '\0';
    stub.sets = 0;
    (void)daran_process_line(&drive, line, strlen(line));
    return reply;
}

void setUp(void)
{
    daran_stub_init(&stub, 1);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive, &collect_port, &stub));
}

void tearDown(void) {}

#define EOL "\r\n"

static void accepted(const char *line, daran_prop_t prop, float want)
{
    TEST_ASSERT_EQUAL_STRING_MESSAGE("", send(line), line);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(1, stub.sets, line);
    TEST_ASSERT_EQUAL_FLOAT_MESSAGE(want, stub.values[prop].f32, line);
}

static void refused(const char *line)
{
    TEST_ASSERT_EQUAL_STRING_MESSAGE("error: value out of range" EOL, send(line), line);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, stub.sets, line);
}

static void test_both_ends_of_0_to_1_are_inside(void)
{
    accepted("w axis0.fan.duty 0", DARAN_PROP_FAN_DUTY, 0.0f);
    accepted("w axis0.fan.duty -0", DARAN_PROP_FAN_DUTY, -0.0f);
    accepted("w axis0.fan.duty 1", DARAN_PROP_FAN_DUTY, 1.0f);
    accepted("w axis0.fan.duty 1.0000000001", DARAN_PROP_FAN_DUTY, 1.0f); /* rounds to 1 */
    accepted("w axis0.fan.duty 0.5", DARAN_PROP_FAN_DUTY, 0.5f);
    accepted("w axis0.fan.duty 1e-30", DARAN_PROP_FAN_DUTY, 1e-30f);
}

static void test_outside_0_to_1_is_refused_without_a_call(void)
{
    refused("w axis0.fan.duty 1.0000001");
    refused("w axis0.fan.duty -1e-30");
    refused("w axis0.fan.duty 2");
    refused("w axis0.fan.duty -1");
    refused("w axis0.fan.duty 1e38");
}

static void test_negative_decimal_and_exponent_ends(void)
{
    accepted("w trim -2.5 1", DARAN_PROP_TRIM, -2.5f);
    accepted("w trim 2.5 1", DARAN_PROP_TRIM, 2.5f);
    accepted("w trim 0 1", DARAN_PROP_TRIM, 0.0f);
    refused("w trim 2.5000002 1");
    refused("w trim -2.5000002 1");
    accepted("w wide_value -1000 1", DARAN_PROP_WIDE_VALUE, -1000.0f);
    accepted("w wide_value 0.1 1", DARAN_PROP_WIDE_VALUE, 0.1f);
    refused("w wide_value 0.10000001 1");
    refused("w wide_value -1000.0001 1");
    /* a range text may start with any digit */
    accepted("w nine 9 1", DARAN_PROP_NINE, 9.0f);
    accepted("w nine 9.25 1", DARAN_PROP_NINE, 9.25f);
    refused("w nine 8.5 1");
    refused("w nine 10 1");
}

static void test_sign_ranges_still_hold_beside_intervals(void)
{
    /* >= 0 takes 0 and -0 (D27) in a build with intervals too */
    accepted("w axis0.output_shaft.load_inertia 0", DARAN_PROP_LOAD_INERTIA, 0.0f);
    accepted("w axis0.output_shaft.load_inertia -0", DARAN_PROP_LOAD_INERTIA, -0.0f);
    refused("w axis0.output_shaft.load_inertia -1e-30");
    refused("w axis0.output_shaft.vel_limit 0");
    accepted("w axis0.output_shaft.vel_limit 5", DARAN_PROP_SHAFT_VEL_LIMIT, 5.0f);
    refused("w axis0.output_shaft.vel_limit -5");
}

static void test_discovery_prints_the_interval(void)
{
    TEST_ASSERT_EQUAL_STRING("axis0.fan.duty f32 rw - 0..1" EOL "end" EOL,
                             send("h 1 properties axis0.fan"));
    TEST_ASSERT_EQUAL_STRING("trim f32 rw deg -2.5..2.5" EOL "end" EOL, send("h 1 properties trim"));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_both_ends_of_0_to_1_are_inside);
    RUN_TEST(test_outside_0_to_1_is_refused_without_a_call);
    RUN_TEST(test_negative_decimal_and_exponent_ends);
    RUN_TEST(test_sign_ranges_still_hold_beside_intervals);
    RUN_TEST(test_discovery_prints_the_interval);
    return UNITY_END();
}
