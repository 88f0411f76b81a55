/* Simulated time moves: control ticks (the line, the CAN bus and the front
 * ends), the CAN bus alone inside a tick, and, in lock-step with --bridge,
 * until drive 1's bridge has its answer. Each hands the output out. */
#ifndef SIM_TIME_H
#define SIM_TIME_H

#include <stdint.h>

/* @p n control ticks; a signal stops the run between two ticks. */
void run_ticks(uint64_t n);
/* The simulated time of the next control tick, in nanoseconds. */
uint64_t next_tick_ns(void);
/* --can: the bus alone runs on to @p sim_ns, inside the current tick. */
void run_bus(uint64_t sim_ns);
/* Lock-step --bridge: time runs until the bridged query is answered. */
void wait_for_gateway(void);

#endif /* SIM_TIME_H */
