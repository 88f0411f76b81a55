/* daran-sim's files of a session: --trace (the shafts at every tick, CSV)
 * and --record (every protocol line the drives receive, for tools/replay). */
#ifndef SIM_RECORD_H
#define SIM_RECORD_H

#include <stddef.h>
#include <stdint.h>

/* --trace: the header, then a row at every tick (every --trace-every). */
void trace_header(void);
void trace_row(void);
/* --record: the header (how the session ran), then one line of @p kept of
 * the line's @p total bytes before its '\n' (a longer one keeps only
 * PROTOCOL_KEEP, after a comment). */
void record_header(void);
void record_line(const char *bytes, size_t kept, uint64_t total);

#endif /* SIM_RECORD_H */
