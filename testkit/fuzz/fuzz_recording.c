/* Recordings (the format of examples/recordings/, daran-sim --record and
 * daran-record) read as fuzz seeds: the request lines, in order, cut into
 * inputs of whole lines. */
#include <string.h>

#include "daran_fuzz.h"

void daran_fuzz_recording_open(daran_fuzz_recording_t *rec, const char *text, size_t len)
{
    rec->text = text;
    rec->len = len;
    rec->pos = 0;
    rec->line_no = 0;
}

/* A request's time stamp: digits with at most one '.', not empty. */
static bool is_seconds(const char *s, size_t n)
{
    bool digit = false;
    bool point = false;
    for (size_t i = 0; i < n; i++) {
        if (s[i] >= '0' && s[i] <= '9') {
            digit = true;
        } else if (s[i] == '.' && !point) {
            point = true;
        } else {
            return false;
        }
    }
    return digit;
}

int daran_fuzz_recording_next(daran_fuzz_recording_t *rec, char *out, size_t cap, size_t *len,
                              unsigned *first, unsigned *last)
{
    size_t used = 0;
    unsigned requests = 0;
    while (rec->pos < rec->len) {
        const char *start = rec->text + rec->pos;
        size_t rest = rec->len - rec->pos;
        const char *newline = memchr(start, '\n', rest);
        size_t line_len = newline != NULL ? (size_t)(newline - start) : rest;
        size_t next = rec->pos + line_len + (newline != NULL ? 1u : 0u);
        unsigned line_no = rec->line_no + 1u;
        if (line_len == 0u || start[0] == '#' || start[0] == '<') {
            rec->pos = next;
            rec->line_no = line_no;
            continue;
        }
        const char *tab = memchr(start, '\t', line_len);
        if (tab == NULL || !is_seconds(start, (size_t)(tab - start))) {
            *first = line_no;
            return -1;
        }
        const char *request = tab + 1;
        size_t request_len = line_len - (size_t)(request - start);
        /* the seed with this line, and the '\n' that ends the seed */
        size_t need = used + (used > 0u ? 1u : 0u) + request_len + 1u;
        if (requests > 0u && need > DARAN_FUZZ_SEED_MAX) {
            break; /* this line starts the next seed */
        }
        if (need > cap) {
            *first = line_no;
            return -1;
        }
        if (used > 0u) {
            out[used++] = '\n';
        }
        memcpy(out + used, request, request_len);
        used += request_len;
        if (requests == 0u) {
            *first = line_no;
        }
        *last = line_no;
        requests++;
        rec->pos = next;
        rec->line_no = line_no;
    }
    if (requests == 0u) {
        return 0;
    }
    out[used++] = '\n'; /* every line ends in '\n', as the host sent it */
    *len = used;
    return 1;
}
