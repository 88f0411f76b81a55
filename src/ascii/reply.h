/* The reply writer (reply.c): one line at a time in drive->reply, handed
 * whole to the port. */
#ifndef DARAN_REPLY_H
#define DARAN_REPLY_H

#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

void daran_reply_begin(daran_drive_t *drive);
void daran_reply_text(daran_drive_t *drive, const char *text, size_t len);
void daran_reply_cstr(daran_drive_t *drive, const char *text);
void daran_reply_f32(daran_drive_t *drive, float value);
void daran_reply_u64(daran_drive_t *drive, uint64_t value);
void daran_reply_space(daran_drive_t *drive);
void daran_reply_end(daran_drive_t *drive);
void daran_reply_error(daran_drive_t *drive, daran_result_t result);

#endif /* DARAN_REPLY_H */
