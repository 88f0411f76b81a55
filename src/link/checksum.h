/* The optional "*N" field (checksum.c). */
#ifndef DARAN_CHECKSUM_H
#define DARAN_CHECKSUM_H

#include <stddef.h>
#include <stdint.h>

#include "daran_result.h"
#include "line.h"

uint8_t daran_xor(const char *text, size_t len);

/* Check the "*N" field of a line (D4). DARAN_OK with *has_checksum 0 when
 * there is none, 1 when it is well-formed and matches;
 * DARAN_ERR_CHECKSUM_MISMATCH (*has_checksum 1) or DARAN_ERR_INVALID_CHECKSUM
 * (*has_checksum 0) otherwise. */
daran_result_t daran_checksum_check(const daran_line_t *line, uint8_t *has_checksum);

#endif /* DARAN_CHECKSUM_H */
