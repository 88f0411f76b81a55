/* A master-side program that takes daran_client from an installed prefix
 * (tools/ci.d/50-package.sh, find_package(daran_ascii) and
 * daran_ascii::daran_client): it builds requests, reads reply lines, and
 * sends one request it built to a core (tests/support's stub HAL) and reads
 * the core's answer back, so the installed client, its header and the core
 * it links all agree. Exits 1 on any wrong result. */
#include <stdio.h>
#include <string.h>

#include "daran_ascii.h"
#include "daran_client.h"
#include "stub_hal.h"

static int passed;
static int failed;

static void check(int ok, const char *what)
{
    if (ok) {
        passed++;
    } else {
        printf("FAIL: %s\n", what);
        failed++;
    }
}

/* Build `request` and compare the line with `want`. */
static void expect_built(const daran_client_request_t *request, bool with_checksum,
                         const char *want)
{
    char line[DARAN_CLIENT_LINE_MAX];
    size_t len = 0;
    daran_result_t result = daran_client_build(request, with_checksum, line, sizeof line, &len);
    int ok = result == DARAN_OK && len == strlen(want) && memcmp(line, want, len) == 0;
    if (!ok) {
        printf("built \"%.*s\" (%s), want \"%s\"\n", (int)len, line, daran_result_phrase(result),
               want);
    }
    check(ok, "daran_client_build");
}

static char reply[DARAN_REPLY_MAX + 1];
static size_t reply_len;

static void keep_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len > DARAN_REPLY_MAX) {
        len = DARAN_REPLY_MAX;
    }
    memcpy(reply, line, len);
    reply_len = len;
}

static const daran_hal_t keep_reply_port = {DARAN_STUB_HAL_FUNCTIONS, .write = keep_reply};

int main(void)
{
    daran_client_request_t move;
    memset(&move, 0, sizeof move);
    move.command = DARAN_CLIENT_CMD_T;
    move.id = 1;
    move.value_count = 3;
    move.values[0] = 10.0f;
    move.values[1] = 0.0f;
    move.values[2] = 25.0f;
    expect_built(&move, true, "t 1 10 0 25 *83\n"); /* protocol.md section 9's example */

    /* The scope comes from the core's property list: an axis path carries
     * the id in front, a system path after it. */
    daran_client_request_t read;
    memset(&read, 0, sizeof read);
    read.command = DARAN_CLIENT_CMD_R;
    read.id = 2;
    read.path = "output_shaft.vel_limit";
    expect_built(&read, false, "r axis2.output_shaft.vel_limit\n");
    read.path = "vbus_voltage";
    read.id = 1;
    expect_built(&read, false, "r vbus_voltage 1\n");

    /* A checksummed `f` reply, as a drive sends it. */
    const char *f_reply = "12.5 -3.25 *47\r\n";
    daran_client_line_t line;
    daran_client_number_t numbers[DARAN_CLIENT_REPORT_MAX];
    size_t count = 0;
    check(daran_client_read_line(f_reply, strlen(f_reply), true, &line) == DARAN_OK &&
              line.kind == DARAN_CLIENT_LINE_TEXT && line.had_checksum,
          "read_line of a checksummed values line");
    check(daran_client_parse_values(&line, numbers, DARAN_CLIENT_REPORT_MAX, 2u, &count) ==
                  DARAN_OK &&
              count == 2u && numbers[0].f32 == 12.5f && numbers[1].f32 == -3.25f,
          "parse_values: 12.5 -3.25");
    const char *damaged = "12.5 -3.75 *47\r\n";
    check(daran_client_read_line(damaged, strlen(damaged), true, &line) ==
              DARAN_ERR_CHECKSUM_MISMATCH,
          "read_line: a wrong checksum is refused");
    const char *error_line = "error: invalid property\r\n";
    check(daran_client_read_line(error_line, strlen(error_line), false, &line) == DARAN_OK &&
              line.kind == DARAN_CLIENT_LINE_ERROR && line.error == DARAN_ERR_INVALID_PROPERTY,
          "read_line: an error phrase back to its result");

    /* The request the client built, answered by a core. */
    static daran_drive_t drive;
    static daran_stub_t stub;
    daran_stub_init(&stub, 1);
    stub.values[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.5f;
    char request_line[DARAN_CLIENT_LINE_MAX];
    size_t request_len = 0;
    int ok = daran_init(&drive, &keep_reply_port, &stub) == DARAN_OK &&
             daran_client_build(&read, true, request_line, sizeof request_line, &request_len) ==
                 DARAN_OK;
    reply_len = 0;
    if (ok) { /* daran_process_line() takes a line without its `\n` */
        (void)daran_process_line(&drive, request_line, request_len - 1u);
    }
    ok = ok && daran_client_read_line(reply, reply_len, true, &line) == DARAN_OK &&
         daran_client_parse_values(&line, numbers, DARAN_CLIENT_REPORT_MAX, 1u, &count) ==
             DARAN_OK &&
         numbers[0].f32 == 24.5f;
    check(ok, "a core answers the built `r vbus_voltage 1 *N` with 24.5 *N");

    printf("client_consumer (daran-ascii %s): %d passed, %d failed\n", daran_version(), passed,
           failed);
    return failed == 0 ? 0 : 1;
}
