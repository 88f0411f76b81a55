/* One simulated drive and its protocol instance for the Unity suites of the
 * simulator library (test_sim_library.c, test_sim_port_rows.c): setUp()
 * makes drive 1 at 1 kHz; sim_say() sends a line and returns its reply.
 * Compiled into each program, against that program's core. */
#ifndef SIM_ONE_DRIVE_H
#define SIM_ONE_DRIVE_H

#include "daran_sim.h"

extern daran_sim_drive_t sim;
extern daran_drive_t drive;

/* Send one line; returns the replies without the last line end ("" for none). */
const char *sim_say(const char *line);

#endif /* SIM_ONE_DRIVE_H */
