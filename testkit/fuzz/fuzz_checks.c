/* The harness's own reading of the protocol: is a reply line well-formed
 * (invariant 4), and which drive is a request line for (invariant 3).
 * Written from docs/protocol.md, not from the core's code. */
#include <string.h>

#include "daran_fuzz.h"

/* protocol.md section 8, in daran_result_t order (index = result). */
static const char *const error_phrases[] = {
    "unknown command", "invalid command format", "invalid motor", "invalid value",
    "value out of range", "invalid mode", "invalid property", "read only property",
    "invalid checksum", "checksum mismatch", "line too long", "invalid character",
    "no preset", "trajectory infeasible", "estop active", "motor fault", "motor idle",
    "updating", "not idle", "no update", "bad image", /* the update's (docs/update.md) */
    "no reply", "bus error", "not bridged", /* a gateway's (docs/can.md) */
};

static bool is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static bool known_phrase(const char *text, size_t len)
{
    for (size_t i = 0; i < sizeof error_phrases / sizeof error_phrases[0]; i++) {
        if (strlen(error_phrases[i]) == len && memcmp(error_phrases[i], text, len) == 0) {
            return true;
        }
    }
    return false;
}

const char *daran_fuzz_reply_problem(const char *line, size_t len)
{
    if (len > DARAN_REPLY_MAX) {
        return "longer than DARAN_REPLY_MAX";
    }
#if DARAN_REPLY_CRLF
    static const char line_end[] = "\r\n";
#else
    static const char line_end[] = "\n";
#endif
    const size_t end_len = sizeof line_end - 1u;
    if (len < end_len || memcmp(line + len - end_len, line_end, end_len) != 0) {
        return DARAN_REPLY_CRLF ? "does not end in CR LF" : "does not end in LF";
    }
    size_t body = len - end_len;
    if (body == 0u) {
        return "empty";
    }
    for (size_t i = 0; i < body; i++) {
        unsigned char c = (unsigned char)line[i];
        if (c < 0x20u || c > 0x7eu) {
            return "a byte that is not printable ASCII (or a line end inside)";
        }
    }
    size_t payload = body;
    const char *star = memchr(line, '*', body);
    if (star != NULL) {
        size_t at = (size_t)(star - line);
        size_t digits = body - at - 1u;
        if (at < 2u || line[at - 1u] != ' ' || digits < 1u || digits > 3u ||
            memchr(star + 1, '*', digits) != NULL) {
            return "a '*' that is not a ` *N` checksum tail at the end";
        }
        unsigned n = 0;
        for (size_t i = at + 1u; i < body; i++) {
            if (!is_digit(line[i])) {
                return "a checksum tail that is not decimal";
            }
            n = n * 10u + (unsigned)(line[i] - '0');
        }
        if (n > 255u || (digits > 1u && line[at + 1u] == '0')) {
            return "a checksum above 255 or with a leading zero";
        }
        unsigned x = 0;
        for (size_t i = 0; i < at; i++) {
            x ^= (unsigned char)line[i];
        }
        if (x != n) {
            return "a checksum that is not the XOR of the bytes before the '*'";
        }
        payload = at - 1u;
    }
    if (payload >= 5u && memcmp(line, "error", 5) == 0) {
        if (payload < 7u || memcmp(line, "error: ", 7) != 0 ||
            !known_phrase(line + 7, payload - 7u)) {
            return "an error that is not `error: ` and a phrase of protocol.md section 8";
        }
    }
    return NULL;
}

/* ---- which drive a request line is for ---- */

static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

typedef struct field {
    const char *text;
    size_t len;
} field_t;

/* The fields of @p len bytes split on blanks; returns how many there are
 * (the first @p max stored). */
static size_t split_fields(const char *s, size_t len, field_t *out, size_t max)
{
    size_t count = 0;
    size_t i = 0;
    for (;;) {
        while (i < len && is_blank(s[i])) {
            i++;
        }
        if (i == len) {
            return count;
        }
        size_t start = i;
        while (i < len && !is_blank(s[i])) {
            i++;
        }
        if (count < max) {
            out[count].text = s + start;
            out[count].len = i - start;
        }
        count++;
    }
}

static bool word_equals(field_t f, const char *word)
{
    size_t n = strlen(word);
    if (f.len != n) {
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        char c = f.text[i];
        if (c >= 'A' && c <= 'Z') {
            c = (char)(c - 'A' + 'a');
        }
        if (c != word[i]) {
            return false;
        }
    }
    return true;
}

/* The vendor's command words this build answers (protocol.md section 6;
 * daran_config.h's options leave some out: they answer `unknown command`). */
static const char *const vendor_words[] = {
    "t",  "q",  "p",  "v",  "c",  "d",  "r",  "w",  "ss", "se", "sr", "sc", "sz", "st",
    "f",  "g",  "i",  "e",  "u",
#if DARAN_ENABLE_HELP
    "h",
#endif
#if DARAN_ENABLE_MULTI_MOTOR
    "ms", "mt", "mq", "mp", "mv", "mc",
#endif
};

/* A motor id (protocol.md section 5's grammar, D7: an exact decimal
 * integer; `5.0`, `+5`, `05`, `50e-1` are 5, `-0` is 0), or -1. */
static int motor_id_value(const char *p, size_t n)
{
    char digits[DARAN_LINE_MAX];
    size_t count = 0;
    long scale = 0; /* the value is digits x 10^scale */
    bool negative = false;
    bool any = false;
    size_t i = 0;
    if (n > sizeof digits) {
        return -1;
    }
    if (i < n && (p[i] == '+' || p[i] == '-')) {
        negative = p[i] == '-';
        i++;
    }
    while (i < n && is_digit(p[i])) {
        digits[count++] = p[i++];
        any = true;
    }
    if (i < n && p[i] == '.') {
        i++;
        while (i < n && is_digit(p[i])) {
            digits[count++] = p[i++];
            scale--;
            any = true;
        }
    }
    if (!any) {
        return -1;
    }
    if (i < n && (p[i] == 'e' || p[i] == 'E')) {
        i++;
        bool exp_negative = false;
        if (i < n && (p[i] == '+' || p[i] == '-')) {
            exp_negative = p[i] == '-';
            i++;
        }
        size_t start = i;
        long e = 0;
        while (i < n && is_digit(p[i])) {
            if (e < 100000L) {
                e = e * 10L + (long)(p[i] - '0');
            }
            i++;
        }
        if (i == start) {
            return -1;
        }
        scale += exp_negative ? -e : e;
    }
    if (i != n) {
        return -1;
    }
    size_t first = 0;
    while (first < count && digits[first] == '0') {
        first++;
    }
    if (first == count) {
        return 0; /* zero, `-0` included */
    }
    if (negative) {
        return -1;
    }
    size_t last = count;
    while (digits[last - 1u] == '0') {
        last--;
        scale++;
    }
    if (scale < 0 || (long)(last - first) + scale > 9L) {
        return -1; /* a fraction, or far beyond any id */
    }
    uint64_t value = 0;
    for (size_t k = first; k < last; k++) {
        value = value * 10u + (uint64_t)(digits[k] - '0');
    }
    for (long k = 0; k < scale; k++) {
        value *= 10u;
    }
    return value <= (uint64_t)DARAN_MOTOR_ID_MAX ? (int)value : -1;
}

/* The checksum field (protocol.md section 2): false when the line has one
 * that is malformed or wrong; *payload is the length before the '*'. */
static bool checksum_right(const char *line, size_t len, size_t *payload)
{
    const char *star = memchr(line, '*', len);
    if (star == NULL) {
        *payload = len;
        return true;
    }
    size_t at = (size_t)(star - line);
    size_t i = at + 1u;
    unsigned n = 0;
    size_t digits = 0;
    while (i < len && is_digit(line[i])) {
        if (digits < 4u) {
            n = n * 10u + (unsigned)(line[i] - '0');
        }
        digits++;
        i++;
    }
    while (i < len && is_blank(line[i])) {
        i++;
    }
    if (digits < 1u || digits > 3u || n > 255u || i != len) {
        return false;
    }
    unsigned x = 0;
    for (size_t k = 0; k < at; k++) {
        x ^= (unsigned char)line[k];
    }
    *payload = at;
    return x == n;
}

int daran_fuzz_line_motor(const char *line, size_t len, const char *const *words,
                          size_t word_count)
{
    if (len > DARAN_LINE_MAX) {
        return DARAN_FUZZ_EVERY_DRIVE;
    }
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)line[i];
        if (!((c >= 0x20u && c <= 0x7eu) || c == '\t' || c == '\r')) {
            return DARAN_FUZZ_EVERY_DRIVE;
        }
    }
    size_t payload = 0;
    if (!checksum_right(line, len, &payload)) {
        return DARAN_FUZZ_EVERY_DRIVE;
    }
    field_t f[5];
    size_t count = split_fields(line, payload, f, sizeof f / sizeof f[0]);
    if (count < 2u) {
        return DARAN_FUZZ_EVERY_DRIVE; /* blank, or no id: answered by every drive */
    }
    bool known = false;
    for (size_t i = 0; i < sizeof vendor_words / sizeof vendor_words[0] && !known; i++) {
        known = word_equals(f[0], vendor_words[i]);
    }
    for (size_t i = 0; i < word_count && !known; i++) {
        known = word_equals(f[0], words[i]);
    }
    if (!known) {
        return DARAN_FUZZ_EVERY_DRIVE;
    }
    bool is_read = word_equals(f[0], "r");
    if (!is_read && !word_equals(f[0], "w")) {
        return motor_id_value(f[1].text, f[1].len);
    }
    /* D8: `axis` then a '.' somewhere: N is the text between. */
    field_t path = f[1];
    if (path.len > 4u && memcmp(path.text, "axis", 4) == 0) {
        const char *dot = memchr(path.text + 4, '.', path.len - 4u);
        if (dot != NULL) {
            return motor_id_value(path.text + 4, (size_t)(dot - path.text) - 4u);
        }
    }
    /* D9: a system path's trailing id, present with the most fields. */
    size_t fewest = is_read ? 2u : 3u;
    if (count == fewest) {
        return 0;
    }
    if (count == fewest + 1u) {
        return motor_id_value(f[fewest].text, f[fewest].len);
    }
    return DARAN_FUZZ_EVERY_DRIVE;
}
