/* daran-sim's outputs of the drives (sim_replies.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_replies.h"

#include <stdio.h>
#include <string.h>

#include "sim_app.h"
#include "sim_can_text.h"
#include "sim_diag.h"
#include "sim_outq.h"

/* Reply bytes a drive could not hold (its output buffer full): never
 * silent. */
static void report_lost(void)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        uint32_t lost = app.bus.node[i].out_lost;
        if (lost != app.lost_reported[i]) {
            diag_msg("drive %u: %u reply bytes lost (its output buffer of %u bytes was full)",
                     daran_sim_drive_id(&app.bus.node[i].sim), lost - app.lost_reported[i],
                     DARAN_SIM_OUT_MAX);
            app.lost_reported[i] = lost;
        }
    }
}

/* A count that a power cycle may have restarted: what is new since @p told. */
static uint32_t news(uint32_t now, uint32_t *told)
{
    uint32_t fresh;
    if (now < *told) {
        *told = 0u;
    }
    fresh = now - *told;
    *told = now;
    return fresh;
}

/* CAN frames a drive lost (its receive ring full) or could not send, and
 * frames an adapter dropped or had refused: never silent. */
void report_can(void)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        uint32_t id = daran_sim_drive_id(&app.bus.node[i].sim);
        uint32_t lost = news(daran_can_dropped(&app.can.front[i]), &app.can_dropped_told[i]);
        uint32_t unsent = news(daran_can_unsent(&app.can.front[i]), &app.can_unsent_told[i]);
        if (lost > 0u) {
            diag_msg("drive %u: %u CAN frames lost (its receive ring of %u frames was full)", id,
                     lost, (unsigned)DARAN_CAN_RX_FRAMES);
        }
        if (unsent > 0u) {
            diag_msg("drive %u: %u CAN frames not sent (bus-off, or its transmit queue full)", id,
                     unsent);
        }
    }
    for (i = 0; i < app.can_ptys; i++) {
        const sim_can_pty_t *p = &app.can_pty[i];
        if (p->dropped != app.pty_dropped_told[i]) {
            diag_msg("%s: %lu frames for the client dropped (it has not read %u KiB)",
                     sim_can_pty_option(p), p->dropped - app.pty_dropped_told[i],
                     (unsigned)(SIM_CAN_PTY_OUT_MAX / 1024u));
            app.pty_dropped_told[i] = p->dropped;
        }
        if (p->refused != app.pty_refused_told[i]) {
            diag_msg("%s: %lu of the client's frames refused (bus-off)", sim_can_pty_option(p),
                     p->refused - app.pty_refused_told[i]);
            app.pty_refused_told[i] = p->refused;
        }
    }
}

void console_receive(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    char line[SIM_CAN_TEXT_LINE_MAX];
    size_t n = sim_can_text_format(frame, end_ns, line);
    (void)ctx;
    fwrite(line, 1, n, stdout);
    app.stdout_pending = true;
}

void sink_stdout(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
    app.stdout_pending = true; /* a tick's output is flushed in real time */
    if (!app.echo) {
        fwrite(bytes, 1, len, stdout);
        return;
    }
    while (len > 0u) {
        const char *nl = memchr(bytes, '\n', len);
        size_t n = nl != NULL ? (size_t)(nl - bytes) + 1u : len;
        fputs("< ", stdout);
        fwrite(bytes, 1, n, stdout);
        bytes += n;
        len -= n;
    }
}

typedef struct collect_ctx {
    daran_sim_sink_fn sink;
    uint32_t ids[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
} collect_ctx_t;

static void sink_recording(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    collect_ctx_t *c = ctx;
    if (c->n < DARAN_SIM_MAX_DRIVES) {
        c->ids[c->n++] = id;
    }
    c->sink(NULL, id, bytes, len);
}

/* After one line: hand its replies out (drives in id order); report a
 * collision on stderr when two or more drives answered that line. */
void collect(daran_sim_sink_fn sink, const char *what, size_t what_len)
{
    collect_ctx_t c;
    char ids[DARAN_SIM_MAX_DRIVES * 4u + 1u];
    char quoted[100];
    size_t o = 0u;
    uint32_t i;
    c.sink = sink;
    c.n = 0u;
    if (daran_sim_bus_collect(&app.bus, sink_recording, &c) >= 2u) {
        for (i = 0; i < c.n; i++) {
            o += (size_t)snprintf(ids + o, sizeof ids - o, " %u", c.ids[i]);
        }
        quote_line(quoted, sizeof quoted, what, what_len);
        diag_msg("collision: %u drives answered `%s` (ids%s)", c.n, quoted, ids);
    }
    report_lost();
}

/* What the drives wrote while a tick (or the bus) ran goes out. Telemetry
 * reports leave after the tick that made them, so they interleave with
 * replies in time order; they are no collision (protocol.md 11.2:
 * streaming is for point-to-point links). So does the gateway's answer to a
 * bridged query, to the input that asked (it waited for it: @p answering). */
void hand_out(bool answering)
{
    if (daran_sim_bus_collect(&app.bus, answering ? app.asker : app.pty ? sink_pty : sink_stdout,
                              NULL) > 0u) {
        report_lost();
    }
}
