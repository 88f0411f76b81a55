/* daran-sim's messages on stderr: rate-limited (at most DIAG_PER_SECOND a
 * second, the rest counted and the count told), never blocking. */
#ifndef SIM_DIAG_H
#define SIM_DIAG_H

#include <stdbool.h>
#include <stddef.h>

/* Set up the non-blocking way to stderr; once, before any message. */
void diag_init(void);
/* A new second: room for messages again (call it now and then). */
void diag_tick(void);
/* The count of suppressed messages, if any, when stderr takes it (false
 * when it did not). */
bool diag_summary(void);
/* "daran-sim: " + the message; urgent ones (a failure at exit) are not
 * rate-limited, only never blocking. */
void diag_msg(const char *fmt, ...);
void diag_urgent(const char *fmt, ...);
/* A bad input line: "line N: " + the message, and the exit status 1. */
void complain(const char *fmt, ...);
/* A line's bytes for a message: printable ASCII as is, others as \xNN, at
 * most about 80 characters. */
void quote_line(char *out, size_t size, const char *bytes, size_t len);

#endif /* SIM_DIAG_H */
