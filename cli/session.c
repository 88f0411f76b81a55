/* A session: the port, the link over it, and the one place where a link
 * result becomes an exit status and a message (cli.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "serial.h"

static void session_report(void *ctx, const daran_client_report_t *report)
{
    cli_session_t *s = ctx;
    if (s->on_report != NULL) {
        s->on_report(s->report_ctx, report);
    } else {
        s->reports_seen++;
    }
}

static void session_stray(void *ctx, const daran_client_line_t *line)
{
    cli_session_t *s = ctx;
    if (s->on_stray != NULL) {
        s->on_stray(s->stray_ctx, line);
    }
}

static cli_status_t pick_port(cli_session_t *s, const cli_options_t *options)
{
    const char *path = options->port;
    if (path == NULL || path[0] == '\0') {
        path = getenv("DARAN_PORT");
    }
    if (path != NULL && path[0] != '\0') {
        if (strlen(path) >= sizeof s->port_path) {
            return cli_fail(CLI_USAGE, "port path too long: %s", path);
        }
        memcpy(s->port_path, path, strlen(path) + 1);
        return CLI_OK;
    }
    char found[4][256];
    size_t count = cli_serial_candidates(found, 4);
    if (count == 0) {
        return cli_fail(CLI_PORT_ERROR, "no port: no /dev/ttyACM* or /dev/ttyUSB* found; "
                                        "name one with --port PATH or DARAN_PORT");
    }
    if (count > 1) {
        return cli_fail(CLI_PORT_ERROR, "%zu ports found (%s, %s%s); name one with --port PATH "
                                        "or DARAN_PORT", count, found[0], found[1],
                        count > 2 ? ", …" : "");
    }
    memcpy(s->port_path, found[0], sizeof s->port_path);
    return CLI_OK;
}

void cli_session_init(cli_session_t *s, const cli_options_t *options)
{
    memset(s, 0, sizeof *s);
    s->fd = -1;
    s->options = *options;
}

cli_status_t cli_session_connect(cli_session_t *s)
{
    if (s->fd >= 0) {
        return CLI_OK;
    }
    const cli_options_t *options = &s->options;
    cli_status_t status = pick_port(s, options);
    if (status != CLI_OK) {
        return status;
    }
    s->fd = cli_serial_open(s->port_path, options->baud);
    if (s->fd < 0) {
        return cli_fail(CLI_PORT_ERROR, "%s: cannot open: %s", s->port_path,
                        errno == EBUSY ? "another program is using it" : strerror(errno));
    }
    cli_serial_transport(s);
    daran_client_link_config_t config = {
        .checksum = options->checksum,
        .retries = 1,
        .quiet_ms = CLI_QUIET_MS,
        .on_report = session_report,
        .report_ctx = s,
        .on_stray = session_stray,
        .stray_ctx = s,
    };
    if (daran_client_link_init(&s->link, &s->transport, &config) != DARAN_OK) {
        cli_session_close(s);
        return cli_fail(CLI_PORT_ERROR, "%s: cannot set up the link", s->port_path);
    }
    return CLI_OK;
}

void cli_session_close(cli_session_t *s)
{
    if (s->fd >= 0) {
        close(s->fd);
        s->fd = -1;
    }
}

cli_status_t cli_status_of(daran_result_t result, bool drive_error)
{
    if (result == DARAN_OK) {
        return CLI_OK;
    }
    /* A gateway's `error: no reply` (can.md C32) is the addressed drive's
     * silence, told sooner than the timeout: not an answer from that drive. */
    if (result == DARAN_ERR_NO_REPLY) {
        return CLI_NO_REPLY;
    }
    /* A gateway's `error: bus error` (can.md C33): it could not put the
     * request on its bus, so the drive behind it did not get it. */
    if (result == DARAN_ERR_BUS_ERROR && drive_error) {
        return CLI_GATEWAY_BUS_ERROR;
    }
    if (drive_error) {
        return CLI_DRIVE_ERROR;
    }
    switch (result) {
    case DARAN_ERR_BUS_ERROR:
        return CLI_PORT_ERROR;
    case DARAN_ERR_NO_REPLY:
    case DARAN_ERR_CHECKSUM_MISMATCH:
    case DARAN_ERR_INVALID_CHECKSUM:
    case DARAN_ERR_INVALID_VALUE:
        return CLI_NO_REPLY;
    default:
        return CLI_USAGE; /* the request could not be built */
    }
}

size_t cli_request_text(const daran_client_request_t *request, char *buf, size_t size)
{
    size_t len = 0;
    if (daran_client_build(request, false, buf, size, &len) != DARAN_OK || len == 0) {
        (void)snprintf(buf, size, "?");
        return 1;
    }
    buf[len - 1] = '\0'; /* the line end */
    return len - 1;
}

static const char *damage_of(daran_result_t result)
{
    switch (result) {
    case DARAN_ERR_CHECKSUM_MISMATCH:
        return "its checksum is wrong";
    case DARAN_ERR_INVALID_CHECKSUM:
        return "it has no valid checksum";
    default:
        return "it cannot be read";
    }
}

cli_status_t cli_port_status(cli_session_t *s)
{
    return cli_fail(CLI_PORT_ERROR, "%s: %s failed: %s", s->port_path,
                    s->port_what != NULL ? s->port_what : "i/o", strerror(s->port_errno));
}

/* Whether the reply the link took last is a gateway's `error: no reply`
 * (the link keeps an error line as its last reply line; a timeout leaves
 * none, or a partial reply's text). */
static bool gateway_said_no_reply(const cli_session_t *s)
{
    char line[DARAN_CLIENT_LINE_MAX];
    int len = snprintf(line, sizeof line, "error: %s", daran_result_phrase(DARAN_ERR_NO_REPLY));
    return len > 0 && s->link.last_len == (size_t)len &&
           memcmp(s->link.last, line, s->link.last_len) == 0;
}

cli_status_t cli_failure_text(cli_session_t *s, const daran_client_request_t *request,
                              cli_status_t status, daran_result_t result, char *buf, size_t size)
{
    char text[DARAN_CLIENT_LINE_MAX];
    (void)cli_request_text(request, text, sizeof text);
    buf[0] = '\0';
    if (s->port_failed) {
        (void)snprintf(buf, size, "%s: %s failed: %s (during \"%s\" to drive %u)", s->port_path,
                       s->port_what != NULL ? s->port_what : "i/o", strerror(s->port_errno),
                       text, request->id);
        return CLI_PORT_ERROR;
    }
    switch (status) {
    case CLI_OK:
        break;
    case CLI_DRIVE_ERROR:
        (void)snprintf(buf, size, "drive %u refused \"%s\": %s", request->id, text,
                       daran_result_phrase(result));
        break;
    case CLI_NO_REPLY:
        if (cli_interrupted()) {
            (void)snprintf(buf, size, "interrupted while waiting for \"%s\"", text);
        } else if (result == DARAN_ERR_NO_REPLY && gateway_said_no_reply(s)) {
            (void)snprintf(buf, size, "drive %u did not answer \"%s\": the gateway on %s "
                           "answered \"error: no reply\"", request->id, text, s->port_path);
        } else if (result == DARAN_ERR_NO_REPLY) {
            (void)snprintf(buf, size, "drive %u did not answer \"%s\" within %u ms on %s",
                           request->id, text, (unsigned)s->options.timeout_ms, s->port_path);
        } else {
            (void)snprintf(buf, size, "drive %u's reply to \"%s\" on %s was damaged: %s",
                           request->id, text, s->port_path, damage_of(result));
        }
        break;
    case CLI_PORT_ERROR:
        (void)snprintf(buf, size, "%s: cannot write \"%s\"", s->port_path, text);
        break;
    case CLI_GATEWAY_BUS_ERROR:
        (void)snprintf(buf, size, "drive %u did not get \"%s\": the gateway on %s answered "
                       "\"error: %s\" (it could not send it on its CAN bus)", request->id, text,
                       s->port_path, daran_result_phrase(DARAN_ERR_BUS_ERROR));
        break;
    default:
        (void)snprintf(buf, size, "cannot build the request \"%s\": %s", text,
                       daran_result_phrase(result));
        break;
    }
    return status;
}

cli_status_t cli_transact_failed(cli_session_t *s, const daran_client_request_t *request,
                                 cli_status_t status, daran_result_t result)
{
    char why[CLI_FAILURE_MAX];
    status = cli_failure_text(s, request, status, result, why, sizeof why);
    return status == CLI_OK ? CLI_OK : cli_fail(status, "%s", why);
}

cli_status_t cli_transact(cli_session_t *s, const daran_client_request_t *request,
                          daran_client_line_fn on_line, void *line_ctx, bool quiet,
                          daran_result_t *result)
{
    daran_client_outcome_t outcome;
    daran_result_t r = daran_client_transact(&s->link, request, s->options.timeout_ms, on_line,
                                             line_ctx, &outcome);
    if (result != NULL) {
        *result = r;
    }
    cli_status_t status = s->port_failed ? CLI_PORT_ERROR : cli_status_of(r, outcome.drive_error);
    if (status == CLI_OK || quiet) {
        return status;
    }
    return cli_transact_failed(s, request, status, r);
}

void cli_session_pump(cli_session_t *s, uint32_t ms)
{
    uint32_t start = cli_now_ms();
    for (;;) {
        daran_client_link_service(&s->link);
        uint32_t waited = cli_now_ms() - start;
        if (waited >= ms || cli_interrupted() || s->port_failed) {
            return;
        }
        /* wait for input without taking it: the link reads it next round */
        cli_serial_wait(s, ms - waited);
    }
}
