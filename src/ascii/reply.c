/* The reply writer: builds one line in the instance's reply buffer and hands
 * it whole to the port, with " *N" when the request carried a checksum. */
#include "checksum.h"
#include "hal.h"
#include "number.h"
#include "reply.h"
#include "text.h"

#if DARAN_REPLY_CRLF
#define LINE_END "\r\n"
#else
#define LINE_END "\n"
#endif

/* Room kept free for " *255" and the line end, so a reply is never cut there. */
#define TAIL_ROOM (5u + sizeof LINE_END - 1u)

void daran_reply_begin(daran_drive_t *drive)
{
    drive->reply_len = 0;
}

/* What the line may still take before the tail room. */
static size_t reply_room(const daran_drive_t *drive)
{
    return DARAN_REPLY_MAX - TAIL_ROOM - drive->reply_len;
}

void daran_reply_text(daran_drive_t *drive, const char *text, size_t len)
{
    size_t room = reply_room(drive);
    if (len > room) {
        len = room; /* cannot happen: daran_config.h keeps DARAN_REPLY_MAX above the longest reply */
    }
    for (size_t i = 0; i < len; i++) {
        drive->reply[drive->reply_len + i] = text[i];
    }
    drive->reply_len = (uint16_t)(drive->reply_len + len);
}

void daran_reply_cstr(daran_drive_t *drive, const char *text)
{
    daran_reply_text(drive, text, daran_text_len(text));
}

void daran_reply_space(daran_drive_t *drive)
{
    daran_reply_text(drive, " ", 1);
}

/* Numbers go straight into the line: the printers write nothing when the
 * text would not fit (daran_config.h keeps that from happening). */
void daran_reply_f32(daran_drive_t *drive, float value)
{
    size_t len = daran_format_float(value, drive->reply + drive->reply_len, reply_room(drive));
    drive->reply_len = (uint16_t)(drive->reply_len + len);
}

void daran_reply_u64(daran_drive_t *drive, uint64_t value)
{
    size_t len = daran_format_uint(value, drive->reply + drive->reply_len, reply_room(drive));
    drive->reply_len = (uint16_t)(drive->reply_len + len);
}

void daran_reply_end(daran_drive_t *drive)
{
    size_t len = drive->reply_len;
    char *out = drive->reply;
    if (drive->reply_wants_checksum) {
        uint8_t sum = (uint8_t)(daran_xor(out, len) ^ (uint8_t)' ');
        out[len++] = ' ';
        out[len++] = '*';
        /* 3 digits at most, inside TAIL_ROOM: the room before the line end fits them */
        len += daran_format_uint(sum, out + len, DARAN_REPLY_MAX - (sizeof LINE_END - 1u) - len);
    }
    for (size_t i = 0; i < sizeof LINE_END - 1u; i++) {
        out[len++] = LINE_END[i];
    }
    daran_write_line(drive, out, len);
    drive->reply_len = 0;
}

void daran_reply_error(daran_drive_t *drive, daran_result_t result)
{
    daran_reply_begin(drive);
    static const char error_prefix[] = "error: ";
    daran_reply_text(drive, error_prefix, sizeof error_prefix - 1u);
    daran_reply_cstr(drive, daran_result_phrase(result));
    daran_reply_end(drive);
}
