/* The optional "*N" field: XOR of every byte before the '*'. */
#include "checksum.h"
#include "line.h"

uint8_t daran_xor(const char *text, size_t len)
{
    uint8_t sum = 0;
    for (size_t i = 0; i < len; i++) {
        sum = (uint8_t)(sum ^ (uint8_t)text[i]);
    }
    return sum;
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
    return line->xor_before_star == value ? DARAN_OK : DARAN_ERR_CHECKSUM_MISMATCH;
}
