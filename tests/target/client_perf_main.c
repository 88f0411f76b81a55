/* Instruction-count image of the client library (daran-client-perf.elf):
 * building requests, reading reply lines, and whole transactions of `f 1`
 * against a core (port/minimal's HAL) in the same image over an in-memory
 * link. The approach of perf_main.c: a marker call after each measured
 * step, counted by tools/qemu-insn-count under QEMU (measure_insns.py
 * subtracts the marker's own cost), then each step's label and example on
 * UART0 in the same order. Every result is checked after the measured
 * steps, so a wrong figure cannot pass for a right one: the image exits 1
 * on the first wrong result and measure_insns.py fails on that exit.
 *
 * Which work a step counts: builds and reads are the client's calls alone
 * (their arguments are set up before the step). The transactions count the
 * client, the in-memory link (a memcpy each way) and, in "client + core",
 * the core's processing of the request, which runs inside the transport's
 * write; "client only" replays the core's very reply bytes instead, and
 * "core alone" is that core processing by itself, so the first is about the
 * sum of the other two. */
#include <string.h>

#include "board.h"
#include "daran_ascii.h"
#include "daran_client.h"
#include "minimal_hal.h"

#define TIMEOUT_MS 50u
#define WIRE_MAX 256u

/* The plugin watches this function's entry. */
void daran_perf_mark(void) __attribute__((noinline));
void daran_perf_mark(void)
{
    __asm volatile("" ::: "memory");
}

/* ---- the in-memory link ---------------------------------------------- */

static minimal_drive_t hal;
static daran_drive_t drive;
static char wire[WIRE_MAX]; /* drive -> client bytes: wire[wire_pos..wire_len) unread */
static size_t wire_pos;
static size_t wire_len;
static uint32_t clock_ms;
static char canned[WIRE_MAX];    /* the core's reply to `f 1`, recorded before measuring */
static size_t canned_len;

static void wire_append(const char *bytes, size_t len)
{
    if (wire_pos == wire_len) { /* all read: start over at the front */
        wire_pos = 0;
        wire_len = 0;
    }
    if (wire_len + len > WIRE_MAX) {
        daran_board_exit(1);
    }
    memcpy(wire + wire_len, bytes, len);
    wire_len += len;
}

/* The core's reply callback: onto the wire. */
static void drive_write(void *ctx, const char *text, size_t len)
{
    (void)ctx;
    wire_append(text, len);
}

static const daran_hal_t drive_write_port = {MINIMAL_HAL_FUNCTIONS, .write = drive_write};

/* The request goes to the core, whose reply goes onto the wire. */
static bool port_write(void *ctx, const char *bytes, size_t len)
{
    (void)ctx;
    if (daran_rx_write(&drive, bytes, len) != len) {
        return false;
    }
    (void)daran_poll(&drive);
    return true;
}

/* What the wire holds, up to size bytes; a read that finds nothing takes
 * its whole timeout, as a blocking read would. */
static size_t port_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms)
{
    (void)ctx;
    size_t unread = wire_len - wire_pos;
    if (unread == 0u) {
        clock_ms += timeout_ms;
        return 0;
    }
    size_t n = unread < size ? unread : size;
    memcpy(buf, wire + wire_pos, n);
    wire_pos += n;
    return n;
}

static uint32_t port_now(void *ctx)
{
    (void)ctx;
    return clock_ms;
}

/* The request goes nowhere; the core's recorded reply comes back. */
static bool replay_write(void *ctx, const char *bytes, size_t len)
{
    (void)ctx;
    (void)bytes;
    (void)len;
    wire_append(canned, canned_len);
    return true;
}

static const daran_client_transport_t transport = {port_write, port_read, port_now, NULL};
static const daran_client_transport_t replay_transport = {replay_write, port_read, port_now,
                                                          NULL};

/* ---- what is measured, and what each step left ------------------------ */

/* A step's label and the line it built or read, for the table. */
typedef struct step {
    const char *label;
    const char *line;
    size_t len;
} step_t;

enum {
    STEP_BUILD_T,
    STEP_BUILD_R,
    STEP_BUILD_R_CHECKSUM,
    STEP_BUILD_R_AXIS,
    STEP_BUILD_W,
    STEP_READ_F,
    STEP_READ_ERROR,
    STEP_READ_REPORT,
    STEP_READ_PROPERTY,
    STEP_TRANSACT,
    STEP_TRANSACT_CHECKSUM,
    STEP_TRANSACT_CLIENT,
    STEP_CORE_ALONE,
    STEP_COUNT
};

/* The reply lines read, as a drive sends them (`\r\n`; checksums computed
 * by hand from protocol.md section 2). */
static const char f_reply[] = "12.5 -3.25 *47\r\n";
static const char error_reply[] = "error: invalid property\r\n";
static const char report_line[] = "@1 12.34 1.5 -2 *110\r\n";
static const char property_line[] = "axis0.output_shaft.vel_limit f32 rw r/min >0\r\n";
static const char f_request[] = "f 1\n";

static step_t steps[STEP_COUNT] = {
    [STEP_BUILD_T] = {"build t with checksum", NULL},
    [STEP_BUILD_R] = {"build r", NULL},
    [STEP_BUILD_R_CHECKSUM] = {"build r with checksum", NULL},
    [STEP_BUILD_R_AXIS] = {"build r, scope AXIS given (no lookup of the path)", NULL},
    [STEP_BUILD_W] = {"build w", NULL},
    [STEP_READ_F] = {"read f reply (read_line + parse_values)", f_reply},
    [STEP_READ_ERROR] = {"read error line (read_line)", error_reply},
    [STEP_READ_REPORT] = {"read telemetry report (read_line + parse_report)", report_line},
    [STEP_READ_PROPERTY] = {"read discovery line (read_line + parse_property)", property_line},
    [STEP_TRANSACT] = {"transact f 1 (client + core)", f_request},
    [STEP_TRANSACT_CHECKSUM] = {"transact f 1 with checksum (client + core)", "f 1 *87\n"},
    [STEP_TRANSACT_CLIENT] = {"transact f 1 (client only, the core's reply replayed)", f_request},
    [STEP_CORE_ALONE] = {"core alone: f 1 (daran_rx_write + daran_poll)", f_request},
};

#define BUILDS 5u /* the steps STEP_BUILD_T..STEP_BUILD_W, in order */
static daran_client_request_t requests[BUILDS];
static char built[BUILDS][DARAN_CLIENT_LINE_MAX];
static size_t built_len[BUILDS];
static daran_result_t results[STEP_COUNT];
static daran_result_t second_results[STEP_COUNT]; /* the parse after read_line */
static daran_client_line_t lines[4];
static daran_client_number_t numbers[DARAN_CLIENT_REPORT_MAX];
static size_t number_count;
static daran_client_report_t report;
static daran_client_property_t property;
static daran_client_link_t link;
static daran_client_link_t checksum_link;
static daran_client_link_t replay_link;
static daran_client_outcome_t outcomes[3];
static size_t core_lines;

static void fail_unless(bool ok)
{
    if (!ok) {
        daran_board_exit(1);
    }
}

static bool view_is(const char *view, size_t len, const char *text)
{
    return len == strlen(text) && memcmp(view, text, len) == 0;
}

static void prepare(void)
{
    memset(requests, 0, sizeof requests);
    requests[0].command = DARAN_CLIENT_CMD_T;
    requests[0].id = 1;
    requests[0].value_count = 3;
    requests[0].values[0] = 10.0f;
    requests[0].values[1] = 0.0f;
    requests[0].values[2] = 25.0f;
    requests[1].command = DARAN_CLIENT_CMD_R;
    requests[1].id = 1;
    requests[1].path = "output_shaft.vel_limit"; /* scope AUTO: the core's list decides */
    requests[2] = requests[1];
    requests[3] = requests[1];
    requests[3].scope = DARAN_CLIENT_SCOPE_AXIS;
    requests[4] = requests[1];
    requests[4].command = DARAN_CLIENT_CMD_W;
    requests[4].value.kind = DARAN_CLIENT_VALUE_F32;
    requests[4].value.f32 = 300.0f;

    minimal_drive_init(&hal);
    fail_unless(daran_init(&drive, &drive_write_port, &hal) == DARAN_OK);
    daran_client_link_config_t config = {false, 0, 5u, NULL, NULL, NULL, NULL};
    fail_unless(daran_client_link_init(&link, &transport, &config) == DARAN_OK);
    config.checksum = true;
    fail_unless(daran_client_link_init(&checksum_link, &transport, &config) == DARAN_OK);
    config.checksum = false;
    fail_unless(daran_client_link_init(&replay_link, &replay_transport, &config) == DARAN_OK);

    /* Record the core's reply to `f 1` for the replayed transaction; the
     * same transaction also runs every path once before it is measured. */
    daran_client_request_t f = {0};
    f.command = DARAN_CLIENT_CMD_F;
    f.id = 1;
    fail_unless(daran_rx_write(&drive, f_request, strlen(f_request)) == strlen(f_request));
    (void)daran_poll(&drive);
    fail_unless(wire_pos == 0u && wire_len > 0u && wire_len <= sizeof canned);
    memcpy(canned, wire, wire_len);
    canned_len = wire_len;
    wire_len = 0;
    fail_unless(daran_client_transact(&link, &f, TIMEOUT_MS, NULL, NULL, NULL) == DARAN_OK);
    fail_unless(wire_pos == wire_len); /* the reply was read whole */
}

/* Every result against what it must be. */
static void check(void)
{
    static const char *const want_built[BUILDS] = {
        "t 1 10 0 25 *83\n",
        "r axis1.output_shaft.vel_limit\n",
        "r axis1.output_shaft.vel_limit *61\n",
        "r axis1.output_shaft.vel_limit\n",
        "w axis1.output_shaft.vel_limit 300\n",
    };
    for (size_t i = 0; i < BUILDS; i++) {
        fail_unless(results[STEP_BUILD_T + i] == DARAN_OK);
        fail_unless(view_is(built[i], built_len[i], want_built[i]));
    }

    fail_unless(results[STEP_READ_F] == DARAN_OK && second_results[STEP_READ_F] == DARAN_OK);
    fail_unless(lines[0].kind == DARAN_CLIENT_LINE_TEXT && lines[0].had_checksum);
    fail_unless(number_count == 2u && numbers[0].f32 == 12.5f && numbers[1].f32 == -3.25f);

    fail_unless(results[STEP_READ_ERROR] == DARAN_OK);
    fail_unless(lines[1].kind == DARAN_CLIENT_LINE_ERROR &&
                lines[1].error == DARAN_ERR_INVALID_PROPERTY);

    fail_unless(results[STEP_READ_REPORT] == DARAN_OK &&
                second_results[STEP_READ_REPORT] == DARAN_OK);
    fail_unless(lines[2].kind == DARAN_CLIENT_LINE_TELEMETRY && report.id == 1u &&
                report.time_s == 12.34f && report.count == 2u);
    fail_unless(report.values[0].f32 == 1.5f && report.values[1].is_integer &&
                report.values[1].negative && report.values[1].magnitude == 2u);

    fail_unless(results[STEP_READ_PROPERTY] == DARAN_OK &&
                second_results[STEP_READ_PROPERTY] == DARAN_OK);
    fail_unless(view_is(property.path, property.path_len, "axis0.output_shaft.vel_limit"));
    fail_unless(property.type == DARAN_CLIENT_TYPE_F32 && property.writable);
    fail_unless(view_is(property.unit, property.unit_len, "r/min"));
    fail_unless(view_is(property.range, property.range_len, ">0"));

    /* The three transactions: one reply line each, the core's (the
     * checksummed one with its `*N` cut off by the link). */
    daran_client_line_t recorded;
    fail_unless(daran_client_read_line(canned, canned_len, false, &recorded) == DARAN_OK);
    const daran_client_link_t *links[3] = {&link, &checksum_link, &replay_link};
    for (size_t i = 0; i < 3u; i++) {
        fail_unless(results[STEP_TRANSACT + i] == DARAN_OK);
        fail_unless(outcomes[i].attempts == 1u && outcomes[i].lines == 1u);
        fail_unless(links[i]->last_len == recorded.len &&
                    memcmp(links[i]->last, recorded.payload, recorded.len) == 0);
    }
    fail_unless(core_lines == 1u && wire_len - wire_pos == canned_len &&
                memcmp(wire + wire_pos, canned, canned_len) == 0);
}

/* Text without its line end. */
static size_t text_len(const char *text, size_t len)
{
    while (len > 0u && (text[len - 1u] == '\n' || text[len - 1u] == '\r')) {
        len--;
    }
    return len;
}

/* One row of the table: `label<TAB>line`, and ` -> answer` when there is one. */
static void say(const char *label, const char *line, size_t len, const char *answer,
                size_t answer_len)
{
    daran_board_uart0_write(label, strlen(label));
    daran_board_uart0_write("\t", 1u);
    daran_board_uart0_write(line, text_len(line, len));
    if (answer_len > 0u) {
        daran_board_uart0_write(" -> ", 4u);
        daran_board_uart0_write(answer, text_len(answer, answer_len));
    }
    daran_board_uart0_write("\n", 1u);
}

int main(void)
{
    daran_board_uart0_init(115200u);
    prepare();
    daran_client_request_t f = {0};
    f.command = DARAN_CLIENT_CMD_F;
    f.id = 1;
    const size_t f_reply_len = strlen(f_reply);
    const size_t error_reply_len = strlen(error_reply);
    const size_t report_line_len = strlen(report_line);
    const size_t property_line_len = strlen(property_line);
    const size_t f_request_len = strlen(f_request);

    (void)daran_board_irq_save(); /* nothing may run between markers but the step */
    daran_perf_mark();
    daran_perf_mark(); /* empty interval: the marker's own cost */
    results[STEP_BUILD_T] =
        daran_client_build(&requests[0], true, built[0], sizeof built[0], &built_len[0]);
    daran_perf_mark();
    results[STEP_BUILD_R] =
        daran_client_build(&requests[1], false, built[1], sizeof built[1], &built_len[1]);
    daran_perf_mark();
    results[STEP_BUILD_R_CHECKSUM] =
        daran_client_build(&requests[2], true, built[2], sizeof built[2], &built_len[2]);
    daran_perf_mark();
    results[STEP_BUILD_R_AXIS] =
        daran_client_build(&requests[3], false, built[3], sizeof built[3], &built_len[3]);
    daran_perf_mark();
    results[STEP_BUILD_W] =
        daran_client_build(&requests[4], false, built[4], sizeof built[4], &built_len[4]);
    daran_perf_mark();
    results[STEP_READ_F] = daran_client_read_line(f_reply, f_reply_len, true, &lines[0]);
    second_results[STEP_READ_F] = daran_client_parse_values(
        &lines[0], numbers, DARAN_CLIENT_REPORT_MAX, 2u, &number_count);
    daran_perf_mark();
    results[STEP_READ_ERROR] = daran_client_read_line(error_reply, error_reply_len, false, &lines[1]);
    daran_perf_mark();
    results[STEP_READ_REPORT] = daran_client_read_line(report_line, report_line_len, false, &lines[2]);
    second_results[STEP_READ_REPORT] = daran_client_parse_report(&lines[2], &report);
    daran_perf_mark();
    results[STEP_READ_PROPERTY] =
        daran_client_read_line(property_line, property_line_len, false, &lines[3]);
    second_results[STEP_READ_PROPERTY] = daran_client_parse_property(&lines[3], &property);
    daran_perf_mark();
    results[STEP_TRANSACT] =
        daran_client_transact(&link, &f, TIMEOUT_MS, NULL, NULL, &outcomes[0]);
    daran_perf_mark();
    results[STEP_TRANSACT_CHECKSUM] =
        daran_client_transact(&checksum_link, &f, TIMEOUT_MS, NULL, NULL, &outcomes[1]);
    daran_perf_mark();
    results[STEP_TRANSACT_CLIENT] =
        daran_client_transact(&replay_link, &f, TIMEOUT_MS, NULL, NULL, &outcomes[2]);
    daran_perf_mark();
    (void)daran_rx_write(&drive, f_request, f_request_len);
    core_lines = daran_poll(&drive);
    daran_perf_mark();

    check();
    for (size_t i = 0; i < BUILDS; i++) {
        steps[STEP_BUILD_T + i].line = built[i];
        steps[STEP_BUILD_T + i].len = built_len[i];
    }
    for (size_t i = 0; i < STEP_COUNT; i++) {
        size_t len = steps[i].len != 0u ? steps[i].len : strlen(steps[i].line);
        /* the transactions show the core's answer (port/minimal's factory
         * values; the checksummed one gets it with its `*N`) */
        size_t answer_len = i >= STEP_TRANSACT && i != STEP_TRANSACT_CHECKSUM ? canned_len : 0u;
        say(steps[i].label, steps[i].line, len, canned, answer_len);
    }
    daran_board_exit(0);
}
