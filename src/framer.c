/* The framer: bytes -> one line at a time in the instance's line buffer.
 * Overlong lines, lost bytes and invalid bytes are decided here, once, and
 * answered at the line's '\n'. On the way in it also notes the first '*'
 * and the XOR of the bytes before it, so no later stage scans the line for
 * the checksum again. */
#include "internal.h"

void daran_framer_reset(daran_drive_t *drive)
{
    drive->line_len = 0;
    drive->line_flags = 0;
    drive->star_at = DARAN_LINE_MAX;
    drive->line_xor = 0;
}

size_t daran_framer_append(daran_drive_t *drive, const uint8_t *bytes, size_t n)
{
    /* The state lives in locals while the loop runs: stores into the line
     * buffer are char stores, which may alias anything, and would otherwise
     * force every field of the instance to be reloaded for every byte. */
    size_t len = drive->line_len;
    size_t star_at = drive->star_at;
    uint8_t flags = drive->line_flags;
    uint8_t sum = drive->line_xor;
    size_t i = 0;
    for (; i < n; i++) {
        uint8_t byte = bytes[i];
        if (byte == '\n') {
            break;
        }
        if (len == DARAN_LINE_MAX) {
            flags |= DARAN_LINE_TOO_LONG;
            continue;
        }
        drive->line[len] = (char)byte;
        if (!daran_byte_allowed(byte)) {
            flags |= DARAN_LINE_INVALID_BYTE;
        }
        if (star_at == DARAN_LINE_MAX) {
            if (byte == '*') {
                star_at = len;
            } else {
                sum = (uint8_t)(sum ^ byte);
            }
        }
        len++;
    }
    drive->line_len = (uint16_t)len;
    drive->star_at = (uint16_t)star_at;
    drive->line_flags = flags;
    drive->line_xor = sum;
    return i;
}

daran_result_t daran_framer_end_line(daran_drive_t *drive, bool damaged)
{
    uint8_t flags = drive->line_flags;
    daran_line_t line = {drive->line, drive->line_len, drive->star_at, drive->line_xor};
    if (line.star_at == DARAN_LINE_MAX) {
        line.star_at = line.len;
    }
    daran_framer_reset(drive);
    drive->reply_checksum = 0;
    daran_result_t result;
    if (damaged || (flags & DARAN_LINE_TOO_LONG) != 0u) {
        result = DARAN_ERR_LINE_TOO_LONG;
    } else if ((flags & DARAN_LINE_INVALID_BYTE) != 0u) {
        result = DARAN_ERR_INVALID_CHARACTER;
    } else {
        return daran_execute_line(drive, &line);
    }
    daran_reply_error(drive, result);
    return result;
}
