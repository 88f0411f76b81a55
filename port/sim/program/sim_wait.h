/* How long daran-sim's real-time loop may sleep before its next event: a
 * control tick or a frame's end on the CAN bus. A pure function (no clock,
 * no I/O), so its choices are tested apart from the loop. */
#ifndef SIM_WAIT_H
#define SIM_WAIT_H

#include <stdint.h>

/* A frame's end closer than this is waited for by polling without a
 * timeout rather than in the kernel: a timed wake-up comes tens of
 * microseconds late on a busy machine, and a request and its answer are
 * two of them in a round trip of about 0.26 ms. Only while a frame is on
 * the bus, so an idle simulator does not spin. */
#define SIM_SPIN_BEFORE_FRAME_END_NS 150000u

/* Nanoseconds to sleep at @p now_ns (all times on the same clock): until the
 * next tick at @p tick_ns, or until the end of the next frame at
 * @p frame_end_ns (UINT64_MAX: no frame on or waiting for the bus) is
 * SIM_SPIN_BEFORE_FRAME_END_NS away, whichever comes first; 0 (poll, do not
 * sleep) when one of them is due or the frame's end is that near. */
uint64_t sim_wait_ns(uint64_t now_ns, uint64_t tick_ns, uint64_t frame_end_ns);

#endif /* SIM_WAIT_H */
