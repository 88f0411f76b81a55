/* The port under the link: a serial device or pseudo-terminal (serial.c). */
#ifndef DARAN_CLI_SERIAL_H
#define DARAN_CLI_SERIAL_H

#include "cli.h"

/** Whether `baud` is a speed the port can be set to. */
bool cli_serial_baud_supported(uint32_t baud);
/** Open `path` raw, non-blocking, at `baud`, input flushed, and lock it
 * (flock) against another program using it: the fd, or -1 with errno
 * (ENOTTY: not a terminal; EBUSY: another program holds it). */
int cli_serial_open(const char *path, uint32_t baud);
/** Wait until the port has input or timeout_ms passes (a signal ends it early). */
void cli_serial_wait(cli_session_t *s, uint32_t timeout_ms);
/** Point s->transport at s->fd. */
void cli_serial_transport(cli_session_t *s);
/** The /dev/ttyACM* and /dev/ttyUSB* that exist: how many (the first `max`
 * copied into paths). */
size_t cli_serial_candidates(char paths[][256], size_t max);

#endif /* DARAN_CLI_SERIAL_H */
