/* daran_client's reply shapes and retry rule: what each command is answered
 * with when it succeeds, and that only queries are ever sent twice. */
#include <string.h>

#include "daran_client.h"
#include "unity.h"

void setUp(void)
{
}

void tearDown(void)
{
}

typedef struct expectation {
    daran_client_command_t command;
    const char *word;
    daran_client_reply_shape_t shape;
    daran_client_class_t cls;
} expectation_t;

/* protocol.md section 4, 10.4 and 11.1, written out once more by hand so
 * the table in daran_client.h is checked against an independent reading */
static const expectation_t expected[] = {
    {DARAN_CLIENT_CMD_T, "t", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_Q, "q", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_P, "p", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_V, "v", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_C, "c", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_D, "d", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_MS, "ms", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_PRESET},
    {DARAN_CLIENT_CMD_MT, "mt", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_MQ, "mq", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_MP, "mp", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_MV, "mv", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_MC, "mc", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_MOTION},
    {DARAN_CLIENT_CMD_R, "r", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_W, "w", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_WRITE},
    {DARAN_CLIENT_CMD_SS, "ss", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_SE, "se", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_SR, "sr", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_SC, "sc", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_SZ, "sz", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_ST, "st", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_U, "u", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_SYSTEM},
    {DARAN_CLIENT_CMD_F, "f", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_G, "g", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_I, "i", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_E, "e", DARAN_CLIENT_REPLY_ERROR_LINES, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_H, "h", DARAN_CLIENT_REPLY_UNTIL_QUIET, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_H_PROPERTIES, "h", DARAN_CLIENT_REPLY_UNTIL_END, DARAN_CLIENT_CLASS_QUERY},
    {DARAN_CLIENT_CMD_UB, "ub", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UW, "uw", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UV, "uv", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UG, "ug", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UY, "uy", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UA, "ua", DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_CLASS_UPDATE},
    {DARAN_CLIENT_CMD_UQ, "uq", DARAN_CLIENT_REPLY_ONE_LINE, DARAN_CLIENT_CLASS_UPDATE},
};

static void test_every_command_has_its_reply_shape_and_class(void)
{
    TEST_ASSERT_EQUAL_UINT64(DARAN_CLIENT_CMD_COUNT, sizeof expected / sizeof expected[0]);
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; i++) {
        const expectation_t *e = &expected[i];
        TEST_ASSERT_EQUAL_STRING(e->word, daran_client_command_word(e->command));
        TEST_ASSERT_EQUAL_INT_MESSAGE(e->shape, daran_client_reply_shape(e->command), e->word);
        TEST_ASSERT_EQUAL_INT_MESSAGE(e->cls, daran_client_command_class(e->command), e->word);
    }
}

static void test_only_queries_and_repeatable_update_steps_may_be_retried(void)
{
    size_t retried = 0;
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; i++) {
        /* an update step is idempotent (a chunk by its offset) but the commit */
        bool again = expected[i].cls == DARAN_CLIENT_CLASS_QUERY ||
                     (expected[i].cls == DARAN_CLIENT_CLASS_UPDATE &&
                      strcmp(expected[i].word, "ug") != 0);
        TEST_ASSERT_EQUAL_INT_MESSAGE(again, daran_client_may_retry(expected[i].command),
                                      expected[i].word);
        retried += again ? 1u : 0u;
    }
    TEST_ASSERT_EQUAL_UINT64(13, retried); /* r f g i e h, h properties; ub uw uv uy ua uq */
    TEST_ASSERT_FALSE(daran_client_may_retry(DARAN_CLIENT_CMD_MQ));
    TEST_ASSERT_FALSE(daran_client_may_retry(DARAN_CLIENT_CMD_SZ));
}

static void test_a_value_outside_the_enum_gets_the_safe_answers(void)
{
    daran_client_command_t bogus = DARAN_CLIENT_CMD_COUNT;
    TEST_ASSERT_NULL(daran_client_command_word(bogus));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_REPLY_SILENT, daran_client_reply_shape(bogus));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_CLASS_MOTION, daran_client_command_class(bogus));
    TEST_ASSERT_FALSE(daran_client_may_retry(bogus));
}

/* A raw line's reply shape comes from its first word (and `properties` as
 * the third field of `h`), whatever blanks stand between the fields. */
static void test_a_raw_lines_shape_comes_from_its_word(void)
{
    static const struct {
        const char *line;
        daran_client_reply_shape_t shape;
        bool known;
    } lines[] = {
        {"t 1 10 0 25", DARAN_CLIENT_REPLY_SILENT, true},
        {"  f 1", DARAN_CLIENT_REPLY_ONE_LINE, true},
        {"r axis1.vbus_voltage", DARAN_CLIENT_REPLY_ONE_LINE, true},
        {"e\t2", DARAN_CLIENT_REPLY_ERROR_LINES, true},
        {"h 1", DARAN_CLIENT_REPLY_UNTIL_QUIET, true},
        {"h 1 properties", DARAN_CLIENT_REPLY_UNTIL_END, true},
        {"h  1  properties axis0.telemetry", DARAN_CLIENT_REPLY_UNTIL_END, true},
        {"h 1 propertiesx", DARAN_CLIENT_REPLY_UNTIL_QUIET, true},
        {"ms 1 1 2 3", DARAN_CLIENT_REPLY_SILENT, true},
        {"mss 1", DARAN_CLIENT_REPLY_SILENT, false},
        {"m 1", DARAN_CLIENT_REPLY_SILENT, false},
        {"blink 1", DARAN_CLIENT_REPLY_SILENT, false},
        {"", DARAN_CLIENT_REPLY_SILENT, false},
        {"   ", DARAN_CLIENT_REPLY_SILENT, false},
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        bool known = !lines[i].known;
        TEST_ASSERT_EQUAL_INT_MESSAGE(lines[i].shape,
                                      daran_client_line_shape(lines[i].line,
                                                              strlen(lines[i].line), &known),
                                      lines[i].line);
        TEST_ASSERT_EQUAL_MESSAGE(lines[i].known, known, lines[i].line);
    }
    /* only len bytes are read: "f 1" cut to "f" is still f */
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_REPLY_ONE_LINE, daran_client_line_shape("fx", 1, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_REPLY_SILENT, daran_client_line_shape(NULL, 3, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_command_has_its_reply_shape_and_class);
    RUN_TEST(test_only_queries_and_repeatable_update_steps_may_be_retried);
    RUN_TEST(test_a_value_outside_the_enum_gets_the_safe_answers);
    RUN_TEST(test_a_raw_lines_shape_comes_from_its_word);
    return UNITY_END();
}
