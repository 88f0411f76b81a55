/* Real time (--pty, --slcan, --usbcan): simulated time runs at the clock's
 * pace; the ASCII pty, stdin and the CAN adapters' ptys are served as their
 * bytes come, the drives answer CAN frames in bus time. */
#ifndef SIM_REALTIME_H
#define SIM_REALTIME_H

/* Print the ptys' paths and serve them until a signal asks to stop; 0, or
 * 1 when a pty could not be made or waiting failed. */
int run_realtime(void);

#endif /* SIM_REALTIME_H */
