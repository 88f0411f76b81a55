/* Bytes -> the instance's line buffer and its fields (framer.c). */
#ifndef DARAN_FRAMER_H
#define DARAN_FRAMER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

void daran_framer_reset(daran_drive_t *drive);

/* Frame bytes[0..n) into the current line up to and including the first
 * line end ('\n'; from the ring also DARAN_RX_DAMAGED_END); returns how many
 * bytes it took and sets *ended when a line end was among them. */
size_t daran_framer_feed(daran_drive_t *drive, const uint8_t *bytes, size_t n, bool from_ring,
                         bool *ended);

#endif /* DARAN_FRAMER_H */
