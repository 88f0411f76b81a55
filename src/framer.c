/* The framer: bytes -> one line at a time in the instance's line buffer.
 * Overlong lines, lost bytes and invalid bytes are decided here, once, and
 * answered at the line's '\n'. */
#include "internal.h"

#define LINE_TOO_LONG 0x01u
#define LINE_INVALID_BYTE 0x02u

void daran_framer_reset(daran_drive_t *drive)
{
    drive->line_len = 0;
    drive->line_flags = 0;
}

bool daran_framer_feed(daran_drive_t *drive, uint8_t byte, bool damaged)
{
    if (byte != '\n') {
        if (drive->line_len == DARAN_LINE_MAX) {
            drive->line_flags |= LINE_TOO_LONG;
            return false;
        }
        if (!daran_byte_allowed(byte)) {
            drive->line_flags |= LINE_INVALID_BYTE;
        }
        drive->line[drive->line_len++] = (char)byte;
        return false;
    }

    uint8_t flags = drive->line_flags;
    size_t len = drive->line_len;
    daran_framer_reset(drive);
    drive->reply_checksum = 0;
    if (damaged || (flags & LINE_TOO_LONG) != 0u) {
        daran_reply_error(drive, DARAN_ERR_LINE_TOO_LONG);
    } else if ((flags & LINE_INVALID_BYTE) != 0u) {
        daran_reply_error(drive, DARAN_ERR_INVALID_CHARACTER);
    } else {
        (void)daran_execute_line(drive, drive->line, len);
    }
    return true;
}
