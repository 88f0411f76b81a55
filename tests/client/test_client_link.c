/* daran_client's link against a real core (port/minimal's HAL) over an
 * in-memory byte link with a simulated clock: a read that finds nothing
 * moves the clock by its whole timeout, as a blocking read would take.
 * The link can lose the drive (it answers nothing), damage reply lines,
 * refuse writes, and the drive streams telemetry between replies. */
#include <string.h>

#include "daran_ascii.h"
#include "daran_client.h"
#include "minimal_hal.h"
#include "unity.h"

#define WIRE_MAX 32768u
#define TIMEOUT_MS 50u
#define QUIET_MS 5u

static minimal_drive_t hal;
static daran_drive_t drive;
static daran_client_link_t link;
static uint32_t clock_ms;
static uint32_t tick;
static char wire[WIRE_MAX]; /* drive -> host bytes not yet read */
static size_t wire_len;
static bool unplugged;     /* the drive receives nothing */
static bool write_refused; /* the port cannot write */
static unsigned damage_lines; /* reply lines still to damage (not reports) */
static unsigned damage_reports;
static unsigned lines_received; /* lines the drive processed */
static bool telemetry_on_write; /* a control tick runs before each line */

static daran_client_report_t reports[8];
static size_t report_count;
static char strays[4][DARAN_CLIENT_LINE_MAX];
static size_t stray_count;
static char got[64][DARAN_CLIENT_LINE_MAX];
static size_t got_count;

/* The drive's write callback: onto the wire, damaged when asked. */
static void drive_write(void *ctx, const char *text, size_t len)
{
    (void)ctx;
    TEST_ASSERT_TRUE(wire_len + len <= WIRE_MAX);
    memcpy(wire + wire_len, text, len);
    bool report = text[0] == '@';
    if (!report && damage_lines > 0u) {
        damage_lines--;
        wire[wire_len] ^= 0x02; /* one bit of the first byte: its checksum no longer fits */
    } else if (report && damage_reports > 0u) {
        damage_reports--;
        wire[wire_len + 1u] ^= 0x02;
    }
    wire_len += len;
}

static const daran_hal_t drive_write_port = {MINIMAL_HAL_FUNCTIONS, .write = drive_write};

static bool port_write(void *ctx, const char *bytes, size_t len)
{
    (void)ctx;
    if (write_refused) {
        return false;
    }
    if (unplugged) {
        return true;
    }
    if (telemetry_on_write) {
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&drive, ++tick, 1000u));
    }
    TEST_ASSERT_EQUAL_UINT64(len, daran_rx_write(&drive, bytes, len));
    lines_received += (unsigned)daran_poll(&drive);
    return true;
}

static size_t port_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms)
{
    (void)ctx;
    if (wire_len == 0u) {
        clock_ms += timeout_ms; /* waited the whole timeout for nothing */
        return 0;
    }
    size_t n = wire_len < size ? wire_len : size;
    memcpy(buf, wire, n);
    memmove(wire, wire + n, wire_len - n);
    wire_len -= n;
    return n;
}

static uint32_t port_now(void *ctx)
{
    (void)ctx;
    return clock_ms;
}

static const daran_client_transport_t transport = {port_write, port_read, port_now, NULL};

static void on_report(void *ctx, const daran_client_report_t *report)
{
    (void)ctx;
    if (report_count < 8u) {
        reports[report_count] = *report;
    }
    report_count++;
}

/* Keep a line's payload as a C string in the next of `room` slots. */
static void keep_line(char (*slots)[DARAN_CLIENT_LINE_MAX], size_t room, size_t *count,
                      const daran_client_line_t *line)
{
    TEST_ASSERT_TRUE(*count < room && line->len < DARAN_CLIENT_LINE_MAX);
    memcpy(slots[*count], line->payload, line->len);
    slots[*count][line->len] = '\0';
    (*count)++;
}

static void on_stray(void *ctx, const daran_client_line_t *line)
{
    (void)ctx;
    keep_line(strays, 4u, &stray_count, line);
}

static void on_line(void *ctx, const daran_client_line_t *line)
{
    (void)ctx;
    keep_line(got, 64u, &got_count, line);
}

static void open_link(bool checksum, uint8_t retries)
{
    daran_client_link_config_t config = {checksum, retries, QUIET_MS, on_report, NULL, on_stray,
                                         NULL};
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_link_init(&link, &transport, &config));
}

void setUp(void)
{
    minimal_drive_init(&hal);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive, &drive_write_port, &hal));
    clock_ms = 0xFFFFFF00u; /* the clock wraps during the tests */
    tick = 0;
    wire_len = 0;
    unplugged = false;
    write_refused = false;
    damage_lines = 0;
    damage_reports = 0;
    lines_received = 0;
    telemetry_on_write = false;
    report_count = 0;
    stray_count = 0;
    got_count = 0;
    open_link(false, 2);
}

void tearDown(void)
{
}

static daran_client_request_t request_of(daran_client_command_t command, uint8_t id)
{
    daran_client_request_t request;
    memset(&request, 0, sizeof request);
    request.command = command;
    request.id = id;
    return request;
}

static daran_result_t send_request(const daran_client_request_t *request,
                                   daran_client_outcome_t *outcome)
{
    return daran_client_transact(&link, request, TIMEOUT_MS, on_line, NULL, outcome);
}

static daran_client_line_t last_line(void)
{
    daran_client_line_t line;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_read_line(link.last, link.last_len, false, &line));
    return line;
}

#if DARAN_ENABLE_TELEMETRY
static void write_property(const char *path, daran_client_value_t value)
{
    daran_client_request_t w = request_of(DARAN_CLIENT_CMD_W, 1);
    w.path = path;
    w.value = value;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&w, NULL));
}
#endif

static void test_a_query_gets_its_values(void)
{
    for (int checksum = 0; checksum < 2; checksum++) {
        open_link(checksum != 0, 2);
        daran_client_request_t move = request_of(DARAN_CLIENT_CMD_P, 1);
        move.value_count = 1;
        move.values[0] = -12.5f;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&move, NULL));
        daran_client_request_t read = request_of(DARAN_CLIENT_CMD_R, 1);
        read.path = "output_shaft.input_pos";
        daran_client_outcome_t outcome;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&read, &outcome));
        TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
        TEST_ASSERT_EQUAL_UINT64(1, outcome.lines);
        TEST_ASSERT_FALSE(outcome.drive_error);
        daran_client_line_t line = last_line();
        daran_client_number_t value;
        size_t count = 0;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_values(&line, &value, 1, 1, &count));
        TEST_ASSERT_EQUAL_FLOAT(-12.5f, value.f32);
        daran_client_request_t version = request_of(DARAN_CLIENT_CMD_I, 1);
        TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&version, NULL));
        daran_client_number_t values[3];
        line = last_line();
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_values(&line, values, 3, 3, &count));
    }
    TEST_ASSERT_EQUAL_UINT64(0, link.bad_lines);
}

static void test_a_refused_command_answers_the_drives_error(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_ST, .id = 1}, NULL));
    daran_client_request_t move = request_of(DARAN_CLIENT_CMD_T, 1);
    move.value_count = 1;
    move.values[0] = 10;
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_ESTOP_ACTIVE, send_request(&move, &outcome));
    TEST_ASSERT_TRUE(outcome.drive_error);
    TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
    daran_client_request_t read = request_of(DARAN_CLIENT_CMD_R, 1);
    read.path = "no.such.path";
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_PROPERTY, send_request(&read, &outcome));
    TEST_ASSERT_TRUE(outcome.drive_error);
    TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts); /* an answer is never retried */
}

static void test_e_answers_seven_registers(void)
{
    open_link(true, 0);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_ST, .id = 1}, NULL));
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_E, .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT64(DARAN_CLIENT_ERROR_REGISTERS, outcome.lines);
    TEST_ASSERT_EQUAL_UINT64(DARAN_CLIENT_ERROR_REGISTERS, got_count);
    daran_client_errors_t errors;
    for (size_t i = 0; i < got_count; i++) {
        daran_client_line_t line;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_read_line(got[i], strlen(got[i]), false, &line));
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_error_line(&line, i, &errors));
    }
    TEST_ASSERT_EQUAL_HEX32(0x4000u, errors.reg[0]); /* e-stop requested */
    TEST_ASSERT_EQUAL_UINT64(0, wire_len);
}

#if DARAN_ENABLE_DISCOVERY
static void test_discovery_is_collected_until_end(void)
{
    daran_client_request_t discover = request_of(DARAN_CLIENT_CMD_H_PROPERTIES, 1);
    discover.path = "axis0.telemetry";
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&discover, &outcome));
    TEST_ASSERT_EQUAL_UINT64(2, outcome.lines);
    daran_client_property_t property;
    daran_client_line_t line;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_read_line(got[1], strlen(got[1]), false, &line));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_property(&line, &property));
    TEST_ASSERT_EQUAL_STRING_LEN("axis0.telemetry.period", property.path, property.path_len);
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_TYPE_F32, property.type);
    /* the whole table, with checksums */
    open_link(true, 0);
    got_count = 0;
    discover.path = NULL;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_transact(&link, &discover, TIMEOUT_MS, NULL,
                                                          NULL, &outcome));
    TEST_ASSERT_EQUAL_UINT64(DARAN_PROP_COUNT, outcome.lines);
}
#endif

#if DARAN_ENABLE_HELP
static void test_help_ends_when_the_link_falls_quiet(void)
{
    /* what the drive answers `h 1` with, counted at the source */
    wire_len = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_process_line(&drive, "h 1", 3));
    size_t expected = 0;
    for (size_t i = 0; i < wire_len; i++) {
        expected += wire[i] == '\n' ? 1u : 0u;
    }
    wire_len = 0;
    TEST_ASSERT_TRUE(expected > 20u);
    daran_client_outcome_t outcome;
    uint32_t start = clock_ms;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_H, .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT64(expected, outcome.lines);
    TEST_ASSERT_EQUAL_UINT32(QUIET_MS, clock_ms - start); /* one quiet gap, not the timeout */
    daran_client_help_t help;
    daran_client_line_t line;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_read_line(got[0], strlen(got[0]), false, &line));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_parse_help(&line, &help));
    TEST_ASSERT_EQUAL_STRING_LEN("t", help.word, help.word_len);
}
#endif

static void test_a_drive_that_does_not_answer_times_out(void)
{
    unplugged = true;
    daran_client_outcome_t outcome;
    uint32_t start = clock_ms;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_REPLY, send_request(&(daran_client_request_t){.command =
                                                             DARAN_CLIENT_CMD_F, .id = 1},
                                                         &outcome));
    TEST_ASSERT_FALSE(outcome.drive_error);
    TEST_ASSERT_EQUAL_UINT8(3, outcome.attempts); /* retries 2 */
    /* never longer than the bound the header gives */
    TEST_ASSERT_EQUAL_UINT32(3u * (TIMEOUT_MS + QUIET_MS), clock_ms - start);
    /* a drive of another id is silent too */
    unplugged = false;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_REPLY, send_request(&(daran_client_request_t){.command =
                                                             DARAN_CLIENT_CMD_G, .id = 2},
                                                         &outcome));
    TEST_ASSERT_EQUAL_UINT32(3, lines_received);
}

static void test_a_damaged_query_reply_is_retried(void)
{
    open_link(true, 2);
    damage_lines = 1;
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_F, .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT8(2, outcome.attempts);
    TEST_ASSERT_EQUAL_UINT32(2, lines_received);
    damage_lines = 10;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH,
                          send_request(&(daran_client_request_t){.command = DARAN_CLIENT_CMD_F,
                                                                 .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT8(3, outcome.attempts);
}

static void test_a_motion_command_is_never_sent_twice(void)
{
    open_link(true, 5);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_ST, .id = 1}, NULL));
    /* its error comes back damaged: the link reports it, and sends nothing again */
    damage_lines = 1;
    lines_received = 0;
    daran_client_request_t start = request_of(DARAN_CLIENT_CMD_MQ, 1);
    start.value_count = 1;
    start.values[0] = 1;
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH, send_request(&start, &outcome));
    TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
    TEST_ASSERT_EQUAL_UINT32(1, lines_received);
    unplugged = true;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&start, &outcome)); /* silence is success */
    TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
}

#if DARAN_ENABLE_TELEMETRY
static void test_telemetry_reports_are_told_apart_from_replies(void)
{
    write_property("telemetry.fields", (daran_client_value_t){DARAN_CLIENT_VALUE_UINT, 0, 0x181u,
                                                              0});
    write_property("telemetry.period", (daran_client_value_t){DARAN_CLIENT_VALUE_F32, 0.001f, 0,
                                                              0});
    telemetry_on_write = true; /* a report lands before every reply */
    open_link(true, 0);
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_F, .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT64(1, outcome.lines);
    TEST_ASSERT_EQUAL_UINT64(1, report_count);
    TEST_ASSERT_EQUAL_UINT8(1, reports[0].id);
    TEST_ASSERT_EQUAL_UINT64(3, reports[0].count); /* position, error register, trajectory_done */
    TEST_ASSERT_EQUAL_FLOAT(0.001f, reports[0].time_s);
    /* a damaged report is dropped, the reply still arrives */
    damage_reports = 1;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_G, .id = 1}, &outcome));
    TEST_ASSERT_EQUAL_UINT64(1, report_count);
    TEST_ASSERT_EQUAL_UINT32(1, link.bad_lines);
    /* reports that arrive between requests are read by service() */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_telemetry_tick(&drive, ++tick, 1000u));
    daran_client_link_service(&link);
    TEST_ASSERT_EQUAL_UINT64(2, report_count);
}
#endif

static void test_a_late_error_of_an_unwaited_command_is_a_stray(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_ST, .id = 1}, NULL));
    daran_client_request_t move = request_of(DARAN_CLIENT_CMD_V, 1);
    move.value_count = 1;
    move.values[0] = 20;
    /* timeout 0: sent, not waited for (streaming) */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_transact(&link, &move, 0, NULL, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_F, .id = 1}, NULL));
    TEST_ASSERT_EQUAL_UINT64(1, stray_count);
    TEST_ASSERT_EQUAL_STRING("error: estop active", strays[0]);
    daran_client_line_t line = last_line();
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_LINE_TEXT, line.kind);
}

static void test_a_port_that_cannot_write_is_a_bus_error(void)
{
    write_refused = true;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BUS_ERROR, send_request(&(daran_client_request_t){.command =
                                                              DARAN_CLIENT_CMD_F, .id = 1},
                                                          NULL));
}

static void test_a_line_too_long_for_the_link_is_dropped(void)
{
    memset(wire, 'x', DARAN_CLIENT_LINE_MAX + 10u);
    wire[DARAN_CLIENT_LINE_MAX + 10u] = '\n';
    wire_len = DARAN_CLIENT_LINE_MAX + 11u;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_request(&(daran_client_request_t){.command =
                                                     DARAN_CLIENT_CMD_F, .id = 1}, NULL));
    TEST_ASSERT_EQUAL_UINT32(1, link.bad_lines);
    TEST_ASSERT_EQUAL_UINT64(0, stray_count);
}

static void test_a_link_is_not_opened_on_a_half_transport(void)
{
    daran_client_link_config_t config;
    memset(&config, 0, sizeof config);
    daran_client_transport_t half = transport;
    half.read = NULL;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_client_link_init(&link, &half, &config));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_client_link_init(NULL, &transport, &config));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_client_link_init(&link, &transport, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_transact(&link, NULL, TIMEOUT_MS, NULL, NULL, NULL));
}

/* A raw line goes out as written (sealed when the link wants checksums),
 * once, and its reply is collected by the shape the caller gives. */
static void test_a_raw_line_is_sent_once_and_its_reply_collected(void)
{
    for (int checksum = 0; checksum < 2; checksum++) {
        open_link(checksum != 0, 2);
        lines_received = 0;
        got_count = 0;
        static const char line[] = "r axis1.output_shaft.vel_limit";
        daran_client_outcome_t outcome;
        TEST_ASSERT_EQUAL_INT(DARAN_OK,
                              daran_client_transact_line(&link, line, sizeof line - 1u,
                                                         DARAN_CLIENT_REPLY_ONE_LINE, TIMEOUT_MS,
                                                         on_line, NULL, &outcome));
        TEST_ASSERT_EQUAL_UINT32(1, lines_received);
        TEST_ASSERT_EQUAL_UINT64(1, got_count);
        TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
        /* the drive answers a checksummed request with a checksummed line,
         * which read_line verified and cut off */
        daran_client_line_t reply;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_read_line(got[0], strlen(got[0]), false,
                                                               &reply));
        TEST_ASSERT_FALSE(reply.had_checksum);
        /* the drive's own error for a malformed line comes back as itself */
        static const char bad[] = "t 1 nonsense";
        TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                              daran_client_transact_line(&link, bad, sizeof bad - 1u,
                                                         DARAN_CLIENT_REPLY_SILENT, TIMEOUT_MS,
                                                         NULL, NULL, &outcome));
        TEST_ASSERT_TRUE(outcome.drive_error);
    }
    /* a lost reply is not sent again, even for a query */
    damage_lines = 1;
    lines_received = 0;
    daran_client_outcome_t outcome;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH,
                          daran_client_transact_line(&link, "f 1", 3, DARAN_CLIENT_REPLY_ONE_LINE,
                                                     TIMEOUT_MS, NULL, NULL, &outcome));
    TEST_ASSERT_EQUAL_UINT8(1, outcome.attempts);
    TEST_ASSERT_EQUAL_UINT32(1, lines_received);
    /* misuse and a line too long for the link */
    char long_line[DARAN_CLIENT_LINE_MAX];
    memset(long_line, 'x', sizeof long_line);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_LINE_TOO_LONG,
                          daran_client_transact_line(&link, long_line, sizeof long_line,
                                                     DARAN_CLIENT_REPLY_SILENT, TIMEOUT_MS, NULL,
                                                     NULL, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_LINE_TOO_LONG,
                          daran_client_transact_line(&link, long_line, sizeof long_line - 3u,
                                                     DARAN_CLIENT_REPLY_SILENT, TIMEOUT_MS, NULL,
                                                     NULL, NULL)); /* no room for " *N\n" */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_transact_line(&link, NULL, 0, DARAN_CLIENT_REPLY_SILENT,
                                                     TIMEOUT_MS, NULL, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_transact_line(&link, "f 1", 3,
                                                     (daran_client_reply_shape_t)99, TIMEOUT_MS,
                                                     NULL, NULL, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_query_gets_its_values);
    RUN_TEST(test_a_refused_command_answers_the_drives_error);
    RUN_TEST(test_e_answers_seven_registers);
#if DARAN_ENABLE_DISCOVERY
    RUN_TEST(test_discovery_is_collected_until_end);
#endif
#if DARAN_ENABLE_HELP
    RUN_TEST(test_help_ends_when_the_link_falls_quiet);
#endif
    RUN_TEST(test_a_drive_that_does_not_answer_times_out);
    RUN_TEST(test_a_damaged_query_reply_is_retried);
    RUN_TEST(test_a_motion_command_is_never_sent_twice);
#if DARAN_ENABLE_TELEMETRY
    RUN_TEST(test_telemetry_reports_are_told_apart_from_replies);
#endif
    RUN_TEST(test_a_late_error_of_an_unwaited_command_is_a_stray);
    RUN_TEST(test_a_port_that_cannot_write_is_a_bus_error);
    RUN_TEST(test_a_line_too_long_for_the_link_is_dropped);
    RUN_TEST(test_a_link_is_not_opened_on_a_half_transport);
    RUN_TEST(test_a_raw_line_is_sent_once_and_its_reply_collected);
    return UNITY_END();
}
