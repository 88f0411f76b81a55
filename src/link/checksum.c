/* The optional "*N" field: XOR of every byte before the '*'. */
#include "checksum.h"
#include "line.h"

#include <string.h>

uint8_t daran_xor(const char *text, size_t len)
{
    /* four bytes a step, folded at the end: a line's text is short, but
     * this is the only pass over it that the checksum needs */
    uint32_t sum = 0;
    size_t i = 0;
    for (; i + 4u <= len; i += 4u) {
        uint32_t word;
        memcpy(&word, text + i, sizeof word);
        sum ^= word;
    }
    sum ^= sum >> 16;
    sum ^= sum >> 8;
    for (; i < len; i++) {
        sum ^= (uint8_t)text[i];
    }
    return (uint8_t)sum;
}

daran_result_t daran_checksum_check(const daran_line_t *line, uint8_t *has_checksum)
{
    *has_checksum = 0;
    if (line->star_at == line->len) {
        return DARAN_OK;
    }

    /* 1..3 digits, value <= 255, then only blanks (D4). */
    const char *text = line->text;
    size_t i = line->star_at + 1u;
    uint32_t value = 0;
    size_t digits = 0;
    while (i < line->len && text[i] >= '0' && text[i] <= '9') {
        if (digits == 3u) {
            return DARAN_ERR_INVALID_CHECKSUM;
        }
        value = value * 10u + (uint32_t)(text[i] - '0');
        digits++;
        i++;
    }
    if (digits == 0u || value > 255u) {
        return DARAN_ERR_INVALID_CHECKSUM;
    }
    for (; i < line->len; i++) {
        if (!daran_is_blank(text[i])) {
            return DARAN_ERR_INVALID_CHECKSUM;
        }
    }

    *has_checksum = 1;
    /* the XOR of the bytes before the '*', taken only for a line that has one */
    return daran_xor(text, line->star_at) == value ? DARAN_OK : DARAN_ERR_CHECKSUM_MISMATCH;
}
