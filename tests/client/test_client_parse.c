/* daran_client's reply reader: every error phrase back to its result,
 * numbers at the float and integer edges, `e`'s registers, telemetry
 * reports, discovery and help lines, and the `*N` of checksummed replies. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "daran_client.h"
#include "unity.h"

static daran_client_line_t line;

void setUp(void)
{
    memset(&line, 0, sizeof line);
}

void tearDown(void)
{
}

/* text + " *N" + "\r\n" as the drive sends a checksummed line. */
static const char *with_sum(const char *payload)
{
    static char buf[DARAN_CLIENT_LINE_MAX];
    size_t len = strlen(payload);
    memcpy(buf, payload, len);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_seal(buf, sizeof buf - 2u, len, true, &len));
    buf[len - 1u] = '\r';
    buf[len] = '\n';
    buf[len + 1u] = '\0';
    return buf;
}

static daran_result_t read_text(const char *text, bool checksum_expected)
{
    return daran_client_read_line(text, strlen(text), checksum_expected, &line);
}

static void test_every_error_phrase_reads_back_as_its_result(void)
{
    size_t phrases = 0;
    for (unsigned r = 1; r < (unsigned)DARAN_RESULT_COUNT; r++) {
        daran_result_t result = (daran_result_t)r;
        if (result == DARAN_ERR_BAD_ARGUMENT || result == DARAN_ERR_BUILD_MISMATCH) {
            continue; /* never sent on a link */
        }
        char text[64] = "error: ";
        strcat(text, daran_result_phrase(result));
        char plain[72];
        strcpy(plain, text);
        strcat(plain, "\r\n");
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(plain, false));
        TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_ERROR, line.kind);
        TEST_ASSERT_EQUAL_INT_MESSAGE(result, line.error, text);
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum(text), true));
        TEST_ASSERT_EQUAL_INT(result, line.error);
        TEST_ASSERT_TRUE(line.had_checksum);
        phrases++;
    }
    /* section 8's seventeen, the update's four and the gateway's three */
    TEST_ASSERT_EQUAL_UINT64(24, phrases);
}

static void test_an_unknown_phrase_is_not_understood(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, read_text("error: ok\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, read_text("error: bad argument\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, read_text("error: motor idles\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, read_text("error: \r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, read_text("10\x01\r\n", false));
    /* "error:" without its space is not an error line */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("error:x\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_TEXT, line.kind);
}

static void test_a_reply_checksum_is_verified_and_cut_off(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum("10 -3"), true));
    TEST_ASSERT_EQUAL_UINT64(5, line.len);
    TEST_ASSERT_EQUAL_MEMORY("10 -3", line.payload, 5);
    /* one bit off in the payload, and a wrong sum */
    char damaged[32];
    strcpy(damaged, with_sum("10 -3"));
    damaged[0] = '2';
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH, read_text(damaged, true));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH, read_text(damaged, false));
    /* missing where the request had one; malformed ones are no checksum */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_CHECKSUM, read_text("10 -3\r\n", true));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_CHECKSUM, read_text("10 -3 *1234\r\n", true));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_CHECKSUM, read_text("10 -3 *256\r\n", true));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_CHECKSUM, read_text("10 -3*8\r\n", true));
    /* a plain reply read without expecting one keeps all its text, `\n` ends too */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("10 -3\n", false));
    TEST_ASSERT_FALSE(line.had_checksum);
    TEST_ASSERT_EQUAL_UINT64(5, line.len);
}

static uint32_t bits_of(float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

static daran_client_number_t number(const char *text)
{
    daran_client_number_t n;
    TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, daran_client_parse_number(text, strlen(text), &n),
                                  text);
    return n;
}

static void test_floats_are_read_correctly_rounded_at_their_edges(void)
{
    TEST_ASSERT_EQUAL_HEX32(bits_of(FLT_MAX), bits_of(number("3.4028235e+38").f32));
    TEST_ASSERT_EQUAL_HEX32(bits_of(FLT_MIN), bits_of(number("1.1754944e-38").f32));
    TEST_ASSERT_EQUAL_HEX32(0x00000001u, bits_of(number("1.0e-45").f32)); /* smallest subnormal */
    TEST_ASSERT_EQUAL_HEX32(bits_of(0.1f), bits_of(number("0.1").f32));
    TEST_ASSERT_EQUAL_HEX32(bits_of(1e-5f), bits_of(number("0.00001").f32));
    TEST_ASSERT_EQUAL_HEX32(bits_of(1.5e-7f), bits_of(number("1.5e-07").f32));
    TEST_ASSERT_EQUAL_HEX32(0x80000000u, bits_of(number("-0").f32));
    /* a tie between two floats rounds to the even one: 2^24 + 1 */
    TEST_ASSERT_EQUAL_HEX32(bits_of(16777216.0f), bits_of(number("16777217").f32));
    TEST_ASSERT_TRUE(isnan(number("nan").f32));
    TEST_ASSERT_TRUE(isinf(number("inf").f32) && number("inf").f32 > 0);
    TEST_ASSERT_TRUE(isinf(number("-inf").f32) && number("-inf").f32 < 0);
    daran_client_number_t n;
    const char *bad[] = {"", "-", "1e", "0x10", "1..2", "--1", "-nan", "infinity", "1 2"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_INVALID_VALUE,
                                      daran_client_parse_number(bad[i], strlen(bad[i]), &n), bad[i]);
    }
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_client_parse_number("4e38", 4, &n));
}

static void test_integers_keep_every_digit_and_their_sign(void)
{
    uint64_t u64 = 0;
    uint32_t u32 = 0;
    int32_t s32 = 0;
    daran_client_number_t serial = number("18446744073709551615");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_u64(&serial, &u64));
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, u64);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_OUT_OF_RANGE, daran_client_number_u32(&serial, &u32));
    daran_client_number_t big = number("4294967295");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_u32(&big, &u32));
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, u32);
    daran_client_number_t lowest = number("-2147483648");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_s32(&lowest, &s32));
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, s32);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_OUT_OF_RANGE, daran_client_number_u32(&lowest, &u32));
    daran_client_number_t below = number("-2147483649");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_OUT_OF_RANGE, daran_client_number_s32(&below, &s32));
    daran_client_number_t above = number("2147483648");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_OUT_OF_RANGE, daran_client_number_s32(&above, &s32));
    daran_client_number_t minus_one = number("-1");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_s32(&minus_one, &s32));
    TEST_ASSERT_EQUAL_INT32(-1, s32);
    daran_client_number_t minus_zero = number("-0");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_u32(&minus_zero, &u32));
    TEST_ASSERT_EQUAL_UINT32(0, u32);
    daran_client_number_t half = number("1.5");
    TEST_ASSERT_FALSE(half.is_integer);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_client_number_u32(&half, &u32));
    /* too many digits for u64: still a float, not an integer */
    daran_client_number_t huge = number("18446744073709551616");
    TEST_ASSERT_FALSE(huge.is_integer);
    TEST_ASSERT_EQUAL_HEX32(bits_of(18446744073709551616.0f), bits_of(huge.f32));
}

static void test_a_values_line_splits_into_its_numbers(void)
{
    daran_client_number_t values[3];
    size_t count = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("100.5 -3.25e-07\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_values(&line, values, 3, 2, &count));
    TEST_ASSERT_EQUAL_UINT64(2, count);
    TEST_ASSERT_EQUAL_HEX32(bits_of(100.5f), bits_of(values[0].f32));
    TEST_ASSERT_EQUAL_HEX32(bits_of(-3.25e-7f), bits_of(values[1].f32));
    /* the wrong count, or a field that is no number */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_parse_values(&line, values, 3, 3, &count));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_parse_values(&line, values, 1, 0, &count));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("10 x\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_parse_values(&line, values, 3, 0, &count));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_parse_values(&line, values, 3, 0, &count));
    /* `i`: three integers, the serial number whole */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("10203 4 18446744073709551615\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_values(&line, values, 3, 3, &count));
    uint64_t serial = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_u64(&values[2], &serial));
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, serial);
}

static void test_the_seven_error_registers_are_read_by_name(void)
{
    const char *lines[] = {"axis: 16384", "motor: 65536", "encoder: 0", "controller: 1",
                           "fet_thermistor: 1", "motor_thermistor: 0", "can: 4294967295"};
    const uint32_t expected[] = {0x4000u, 0x10000u, 0, 1, 1, 0, UINT32_MAX};
    daran_client_errors_t errors;
    memset(&errors, 0xA5, sizeof errors);
    for (size_t i = 0; i < DARAN_CLIENT_ERROR_REGISTERS; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum(lines[i]), true));
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_error_line(&line, i, &errors));
        TEST_ASSERT_EQUAL_UINT32(expected[i], errors.reg[i]);
    }
    TEST_ASSERT_EQUAL_STRING("motor_thermistor", daran_client_error_register_name(5));
    TEST_ASSERT_NULL(daran_client_error_register_name(7));
    /* a line in the wrong place, a bad value, a missing space */
    const char *bad[] = {"motor: 1", "axis: -1", "axis: 1.5", "axis:1", "axis: ", "axis: 4294967296"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(bad[i], false));
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_INVALID_VALUE,
                                      daran_client_parse_error_line(&line, 0, &errors), bad[i]);
    }
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("axis: 1", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_client_parse_error_line(&line, 7, &errors));
}

static void test_a_telemetry_report_is_decoded_and_needs_its_checksum(void)
{
    daran_client_report_t report;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum("@12 1.5 -90.25 3.0e+12 16384 1"), false));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_TELEMETRY, line.kind);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_report(&line, &report));
    TEST_ASSERT_EQUAL_UINT8(12, report.id);
    TEST_ASSERT_EQUAL_HEX32(bits_of(1.5f), bits_of(report.time_s));
    TEST_ASSERT_EQUAL_UINT64(4, report.count);
    TEST_ASSERT_EQUAL_HEX32(bits_of(-90.25f), bits_of(report.values[0].f32));
    TEST_ASSERT_EQUAL_HEX32(bits_of(3.0e12f), bits_of(report.values[1].f32));
    uint32_t flags = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_number_u32(&report.values[2], &flags));
    TEST_ASSERT_EQUAL_UINT32(16384, flags);
    /* a report always carries `*N`, asked for or not */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_CHECKSUM, read_text("@1 1.5 10\r\n", false));
    char damaged[64];
    strcpy(damaged, with_sum("@1 1.5 10"));
    damaged[5] = '2';
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH, read_text(damaged, false));
    /* not a report: no id, a blank after '@', no time, too many fields */
    const char *bad[] = {"@", "@ 1 1.5", "@1", "@x 1.5", "@256 1", "@1 1 1 2 3 4 5 6 7 8 9 10",
                         "@1 1.5 ten"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum(bad[i]), false));
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_INVALID_VALUE,
                                      daran_client_parse_report(&line, &report), bad[i]);
    }
    /* nine fields fit */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum("@1 1 1 2 3 4 5 6 7 8 9"), false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_report(&line, &report));
    TEST_ASSERT_EQUAL_UINT64(9, report.count);
}

static void test_discovery_lines_and_their_end_are_read(void)
{
    daran_client_property_t p;
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          read_text("axis0.output_shaft.vel_limit f32 rw r/min >0\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_property(&line, &p));
    TEST_ASSERT_EQUAL_STRING_LEN("axis0.output_shaft.vel_limit", p.path, p.path_len);
    TEST_ASSERT_EQUAL_UINT64(strlen("axis0.output_shaft.vel_limit"), p.path_len);
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_TYPE_F32, p.type);
    TEST_ASSERT_TRUE(p.writable);
    TEST_ASSERT_EQUAL_STRING_LEN("r/min", p.unit, p.unit_len);
    TEST_ASSERT_EQUAL_STRING_LEN(">0", p.range, p.range_len);
    TEST_ASSERT_EQUAL_UINT64(2, p.range_len);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum("serial_number u64 ro -"), true));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_property(&line, &p));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_TYPE_U64, p.type);
    TEST_ASSERT_FALSE(p.writable);
    TEST_ASSERT_EQUAL_UINT64(0, p.unit_len);
    TEST_ASSERT_EQUAL_UINT64(0, p.range_len);
    const char *types[] = {"a f32 ro -", "a u32 ro -", "a s32 ro -", "a u64 ro -", "a bool ro -"};
    for (size_t i = 0; i < 5; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(types[i], false));
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_property(&line, &p));
        TEST_ASSERT_EQUAL_INT((int)i, (int)p.type);
    }
    const char *bad[] = {"a f64 ro -", "a f32 wo -", "a f32 ro", "a f32 ro - >0 extra", "a"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(bad[i], false));
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_INVALID_VALUE, daran_client_parse_property(&line, &p),
                                      bad[i]);
    }
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text(with_sum("end"), true));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_END, line.kind);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_client_parse_property(&line, &p));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("end\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_END, line.kind);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("endx\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_TEXT, line.kind);
}

static void test_a_help_line_gives_its_word_and_arguments(void)
{
    daran_client_help_t help;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("t id pos [vel] [bw]\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_help(&line, &help));
    TEST_ASSERT_EQUAL_STRING_LEN("t", help.word, help.word_len);
    TEST_ASSERT_EQUAL_UINT64(1, help.word_len);
    TEST_ASSERT_EQUAL_STRING_LEN("id pos [vel] [bw]", help.arguments, help.arguments_len);
    TEST_ASSERT_EQUAL_UINT64(strlen("id pos [vel] [bw]"), help.arguments_len);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("mv id\r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_help(&line, &help));
    TEST_ASSERT_EQUAL_STRING_LEN("id", help.arguments, help.arguments_len);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, read_text("  \r\n", false));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_client_parse_help(&line, &help));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_error_phrase_reads_back_as_its_result);
    RUN_TEST(test_an_unknown_phrase_is_not_understood);
    RUN_TEST(test_a_reply_checksum_is_verified_and_cut_off);
    RUN_TEST(test_floats_are_read_correctly_rounded_at_their_edges);
    RUN_TEST(test_integers_keep_every_digit_and_their_sign);
    RUN_TEST(test_a_values_line_splits_into_its_numbers);
    RUN_TEST(test_the_seven_error_registers_are_read_by_name);
    RUN_TEST(test_a_telemetry_report_is_decoded_and_needs_its_checksum);
    RUN_TEST(test_discovery_lines_and_their_end_are_read);
    RUN_TEST(test_a_help_line_gives_its_word_and_arguments);
    return UNITY_END();
}
