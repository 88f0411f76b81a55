/* A pseudo-terminal for daran-sim's real-time links (--pty, --slcan,
 * --usbcan): its master side, non-blocking, for the simulator; its path for
 * the client. Host program only (POSIX). */
#ifndef SIM_PTY_H
#define SIM_PTY_H

#include <stddef.h>

/* A raw pseudo-terminal: returns the master's descriptor (non-blocking) and
 * its slave's path in @p path, or -1 (errno set). The slave is kept open in
 * *slave_keep (close it at the end), so the master stays readable, with no
 * hang-up, while no client has the port open. */
int sim_pty_open(char *path, size_t path_size, int *slave_keep);

#endif /* SIM_PTY_H */
