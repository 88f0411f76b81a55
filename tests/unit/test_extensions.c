/* Unit tests of what lies beyond the vendor (protocol.md section 11):
 * property discovery (`h id properties [prefix]`), the port's own commands
 * (daran_set_port_commands and the daran_args_* parsers) and telemetry
 * reports (daran_telemetry_tick). The port's own properties and omitted
 * vendor rows need a build with a port options header: examples/port-brake
 * tests those. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

/* ---- discovery ---- */

typedef struct prop_row {
    const char *path;
    int axis;
    daran_prop_type_t type;
    int rw;
    daran_range_t range;
    const char *unit;
} prop_row_t;

#define SCOPE_SYSTEM 0
#define SCOPE_AXIS 1
#define ROW(id, path, scope, type, access, range, unit, can) \
    {path, SCOPE_##scope, DARAN_TYPE_##type, DARAN_ACCESS_IS_##access, DARAN_RANGE_##range, unit},
#define DARAN_ACCESS_IS_RO 0
#define DARAN_ACCESS_IS_RW 1
static const prop_row_t rows[] = {DARAN_PROPERTY_LIST(ROW)};
#undef ROW
#define N_ROWS (sizeof rows / sizeof rows[0])

#if DARAN_ENABLE_DISCOVERY
/* The discovery line of a row, as protocol.md 11.1 writes it. */
static void expected_line(const prop_row_t *p, char *buf, size_t size)
{
    static const char *const types[] = {"f32", "u32", "s32", "u64", "bool"};
    static const char *const ranges[DARAN_RANGE_COUNT] = {
        [DARAN_RANGE_NONE] = "",           [DARAN_RANGE_NON_NEGATIVE] = " >=0",
        [DARAN_RANGE_POSITIVE] = " >0",    [DARAN_RANGE_NON_POSITIVE] = " <=0",
        [DARAN_RANGE_BOOL] = " 0|1",       [DARAN_RANGE_ZERO] = " 0",
        [DARAN_RANGE_NODE_ID] = " 1..63",  [DARAN_RANGE_UART_BAUD] = " {9600,19200,38400,57600,115200}",
        [DARAN_RANGE_CAN_BAUD] = " {125000,250000,500000,1000000}",
        [DARAN_RANGE_CAN_PROTOCOL] = " 0..1", [DARAN_RANGE_AXIS_STATE] = " {1,8}",
        [DARAN_RANGE_CONTROL_MODE] = " 1..3", [DARAN_RANGE_INPUT_MODE] = " {1,2,3,5,6,9}",
        [DARAN_RANGE_TRAJ_MODE] = " 1..2", [DARAN_RANGE_DIRECTION] = " {-1,1}",
        [DARAN_RANGE_MOTOR_TYPE] = " {0,2,3}", [DARAN_RANGE_POLE_PAIRS] = " 1..128",
        [DARAN_RANGE_TELEMETRY] = " 0..511",
    };
    const char *range = p->rw ? ranges[p->range] : "";
    if (p->rw && p->type == DARAN_TYPE_BOOL) {
        range = " 0|1";
    }
    snprintf(buf, size, "%s%s %s %s %s%s", p->axis ? "axis0." : "", p->path, types[p->type],
             p->rw ? "rw" : "ro", p->unit[0] != '\0' ? p->unit : "-", range);
}

static int by_full_path(const void *a, const void *b)
{
    char x[128], y[128];
    const prop_row_t *p = a, *q = b;
    snprintf(x, sizeof x, "%s%s", p->axis ? "axis0." : "", p->path);
    snprintf(y, sizeof y, "%s%s", q->axis ? "axis0." : "", q->path);
    return strcmp(x, y);
}

/* The whole expected reply of `h 1 properties [prefix]`, lines in path order. */
static void expected_listing(const char *prefix, bool checksum, char *out, size_t size)
{
    static prop_row_t sorted[N_ROWS];
    memcpy(sorted, rows, sizeof rows);
    qsort(sorted, N_ROWS, sizeof sorted[0], by_full_path);
    size_t len = 0;
    out[0] = '\0';
    for (size_t i = 0; i < N_ROWS; i++) {
        char line[160], with_end[200];
        expected_line(&sorted[i], line, sizeof line);
        if (strncmp(line, prefix, strlen(prefix)) != 0) {
            continue;
        }
        mock_reply_line(with_end, sizeof with_end, line, checksum);
        len += (size_t)snprintf(out + len, size - len, "%s", with_end);
    }
    char end[32];
    mock_reply_line(end, sizeof end, "end", checksum);
    snprintf(out + len, size - len, "%s", end);
}

static char listing[MOCK_OUT_MAX];

static void test_discovery_lists_every_property_once_in_path_order_then_end(void)
{
    mock_t *m = mock_new();
    expected_listing("", false, listing, sizeof listing);
    mock_send_line(m, "h 1 properties");
    ASSERT_REPLY(m, listing);
    ASSERT_NO_EFFECT(m);
    TEST_ASSERT_EQUAL_INT64(N_ROWS + 1u, m->n_writes);
}

static void test_discovery_with_a_prefix_lists_only_the_paths_that_start_with_it(void)
{
    static const char *const prefixes[] = {
        "axis0.output_shaft.", "axis0.telemetry", "config.", "axis0.motor.config.d", "ibus",
        "axis0.encoder.spi_buff_", "serial_number",
    };
    for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++) {
        mock_t *m = mock_new();
        char line[96];
        snprintf(line, sizeof line, "h 1 properties %s", prefixes[i]);
        expected_listing(prefixes[i], false, listing, sizeof listing);
        mock_send_line(m, line);
        ASSERT_REPLY(m, listing);
    }
}

static void test_discovery_of_a_prefix_no_path_has_answers_end_alone(void)
{
    mock_t *m = mock_new();
    mock_send_line(m, "h 1 properties axis1.");
    ASSERT_REPLY(m, "end\n"); /* paths are written axis0., as a host writes them */
    mock_send_line(m, "h 0 properties zzz");
    ASSERT_REPLY(m, "end\n");
}

static void test_checksummed_discovery_gets_a_checksum_on_every_line(void)
{
    mock_t *m = mock_new();
    char line[64];
    mock_with_checksum(line, sizeof line, "h 1 properties axis0.controller.config.");
    expected_listing("axis0.controller.config.", true, listing, sizeof listing);
    mock_send_line(m, line);
    ASSERT_REPLY(m, listing);
}

static void test_discovery_refuses_another_word_and_extra_fields(void)
{
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "h 1 property", "invalid value");
    ASSERT_ERROR(m, "h 1 PROPERTIES", "invalid value");
    ASSERT_ERROR(m, "h 1 properties a b", "invalid command format");
    ASSERT_ERROR(m, "h 64 properties", "invalid motor");
    ASSERT_SILENT(m, "h 2 properties");
}

static void test_help_shows_the_discovery_form_of_h(void)
{
    mock_t *m = mock_new();
    mock_send_line(m, "h 1");
    TEST_ASSERT_NOT_NULL(strstr(m->out, "\nh id [properties [prefix]]\n"));
}
#else
static void test_without_discovery_h_properties_is_refused(void)
{
    mock_t *m = mock_new();
#if DARAN_ENABLE_HELP
    /* h stays the vendor's help: its extra fields are a format error */
    ASSERT_ERROR(m, "h 1 properties", "invalid command format");
    ASSERT_ERROR(m, "h 1 properties axis0.", "invalid command format");
#else
    ASSERT_ERROR(m, "h 1", "unknown command");
    ASSERT_ERROR(m, "h 1 properties", "unknown command");
    ASSERT_ERROR(m, "h 1 properties axis0.", "unknown command");
#endif
}
#endif

/* ---- the port's own commands ---- */
#if DARAN_ENABLE_PORT_COMMANDS

typedef struct brake {
    unsigned calls;
    float hz;
    uint8_t motor;
    daran_result_t answer;
} brake_t;
static brake_t brake;
static mock_t *port_m; /* the drive port_mock() made: its context is what a handler gets */

static daran_result_t sb_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)drive;
    TEST_ASSERT_EQUAL_PTR(port_m, ctx); /* the drive's one context (daran_init()) */
    brake_t *b = &brake;
    float hz;
    daran_result_t result = daran_args_f32(args, 0, &hz);
    if (result != DARAN_OK) {
        return result;
    }
    if (!(hz >= 0.0f && hz <= 50000.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (b->answer != DARAN_OK) {
        return b->answer;
    }
    b->calls++;
    b->hz = hz;
    b->motor = daran_args_motor(args);
    return DARAN_OK;
}

/* `bq id [k]`: a query answering the value count, the motor, and k (a mode 1..3). */
static daran_result_t bq_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)ctx;
    uint32_t k = 1;
    if (daran_args_count(args) == 1u) {
        daran_result_t result = daran_args_mode(args, 0, (1u << 1) | (1u << 2) | (1u << 3), &k);
        if (result != DARAN_OK) {
            return result;
        }
    }
    char text[64];
    size_t n = 0;
    n += daran_format_uint(daran_args_count(args), text + n, sizeof text - n);
    text[n++] = ' ';
    n += daran_format_uint(daran_args_motor(args), text + n, sizeof text - n);
    text[n++] = ' ';
    n += daran_format_uint(k, text + n, sizeof text - n);
    text[n++] = ' ';
    n += daran_format_float(0.1f, text + n, sizeof text - n);
    daran_reply(drive, text, n);
    return DARAN_OK;
}

/* `bu id n`: an unsigned count, refused above 1000. */
static daran_result_t bu_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    TEST_ASSERT_EQUAL_PTR(port_m, ctx);
    (void)drive;
    brake_t *b = &brake;
    uint32_t n;
    daran_result_t result = daran_args_u32(args, 0, &n);
    if (result == DARAN_OK && n > 1000u) {
        result = DARAN_ERR_OUT_OF_RANGE;
    }
    if (result == DARAN_OK) {
        b->calls++;
    }
    return result;
}

static const daran_port_command_t port_commands[] = {
    {"sb", 1, 1, 0, sb_handler, "hz"},
    {"bq", 0, 1, DARAN_PORT_COMMAND_QUERY, bq_handler, "[k]"},
    {"bu", 1, 1, 0, bu_handler, "n"},
};

static mock_t *port_mock(void)
{
    mock_t *m = mock_new();
    port_m = m;
    memset(&brake, 0, sizeof brake);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, port_commands, 3));
    return m;
}

static void test_a_port_command_runs_its_handler_with_the_parsed_values(void)
{
    mock_t *m = port_mock();
    ASSERT_SILENT(m, "sb 1 2000");
    TEST_ASSERT_EQUAL_UINT(1, brake.calls);
    TEST_ASSERT_TRUE(brake.hz == 2000.0f);
    TEST_ASSERT_EQUAL_UINT(1, brake.motor);
    ASSERT_SILENT(m, "SB 1 0.5e3"); /* words are case-insensitive */
    TEST_ASSERT_TRUE(brake.hz == 500.0f);
    char line[64];
    mock_with_checksum(line, sizeof line, "sb 1 7");
    ASSERT_SILENT(m, line);
    TEST_ASSERT_EQUAL_UINT(3, brake.calls);
}

static void test_bad_port_command_lines_get_the_library_errors_and_no_call(void)
{
    static const struct {
        const char *line;
        const char *phrase;
    } cases[] = {
        {"sb 1", "invalid command format"},      {"sb 1 1 2", "invalid command format"},
        {"sb", "invalid command format"},        {"sb 1 x", "invalid value"},
        {"sb 1 1..2", "invalid value"},          {"sb 1 60000", "value out of range"},
        {"sb 1 -1", "value out of range"},       {"sb 1 1e39", "value out of range"},
        {"sb x 1", "invalid motor"},             {"sb 64 1", "invalid motor"},
        {"sb 1.5 1", "invalid motor"},           {"sb 1 1 *x", "invalid checksum"},
        {"sbx 1 1", "unknown command"},
        {"bu 1 4294967296", "value out of range"}, {"bu 1 1001", "value out of range"},
        {"bu 1 -1", "value out of range"},       {"bu 1 1.5", "invalid value"},
        {"bq 1 4", "invalid mode"},              {"bq 1 2.5", "invalid value"},
        {"bq 1 32", "invalid mode"},             {"bq 1 33", "invalid mode"}, /* past the set's bits */
        {"bq 1 1 2", "invalid command format"},
    };
    mock_t *m = port_mock();
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ASSERT_ERROR(m, cases[i].line, cases[i].phrase);
        TEST_ASSERT_EQUAL_UINT_MESSAGE(0, brake.calls, cases[i].line);
    }
    char want[64];
    mock_send_line(m, "sb 1 1 *0"); /* a mismatch is answered with a checksum (D6) */
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "error: checksum mismatch", true));
    ASSERT_NO_EFFECT(m);
    TEST_ASSERT_EQUAL_UINT(0, brake.calls);
}

static void test_a_handler_error_is_answered_with_its_phrase(void)
{
    mock_t *m = port_mock();
    brake.answer = DARAN_ERR_MOTOR_IDLE;
    ASSERT_ERROR(m, "sb 1 10", "motor idle");
    brake.answer = DARAN_ERR_BAD_ARGUMENT; /* not a protocol error: a fault (D26) */
    ASSERT_ERROR(m, "sb 1 10", "motor fault");
    brake.answer = (daran_result_t)1234;
    ASSERT_ERROR(m, "sb 1 10", "motor fault");
    TEST_ASSERT_EQUAL_UINT(0, brake.calls);
}

static void test_port_commands_are_addressed_like_the_core_s(void)
{
    mock_t *m = port_mock();
    mock_enable_forward(m);
    ASSERT_SILENT(m, "sb 2 10"); /* another drive's: silent, forwarded */
    TEST_ASSERT_EQUAL_UINT(0, brake.calls);
    TEST_ASSERT_EQUAL_UINT(1, m->n_fwd);
    TEST_ASSERT_EQUAL_UINT(2, m->fwd[0].id);
    mock_send_line(m, "sb 0 10"); /* a broadcast: runs here and goes on */
    TEST_ASSERT_EQUAL_UINT(1, brake.calls);
    TEST_ASSERT_EQUAL_UINT(0, brake.motor);
    TEST_ASSERT_EQUAL_UINT(1, m->n_fwd);
    mock_send_line(m, "bq 0"); /* a query sent to every drive: answered, not forwarded */
    TEST_ASSERT_EQUAL_STRING("0 0 1 0.1\n", m->out);
    TEST_ASSERT_EQUAL_UINT(0, m->n_fwd);
}

/* `dot id`: a reply that starts with '.', which no core reply does, from a
 * payload with no NUL after it (a read past it is an overflow under ASan). */
static const char dot_payload[1] = {'.'};

static daran_result_t dot_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)args;
    (void)ctx;
    daran_reply(drive, dot_payload, sizeof dot_payload);
    return DARAN_OK;
}

/* One handler for two words: it answers the word it was called for. */
static daran_result_t echo_word_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)ctx;
    size_t len = 0;
    const char *word = daran_args_word(args, &len);
    daran_reply(drive, word, len);
    return DARAN_OK;
}

static void test_a_handler_tells_its_words_apart_by_daran_args_word(void)
{
    static const daran_port_command_t two[] = {
        {"ping", 0, 0, DARAN_PORT_COMMAND_QUERY, echo_word_handler, ""},
        {"pong", 0, 1, DARAN_PORT_COMMAND_QUERY, echo_word_handler, "[x]"}};
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, two, 2));
    mock_send_line(m, "  pong 1 5");
    TEST_ASSERT_EQUAL_STRING("pong\n", m->out);
    mock_clear(m);
    mock_send_line(m, "ping 1");
    TEST_ASSERT_EQUAL_STRING("ping\n", m->out);
}

/* A line of exactly DARAN_LINE_MAX bytes has no line end stored after it, so
 * the byte past a path that ends it is the reply buffer's first: after a
 * port reply of ".", "axis2" is still a path without its dot (a system
 * path, answered here), not one of drive 2's. */
static void test_a_path_that_ends_a_full_length_line_reads_nothing_past_it(void)
{
    static const daran_port_command_t dot[] = {{"dt", 0, 0, DARAN_PORT_COMMAND_QUERY, dot_handler, ""}};
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, dot, 1));
    char line[DARAN_LINE_MAX + 1];
    memset(line, ' ', DARAN_LINE_MAX);
    line[DARAN_LINE_MAX] = '\0';
    memcpy(line + DARAN_LINE_MAX - strlen("r axis2"), "r axis2", strlen("r axis2"));
    ASSERT_ERROR(m, line, "invalid property");
    mock_send_line(m, "dt 1");
    TEST_ASSERT_EQUAL_STRING(".\n", m->out);
    ASSERT_ERROR(m, line, "invalid property");
}

/* The count is kept in a byte: 255 commands are a table, 256 are refused. */
static void test_a_table_of_255_port_commands_is_taken_and_256_refused(void)
{
    static char words[256][4];
    static daran_port_command_t table[256];
    for (size_t i = 0; i < 256u; i++) {
        words[i][0] = 'z';
        words[i][1] = (char)('a' + i / 26u);
        words[i][2] = (char)('a' + i % 26u);
        daran_port_command_t command = {words[i], 1, 1, 0, sb_handler, ""};
        table[i] = command;
    }
    mock_t *m = port_mock();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, table, 255));
    char line[16];
    snprintf(line, sizeof line, "%s 1 3", words[254]);
    ASSERT_SILENT(m, line);
    TEST_ASSERT_EQUAL_UINT(1, brake.calls);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_set_port_commands(&m->drive, table, 256));
    ASSERT_SILENT(m, line); /* the table it had still works */
    TEST_ASSERT_EQUAL_UINT(2, brake.calls);
}

static void test_a_port_query_replies_through_daran_reply_with_the_request_checksum(void)
{
    mock_t *m = port_mock();
    mock_send_line(m, "bq 1 3");
    TEST_ASSERT_EQUAL_STRING("1 1 3 0.1\n", m->out);
    char line[32], want[64];
    mock_with_checksum(line, sizeof line, "bq 1");
    mock_send_line(m, line);
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "0 1 1 0.1", true));
}

#if DARAN_ENABLE_HELP
static void test_help_lists_the_port_commands_after_the_core_s(void)
{
    mock_t *m = port_mock();
    mock_send_line(m, "h 1");
    /* the core's last row, then the port's */
#if DARAN_ENABLE_UPDATE
#define LAST_CORE_HELP "uq id\n"
#else
#define LAST_CORE_HELP "u id\n"
#endif
    const char *tail = strstr(m->out, LAST_CORE_HELP "sb id hz\nbq id [k]\nbu id n\n");
    TEST_ASSERT_NOT_NULL(tail);
    TEST_ASSERT_EQUAL_STRING(LAST_CORE_HELP "sb id hz\nbq id [k]\nbu id n\n", tail);
}
#endif

static void test_a_bad_port_table_is_refused_whole_and_the_drive_keeps_its_own(void)
{
    static const daran_port_command_t vendor_word[] = {{"sb", 1, 1, 0, sb_handler, ""},
                                                       {"ss", 0, 0, 0, sb_handler, ""}};
    static const daran_port_command_t twice[] = {{"sb", 1, 1, 0, sb_handler, ""},
                                                 {"sb", 0, 0, 0, sb_handler, ""}};
    static const daran_port_command_t upper[] = {{"Sb", 1, 1, 0, sb_handler, ""}};
    static const daran_port_command_t digit[] = {{"s1", 1, 1, 0, sb_handler, ""}};
    static const daran_port_command_t empty[] = {{"", 1, 1, 0, sb_handler, ""}};
    static const daran_port_command_t too_long[] = {{"abcdefghi", 1, 1, 0, sb_handler, ""}};
    static const daran_port_command_t no_handler[] = {{"sb", 1, 1, 0, NULL, ""}};
    static const daran_port_command_t no_help[] = {{"sb", 1, 1, 0, sb_handler, NULL}};
    static const daran_port_command_t no_word[] = {{NULL, 1, 1, 0, sb_handler, ""}};
    static const daran_port_command_t min_over_max[] = {{"sb", 2, 1, 0, sb_handler, ""}};
    static const daran_port_command_t too_many[] = {{"sb", 0, DARAN_FIELDS_MAX - 2u, 0, sb_handler, ""}};
    static const daran_port_command_t vendor_h[] = {{"h", 0, 0, 0, sb_handler, ""}};
    static const daran_port_command_t vendor_mq[] = {{"mq", 0, 0, 0, sb_handler, ""}};
    static const struct {
        const daran_port_command_t *table;
        size_t count;
    } bad[] = {
        {vendor_word, 2}, {twice, 2},       {upper, 1},        {digit, 1},    {empty, 1},
        {too_long, 1},    {no_handler, 1},  {no_help, 1},      {no_word, 1},  {min_over_max, 1},
        {too_many, 1},    {vendor_h, 1},    {vendor_mq, 1},    {NULL, 1},
    };
    mock_t *m = port_mock();
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                              daran_set_port_commands(&m->drive, bad[i].table, bad[i].count));
        ASSERT_SILENT(m, "sb 1 3"); /* the table it had still works */
    }
    TEST_ASSERT_EQUAL_UINT(sizeof bad / sizeof bad[0], brake.calls);
    static const daran_port_command_t longest[] = {{"abcdefgh", 0, DARAN_FIELDS_MAX - 3u, 0, sb_handler, ""}};
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, longest, 1));
    ASSERT_ERROR(m, "sb 1 3", "unknown command");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, NULL, 0));
    ASSERT_ERROR(m, "abcdefgh 1", "unknown command");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_set_port_commands(NULL, port_commands, 3));
    /* the alphabet's ends are letters too */
    static const daran_port_command_t a_to_z[] = {{"az", 0, 0, 0, sb_handler, ""},
                                                  {"zap", 0, 0, 0, sb_handler, ""}};
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, a_to_z, 2));
}

static daran_result_t probe_results[3];

static daran_result_t probe_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)drive;
    (void)ctx;
    float f;
    uint32_t u;
    probe_results[0] = daran_args_f32(args, 0, &f);
    probe_results[1] = daran_args_u32(args, 0, &u);
    probe_results[2] = daran_args_mode(args, 0, 2u, &u);
    return DARAN_OK;
}

static void test_args_parsers_refuse_an_index_past_the_values(void)
{
    static const daran_port_command_t probe[] = {{"pr", 0, 0, 0, probe_handler, ""}};
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, probe, 1));
    ASSERT_SILENT(m, "pr 1");
    for (int i = 0; i < 3; i++) {
        TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_FORMAT, probe_results[i]);
    }
}

static uint32_t u32_seen;

static daran_result_t u32_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)drive;
    (void)ctx;
    return daran_args_u32(args, 0, &u32_seen);
}

static void test_args_u32_takes_every_u32_up_to_its_largest(void)
{
    static const daran_port_command_t probe[] = {{"pu", 1, 1, 0, u32_handler, "n"}};
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&m->drive, probe, 1));
    ASSERT_SILENT(m, "pu 1 4294967295");
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, u32_seen);
    ASSERT_SILENT(m, "pu 1 0");
    TEST_ASSERT_EQUAL_UINT32(0, u32_seen);
    ASSERT_ERROR(m, "pu 1 4294967296", "value out of range");
    TEST_ASSERT_EQUAL_UINT32(0, u32_seen); /* a refused value is not stored */
}

#endif /* DARAN_ENABLE_PORT_COMMANDS */

/* ---- telemetry ---- */
#if DARAN_ENABLE_TELEMETRY

static mock_t *telemetry_mock(float period, uint32_t fields)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_TELEMETRY_PERIOD].f32 = period;
    m->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = fields;
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 12.5f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = -3.0f;
    m->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = 0.25f;
    m->props[DARAN_PROP_IQ_MEASURED].f32 = 2.5f;
    m->props[DARAN_PROP_AXIS_ERROR].u32 = 0;
    m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 1;
    mock_clear(m);
    return m;
}

static void test_telemetry_is_off_by_default_and_costs_one_get_per_tick(void)
{
    mock_t *m = telemetry_mock(0.0f, 3);
    for (uint32_t tick = 0; tick < 100; tick++) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, tick, 1000));
    }
    TEST_ASSERT_EQUAL_UINT(0, m->out_len);
    TEST_ASSERT_EQUAL_UINT(100, m->n_gets);
    ASSERT_NO_EFFECT(m);
}

static void test_a_report_has_the_id_the_time_and_the_fields_in_bit_order_with_a_checksum(void)
{
    mock_t *m = telemetry_mock(0.01f, 0x1FF);
    char want[256];
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 1500, 1000));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "@1 1.5 12.5 -3 0.25 2.5 24 30 31 0 1", true));
    m->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = 0x81; /* position and the error register */
    m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 1510, 1000));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "@1 1.51 12.5 16384", true));
    m->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = 0; /* no field: the time alone */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 1520, 1000));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "@1 1.52", true));
    ASSERT_NO_EFFECT(m);
}

static void test_a_report_ignores_field_bits_past_the_ninth_a_hal_returns(void)
{
    /* the range 0..511 keeps them out of `w`; a HAL's own value may have them */
    mock_t *m = telemetry_mock(0.01f, 0xFFFFFE01u);
    char want[256];
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 1500, 1000));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "@1 1.5 12.5", true));
    m->props[DARAN_PROP_TELEMETRY_FIELDS].u32 = 0x200; /* the tenth bit alone: the time alone */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 1510, 1000));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "@1 1.51", true));
    ASSERT_NO_EFFECT(m);
}

static void test_reports_come_every_period_rounded_to_whole_ticks(void)
{
    /* 2.4 ticks round to 2; a period under one tick reports every tick */
    static const struct {
        float period;
        uint32_t hz;
        unsigned want;
    } cases[] = {{0.0024f, 1000, 50}, {0.0026f, 1000, 34}, {0.01f, 1000, 10},
                 {1e-9f, 1000, 100}, {0.1f, 1000, 1},   {1.0f, 8000, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        mock_t *m = telemetry_mock(cases[i].period, 1);
        for (uint32_t tick = 0; tick < 100; tick++) {
            TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, tick, cases[i].hz));
        }
        TEST_ASSERT_EQUAL_UINT_MESSAGE(cases[i].want, m->n_writes, "reports in 100 ticks");
    }
}

static void test_switching_telemetry_on_reports_at_the_next_tick(void)
{
    mock_t *m = telemetry_mock(0.0f, 1);
    for (uint32_t tick = 0; tick < 50; tick++) {
        (void)daran_telemetry_tick(&m->drive, tick, 1000);
    }
    mock_send_line(m, "w axis1.telemetry.period 1");
    TEST_ASSERT_EQUAL_UINT(0, m->out_len);
    TEST_ASSERT_TRUE(m->props[DARAN_PROP_TELEMETRY_PERIOD].f32 == 1.0f);
    mock_clear(m);
    (void)daran_telemetry_tick(&m->drive, 50, 1000);
    TEST_ASSERT_EQUAL_UINT(1, m->n_writes);
    TEST_ASSERT_EQUAL_INT(0, strncmp(m->out, "@1 0.05 ", 8));
}

static void test_a_new_period_starts_at_once_not_after_the_old_report(void)
{
    /* from 10 s to 10 ms: the next report comes at the next tick and then
     * every 10 ms, not after the 10 s the old period still owed */
    mock_t *m = telemetry_mock(10.0f, 1);
    (void)daran_telemetry_tick(&m->drive, 0, 1000);
    TEST_ASSERT_EQUAL_UINT(1, m->n_writes);
    mock_send_line(m, "w axis1.telemetry.period 0.01");
    mock_clear(m);
    for (uint32_t tick = 1; tick <= 101; tick++) {
        (void)daran_telemetry_tick(&m->drive, tick, 1000);
    }
    TEST_ASSERT_EQUAL_UINT(11, m->n_writes); /* ticks 1, 11, ..., 101 */
    /* a refused write changes nothing: no early report */
    mock_clear(m);
    ASSERT_ERROR(m, "w axis1.telemetry.period -1", "value out of range");
    mock_clear(m);
    (void)daran_telemetry_tick(&m->drive, 105, 1000); /* the last report was at 101 */
    TEST_ASSERT_EQUAL_UINT(0, m->n_writes);
}

static void test_the_first_tick_reports_whatever_the_tick_count(void)
{
    /* a port whose counter is far from 0 when telemetry is first on */
    static const uint32_t starts[] = {0x80000000u, 0xFFFFFFF0u, 0x7FFFFF00u, 12345u};
    for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
        mock_t *m = telemetry_mock(0.01f, 1);
        for (uint32_t k = 0; k < 100; k++) {
            (void)daran_telemetry_tick(&m->drive, starts[i] + k, 1000);
        }
        TEST_ASSERT_EQUAL_UINT_MESSAGE(10, m->n_writes, "reports in 100 ticks of 1 ms at 10 ms");
    }
}

static void test_a_failing_read_skips_the_report_and_says_why(void)
{
    mock_t *m = telemetry_mock(0.001f, 3);
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, DARAN_PROP_VEL_ESTIMATE);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_MOTOR_FAULT, daran_telemetry_tick(&m->drive, 7, 1000));
    TEST_ASSERT_EQUAL_UINT(0, m->out_len);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&m->drive, 8, 1000));
    TEST_ASSERT_EQUAL_UINT(1, m->n_writes);
}

static void test_a_report_keeps_the_request_checksum_state_of_replies(void)
{
    /* a report always has a checksum; a reply after it follows its request */
    mock_t *m = telemetry_mock(0.001f, 1);
    mock_send_line(m, "f 1");
    TEST_ASSERT_EQUAL_STRING("12.5 -3\n", m->out);
    mock_clear(m);
    (void)daran_telemetry_tick(&m->drive, 1, 1000);
    mock_send_line(m, "f 1");
    TEST_ASSERT_EQUAL_STRING("12.5 -3\n", m->out);
}

static void test_telemetry_settings_are_written_with_their_ranges(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_UINT(259, ASSERT_SET(m, "w axis1.telemetry.fields 259", DARAN_PROP_TELEMETRY_FIELDS).u32);
    TEST_ASSERT_EQUAL_UINT(511, ASSERT_SET(m, "w axis1.telemetry.fields 511", DARAN_PROP_TELEMETRY_FIELDS).u32);
    ASSERT_ERROR(m, "w axis1.telemetry.fields 512", "value out of range");
    ASSERT_ERROR(m, "w axis1.telemetry.period -0.5", "value out of range");
    TEST_ASSERT_TRUE(ASSERT_SET(m, "w axis1.telemetry.period 0", DARAN_PROP_TELEMETRY_PERIOD).f32 == 0.0f);
}

#endif /* DARAN_ENABLE_TELEMETRY */

int main(void)
{
    UNITY_BEGIN();
#if DARAN_ENABLE_DISCOVERY
    RUN_TEST(test_discovery_lists_every_property_once_in_path_order_then_end);
    RUN_TEST(test_discovery_with_a_prefix_lists_only_the_paths_that_start_with_it);
    RUN_TEST(test_discovery_of_a_prefix_no_path_has_answers_end_alone);
    RUN_TEST(test_checksummed_discovery_gets_a_checksum_on_every_line);
    RUN_TEST(test_discovery_refuses_another_word_and_extra_fields);
    RUN_TEST(test_help_shows_the_discovery_form_of_h);
#else
    RUN_TEST(test_without_discovery_h_properties_is_refused);
#endif
#if DARAN_ENABLE_PORT_COMMANDS
    RUN_TEST(test_a_port_command_runs_its_handler_with_the_parsed_values);
    RUN_TEST(test_bad_port_command_lines_get_the_library_errors_and_no_call);
    RUN_TEST(test_a_handler_error_is_answered_with_its_phrase);
    RUN_TEST(test_port_commands_are_addressed_like_the_core_s);
    RUN_TEST(test_a_path_that_ends_a_full_length_line_reads_nothing_past_it);
    RUN_TEST(test_a_handler_tells_its_words_apart_by_daran_args_word);
    RUN_TEST(test_a_table_of_255_port_commands_is_taken_and_256_refused);
    RUN_TEST(test_a_port_query_replies_through_daran_reply_with_the_request_checksum);
#if DARAN_ENABLE_HELP
    RUN_TEST(test_help_lists_the_port_commands_after_the_core_s);
#endif
    RUN_TEST(test_a_bad_port_table_is_refused_whole_and_the_drive_keeps_its_own);
    RUN_TEST(test_args_parsers_refuse_an_index_past_the_values);
    RUN_TEST(test_args_u32_takes_every_u32_up_to_its_largest);
#endif
#if DARAN_ENABLE_TELEMETRY
    RUN_TEST(test_telemetry_is_off_by_default_and_costs_one_get_per_tick);
    RUN_TEST(test_a_report_has_the_id_the_time_and_the_fields_in_bit_order_with_a_checksum);
    RUN_TEST(test_a_report_ignores_field_bits_past_the_ninth_a_hal_returns);
    RUN_TEST(test_reports_come_every_period_rounded_to_whole_ticks);
    RUN_TEST(test_switching_telemetry_on_reports_at_the_next_tick);
    RUN_TEST(test_a_new_period_starts_at_once_not_after_the_old_report);
    RUN_TEST(test_the_first_tick_reports_whatever_the_tick_count);
    RUN_TEST(test_a_failing_read_skips_the_report_and_says_why);
    RUN_TEST(test_a_report_keeps_the_request_checksum_state_of_replies);
    RUN_TEST(test_telemetry_settings_are_written_with_their_ranges);
#endif
    return UNITY_END();
}
