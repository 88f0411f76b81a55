/* Lock-step: stdin's lines and directives, time moving only with
 * `!advance` (and, with --bridge, while a bridged query waits). */
#ifndef SIM_LOCKSTEP_H
#define SIM_LOCKSTEP_H

/* Until stdin ends or a signal asks to stop. */
void run_lockstep(void);

#endif /* SIM_LOCKSTEP_H */
