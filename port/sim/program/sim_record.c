/* daran-sim's --trace and --record files (sim_record.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_record.h"

#include <inttypes.h>
#include <stdio.h>

#include "sim_app.h"

/* ---- trace ---- */

void trace_header(void)
{
    uint32_t i;
    fputs("time_s", app.trace);
    for (i = 1; i <= app.bus.count; i++) {
        fprintf(app.trace, ",pos_deg_%u,vel_rpm_%u,torque_nm_%u,state_%u", i, i, i, i);
    }
    fputc('\n', app.trace);
}

void trace_row(void)
{
    uint32_t i;
    if (app.trace == NULL || app.bus.ticks % app.trace_every != 0u) {
        return;
    }
    fprintf(app.trace, "%.6f", (double)app.bus.ticks / (double)app.bus.tick_hz);
    for (i = 0; i < app.bus.count; i++) {
        const daran_sim_model_t *m = &app.bus.node[i].sim.model;
        fprintf(app.trace, ",%.6g,%.6g,%.6g,%u", (double)daran_sim_model_pos_deg(m),
                (double)m->vel_rpm, (double)m->torque_cmd, m->state);
    }
    fputc('\n', app.trace);
}

/* ---- --record ---- */

/* The header says how the session ran, so tools/replay can run it the same
 * way without being told. */
void record_header(void)
{
    fputs("# Protocol lines received by daran-sim (--record): seconds since start, a tab,\n"
          "# then the exact bytes of the line before its \\n. Directives are not recorded.\n",
          app.record);
    fprintf(app.record, "# daran-sim --drives %u --tick-hz %u%s%s\n", app.bus.count,
            app.bus.tick_hz, app.gateway.on ? " --bridge" : "",
            app.pty ? " --pty (real time)" : app.realtime ? " (real time)" : "");
}

/* Simulated time in as many decimals as make it exact (4 at 1 kHz, 6 at
 * 8 kHz, at most 9), from the tick count in integers: replaying it gives back
 * the same tick for every line. */
static void record_sim_time(void)
{
    uint64_t hz = app.bus.tick_hz;
    uint64_t scale = 10000u;
    int digits = 4;
    uint64_t whole;
    uint64_t frac;
    while (digits < 9 && scale % hz != 0u) {
        scale *= 10u;
        digits++;
    }
    whole = app.bus.ticks / hz;
    frac = ((app.bus.ticks % hz) * scale + hz / 2u) / hz;
    if (frac >= scale) {
        whole++;
        frac -= scale;
    }
    fprintf(app.record, "%" PRIu64 ".%0*" PRIu64, whole, digits, frac);
}

/* One received line, without its '\n': @p kept of its @p total bytes (a
 * line longer than PROTOCOL_KEEP keeps only those, which the drives answer
 * as they would the whole line: `line too long`). */
void record_line(const char *bytes, size_t kept, uint64_t total)
{
    if (app.record == NULL) {
        return;
    }
    if (total > kept) {
        fprintf(app.record,
                "# overlong line: %" PRIu64 " bytes before its \\n, the first %zu recorded "
                "(more than DARAN_LINE_MAX %u: the drives answer both `line too long`)\n",
                total, kept, (unsigned)DARAN_LINE_MAX);
    }
    if (app.realtime) {
        fprintf(app.record, "%.6f", now_s() - app.record_start_s);
    } else {
        record_sim_time();
    }
    fputc('\t', app.record);
    fwrite(bytes, 1, kept, app.record);
    fputc('\n', app.record);
    fflush(app.record); /* a killed session keeps what it received */
}
