/* daran_client: the link. One request at a time: its line goes out, then
 * the link frames received bytes into lines until the request's reply is
 * complete (by the command's reply shape), handing telemetry reports to
 * their callback on the way. Waiting happens only inside the transport's
 * read, never longer than the deadline left. */
#include "daran_client.h"

static uint32_t now_ms(const daran_client_link_t *link)
{
    return link->transport->now_ms(link->transport->ctx);
}

/* Milliseconds left until deadline (0 when it has passed; the clock wraps). */
static uint32_t time_left(const daran_client_link_t *link, uint32_t deadline)
{
    int32_t left = (int32_t)(deadline - now_ms(link));
    return left > 0 ? (uint32_t)left : 0u;
}

daran_result_t daran_client_link_init(daran_client_link_t *link,
                                      const daran_client_transport_t *transport,
                                      const daran_client_link_config_t *config)
{
    if (link == NULL || transport == NULL || config == NULL || transport->write == NULL ||
        transport->read == NULL || transport->now_ms == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    link->transport = transport;
    link->config = *config;
    link->rx_len = 0;
    link->rx_overflow = false;
    link->in_pos = 0;
    link->in_len = 0;
    link->last_len = 0;
    link->bad_lines = 0;
    return DARAN_OK;
}

/* Frame the next whole line into link->rx (rx_len its length, the `\n`
 * cut), reading from the transport while time is left before deadline.
 * A line longer than rx is dropped whole and counted. */
static bool frame_line(daran_client_link_t *link, uint32_t deadline)
{
    for (;;) {
        while (link->in_pos < link->in_len) {
            char c = link->in[link->in_pos++];
            if (c == '\n') {
                bool whole = !link->rx_overflow;
                link->rx_overflow = false;
                if (whole) {
                    return true;
                }
                link->bad_lines++;
                link->rx_len = 0;
                continue;
            }
            if (link->rx_len == sizeof link->rx) {
                link->rx_overflow = true;
                link->rx_len = 0;
            }
            if (!link->rx_overflow) {
                link->rx[link->rx_len++] = c;
            }
        }
        uint32_t left = time_left(link, deadline);
        link->in_pos = 0;
        link->in_len = link->transport->read(link->transport->ctx, link->in, sizeof link->in, left);
        if (link->in_len > sizeof link->in) {
            link->in_len = 0; /* a port that claims more than it was given */
        }
        if (link->in_len == 0u && left == 0u) {
            return false;
        }
    }
}

/* The framed line as a reply line, or its damage. Telemetry reports go to
 * their callback here and are never replies (*is_report). */
static daran_result_t take_line(daran_client_link_t *link, daran_client_line_t *line,
                                bool *is_report)
{
    size_t len = link->rx_len;
    link->rx_len = 0;
    *is_report = len > 0u && link->rx[0] == '@';
    daran_result_t result = daran_client_read_line(link->rx, len, link->config.checksum, line);
    if (*is_report) {
        daran_client_report_t report;
        if (result == DARAN_OK && daran_client_parse_report(line, &report) == DARAN_OK) {
            if (link->config.on_report != NULL) {
                link->config.on_report(link->config.report_ctx, &report);
            }
        } else {
            link->bad_lines++; /* a damaged report is dropped, never taken for a reply */
        }
    }
    return result;
}

/* The next whole line before deadline that is not a telemetry report
 * (those go to their callback on the way); false when the deadline comes
 * first. *result says whether the line could be read. */
static bool next_line(daran_client_link_t *link, uint32_t deadline, daran_client_line_t *line,
                      daran_result_t *result)
{
    while (frame_line(link, deadline)) {
        bool is_report;
        *result = take_line(link, line, &is_report);
        if (!is_report) {
            return true;
        }
    }
    return false;
}

/* Hand every whole line that arrives before deadline to the report or stray
 * callback. */
static void drain(daran_client_link_t *link, uint32_t deadline)
{
    daran_client_line_t line;
    daran_result_t result;
    while (next_line(link, deadline, &line, &result)) {
        if (result != DARAN_OK) {
            link->bad_lines++;
        } else if (line.len > 0u && link->config.on_stray != NULL) {
            link->config.on_stray(link->config.stray_ctx, &line);
        }
    }
}

void daran_client_link_service(daran_client_link_t *link)
{
    if (link != NULL && link->transport != NULL) {
        drain(link, now_ms(link));
    }
}

static void keep_last(daran_client_link_t *link, const daran_client_line_t *line)
{
    for (size_t i = 0; i < line->len; i++) {
        link->last[i] = line->payload[i];
    }
    link->last_len = line->len;
}

/* Collect the reply of one attempt. */
static daran_result_t collect(daran_client_link_t *link, daran_client_reply_shape_t shape,
                              uint32_t timeout_ms, daran_client_line_fn on_line, void *line_ctx,
                              daran_client_outcome_t *outcome)
{
    uint32_t deadline = now_ms(link) + timeout_ms;
    size_t lines = 0;
    for (;;) {
        daran_client_line_t line;
        daran_result_t result;
        if (!next_line(link, deadline, &line, &result)) {
            if (shape == DARAN_CLIENT_REPLY_SILENT ||
                (shape == DARAN_CLIENT_REPLY_UNTIL_QUIET && lines > 0u)) {
                return DARAN_OK;
            }
            return DARAN_ERR_NO_REPLY;
        }
        if (result != DARAN_OK) {
            return result;
        }
        if (line.len == 0u) {
            continue; /* a blank line answers nothing */
        }
        if (line.kind == DARAN_CLIENT_LINE_ERROR) {
            if (lines != 0u) {
                return DARAN_ERR_INVALID_VALUE; /* no reply breaks off into an error */
            }
            outcome->drive_error = true;
            keep_last(link, &line);
            return line.error;
        }
        if (line.kind == DARAN_CLIENT_LINE_END) {
            return shape == DARAN_CLIENT_REPLY_UNTIL_END ? DARAN_OK : DARAN_ERR_INVALID_VALUE;
        }
        if (shape == DARAN_CLIENT_REPLY_SILENT || line.kind != DARAN_CLIENT_LINE_TEXT) {
            return DARAN_ERR_INVALID_VALUE; /* a silent command answers errors only */
        }
        lines++;
        outcome->lines = lines;
        keep_last(link, &line);
        if (on_line != NULL) {
            on_line(line_ctx, &line);
        }
        if (shape == DARAN_CLIENT_REPLY_ONE_LINE ||
            (shape == DARAN_CLIENT_REPLY_ERROR_LINES && lines == DARAN_CLIENT_ERROR_REGISTERS)) {
            return DARAN_OK;
        }
        if (shape == DARAN_CLIENT_REPLY_UNTIL_QUIET) {
            /* `h id` has no end marker: it ends at the first quiet gap */
            uint32_t quiet_deadline = now_ms(link) + link->config.quiet_ms;
            if ((int32_t)(quiet_deadline - deadline) < 0) {
                deadline = quiet_deadline;
            }
        }
    }
}

/* Whether an attempt's failure is the link's (worth another attempt of a
 * query) rather than the drive's answer. */
static bool link_failed(daran_result_t result, const daran_client_outcome_t *outcome)
{
    return !outcome->drive_error &&
           (result == DARAN_ERR_NO_REPLY || result == DARAN_ERR_CHECKSUM_MISMATCH ||
            result == DARAN_ERR_INVALID_CHECKSUM || result == DARAN_ERR_INVALID_VALUE);
}

/* Send link->tx[0..len) and collect its reply; `attempts` sends at most. */
static daran_result_t exchange(daran_client_link_t *link, size_t len,
                               daran_client_reply_shape_t shape, unsigned attempts,
                               uint32_t timeout_ms, daran_client_line_fn on_line, void *line_ctx,
                               daran_client_outcome_t *outcome)
{
    link->last_len = 0;
    /* whatever arrived before this request is not its reply */
    drain(link, now_ms(link));
    for (;;) {
        outcome->attempts++;
        if (!link->transport->write(link->transport->ctx, link->tx, len)) {
            return DARAN_ERR_BUS_ERROR;
        }
        if (shape == DARAN_CLIENT_REPLY_SILENT && timeout_ms == 0u) {
            return DARAN_OK;
        }
        outcome->lines = 0;
        daran_result_t result = collect(link, shape, timeout_ms, on_line, line_ctx, outcome);
        if (result == DARAN_OK || !link_failed(result, outcome)) {
            return result;
        }
        /* the rest of a damaged or late reply must not pass for the next one's */
        link->rx_len = 0;
        link->rx_overflow = false;
        drain(link, now_ms(link) + link->config.quiet_ms);
        if (outcome->attempts >= attempts) {
            return result;
        }
    }
}

static daran_client_outcome_t *outcome_reset(daran_client_outcome_t *outcome,
                                             daran_client_outcome_t *local)
{
    if (outcome == NULL) {
        outcome = local;
    }
    outcome->drive_error = false;
    outcome->attempts = 0;
    outcome->lines = 0;
    return outcome;
}

daran_result_t daran_client_transact(daran_client_link_t *link,
                                     const daran_client_request_t *request, uint32_t timeout_ms,
                                     daran_client_line_fn on_line, void *line_ctx,
                                     daran_client_outcome_t *outcome)
{
    daran_client_outcome_t local;
    outcome = outcome_reset(outcome, &local);
    if (link == NULL || link->transport == NULL || request == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    size_t len = 0;
    daran_result_t result =
        daran_client_build(request, link->config.checksum, link->tx, sizeof link->tx, &len);
    if (result != DARAN_OK) {
        return result;
    }
    unsigned attempts = daran_client_may_retry(request->command) ? 1u + link->config.retries : 1u;
    return exchange(link, len, daran_client_reply_shape(request->command), attempts, timeout_ms,
                    on_line, line_ctx, outcome);
}

daran_result_t daran_client_transact_line(daran_client_link_t *link, const char *payload,
                                          size_t payload_len, daran_client_reply_shape_t shape,
                                          uint32_t timeout_ms, daran_client_line_fn on_line,
                                          void *line_ctx, daran_client_outcome_t *outcome)
{
    daran_client_outcome_t local;
    outcome = outcome_reset(outcome, &local);
    if (link == NULL || link->transport == NULL || payload == NULL ||
        shape > DARAN_CLIENT_REPLY_UNTIL_QUIET) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (payload_len >= sizeof link->tx) {
        return DARAN_ERR_LINE_TOO_LONG;
    }
    for (size_t i = 0; i < payload_len; i++) {
        link->tx[i] = payload[i];
    }
    size_t len = 0;
    daran_result_t result = daran_client_seal(link->tx, sizeof link->tx, payload_len,
                                              link->config.checksum, &len);
    if (result != DARAN_OK) {
        return result;
    }
    return exchange(link, len, shape, 1u, timeout_ms, on_line, line_ctx, outcome);
}
