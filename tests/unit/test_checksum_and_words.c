/* Unit tests of the optional `*N` checksum (spec section 2, D4-D6), of
 * field splitting (blanks, tabs) and of command words (case, unknown words). */
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

/* ---- checksum ---- */

static void test_spec_example_t_with_checksum_is_accepted(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT64(83, mock_xor("t 1 10 0 25 "));
    const daran_move_t *mv = ASSERT_MOVE(m, "t 1 10 0 25 *83");
    ASSERT_MOVE_EQUALS(m, mv, {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 10, 0, 0, 25, 0, 0});
}

static void test_spec_example_f_with_checksum_answers_with_checksum(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 12.5f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = -3.0f;
    char want[64];
    mock_reply_line(want, sizeof want, "12.5 -3", true);
    const char *got = ASSERT_QUERY(m, "f 1 *87");
    TEST_ASSERT_EQUAL_STRING(want, got);
}

static void test_spec_example_write_with_checksum_is_accepted(void)
{
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis0.config.can_node_id 5 *58", DARAN_PROP_CAN_NODE_ID);
    TEST_ASSERT_EQUAL_INT64(5, v.u32);
}

static void test_checksum_may_follow_the_last_field_directly(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 30 1.4142135623730951 10 *24");
    const daran_move_t *mv = ASSERT_MOVE(m, "mq 0 1*29");
    TEST_ASSERT_EQUAL_INT64(DARAN_MOVE_TRAPEZOID, mv->kind);
    char line[32];
    snprintf(line, sizeof line, "t 1 10*%u", mock_xor("t 1 10"));
    ASSERT_MOVE(m, line);
}

static void test_checksum_mismatch_answers_with_a_checksum_and_has_no_effect(void)
{
    mock_t *m = mock_new();
    char want[80];
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "t 1 10 0 25 *84");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
    mock_send_line(m, "f 1 *0");
    ASSERT_REPLY(m, want);
    mock_send_line(m, "f 1 *255");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

static void test_bad_checksum_has_no_effect_on_any_command(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const lines[] = {"st 1", "ss 1", "w axis0.config.can_node_id 5",
                                        "v 1 20 3 1", "ms 1 1 2 3", "u 1", "sz 1"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        char line[80], want[80];
        snprintf(line, sizeof line, "%s *%u", lines[i], (mock_xor(lines[i]) ^ ' ' ^ 1u));
        mock_send_line(m, line);
        mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
        ASSERT_REPLY(m, want);
        ASSERT_NO_EFFECT(m);
    }
    /* the preset was not stored by the refused ms */
    ASSERT_ERROR(m, "mt 1 0", "no preset");
}

static void test_checksum_errors_are_answered_for_any_motor_id(void)
{
    mock_t *m = mock_new();
    mock_enable_forward(m);
    char want[80];
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "t 9 10 *1");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "t 9 10 *x", "invalid checksum");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
}

static const char *const malformed_fields[] = {
    "* 5", "*", "*1234", "*256", "*8*7", "*12x", "*-1", "*+5", "*0x1", "* ", "*1 2", "*999",
};

static void malformed_checksum_case(const void *row_arg)
{
    const char *field = row_arg;
    mock_t *m = mock_new();
    char line[64];
    snprintf(line, sizeof line, "t 1 10 %s", field);
    ASSERT_ERROR(m, line, "invalid checksum");
    snprintf(line, sizeof line, "f 1 %s", field);
    ASSERT_ERROR(m, line, "invalid checksum");
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_framing_errors_answer_without_a_checksum(void)
{
    mock_t *m = mock_new();
    /* D6: no field was parsed, so no checksum on the reply */
    char line[DARAN_LINE_MAX + 40];
    snprintf(line, sizeof line, "t 1 1\x01 *%u", mock_xor("t 1 1\x01 "));
    ASSERT_ERROR(m, line, "invalid character");
    memset(line, ' ', sizeof line);
    memcpy(line, "f 1", 3);
    snprintf(line + DARAN_LINE_MAX + 10, 16, "*%u", mock_xor(" ") /* any */);
    ASSERT_ERROR(m, line, "line too long");
}

static void test_whitespace_after_checksum_digits_is_allowed(void)
{
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "0 0", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1 *87 "));
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1 *87\t"));
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1 *87 \t \r"));
    ASSERT_MOVE(m, "t 1 10 0 25 *83   ");
}

static void test_checksum_with_leading_zeros_is_well_formed(void)
{
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "0 0", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1 *087"));
    /* "sc 1" XORs to 1 */
    ASSERT_ACTION(m, "sc 1*1", DARAN_ACTION_CLEAR_ERRORS);
    ASSERT_ACTION(m, "sc 1*01", DARAN_ACTION_CLEAR_ERRORS);
    ASSERT_ACTION(m, "sc 1*001", DARAN_ACTION_CLEAR_ERRORS);
}

static void test_value_reply_checksum_covers_the_payload_and_the_space(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 23.75f;
    m->props[DARAN_PROP_IQ_MEASURED].f32 = -0.5f;
    char line[64], want[64];
    mock_with_checksum(line, sizeof line, "g 1");
    mock_reply_line(want, sizeof want, "23.75 -0.5", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    mock_with_checksum(line, sizeof line, "r config.uart_baudrate 1");
    mock_reply_line(want, sizeof want, "115200", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
}

static void test_error_reply_to_a_checksummed_line_carries_a_checksum(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const cases[][2] = {
        {"x 1", "error: unknown command"},
        {"f 64", "error: invalid motor"},
        {"t 1 abc", "error: invalid value"},
        {"t 1 10 0 -1", "error: value out of range"},
        {"w axis1.config_warnings 1", "error: value out of range"},
        {"v 1 20 0 7", "error: invalid mode"},
        {"r axis1.nope", "error: invalid property"},
        {"w vbus_voltage 5 1", "error: read only property"},
        {"f 1 2", "error: invalid command format"},
        {"mt 1 0", "error: no preset"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char line[80], want[80];
        mock_with_checksum(line, sizeof line, cases[i][0]);
        mock_reply_line(want, sizeof want, cases[i][1], true);
        mock_send_line(m, line);
        ASSERT_REPLY(m, want);
        ASSERT_NO_EFFECT(m);
    }
}

static void test_line_that_is_only_a_checksum_is_an_unknown_command(void)
{
    mock_t *m = mock_new();
    char want[64];
    mock_reply_line(want, sizeof want, "error: unknown command", true);
    mock_send_line(m, "*0");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
    mock_send_line(m, " *32");
    ASSERT_REPLY(m, want);
    mock_send_line(m, "  *0");
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

static void test_checksummed_silent_commands_stay_silent(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    char line[80];
    ASSERT_ACTION(m, mock_with_checksum(line, sizeof line, "ss 1"), DARAN_ACTION_SAVE_CONFIG);
    ASSERT_ACTION(m, mock_with_checksum(line, sizeof line, "u 1"), DARAN_ACTION_FEED_WATCHDOG);
    ASSERT_SILENT(m, mock_with_checksum(line, sizeof line, "ms 1 1 2 3"));
    ASSERT_SILENT(m, mock_with_checksum(line, sizeof line, "t 5 10"));
}

static void test_checksum_state_does_not_leak_to_the_next_line(void)
{
    mock_t *m = mock_new();
    (void)ASSERT_QUERY(m, "f 1 *87");
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 1"));
    mock_send_line(m, "f 1 *88");
    ASSERT_ERROR(m, "x 1", "unknown command");
}

/* A line of exactly DARAN_LINE_MAX bytes has no line end stored after it:
 * the byte past it is the instance's reply buffer, here holding the last
 * reply's '1'. The checksum field ends with the line, whatever follows. */
static void test_a_full_length_line_ends_its_checksum_at_its_last_byte(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis0.config.can_node_id"));
    char line[DARAN_LINE_MAX + 1];
    size_t before_star = DARAN_LINE_MAX - 4u; /* then '*' and three digits */
    memset(line, ' ', before_star);
    memcpy(line, "r axis0.config.can_node_id", strlen("r axis0.config.can_node_id"));
    line[before_star] = '\0';
    snprintf(line + before_star, 5, "*%03u", mock_xor(line));
    TEST_ASSERT_EQUAL_UINT64(DARAN_LINE_MAX, strlen(line));
    char want[32];
    mock_reply_line(want, sizeof want, "1", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    line[before_star] = '\0';
    snprintf(line + before_star, 5, "*%03u", mock_xor(line) ^ 1u);
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, line);
    ASSERT_REPLY(m, want);
}

/* ---- fields ---- */

static void test_multiple_spaces_separate_fields(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "t  1   10    0     25");
    ASSERT_MOVE_EQUALS(m, mv, {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 10, 0, 0, 25, 0, 0});
}

static void test_tabs_separate_fields(void)
{
    mock_t *m = mock_new();
    const daran_move_t *mv = ASSERT_MOVE(m, "t\t1\t10 \t 0\t\t25");
    ASSERT_MOVE_EQUALS(m, mv, {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 10, 0, 0, 25, 0, 0});
}

static void test_leading_and_trailing_blanks_are_ignored(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "   f 1"));
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "\t f 1 \t "));
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 1 "));
    ASSERT_MOVE(m, "  t 1 10 0 25 ");
}

static void test_trailing_space_before_the_checksum_is_part_of_the_xor(void)
{
    mock_t *m = mock_new();
    /* "f 1  " (two spaces) XORs to 87 ^ ' ' = 119 */
    char want[64];
    mock_reply_line(want, sizeof want, "0 0", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1  *119"));
    mock_reply_line(want, sizeof want, "error: checksum mismatch", true);
    mock_send_line(m, "f 1  *87");
    ASSERT_REPLY(m, want);
}

static void test_too_many_fields_is_invalid_command_format(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "t 1 10 0 25 1", "invalid command format");
    ASSERT_ERROR(m, "d 1 1 2 3 4 5 6", "invalid command format");
    ASSERT_ERROR(m, "d 1 1 2 3 4 5 6 7 8 9 10 11 12", "invalid command format");
    ASSERT_ERROR(m, "f 1 1", "invalid command format");
    ASSERT_ERROR(m, "ss 1 1", "invalid command format");
    ASSERT_ERROR(m, "mt 1 0 0", "invalid command format");
    ASSERT_ERROR(m, "mv 1 0", "invalid command format");
}

static void test_too_few_fields_is_invalid_command_format(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "t 1", "invalid command format");
    ASSERT_ERROR(m, "q 1", "invalid command format");
    ASSERT_ERROR(m, "d 1 1 2 3 4", "invalid command format");
    ASSERT_ERROR(m, "ms 1 1 2", "invalid command format");
    ASSERT_ERROR(m, "mq 1", "invalid command format");
    ASSERT_ERROR(m, "w axis1.output_shaft.input_pos", "invalid command format");
    ASSERT_ERROR(m, "r", "invalid command format");
}

/* ---- command words ---- */

static void test_command_words_are_case_insensitive(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "SS 1", DARAN_ACTION_SAVE_CONFIG);
    ASSERT_ACTION(m, "Ss 1", DARAN_ACTION_SAVE_CONFIG);
    ASSERT_ACTION(m, "sS 1", DARAN_ACTION_SAVE_CONFIG);
    const daran_move_t *mv = ASSERT_MOVE(m, "T 1 10");
    ASSERT_MOVE_EQUALS(m, mv, {DARAN_MOVE_FILTERED_POSITION, 0, 10, 0, 0, 0, 0, 0});
    ASSERT_SILENT(m, "MS 1 10 2 10");
    mv = ASSERT_MOVE(m, "Mq 0 1");
    TEST_ASSERT_EQUAL_INT64(DARAN_MOVE_TRAPEZOID, mv->kind);
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "F 1"));
    TEST_ASSERT_EQUAL_STRING("115200\n", ASSERT_QUERY(m, "R config.uart_baudrate 1"));
    (void)ASSERT_SET(m, "W axis1.output_shaft.input_pos 3", DARAN_PROP_INPUT_POS);
    ASSERT_ACTION(m, "ST 1", DARAN_ACTION_ESTOP);
}

static void test_every_command_word_works_in_upper_case(void)
{
    SKIP_IF_NO_MULTI();
    static const char *const lines[] = {
        "T 1 10", "Q 1 10", "P 1 10", "V 1 10", "C 1 1", "D 1 0 0 0 0 0", "MS 1 10 0 5",
        "MT 1 0", "MS 1 10 2 10", "MQ 1 1", "MS 1 10 0 0", "MP 1 0", "MS 1 1 0 1", "MV 1",
        "MS 1 1 0 1", "MC 1", "R axis1.error", "W axis1.output_shaft.input_pos 1", "SS 1",
        "SE 1", "SZ 1", "U 1",
#if DARAN_ENABLE_HELP
        "H 1",
#endif
        "F 1", "G 1", "I 1", "E 1", "ST 1", "SC 1", "SR 1",
    };
    mock_t *m = mock_new();
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        mock_send_line(m, lines[i]);
        mock_check(strstr(m->out, "error") == NULL, m, __FILE__, __LINE__,
                   "an upper-case command word must work");
        mock_check(m->n_calls > 0 || m->n_writes > 0 || lines[i][1] == 'S', m, __FILE__, __LINE__,
                   "the command must have run");
    }
}

static void test_multi_motor_words_follow_the_build_option(void)
{
    mock_t *m = mock_new();
    static const char *const lines[] = {"ms 1 10 0 5", "mt 1 0", "mq 1 1", "mp 1 0", "mv 1",
                                        "mc 1", "ms 2 1 2 3", "mt 0 0"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        TEST_ASSERT_TRUE(mock_uses_multi(lines[i]));
        if (DARAN_ENABLE_MULTI_MOTOR) {
            mock_send_line(m, lines[i]);
            mock_check(strstr(m->out, "unknown command") == NULL, m, __FILE__, __LINE__,
                       "multi-motor commands are built in");
        } else {
            ASSERT_ERROR(m, lines[i], "unknown command");
        }
    }
    TEST_ASSERT_FALSE(mock_uses_multi("m 1"));
    TEST_ASSERT_FALSE(mock_uses_multi("mx 1"));
    TEST_ASSERT_FALSE(mock_uses_multi("msx 1"));
    TEST_ASSERT_TRUE(mock_uses_multi("MQ 0 1*29"));
}

static void test_property_paths_are_case_sensitive(void)
{
    mock_t *m = mock_new();
    (void)ASSERT_QUERY(m, "r axis1.motor.current_control.Iq_measured");
    ASSERT_ERROR(m, "r axis1.motor.current_control.iq_measured", "invalid property");
    ASSERT_ERROR(m, "r Vbus_voltage 1", "invalid property");
    ASSERT_ERROR(m, "r AXIS1.output_shaft.input_pos", "invalid property");
}

static const char *const unknown_words[] = {"x 1", "tt 1", "m 1", "s 1", "mm 1", "sss 1", "ff 1",
                                            "t1 1", "1 1", "mx 0", "sa 1", "-t 1", "z 1", "ma 0",
                                            /* a known one-letter word, then more */
                                            "fff 1", "ttt 1 10"};

static void unknown_word_case(const void *row_arg)
{
    const char *line = row_arg;
    mock_t *m = mock_new();
    ASSERT_ERROR(m, line, "unknown command");
}

static void test_command_word_is_checked_before_the_motor_id(void)
{
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "x", "unknown command");
    ASSERT_ERROR(m, "x 99", "unknown command");
    ASSERT_ERROR(m, "x 2", "unknown command");
    ASSERT_ERROR(m, "x abc", "unknown command");
    ASSERT_ERROR(m, "xyz 1 2 3 4 5 6 7 8 9", "unknown command");
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    ADD(test_spec_example_t_with_checksum_is_accepted);
    ADD(test_spec_example_f_with_checksum_answers_with_checksum);
    ADD(test_spec_example_write_with_checksum_is_accepted);
    ADD(test_checksum_may_follow_the_last_field_directly);
    ADD(test_checksum_mismatch_answers_with_a_checksum_and_has_no_effect);
    ADD(test_bad_checksum_has_no_effect_on_any_command);
    ADD(test_checksum_errors_are_answered_for_any_motor_id);
    for (size_t i = 0; i < sizeof malformed_fields / sizeof malformed_fields[0]; i++)
        mock_suite_add(&s, malformed_checksum_case, (void *)(uintptr_t)malformed_fields[i],
                       "test_checksum_field_\"%s\"_is_an_invalid_checksum", malformed_fields[i]);
    ADD(test_framing_errors_answer_without_a_checksum);
    ADD(test_whitespace_after_checksum_digits_is_allowed);
    ADD(test_checksum_with_leading_zeros_is_well_formed);
    ADD(test_value_reply_checksum_covers_the_payload_and_the_space);
    ADD(test_error_reply_to_a_checksummed_line_carries_a_checksum);
    ADD(test_line_that_is_only_a_checksum_is_an_unknown_command);
    ADD(test_checksummed_silent_commands_stay_silent);
    ADD(test_checksum_state_does_not_leak_to_the_next_line);
    ADD(test_a_full_length_line_ends_its_checksum_at_its_last_byte);
    ADD(test_multiple_spaces_separate_fields);
    ADD(test_tabs_separate_fields);
    ADD(test_leading_and_trailing_blanks_are_ignored);
    ADD(test_trailing_space_before_the_checksum_is_part_of_the_xor);
    ADD(test_too_many_fields_is_invalid_command_format);
    ADD(test_too_few_fields_is_invalid_command_format);
    ADD(test_command_words_are_case_insensitive);
    ADD(test_every_command_word_works_in_upper_case);
    ADD(test_multi_motor_words_follow_the_build_option);
    ADD(test_property_paths_are_case_sensitive);
    for (size_t i = 0; i < sizeof unknown_words / sizeof unknown_words[0]; i++)
        mock_suite_add(&s, unknown_word_case, (void *)(uintptr_t)unknown_words[i],
                       "test_\"%s\"_is_an_unknown_command", unknown_words[i]);
    ADD(test_command_word_is_checked_before_the_motor_id);
    mock_suite_run(&s);
    return UNITY_END();
}
