/* daran-sim's input lines (sim_lines.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_lines.h"

#include <stdio.h>
#include <string.h>

#include "sim_app.h"
#include "sim_diag.h"
#include "sim_directives.h"
#include "sim_record.h"
#include "sim_replies.h"
#include "sim_time.h"

void source_init(line_source_t *s, bool directives, daran_sim_sink_fn sink)
{
    memset(s, 0, sizeof *s);
    s->directives = directives;
    s->sink = sink;
}

size_t source_take(line_source_t *s, const char *bytes, size_t len, bool *ended)
{
    const char *nl = memchr(bytes, '\n', len);
    size_t n = nl != NULL ? (size_t)(nl - bytes) : len;
    size_t room;
    if (s->total == 0u && n > 0u) {
        s->directive = s->directives && bytes[0] == '!';
    }
    room = (s->directive ? DIRECTIVE_MAX : PROTOCOL_KEEP) - s->kept;
    if (room > n) {
        room = n;
    }
    memcpy(s->line + s->kept, bytes, room);
    s->kept += room;
    s->total += n;
    *ended = nl != NULL;
    return nl != NULL ? n + 1u : n;
}

static void protocol_line(line_source_t *s)
{
    if (app.echo && s->sink == sink_stdout) { /* a pty client's lines are not echoed */
        fputs("> ", stdout);
        fwrite(s->line, 1, s->kept, stdout);
        fputc('\n', stdout);
    }
    record_line(s->line, s->kept, s->total);
    s->line[s->kept] = '\n';
    if (app.gateway.on) {
        daran_sim_bus_send_to(&app.bus, SIM_GATEWAY_INDEX, s->line, s->kept + 1u);
    } else {
        daran_sim_bus_send(&app.bus, s->line, s->kept + 1u);
    }
    collect(s->sink, s->line, s->kept);
    if (sim_gateway_busy(&app.gateway)) {
        app.asker = s->sink;
        if (!app.realtime) {
            wait_for_gateway();
        }
    }
}

static void directive_line(line_source_t *s)
{
    if (app.echo) {
        fwrite(s->line, 1, s->kept, stdout);
        fputc('\n', stdout);
    }
    if (s->total > s->kept) {
        if (s->line[1] != '#') {
            complain("directive longer than %u bytes: skipped", DIRECTIVE_MAX);
        }
        return;
    }
    s->line[s->kept] = '\0';
    directive(s->line);
}

/* The current line has ended (its '\n' arrived, or the input did). */
void source_end_line(line_source_t *s)
{
    if (s->directives) {
        app.line_no++;
    }
    if (s->directive) {
        directive_line(s);
    } else {
        protocol_line(s);
    }
    if (s->sink == sink_stdout) {
        fflush(stdout);
    }
    s->kept = 0u;
    s->total = 0u;
    s->directive = false;
}

void source_feed(line_source_t *s, const char *bytes, size_t len)
{
    while (len > 0u && stop_signal == 0) {
        bool ended;
        size_t n = source_take(s, bytes, len, &ended);
        if (ended) {
            source_end_line(s);
        }
        bytes += n;
        len -= n;
    }
}

/* A last line without its '\n' is taken as if it had one. */
void source_eof(line_source_t *s)
{
    if (s->total > 0u && stop_signal == 0) {
        source_end_line(s);
    }
}
