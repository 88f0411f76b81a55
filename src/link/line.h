/* A line as the framer leaves it: the text, what the framer learnt on the
 * way in, and views of its fields. The stages after the framer read it;
 * none of them scans the line again. */
#ifndef DARAN_LINE_H
#define DARAN_LINE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

/* A field: a view into the line, never a copy. */
typedef struct daran_field {
    const char *text;
    uint16_t len;
} daran_field_t;

/* Field i of a line as a view. */
static inline daran_field_t daran_field_of(const char *line, const daran_fields_t *fields,
                                           unsigned i)
{
    daran_field_t field = {line + fields->start[i], fields->len[i]};
    return field;
}

/* A framed line and what the framer learnt of it on the way in. */
typedef struct daran_line {
    const char *text;
    size_t len;
    size_t star_at; /* index of the first '*'; len when there is none */
} daran_line_t;

/* daran_drive_t.line_flags */
#define DARAN_LINE_TOO_LONG 0x01u
#define DARAN_LINE_INVALID_BYTE 0x02u
#define DARAN_LINE_DAMAGED 0x04u  /* the ring lost bytes of this line */
#define DARAN_LINE_IN_FIELD 0x08u /* the last byte framed was inside a field */

/* A blank in a line the framer accepted: space, tab or '\r' are the only
 * accepted bytes at or below ' ', so one comparison tells. */
static inline bool daran_is_blank(char c)
{
    return (unsigned char)c <= (unsigned char)' ';
}

/* Printable ASCII, tab or '\r': branch-light, for the per-byte path. */
static inline bool daran_byte_allowed(uint8_t byte)
{
    return (uint8_t)(byte - 0x20u) < 0x5Fu || byte == '\t' || byte == '\r';
}

#endif /* DARAN_LINE_H */
