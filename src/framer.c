/* The framer: bytes -> one line at a time in the instance's line buffer, in
 * one pass over each byte. A field byte is copied and classified, nothing
 * more; every other byte (blank, '*', line end, invalid) ends the field
 * before it, whose offset and length are noted then, so no later stage
 * walks the line to find its fields. Overlong lines, lost bytes and invalid
 * bytes are decided here, once. The checksum's XOR is not taken here: only
 * a line with a '*' needs it, and checksum.c takes it four bytes a step.
 * The framer hands back how far it got and whether a line ended; drive.c
 * runs the line (docs/performance.md has the designs measured). */
#include "framer.h"

#include "compiler.h"
#include "line.h"
#include "rx_ring.h"

void daran_framer_reset(daran_drive_t *drive)
{
    drive->line_len = 0;
    drive->line_flags = 0;
    drive->star_at = DARAN_LINE_MAX;
    drive->fields.count = 0;
    drive->fields.start[0] = 0; /* where the first field would start */
}

/* A byte that can be part of a field: printable, not blank, not '*'. */
static bool is_field_byte(uint8_t byte)
{
    return (uint8_t)(byte - 0x21u) < 0x5Eu && byte != '*';
}

/* Is this byte a line end: '\n', or from the ring the mark of a damaged one? */
static bool is_line_end(uint8_t byte, bool from_ring)
{
    return byte == '\n' || (from_ring && byte == DARAN_RX_DAMAGED_END);
}

/* The byte at offset `at` is no field byte and comes before any '*': it ends
 * the field that started at fields->start[count] if that is not empty, and
 * the next one may start after it. Past DARAN_FIELDS_MAX fields nothing is
 * recorded: the count stays there, and the line has too many fields whatever
 * its command. */
static DARAN_ALWAYS_INLINE unsigned end_field(daran_fields_t *fields, unsigned count, size_t at)
{
    if (count < DARAN_FIELDS_MAX) {
        size_t start = fields->start[count];
        if (at > start) {
            fields->len[count] = (daran_line_offset_t)(at - start);
            count++;
        }
        if (count < DARAN_FIELDS_MAX) {
            fields->start[count] = (daran_line_offset_t)(at + 1u);
        }
    }
    return count;
}

/* A byte that is no field byte, just stored at `stored`: it ends the field
 * before it, and is noted if it is the first '*' or an invalid byte.
 * Returns true for a line end, which is not part of the line. Out of the
 * byte loop's way, so that loop keeps its values in registers. */
static DARAN_NOINLINE bool other_byte(daran_drive_t *drive, const char *stored, bool from_ring)
{
    uint8_t byte = (uint8_t)*stored;
    size_t at = (size_t)(stored - drive->line);
    if (drive->star_at == DARAN_LINE_MAX) {
        drive->fields.count = (uint8_t)end_field(&drive->fields, drive->fields.count, at);
        if (byte == '*') {
            drive->star_at = (uint16_t)at;
        }
    }
    if (is_line_end(byte, from_ring)) {
        if (byte != '\n') {
            drive->line_flags |= DARAN_LINE_DAMAGED;
        }
        return true;
    }
    if (!daran_byte_allowed(byte)) {
        drive->line_flags |= DARAN_LINE_INVALID_BYTE;
    }
    return false;
}

size_t daran_framer_feed(daran_drive_t *drive, const uint8_t *bytes, size_t n, bool from_ring,
                         bool *ended)
{
    if (n == 0u) {
        *ended = false;
        return 0; /* nothing to frame (and bytes may be NULL: no pointer is made from it) */
    }
    char *line = drive->line;
    char *out = line + drive->line_len;
    if ((drive->line_flags & DARAN_LINE_IN_FIELD) != 0u) {
        drive->fields.count--; /* the field the last bytes ended in goes on */
    }
    const uint8_t *in = bytes;
    const uint8_t *all = bytes + n;
    /* Every byte taken before the line end is stored: the line has room for
     * the bytes up to `end`, so the loop checks no length of its own. */
    size_t room = (size_t)(line + DARAN_LINE_MAX - out);
    const uint8_t *end = bytes + (n < room ? n : room);
    bool line_ended = false;
    for (;;) {
        /* A field byte is copied, nothing more (the checksum stage XORs the
         * line, and only a line that has a '*'). Any other byte is stored
         * too, then other_byte() decides. */
        while (in != end) {
            uint8_t byte = *in++;
            *out = (char)byte;
            if (!is_field_byte(byte)) {
                if (byte == ' ' && drive->star_at == DARAN_LINE_MAX) {
                    /* a blank between fields, the most common of the others */
                    drive->fields.count = (uint8_t)end_field(&drive->fields, drive->fields.count,
                                                             (size_t)(out - drive->line));
                } else if (other_byte(drive, out, from_ring)) {
                    line_ended = true;
                    goto done;
                }
            }
            out++;
        }
        if (in == all) {
            break; /* every byte taken; a field may go on in the next ones */
        }
        /* A full line takes only its line end; anything else makes it too
         * long: discard up to the line end, which is still honoured. */
        const uint8_t *stop = in;
        while (stop != all && !is_line_end(*stop, from_ring)) {
            stop++;
        }
        if (stop != in) {
            drive->line_flags |= DARAN_LINE_TOO_LONG;
            in = stop;
        }
        if (in == all) {
            break;
        }
        /* the line end: it ends the last field, and is never stored */
        if (drive->star_at == DARAN_LINE_MAX) {
            drive->fields.count =
                (uint8_t)end_field(&drive->fields, drive->fields.count, (size_t)(out - line));
        }
        if (*in++ != '\n') {
            drive->line_flags |= DARAN_LINE_DAMAGED;
        }
        line_ended = true;
        break;
    }
done:;
    size_t len = (size_t)(out - line);
    drive->line_len = (daran_line_offset_t)len;
    drive->line_flags &= (uint8_t)~DARAN_LINE_IN_FIELD;
    if (drive->star_at == DARAN_LINE_MAX) {
        /* The bytes end inside a field (a text without its line end, or the
         * ring's run): count it, so the line is whole if nothing follows. */
        daran_fields_t *fields = &drive->fields;
        if (fields->count < DARAN_FIELDS_MAX && len > fields->start[fields->count]) {
            fields->len[fields->count] = (daran_line_offset_t)(len - fields->start[fields->count]);
            fields->count++;
            drive->line_flags |= DARAN_LINE_IN_FIELD;
        }
    }
    *ended = line_ended;
    return n - (size_t)(all - in);
}
