/* A write and its read-back as one round trip (cli.h): `w` goes out
 * without waiting for the silence that means success, `r` right behind it.
 * The drive answers in order, so an `error:` before r's value is w's; it
 * may come in before r is sent (the link hands it to the stray handler) or
 * as r's answer (then r's own reply follows and is taken off the line).
 * A gateway's `error: no reply` is r's: a write through a gateway waits for
 * nothing, so the write went out and may have taken effect. */
#include <string.h>

#include "cli.h"

typedef struct readback {
    daran_result_t stray_error;
    char value[DARAN_CLIENT_LINE_MAX];
    size_t value_len;
    bool value_seen;
} readback_t;

static void catch_stray(void *ctx, const daran_client_line_t *line)
{
    readback_t *rb = ctx;
    if (line->kind == DARAN_CLIENT_LINE_ERROR && rb->stray_error == DARAN_OK) {
        rb->stray_error = line->error;
    } else if (line->kind == DARAN_CLIENT_LINE_TEXT && !rb->value_seen) {
        memcpy(rb->value, line->payload, line->len);
        rb->value_len = line->len;
        rb->value_seen = true;
    }
}

static void take_value(void *ctx, const daran_client_line_t *line)
{
    readback_t *rb = ctx;
    memcpy(rb->value, line->payload, line->len);
    rb->value_len = line->len;
    rb->value_seen = true;
}

cli_status_t cli_write_read_back(cli_session_t *s, uint8_t id, const char *path,
                                 const daran_client_value_t *value, char *kept, size_t kept_size,
                                 daran_result_t *refused)
{
    cli_read_back_t out;
    cli_status_t status =
        cli_write_read_back_scoped(s, id, path, DARAN_CLIENT_SCOPE_AUTO, value, &out);
    size_t len = strlen(out.kept) < kept_size - 1 ? strlen(out.kept) : kept_size - 1;
    memcpy(kept, out.kept, len);
    kept[len] = '\0';
    *refused = out.refused;
    if (status != CLI_OK && status != CLI_DRIVE_ERROR) {
        return cli_fail(status, "%s", out.failure);
    }
    return status;
}

cli_status_t cli_write_read_back_scoped(cli_session_t *s, uint8_t id, const char *path,
                                        daran_client_scope_t scope,
                                        const daran_client_value_t *value, cli_read_back_t *out)
{
    readback_t rb = {.stray_error = DARAN_OK};
    daran_client_line_fn saved_stray = s->on_stray;
    void *saved_ctx = s->stray_ctx;
    s->on_stray = catch_stray;
    s->stray_ctx = &rb;
    out->refused = DARAN_OK;
    out->result = DARAN_OK;
    out->kept[0] = '\0';
    out->failure[0] = '\0';

    daran_client_request_t write = {
        .command = DARAN_CLIENT_CMD_W, .id = id, .path = path, .value = *value, .scope = scope};
    daran_client_request_t read = {
        .command = DARAN_CLIENT_CMD_R, .id = id, .path = path, .scope = scope};
    daran_client_outcome_t outcome;
    daran_result_t result =
        daran_client_transact(&s->link, &write, 0, NULL, NULL, &outcome);
    cli_status_t status = CLI_OK;
    if (result != DARAN_OK || s->port_failed) {
        out->result = result;
        status = cli_failure_text(s, &write, cli_status_of(result, false), result, out->failure,
                                  sizeof out->failure);
    } else {
        result = daran_client_transact(&s->link, &read, s->options.timeout_ms, take_value, &rb,
                                       &outcome);
        if (s->port_failed) {
            out->result = result;
            status = cli_failure_text(s, &read, CLI_PORT_ERROR, result, out->failure,
                                      sizeof out->failure);
        } else if (outcome.drive_error && result != DARAN_ERR_NO_REPLY) {
            /* w's error (a gateway's `no reply` is never a write's: can.md
             * C32); r's own answer is still on its way */
            out->refused = result;
            rb.value_seen = false;
            uint32_t start = cli_now_ms();
            while (!rb.value_seen && cli_now_ms() - start < s->options.timeout_ms &&
                   !s->port_failed && !cli_interrupted()) {
                cli_session_pump(s, s->options.timeout_ms - (cli_now_ms() - start));
                if (rb.stray_error != DARAN_OK) {
                    break; /* r refused too (a path the drive lacks) */
                }
            }
        } else if (rb.stray_error != DARAN_OK) {
            out->refused = rb.stray_error; /* w's error came before r went out */
        } else if (result != DARAN_OK) {
            char text[DARAN_CLIENT_LINE_MAX];
            (void)cli_request_text(&write, text, sizeof text);
            out->result = result;
            status = cli_failure_text(s, &read, cli_status_of(result, outcome.drive_error),
                                      result, out->failure, sizeof out->failure);
            size_t len = strlen(out->failure);
            (void)snprintf(out->failure + len, sizeof out->failure - len,
                           "; \"%s\" went out before it and may have taken effect", text);
        }
    }
    if (status == CLI_OK && rb.value_seen) {
        size_t len = rb.value_len < sizeof out->kept - 1 ? rb.value_len : sizeof out->kept - 1;
        memcpy(out->kept, rb.value, len);
        out->kept[len] = '\0';
    }
    s->on_stray = saved_stray;
    s->stray_ctx = saved_ctx;
    if (status == CLI_OK && out->refused != DARAN_OK) {
        return CLI_DRIVE_ERROR;
    }
    return status;
}
