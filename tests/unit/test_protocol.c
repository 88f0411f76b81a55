/* The protocol table (include/daran_protocol.h) against what the drive made
 * of it: every row this build has is found by its word with its field
 * counts, its read flag and its CAN form (what the bridge sends), `h`
 * lists it with its text, and the text's brackets agree with the fields
 * it declares. The client's view is held to the same rows in
 * tests/client/test_client_build.c. */
#include <stdio.h>
#include <string.h>

#include "command.h"
#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

typedef struct row {
    const char *name;
    char word[3];
    int in_build;      /* 1: this build's drive has the row as a command of its own */
    int variant_of_h;  /* the properties form of `h` */
    int reads;         /* answered for id 0, never forwarded */
    int path_first;
    int min_fields;    /* after the word */
    int max_fields;
    int can_form;
    const char *help;
    int optional_fields; /* OPT_ fields: the most fields less the fewest */
} row_t;

#define IN_BUILD_ALWAYS 1
#define IN_BUILD_MULTI DARAN_ENABLE_MULTI_MOTOR
#define IN_BUILD_HELP DARAN_ENABLE_HELP
#define IN_BUILD_DISCOVERY 0
#define IN_BUILD_UPDATE DARAN_ENABLE_UPDATE
#define VARIANT_ALWAYS 0
#define VARIANT_MULTI 0
#define VARIANT_HELP 0
#define VARIANT_DISCOVERY 1
#define VARIANT_UPDATE 0
#define READS_MOTION 0
#define READS_START 0
#define READS_PRESET 0
#define READS_SYSTEM 0
#define READS_WRITE 0
#define READS_QUERY 1
#define READS_READ 1
#define READS_UPDATE 0
#define ROW(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, f4, f5, \
            f6)                                                                                \
    {#name,                                                                                    \
     {c0, c1, 0},                                                                              \
     IN_BUILD_##feature,                                                                       \
     VARIANT_##feature,                                                                        \
     READS_##cls,                                                                              \
     DARAN_PROTOCOL_PATH_FIRST(f1),                                                            \
     DARAN_PROTOCOL_MIN_FIELDS(f1, f2, f3, f4, f5, f6),                                        \
     DARAN_PROTOCOL_MAX_FIELDS(f1, f2, f3, f4, f5, f6),                                        \
     DARAN_CAN_FORM_##can,                                                                     \
     help,                                                                                     \
     DARAN_PROTOCOL_MAX_FIELDS(f1, f2, f3, f4, f5, f6) -                                       \
         DARAN_PROTOCOL_MIN_FIELDS(f1, f2, f3, f4, f5, f6)},
static const row_t rows[] = {DARAN_PROTOCOL_COMMANDS(ROW)};
#undef ROW
#define ROW_COUNT (sizeof rows / sizeof rows[0])
#define LINE_END "\n" /* the mock stores every reply line so */

static const daran_command_t *find(const char *word)
{
    daran_field_t field = {word, (uint16_t)strlen(word)};
    return daran_find_command(&field);
}

static void test_every_row_of_the_build_is_a_command_as_the_table_says(void)
{
    for (size_t i = 0; i < ROW_COUNT; i++) {
        const row_t *row = &rows[i];
        if (row->variant_of_h) {
            continue; /* the next test */
        }
        const daran_command_t *command = find(row->word);
        if (!row->in_build) {
            TEST_ASSERT_NULL_MESSAGE(command, row->name);
            continue;
        }
        TEST_ASSERT_NOT_NULL_MESSAGE(command, row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1 + row->min_fields, DARAN_MIN_FIELDS(command), row->name);
        if (!(DARAN_ENABLE_DISCOVERY && strcmp(row->word, "h") == 0)) {
            TEST_ASSERT_EQUAL_INT_MESSAGE(1 + row->max_fields, DARAN_MAX_FIELDS(command), row->name);
        }
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->reads, (command->flags & DARAN_CMD_READ) != 0u, row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->path_first, (command->flags & DARAN_CMD_PATH) != 0u,
                                      row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->can_form, DARAN_CMD_CAN_FORM(command), row->name);
    }
}

static void test_h_takes_its_properties_form_only_with_discovery(void)
{
    for (size_t i = 0; i < ROW_COUNT; i++) {
        if (!rows[i].variant_of_h) {
            continue;
        }
        const daran_command_t *h = find(rows[i].word);
        if (!DARAN_ENABLE_HELP) {
            TEST_ASSERT_NULL(h);
            continue;
        }
        TEST_ASSERT_NOT_NULL(h);
        TEST_ASSERT_EQUAL_INT(DARAN_ENABLE_DISCOVERY ? 1 + rows[i].max_fields : 2,
                              DARAN_MAX_FIELDS(h));
    }
}

/* The names a help text gives and how many of them are in brackets. */
static void count_help(const char *help, int *names, int *bracketed)
{
    *names = 0;
    *bracketed = 0;
    int depth = 0;
    for (const char *c = help; *c != '\0'; c++) {
        if (*c == '[') {
            depth++;
        } else if (*c == ']') {
            depth--;
        } else if (*c != ' ' && (c == help || c[-1] == ' ' || c[-1] == '[')) {
            (*names)++;
            *bracketed += depth > 0;
        }
    }
}

static void test_help_texts_name_the_fields_the_rows_declare(void)
{
    for (size_t i = 0; i < ROW_COUNT; i++) {
        const row_t *row = &rows[i];
        int names;
        int bracketed;
        count_help(row->help, &names, &bracketed);
        /* the id a row begins with is printed by `h` itself */
        int listed = row->max_fields - (row->path_first ? 0 : 1);
        TEST_ASSERT_EQUAL_INT_MESSAGE(listed, names, row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->optional_fields, bracketed, row->name);
    }
}

static void test_h_lists_every_row_of_the_build_with_its_text(void)
{
    if (!DARAN_ENABLE_HELP) {
        TEST_IGNORE_MESSAGE("no `h` in this build");
    }
    mock_t *m = mock_new();
    mock_send_line(m, "h 1");
    for (size_t i = 0; i < ROW_COUNT; i++) {
        const row_t *row = &rows[i];
        if (!row->in_build) {
            continue;
        }
        char want[96];
        if (strcmp(row->word, "h") == 0 && DARAN_ENABLE_DISCOVERY) {
            snprintf(want, sizeof want, "h id [%s]%s", DARAN_H_PROPERTIES_HELP, LINE_END);
        } else {
            snprintf(want, sizeof want, "%s%s%s%s%s", row->word, row->path_first ? "" : " id",
                     row->help[0] != '\0' ? " " : "", row->help, LINE_END);
        }
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(m->out, want), want);
    }
}

static void test_query_lists_end_with_the_serial_number_if_they_have_it(void)
{
    /* the bridge prints the serial number's two CAN halves as one value,
     * last of its line (can_bridge.c) */
    static const uint8_t ends[] = {DARAN_QUERY_END_F, DARAN_QUERY_END_G, DARAN_QUERY_END_I,
                                   DARAN_QUERY_END_E};
    for (uint8_t at = 0; at < DARAN_QUERY_END_E; at++) {
        if (daran_query_props[at] != DARAN_PROP_SERIAL_NUMBER) {
            continue;
        }
        bool last = false;
        for (size_t k = 0; k < sizeof ends; k++) {
            last = last || at + 1u == ends[k];
        }
        TEST_ASSERT_TRUE(last);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_row_of_the_build_is_a_command_as_the_table_says);
    RUN_TEST(test_h_takes_its_properties_form_only_with_discovery);
    RUN_TEST(test_help_texts_name_the_fields_the_rows_declare);
    RUN_TEST(test_h_lists_every_row_of_the_build_with_its_text);
    RUN_TEST(test_query_lists_end_with_the_serial_number_if_they_have_it);
    return UNITY_END();
}
