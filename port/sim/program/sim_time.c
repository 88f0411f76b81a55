/* daran-sim's simulated time (sim_time.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_time.h"

#include <inttypes.h>

#include "sim_app.h"
#include "sim_diag.h"
#include "sim_record.h"
#include "sim_replies.h"

void run_ticks(uint64_t n)
{
    uint64_t k;
    for (k = 0; k < n && stop_signal == 0; k++) {
        bool answering = sim_gateway_busy(&app.gateway);
        if (app.can_on) {
            daran_sim_can_tick(&app.can); /* the bus, the line's tick, the front ends */
            sim_gateway_after_run(&app.gateway, &app.bus);
            report_can();
        } else {
            daran_sim_bus_tick(&app.bus);
        }
        trace_row();
        hand_out(answering);
    }
}

uint64_t next_tick_ns(void)
{
    return daran_sim_can_tick_ns(&app.bus, app.bus.ticks + 1u);
}

/* --can: the bus alone runs on to @p sim_ns, inside the current tick (the
 * drives answer the frames that end by then); what that made goes out as
 * a tick's output does. */
void run_bus(uint64_t sim_ns)
{
    bool answering = sim_gateway_busy(&app.gateway);
    if (app.can_on && daran_sim_can_bus_run(&app.can.wire, sim_ns) > 0u) {
        sim_gateway_after_run(&app.gateway, &app.bus);
        report_can();
        hand_out(answering);
    }
}

/* Lock-step --bridge: the line just sent left a query waiting; simulated
 * time runs, frame by frame inside a tick and tick by tick, until its
 * answer (or `error: no reply`) has come, so answers keep the order of the
 * lines and come in the bus's time, which the `can` lines show. */
void wait_for_gateway(void)
{
    uint64_t limit = sim_gateway_wait_limit(app.bus.tick_hz);
    uint64_t ticks = 0u;
    while (sim_gateway_busy(&app.gateway) && ticks < limit && stop_signal == 0) {
        uint64_t frame_end = daran_sim_can_bus_next_ns(&app.can.wire);
        if (frame_end < next_tick_ns()) {
            run_bus(frame_end);
        } else {
            run_ticks(1u);
            ticks++;
        }
    }
    if (sim_gateway_busy(&app.gateway) && stop_signal == 0) {
        complain("drive 1's bridge still waits after %" PRIu64 " ticks (more than its timeouts)",
                 ticks);
    }
}
