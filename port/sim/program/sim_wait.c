/* The real-time loop's sleep (sim_wait.h). */
#include "sim_wait.h"

uint64_t sim_wait_ns(uint64_t now_ns, uint64_t tick_ns, uint64_t frame_end_ns)
{
    uint64_t wake = tick_ns;
    if (frame_end_ns != UINT64_MAX) {
        /* from here on the frame's end is polled for, whatever tick comes
         * first (a tick due meanwhile runs in a pass of the poll) */
        uint64_t spin_from = frame_end_ns > SIM_SPIN_BEFORE_FRAME_END_NS
                                 ? frame_end_ns - SIM_SPIN_BEFORE_FRAME_END_NS
                                 : 0u;
        if (spin_from <= now_ns) {
            return 0u;
        }
        if (spin_from < wake) {
            wake = spin_from;
        }
    }
    return wake > now_ns ? wake - now_ns : 0u;
}
