/* daran-sim's inputs (stdin, the pty), whole lines, one at a time.
 *
 * Each input (stdin, the pty) assembles its lines in a bounded buffer and
 * hands each to the drives whole, when its '\n' arrives, then collects the
 * replies of that line alone: replies leave in the order the requests came,
 * as on a real multi-drop line, a collision is a property of one line, and
 * lines from stdin and the pty never interleave inside the drives. A
 * protocol line keeps PROTOCOL_KEEP bytes (the drives answer a longer one
 * `line too long` whatever follows), a directive DIRECTIVE_MAX: memory does
 * not grow with a line that never ends. */
#ifndef SIM_LINES_H
#define SIM_LINES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_sim.h"

/* A protocol line is kept (recorded, sent to the drives) up to one byte past
 * the drive's line buffer: a longer line is answered `line too long` by the
 * drives whatever its remaining bytes, so the rest need not be stored. */
#define PROTOCOL_KEEP ((size_t)DARAN_LINE_MAX + 1u)
/* Longest directive line (a longer `!#` comment is still just ignored). */
#define DIRECTIVE_MAX 1024u

typedef struct line_source {
    bool directives;        /* lines starting with '!' are directives (stdin) */
    daran_sim_sink_fn sink; /* where the replies to its lines go */
    bool directive;         /* the current line is one */
    size_t kept;            /* bytes of the current line in line[] */
    uint64_t total;         /* bytes of the current line so far, before its '\n' */
    char line[DIRECTIVE_MAX + 2u];
} line_source_t;

/* An input whose replies go to @p sink; with @p directives its lines
 * starting with '!' are directives (stdin). */
void source_init(line_source_t *s, bool directives, daran_sim_sink_fn sink);
/* Bytes up to the end of the current line (its '\n' included, *ended set)
 * or all of them; returns how many were taken. */
size_t source_take(line_source_t *s, const char *bytes, size_t len, bool *ended);
/* The current line has ended (its '\n' arrived, or the input did): it runs. */
void source_end_line(line_source_t *s);
/* Every line of @p bytes, until a signal asks to stop. */
void source_feed(line_source_t *s, const char *bytes, size_t len);
/* The input ended: a last line without its '\n' is taken as if it had one. */
void source_eof(line_source_t *s);

#endif /* SIM_LINES_H */
