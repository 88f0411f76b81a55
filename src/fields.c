/* Splitting a line into blank-separated fields: views, never copies. */
#include "internal.h"

bool daran_is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

void daran_split_fields(const char *text, size_t len, daran_fields_t *out)
{
    size_t i = 0;
    out->count = 0;
    while (i < len) {
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
        if (out->count == DARAN_FIELDS_MAX) {
            return; /* "too many" is all the caller needs to know */
        }
        out->at[out->count].text = text + start;
        out->at[out->count].len = (uint16_t)(i - start);
        out->count++;
    }
}
