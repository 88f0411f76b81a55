/* A write and its read-back as one round trip (cli.h): `w` goes out
 * without waiting for the silence that means success, `r` right behind it.
 * The drive answers in order: w's answer (nothing, or an `error:` line),
 * then r's (the value, or an `error:` line). w's error may come in before r
 * is sent (the link hands it to the stray handler) or as r's answer (then
 * r's own answer follows and is taken off the line).
 * Through a gateway (can.md C32, C33) a write waits for nothing, so its
 * `error: no reply` is always r's: the write went out and may have taken
 * effect. Its `error: bus error` (a frame it could not send) may be either
 * one's: w's when r's own answer follows it (the write was never sent), r's
 * when nothing follows (the write went out before it). */
#include <string.h>

#include "cli.h"

/* How long one wait for r's answer after w's error lasts before it looks
 * again, so that an answer that came is taken at once. */
#define ANSWER_SLICE_MS 5u

typedef struct readback {
    daran_result_t stray_error;
    char value[DARAN_CLIENT_LINE_MAX];
    size_t value_len;
    bool value_seen;
} readback_t;

/* Whose answer was whose: w's error (DARAN_OK: none came) and r's outcome
 * (DARAN_OK: readback_t.value holds the value). */
typedef struct answers {
    daran_result_t write_error;
    daran_result_t read_result;
    bool read_drive_error; /* read_result is an `error:` line that came */
} answers_t;

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

/* After an `error:` line came as r's answer: r's own answer, if one
 * follows within the timeout (a value, or an error line of its own). */
static void wait_for_read_answer(cli_session_t *s, readback_t *rb)
{
    uint32_t timeout = s->options.timeout_ms;
    uint32_t start = cli_now_ms();
    rb->value_seen = false;
    while (!rb->value_seen && rb->stray_error == DARAN_OK && !s->port_failed &&
           !cli_interrupted()) {
        uint32_t waited = cli_now_ms() - start;
        if (waited >= timeout) {
            return;
        }
        uint32_t left = timeout - waited;
        cli_session_pump(s, left < ANSWER_SLICE_MS ? left : ANSWER_SLICE_MS);
    }
}

/* Sort the lines that came into w's answer and r's (the head comment). */
static answers_t sort_answers(cli_session_t *s, readback_t *rb, daran_result_t result,
                              bool drive_error)
{
    answers_t a = {.write_error = DARAN_OK, .read_result = result, .read_drive_error = drive_error};
    if (rb->stray_error != DARAN_OK) {
        a.write_error = rb->stray_error; /* it came before r went out */
        return a;
    }
    if (!drive_error || result == DARAN_ERR_NO_REPLY) {
        return a; /* r's value, or r's failure */
    }
    wait_for_read_answer(s, rb);
    if (rb->value_seen || rb->stray_error != DARAN_OK) {
        a.write_error = result; /* r's own answer followed it */
        a.read_result = rb->value_seen ? DARAN_OK : rb->stray_error;
    } else if (result != DARAN_ERR_BUS_ERROR) {
        a.write_error = result; /* a refusal, r's answer lost: the write had no effect */
        a.read_result = DARAN_ERR_NO_REPLY;
        a.read_drive_error = false;
    } /* else a bus error alone: r's, the write went out before it */
    return a;
}

/* out's status and failure text once the answers are sorted. */
static cli_status_t judge(cli_session_t *s, const daran_client_request_t *write,
                          const daran_client_request_t *read, const answers_t *a,
                          cli_read_back_t *out)
{
    if (a->write_error == DARAN_ERR_BUS_ERROR) {
        out->result = a->write_error;
        out->may_have_taken_effect = false;
        return cli_failure_text(s, write, CLI_GATEWAY_BUS_ERROR, a->write_error, out->failure,
                                sizeof out->failure);
    }
    if (a->write_error != DARAN_OK) {
        out->refused = a->write_error;
        out->may_have_taken_effect = false;
        return CLI_DRIVE_ERROR;
    }
    if (a->read_result == DARAN_OK) {
        return CLI_OK;
    }
    out->result = a->read_result;
    cli_status_t status = cli_failure_text(s, read, cli_status_of(a->read_result,
                                                                  a->read_drive_error),
                                           a->read_result, out->failure, sizeof out->failure);
    char text[DARAN_CLIENT_LINE_MAX];
    (void)cli_request_text(write, text, sizeof text);
    size_t len = strlen(out->failure);
    (void)snprintf(out->failure + len, sizeof out->failure - len,
                   "; \"%s\" went out before it and may have taken effect", text);
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
    out->may_have_taken_effect = true;
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
        out->may_have_taken_effect = s->port_failed; /* else it could not be built */
        status = cli_failure_text(s, &write, cli_status_of(result, false), result, out->failure,
                                  sizeof out->failure);
    } else {
        result = daran_client_transact(&s->link, &read, s->options.timeout_ms, take_value, &rb,
                                       &outcome);
        if (s->port_failed) {
            out->result = result;
            status = cli_failure_text(s, &read, CLI_PORT_ERROR, result, out->failure,
                                      sizeof out->failure);
        } else {
            answers_t answers = sort_answers(s, &rb, result, outcome.drive_error);
            status = judge(s, &write, &read, &answers, out);
        }
    }
    /* what the drive holds after a write that took effect, or had none */
    if (rb.value_seen && (status == CLI_OK || !out->may_have_taken_effect)) {
        size_t len = rb.value_len < sizeof out->kept - 1 ? rb.value_len : sizeof out->kept - 1;
        memcpy(out->kept, rb.value, len);
        out->kept[len] = '\0';
    }
    s->on_stray = saved_stray;
    s->stray_ctx = saved_ctx;
    return status;
}
