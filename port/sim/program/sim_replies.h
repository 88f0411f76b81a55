/* Where the drives' output goes: stdout (lock-step, stdin's lines), the
 * --pty queue, the console's `can ...` lines; collisions, lost reply bytes
 * and lost frames said on stderr, never silent. */
#ifndef SIM_REPLIES_H
#define SIM_REPLIES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_sim.h"

/* The sink of stdin's replies (with --echo, each line as "< line"). */
void sink_stdout(void *ctx, uint32_t id, const char *bytes, size_t len);
/* The console's node received a frame: a `can ...` line on stdout. */
void console_receive(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns);
/* After one line: its replies to @p sink (drives in id order); two or more
 * drives answering it are a collision, said on stderr. */
void collect(daran_sim_sink_fn sink, const char *what, size_t what_len);
/* What the drives wrote while a tick (or the bus) ran goes out; with
 * @p answering the gateway's answer goes to the input that asked. */
void hand_out(bool answering);
/* CAN frames lost or refused since the last call, said on stderr. */
void report_can(void);

#endif /* SIM_REPLIES_H */
