/* The framer: bytes -> one line at a time in the instance's line buffer, in
 * one pass over each byte. While a byte is in a register it is copied,
 * classified, XORed into the checksum (up to the first '*') and, at the
 * edges of a field, the field's offset and length are noted, so no later
 * stage walks the line again. Overlong lines, lost bytes and invalid bytes
 * are decided here, once. The framer hands back how far it got and whether
 * a line ended; drive.c runs the line.
 *
 * (A word-at-a-time version, classifying 8 bytes with bit masks, saved only
 * about 10% on recorded sessions, whose fields are short, for 470 bytes of
 * flash; an inner loop per field saved 110 instructions a line for 72
 * bytes. Flash decided both: docs/performance.md.) */
#include "framer.h"
#include "line.h"
#include "rx_ring.h"

void daran_framer_reset(daran_drive_t *drive)
{
    drive->line_len = 0;
    drive->line_flags = 0;
    drive->star_at = DARAN_LINE_MAX;
    drive->line_xor = 0;
    drive->fields.count = 0;
}

/* A byte that can be part of a field: printable, not blank, not '*'. */
static bool is_field_byte(uint8_t byte)
{
    return (uint8_t)(byte - 0x21u) < 0x5Eu && byte != '*';
}

size_t daran_framer_feed(daran_drive_t *drive, const uint8_t *bytes, size_t n, bool from_ring,
                         bool *ended)
{
    /* The state lives in locals while the loop runs: stores into the line
     * buffer are char stores, which may alias anything, and would otherwise
     * force every field of the instance to be reloaded for every byte. */
    daran_fields_t *fields = &drive->fields;
    char *line = drive->line;
    size_t len = drive->line_len;
    size_t star_at = drive->star_at;
    uint8_t flags = drive->line_flags;
    uint8_t sum = drive->line_xor;
    unsigned count = fields->count;
    size_t i = 0;
    *ended = false;
    while (i < n) {
        if (len >= DARAN_LINE_MAX) {
            /* A full line takes only its line end; anything else makes it too
             * long: discard up to the line end, which is still honoured. */
            size_t end = i;
            while (end < n && bytes[end] != '\n' && !(from_ring && bytes[end] == DARAN_RX_DAMAGED_END)) {
                end++;
            }
            if (end > i) {
                flags |= DARAN_LINE_TOO_LONG;
                i = end;
            }
            if (i == n) {
                break;
            }
        }
        uint8_t byte = bytes[i++];
        if (star_at == DARAN_LINE_MAX && is_field_byte(byte)) {
            if ((flags & DARAN_LINE_IN_FIELD) == 0u) {
                flags |= DARAN_LINE_IN_FIELD;
                if (count < DARAN_FIELDS_MAX) {
                    fields->start[count++] = (daran_line_offset_t)len;
                }
            }
            line[len++] = (char)byte;
            sum = (uint8_t)(sum ^ byte);
            continue;
        }
        if ((flags & DARAN_LINE_IN_FIELD) != 0u) {
            /* Past DARAN_FIELDS_MAX fields this rewrites the last one's
             * length, which is never read: the line has too many fields
             * whatever its command. */
            flags &= (uint8_t)~DARAN_LINE_IN_FIELD;
            fields->len[count - 1u] = (daran_line_offset_t)(len - fields->start[count - 1u]);
        }
        if (byte == ' ' && star_at == DARAN_LINE_MAX) {
            line[len++] = ' ';
            sum = (uint8_t)(sum ^ ' ');
            continue;
        }
        if (byte == '\n' || (from_ring && byte == DARAN_RX_DAMAGED_END)) {
            if (byte != '\n') {
                flags |= DARAN_LINE_DAMAGED;
            }
            *ended = true;
            break;
        }
        line[len++] = (char)byte;
        if (!daran_byte_allowed(byte)) {
            flags |= DARAN_LINE_INVALID_BYTE;
        }
        if (star_at == DARAN_LINE_MAX) {
            if (byte == '*') {
                star_at = len - 1u;
            } else {
                sum = (uint8_t)(sum ^ byte);
            }
        }
    }
    if ((flags & DARAN_LINE_IN_FIELD) != 0u) {
        /* the field runs on into the next bytes, or the text ends in it */
        fields->len[count - 1u] = (daran_line_offset_t)(len - fields->start[count - 1u]);
    }
    drive->line_len = (daran_line_offset_t)len;
    drive->star_at = (uint16_t)star_at;
    drive->line_flags = flags;
    drive->line_xor = sum;
    fields->count = (uint8_t)count;
    return i;
}
