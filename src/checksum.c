/* The optional "*N" field: XOR of every byte before the '*'. */
#include "internal.h"

uint8_t daran_xor(const char *text, size_t len)
{
    uint8_t sum = 0;
    for (size_t i = 0; i < len; i++) {
        sum = (uint8_t)(sum ^ (uint8_t)text[i]);
    }
    return sum;
}

daran_result_t daran_checksum_split(const char *line, size_t len, size_t *payload_len,
                                    uint8_t *has_checksum)
{
    size_t star = 0;
    while (star < len && line[star] != '*') {
        star++;
    }
    *payload_len = star;
    *has_checksum = 0;
    if (star == len) {
        return DARAN_OK;
    }

    /* 1..3 digits, value <= 255, then only blanks (D4). */
    size_t i = star + 1;
    uint32_t value = 0;
    size_t digits = 0;
    while (i < len && line[i] >= '0' && line[i] <= '9') {
        if (digits == 3) {
            return DARAN_ERR_INVALID_CHECKSUM;
        }
        value = value * 10u + (uint32_t)(line[i] - '0');
        digits++;
        i++;
    }
    if (digits == 0 || value > 255u) {
        return DARAN_ERR_INVALID_CHECKSUM;
    }
    for (; i < len; i++) {
        if (!daran_is_blank(line[i])) {
            return DARAN_ERR_INVALID_CHECKSUM;
        }
    }

    *has_checksum = 1;
    return daran_xor(line, star) == value ? DARAN_OK : DARAN_ERR_CHECKSUM_MISMATCH;
}
