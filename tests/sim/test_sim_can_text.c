/* daran-sim's text forms of a CAN frame (sim_can_text.h): the arguments of
 * `!can` (ids, bytes in one word or several, remote frames, every bad form
 * refused with a reason) and the console's `can ...` line. */
#include <stdio.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_can_text.h"

static daran_can_frame_t f;
static const char *why;

void setUp(void)
{
    memset(&f, 0, sizeof f);
    why = NULL;
}

void tearDown(void)
{
}

/* Split @p text into words and parse them. */
static bool parse(const char *text)
{
    static char buf[256];
    char *argv[16];
    int argc = 0;
    char *tok;
    snprintf(buf, sizeof buf, "%s", text);
    for (tok = strtok(buf, " "); tok != NULL && argc < 16; tok = strtok(NULL, " ")) {
        argv[argc++] = tok;
    }
    return sim_can_text_parse(argc, argv, &f, &why);
}

static void test_a_standard_frame_in_separate_bytes(void)
{
    static const uint8_t bytes[8] = {0x19, 0x79, 0x03, 0, 0, 0, 0, 0};
    TEST_ASSERT_TRUE(parse("01E 19 79 03 00 00 00 00 00"));
    TEST_ASSERT_EQUAL_HEX32(0x01Eu, f.id);
    TEST_ASSERT_EQUAL_UINT8(8u, f.dlc);
    TEST_ASSERT_EQUAL_UINT8(0u, f.flags);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(bytes, f.data, 8);
}

static void test_bytes_may_come_in_one_word_or_several(void)
{
    TEST_ASSERT_TRUE(parse("7e 1979 030000 0000 00"));
    TEST_ASSERT_EQUAL_HEX32(0x07Eu, f.id);
    TEST_ASSERT_EQUAL_UINT8(8u, f.dlc);
    TEST_ASSERT_EQUAL_HEX8(0x03u, f.data[2]);
    TEST_ASSERT_TRUE(parse("9"));
    TEST_ASSERT_EQUAL_UINT8(0u, f.dlc); /* DLC 0 */
}

static void test_extended_and_remote_frames(void)
{
    TEST_ASSERT_TRUE(parse("1FFFFFFF AB"));
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_EXTENDED, f.flags);
    TEST_ASSERT_EQUAL_HEX32(0x1FFFFFFFu, f.id);
    TEST_ASSERT_TRUE(parse("123 R8"));
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE, f.flags);
    TEST_ASSERT_EQUAL_UINT8(8u, f.dlc);
    TEST_ASSERT_TRUE(parse("00000123 R"));
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE | DARAN_CAN_FRAME_EXTENDED, f.flags);
    TEST_ASSERT_EQUAL_UINT8(0u, f.dlc);
}

static void test_bad_forms_are_refused_with_a_reason(void)
{
    static const char *const bad[] = {
        "",                            /* no id */
        "800 00",                      /* standard id above 7FF */
        "1234 00",                     /* 4 digits: neither form */
        "20000000",                    /* extended above 1FFFFFFF */
        "0x1E 00",                     /* hex digits only */
        "-1E",
        "01E 1",                       /* half a byte */
        "01E 0G",
        "01E 00 00 00 00 00 00 00 00 00", /* nine bytes */
        "01E R9",
        "01E R 00",                    /* a remote frame with data */
    };
    size_t k;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        why = NULL;
        if (parse(bad[k]) || why == NULL) {
            FAIL_F("`!can %s` accepted", bad[k]);
        }
    }
}

static void test_the_console_line_shows_time_id_dlc_and_bytes(void)
{
    char line[SIM_CAN_TEXT_LINE_MAX];
    size_t n;
    TEST_ASSERT_TRUE(parse("03E 19 79 03 00 01 00 00 00"));
    n = sim_can_text_format(&f, 1125000u, line);
    TEST_ASSERT_EQUAL_STRING("can 0.001125 03E [8] 19 79 03 00 01 00 00 00\n", line);
    TEST_ASSERT_EQUAL_UINT32(strlen(line), n);
    TEST_ASSERT_TRUE(parse("1ABCDEF0 R2"));
    (void)sim_can_text_format(&f, 86400000000499u, line); /* rounded to the microsecond */
    TEST_ASSERT_EQUAL_STRING("can 86400.000000 1ABCDEF0 [2] remote\n", line);
    TEST_ASSERT_TRUE(parse("1FFFFFFF FF FF FF FF FF FF FF FF"));
    n = sim_can_text_format(&f, UINT64_MAX, line); /* the longest line fits */
    TEST_ASSERT_EQUAL_UINT32(strlen(line), n);
    TEST_ASSERT_TRUE(n < SIM_CAN_TEXT_LINE_MAX);
    TEST_ASSERT_EQUAL_INT('\n', line[n - 1u]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_standard_frame_in_separate_bytes);
    RUN_TEST(test_bytes_may_come_in_one_word_or_several);
    RUN_TEST(test_extended_and_remote_frames);
    RUN_TEST(test_bad_forms_are_refused_with_a_reason);
    RUN_TEST(test_the_console_line_shows_time_id_dlc_and_bytes);
    return UNITY_END();
}
