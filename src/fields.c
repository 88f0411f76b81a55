/* Splitting a line into blank-separated fields: views, never copies. */
#include "internal.h"

void daran_split_fields(const char *text, size_t len, daran_fields_t *out)
{
    uint8_t count = 0;
    size_t i = 0;
    out->base = text;
    for (;;) {
        while (i < len && daran_is_blank(text[i])) {
            i++;
        }
        if (i == len) {
            break;
        }
        size_t start = i;
        while (i < len && !daran_is_blank(text[i])) {
            i++;
        }
        if (count == DARAN_FIELDS_MAX) {
            break; /* "too many" is all the caller needs to know */
        }
        out->start[count] = (uint16_t)start;
        out->len[count] = (uint16_t)(i - start);
        count++;
    }
    out->count = count;
}
