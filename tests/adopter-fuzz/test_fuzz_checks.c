/* The fuzz harness's own reading of the protocol (testkit/fuzz/fuzz_checks.c
 * and fuzz_recording.c): each check must refuse what breaks the protocol,
 * or the fuzz target would pass a port that does. */
#include <stdio.h>
#include <string.h>

#include "daran_fuzz.h"
#include "unity.h"

/* The line end this build's replies carry (DARAN_REPLY_CRLF). */
#if DARAN_REPLY_CRLF
#define END "\r\n"
#define OTHER_END "\n"
#else
#define END "\n"
#define OTHER_END "\r\n"
#endif

void setUp(void) {}
void tearDown(void) {}

/* The reply checker on a NUL-terminated line. */
static const char *problem(const char *line)
{
    return daran_fuzz_reply_problem(line, strlen(line));
}

static int motor(const char *line)
{
    return daran_fuzz_line_motor(line, strlen(line), NULL, 0);
}

static void test_core_replies_are_well_formed(void)
{
    TEST_ASSERT_NULL(problem("1.5 -2" END));
    TEST_ASSERT_NULL(problem("error: invalid motor" END));
    TEST_ASSERT_NULL(problem("axis: 0" END));
    /* "0 0" XOR " " is 0 ^ ' ' ^ 0 ^ ' ' = 0x30 ^ 0x20 ^ 0x30 ^ 0x20 = 0 */
    TEST_ASSERT_NULL(problem("0 0 *0" END));
    TEST_ASSERT_NULL(problem("error: checksum mismatch *107" END));
}

static void test_a_reply_without_its_line_end_is_refused(void)
{
    TEST_ASSERT_NOT_NULL(problem("1.5"));
    TEST_ASSERT_NOT_NULL(problem("1.5" OTHER_END));
    TEST_ASSERT_NOT_NULL(problem("1.5\r\n" END));
    TEST_ASSERT_NOT_NULL(problem("" END));
}

static void test_a_reply_that_is_not_printable_ascii_is_refused(void)
{
    static const char nul_inside[] = "1\0002" END;
    TEST_ASSERT_NOT_NULL(problem("41.5 \xc2\xb0" "C" END));
    TEST_ASSERT_NOT_NULL(problem("1\t2" END));
    TEST_ASSERT_NOT_NULL(problem("1\r2" END));
    TEST_ASSERT_NOT_NULL(daran_fuzz_reply_problem(nul_inside, sizeof nul_inside - 1u));
}

static void test_a_reply_longer_than_reply_max_is_refused(void)
{
    char line[DARAN_REPLY_MAX + 1];
    memset(line, 'x', sizeof line);
    memcpy(line + sizeof line - (sizeof END - 1u), END, sizeof END - 1u);
    TEST_ASSERT_NOT_NULL(daran_fuzz_reply_problem(line, sizeof line));
    TEST_ASSERT_NULL(daran_fuzz_reply_problem(line + 1, sizeof line - 1u));
}

static void test_a_wrong_or_malformed_checksum_tail_is_refused(void)
{
    TEST_ASSERT_NOT_NULL(problem("0 0 *1" END));    /* wrong */
    TEST_ASSERT_NOT_NULL(problem("0 0 *00" END));   /* leading zero */
    TEST_ASSERT_NOT_NULL(problem("0 0*0" END));     /* no space before '*' */
    TEST_ASSERT_NOT_NULL(problem("0 0 *" END));     /* no digits */
    TEST_ASSERT_NOT_NULL(problem("0 0 *1234" END)); /* four digits */
    TEST_ASSERT_NOT_NULL(problem("a*b 0" END));     /* a '*' inside */
}

static void test_an_error_with_an_unknown_phrase_is_refused(void)
{
    TEST_ASSERT_NOT_NULL(problem("error: no such thing" END));
    TEST_ASSERT_NOT_NULL(problem("error:invalid motor" END));
    TEST_ASSERT_NOT_NULL(problem("error: Invalid motor" END));
    TEST_ASSERT_NOT_NULL(problem("error" END));
}

/* The id cases use ids up to 63, the protocol's default limit. */
#define NEEDS_IDS_UP_TO_63()                                         \
    do {                                                             \
        if (DARAN_MOTOR_ID_MAX < 63) {                               \
            TEST_IGNORE_MESSAGE("this build's DARAN_MOTOR_ID_MAX < 63"); \
        }                                                            \
    } while (0)

static void test_lines_are_read_for_the_id_they_carry(void)
{
    NEEDS_IDS_UP_TO_63();
    TEST_ASSERT_EQUAL_INT(2, motor("t 2 10"));
    TEST_ASSERT_EQUAL_INT(2, motor("  T\t2 10 \r"));
    TEST_ASSERT_EQUAL_INT(5, motor("r axis5.motor.error"));
    TEST_ASSERT_EQUAL_INT(5, motor("r axis5.motor.error 3 4")); /* D9: the id first */
    TEST_ASSERT_EQUAL_INT(3, motor("r config.uart_baudrate 3"));
    TEST_ASSERT_EQUAL_INT(0, motor("r config.uart_baudrate"));
    TEST_ASSERT_EQUAL_INT(4, motor("w config.uart_baudrate 9600 4"));
    TEST_ASSERT_EQUAL_INT(0, motor("w axis0.config.can_node_id 5"));
    TEST_ASSERT_EQUAL_INT(0, motor("mq 0 1"));
}

static void test_ids_follow_the_number_grammar(void)
{
    char beyond[32];
    NEEDS_IDS_UP_TO_63();
    (void)snprintf(beyond, sizeof beyond, "t %d 1", DARAN_MOTOR_ID_MAX + 1);
    TEST_ASSERT_EQUAL_INT(5, motor("t 5e0 1"));
    TEST_ASSERT_EQUAL_INT(5, motor("t 50e-1 1"));
    TEST_ASSERT_EQUAL_INT(5, motor("t +5 1"));
    TEST_ASSERT_EQUAL_INT(5, motor("t 05.000 1"));
    TEST_ASSERT_EQUAL_INT(0, motor("t -0 1"));
    TEST_ASSERT_EQUAL_INT(63, motor("t .63e2 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t 1.5 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t -1 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor(beyond));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t 1e999 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t x 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("r axis.motor.error"));
}

static void test_lines_every_drive_answers_have_no_id(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor(""));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t"));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("x 2 1"));       /* unknown word */
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t 2 \x01"));    /* character */
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t 2 10 *0"));   /* checksum mismatch */
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("t 2 10 *x"));   /* malformed */
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, motor("r config.x 1 2"));
    char longest[DARAN_LINE_MAX + 2];
    memset(longest, ' ', sizeof longest);
    memcpy(longest, "t 2", 3);
    TEST_ASSERT_EQUAL_INT(2, daran_fuzz_line_motor(longest, DARAN_LINE_MAX, NULL, 0));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE,
                          daran_fuzz_line_motor(longest, DARAN_LINE_MAX + 1u, NULL, 0));
}

static void test_a_right_checksum_keeps_the_id(void)
{
    char line[32] = "t 2 10 ";
    unsigned x = 0;
    for (size_t i = 0; line[i] != '\0'; i++) {
        x ^= (unsigned char)line[i];
    }
    size_t n = strlen(line);
    line[n++] = '*';
    n += (size_t)snprintf(line + n, sizeof line - n, "%u", x);
    TEST_ASSERT_EQUAL_INT(2, daran_fuzz_line_motor(line, n, NULL, 0));
}

static void test_port_words_are_commands_of_the_build(void)
{
    static const char *const words[] = {"sb"};
    TEST_ASSERT_EQUAL_INT(3, daran_fuzz_line_motor("SB 3 1", 6, words, 1));
    TEST_ASSERT_EQUAL_INT(DARAN_FUZZ_EVERY_DRIVE, daran_fuzz_line_motor("SB 3 1", 6, NULL, 0));
}

static void test_a_recording_gives_its_requests_as_seeds(void)
{
    static const char text[] = "# header\n"
                               "0.0000\tf 1 \n"
                               "<0.0010\t0 0\n"
                               "\n"
                               "1.5\tt 1 10\r\n";
    char out[sizeof text];
    size_t len = 0;
    unsigned first = 0;
    unsigned last = 0;
    daran_fuzz_recording_t rec;
    daran_fuzz_recording_open(&rec, text, sizeof text - 1u);
    TEST_ASSERT_EQUAL_INT(1, daran_fuzz_recording_next(&rec, out, sizeof out, &len, &first, &last));
    TEST_ASSERT_EQUAL_STRING_LEN("f 1 \nt 1 10\r\n", out, len);
    TEST_ASSERT_EQUAL_UINT64(13, len);
    TEST_ASSERT_EQUAL_UINT(2, first);
    TEST_ASSERT_EQUAL_UINT(5, last);
    TEST_ASSERT_EQUAL_INT(0, daran_fuzz_recording_next(&rec, out, sizeof out, &len, &first, &last));
}

static void test_a_long_recording_is_cut_into_seeds_of_whole_lines(void)
{
    static char text[64 * 40];
    size_t n = 0;
    for (int i = 0; i < 64; i++) {
        n += (size_t)snprintf(text + n, sizeof text - n, "0.%04d\tt 1 %d.123456789 0.5 25 \n", i, i);
    }
    static char out[sizeof text];
    size_t len = 0;
    size_t total = 0;
    unsigned first = 0;
    unsigned last = 0;
    unsigned seeds = 0;
    daran_fuzz_recording_t rec;
    daran_fuzz_recording_open(&rec, text, n);
    while (daran_fuzz_recording_next(&rec, out, sizeof out, &len, &first, &last) == 1) {
        TEST_ASSERT_TRUE(len <= DARAN_FUZZ_SEED_MAX);
        TEST_ASSERT_EQUAL_INT('\n', out[len - 1u]);
        TEST_ASSERT_EQUAL_INT('t', out[0]);
        total += len;
        seeds++;
    }
    TEST_ASSERT_TRUE(seeds > 1u);
    TEST_ASSERT_EQUAL_UINT(64, last);
    TEST_ASSERT_EQUAL_UINT64(n - 64u * 7u, total); /* every request, less "0.0000\t" */
}

static void test_a_line_of_another_form_is_refused_with_its_number(void)
{
    static const char text[] = "# header\n0.5\tf 1\nf 1\n";
    char out[sizeof text];
    size_t len = 0;
    unsigned first = 0;
    unsigned last = 0;
    daran_fuzz_recording_t rec;
    daran_fuzz_recording_open(&rec, text, sizeof text - 1u);
    TEST_ASSERT_EQUAL_INT(-1, daran_fuzz_recording_next(&rec, out, sizeof out, &len, &first, &last));
    TEST_ASSERT_EQUAL_UINT(3, first);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_core_replies_are_well_formed);
    RUN_TEST(test_a_reply_without_its_line_end_is_refused);
    RUN_TEST(test_a_reply_that_is_not_printable_ascii_is_refused);
    RUN_TEST(test_a_reply_longer_than_reply_max_is_refused);
    RUN_TEST(test_a_wrong_or_malformed_checksum_tail_is_refused);
    RUN_TEST(test_an_error_with_an_unknown_phrase_is_refused);
    RUN_TEST(test_lines_are_read_for_the_id_they_carry);
    RUN_TEST(test_ids_follow_the_number_grammar);
    RUN_TEST(test_lines_every_drive_answers_have_no_id);
    RUN_TEST(test_a_right_checksum_keeps_the_id);
    RUN_TEST(test_port_words_are_commands_of_the_build);
    RUN_TEST(test_a_recording_gives_its_requests_as_seeds);
    RUN_TEST(test_a_long_recording_is_cut_into_seeds_of_whole_lines);
    RUN_TEST(test_a_line_of_another_form_is_refused_with_its_number);
    return UNITY_END();
}
