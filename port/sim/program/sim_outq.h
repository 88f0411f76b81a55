/* --pty output: a bounded queue, written without blocking when the pty can
 * take bytes. While OUTQ_HIGH bytes wait, the pty is not read (back-pressure:
 * a client that does not read is slowed down instead of losing replies). */
#ifndef SIM_OUTQ_H
#define SIM_OUTQ_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The sink of the pty's replies and telemetry: queued (telemetry that
 * finds the queue full is dropped whole lines at a time, and counted). */
void sink_pty(void *ctx, uint32_t id, const char *bytes, size_t len);
/* Write what the pty takes now (app.pty_fd, non-blocking). */
void outq_flush(void);
/* Bytes waiting for the client. */
size_t outq_pending(void);
/* Whether the pty's next line may run: less than OUTQ_HIGH waits. */
bool outq_has_room(void);
/* Tell the telemetry lines dropped, at most once a second (@p final: now). */
void outq_report(bool final);

#endif /* SIM_OUTQ_H */
