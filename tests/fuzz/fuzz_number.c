/* Harness 3: the number code of src/text/number.h against references.
 *
 * Input byte 0 picks the test, the rest is its argument:
 *  0: text -> daran_parse_f32 vs glibc strtof (correctly rounded, round to
 *     nearest even), with this harness's own grammar check deciding what must
 *     be accepted; out of range exactly when strtof overflows to infinity;
 *  1: text -> daran_parse_u64 vs an exact decimal reference written here;
 *  2: 4 bytes -> float bits -> daran_format_float: the text follows the
 *     protocol's notation rule, parses back to the same bits through both
 *     daran_parse_f32 and strtof, and is shortest (no decimal with one digit
 *     fewer reads back to the same float);
 *  3: 8 bytes -> daran_format_uint vs printf, and back through parse_u64.
 * Both printers, given one byte less than their text, write nothing and
 * return 0; given exactly its length, write the same text.
 * Errors must leave *out untouched. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "float_bits.h"
#include "fuzz_hal.h"
#include "number.h"

#define TEXT_MAX 400

static bool digit(char c)
{
    return c >= '0' && c <= '9';
}

/* The request grammar, [+-]?(digits[.digits*]|.digits)([eE][+-]?digits)?.
 * Fills the parts an exact reference needs. */
typedef struct parsed {
    bool negative;
    char digits[TEXT_MAX]; /* integer then fraction digits */
    size_t n_digits;
    long frac_digits;
    long exp; /* saturated */
} parsed_t;

static bool grammar(const char *s, size_t n, parsed_t *p)
{
    size_t i = 0;
    memset(p, 0, sizeof *p);
    if (i < n && (s[i] == '+' || s[i] == '-')) {
        p->negative = s[i] == '-';
        i++;
    }
    size_t int_digits = 0, frac = 0;
    while (i < n && digit(s[i])) {
        p->digits[p->n_digits++] = s[i++];
        int_digits++;
    }
    if (i < n && s[i] == '.') {
        i++;
        while (i < n && digit(s[i])) {
            p->digits[p->n_digits++] = s[i++];
            frac++;
        }
    }
    if (int_digits == 0u && frac == 0u) {
        return false;
    }
    p->frac_digits = (long)frac;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        bool eneg = false;
        if (i < n && (s[i] == '+' || s[i] == '-')) {
            eneg = s[i] == '-';
            i++;
        }
        size_t start = i;
        while (i < n && digit(s[i])) {
            if (p->exp < 100000000L) {
                p->exp = p->exp * 10 + (s[i] - '0');
            }
            i++;
        }
        if (i == start) {
            return false;
        }
        if (eneg) {
            p->exp = -p->exp;
        }
    }
    return i == n;
}

static void test_parse_f32(const char *s, size_t n)
{
    parsed_t p;
    bool ok = grammar(s, n, &p);
    float out = 12345.0f;
    daran_result_t r = daran_parse_f32(s, n, &out);
    if (!ok) {
        FUZZ_CHECK(r == DARAN_ERR_INVALID_VALUE && daran_bits_of(out) == daran_bits_of(12345.0f),
                   "parse_f32(\"%s\") = %d, want invalid value, *out untouched", fuzz_escape(s, n),
                   (int)r);
        return;
    }
    char z[TEXT_MAX + 1];
    memcpy(z, s, n);
    z[n] = '\0';
    float want = strtof(z, NULL);
    if (isinf(want)) {
        FUZZ_CHECK(r == DARAN_ERR_OUT_OF_RANGE && daran_bits_of(out) == daran_bits_of(12345.0f),
                   "parse_f32(\"%s\") = %d, want value out of range", z, (int)r);
        return;
    }
    FUZZ_CHECK(r == DARAN_OK && daran_bits_of(out) == daran_bits_of(want),
               "parse_f32(\"%s\") = %d, %08" PRIx32 " (%.9g); strtof %08" PRIx32 " (%.9g)", z,
               (int)r, daran_bits_of(out), (double)out, daran_bits_of(want), (double)want);
}

/* The exact value of a grammatical text as an integer, if it is one. */
static daran_result_t exact_u64(const parsed_t *p, uint64_t *out)
{
    size_t first = 0;
    while (first < p->n_digits && p->digits[first] == '0') {
        first++;
    }
    if (first == p->n_digits) {
        *out = 0; /* "-0" and "0e999" included */
        return DARAN_OK;
    }
    size_t last = p->n_digits;
    long scale = p->exp - p->frac_digits; /* value = digits x 10^scale */
    while (p->digits[last - 1u] == '0') {
        last--;
        scale++;
    }
    if (scale < 0) {
        return DARAN_ERR_INVALID_VALUE; /* a fraction is left */
    }
    if (p->negative) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if ((long)(last - first) + scale > 20) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    uint64_t v = 0;
    for (size_t i = first; i < last; i++) {
        unsigned d = (unsigned)(p->digits[i] - '0');
        if (v > (UINT64_MAX - d) / 10u) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        v = v * 10u + d;
    }
    for (long k = 0; k < scale; k++) {
        if (v > UINT64_MAX / 10u) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        v *= 10u;
    }
    *out = v;
    return DARAN_OK;
}

static void test_parse_u64(const char *s, size_t n)
{
    parsed_t p;
    uint64_t out = 777u, want = 0;
    daran_result_t r = daran_parse_u64(s, n, &out);
    daran_result_t wr = grammar(s, n, &p) ? exact_u64(&p, &want) : DARAN_ERR_INVALID_VALUE;
    FUZZ_CHECK(r == wr, "parse_u64(\"%s\") = %d, want %d", fuzz_escape(s, n), (int)r, (int)wr);
    FUZZ_CHECK(r != DARAN_OK || out == want, "parse_u64(\"%s\") = %" PRIu64 ", want %" PRIu64,
               fuzz_escape(s, n), out, want);
    FUZZ_CHECK(r == DARAN_OK || out == 777u, "parse_u64(\"%s\") wrote *out on error",
               fuzz_escape(s, n));
}

/* Significant digits and decimal exponent k (value = d.ddd x 10^k) of a
 * printed finite nonzero value; checks the notation rule on the way. */
static void check_notation(const char *t, size_t n, float v)
{
    size_t i = t[0] == '-' ? 1u : 0u;
    const char *e = memchr(t, 'e', n);
    long k;
    if (e != NULL) {
        size_t m = (size_t)(e - t);
        FUZZ_CHECK(m >= i + 3u && digit(t[i]) && t[i] != '0' && t[i + 1u] == '.',
                   "scientific mantissa malformed: \"%s\"", fuzz_escape(t, n));
        for (size_t j = i + 2u; j < m; j++) {
            FUZZ_CHECK(digit(t[j]), "scientific mantissa malformed: \"%s\"", fuzz_escape(t, n));
        }
        FUZZ_CHECK(m == i + 3u || t[m - 1u] != '0', "trailing zero: \"%s\"", fuzz_escape(t, n));
        size_t x = m + 1u;
        FUZZ_CHECK(x < n && (t[x] == '+' || t[x] == '-') && n - x - 1u >= 2u,
                   "exponent needs a sign and two digits: \"%s\"", fuzz_escape(t, n));
        k = 0;
        for (size_t j = x + 1u; j < n; j++) {
            FUZZ_CHECK(digit(t[j]), "exponent malformed: \"%s\"", fuzz_escape(t, n));
            k = k * 10 + (t[j] - '0');
        }
        FUZZ_CHECK(n - x - 1u == 2u || t[x + 1u] != '0', "exponent padded: \"%s\"",
                   fuzz_escape(t, n));
        if (t[x] == '-') {
            k = -k;
        }
        FUZZ_CHECK(k < -5 || k > 8, "scientific for k = %ld: \"%s\"", k, fuzz_escape(t, n));
    } else {
        const char *dot = memchr(t, '.', n);
        size_t int_end = dot != NULL ? (size_t)(dot - t) : n;
        for (size_t j = i; j < n; j++) {
            FUZZ_CHECK(digit(t[j]) || t + j == dot, "positional malformed: \"%s\"",
                       fuzz_escape(t, n));
        }
        FUZZ_CHECK(int_end > i && (int_end == i + 1u || t[i] != '0'),
                   "integer part malformed: \"%s\"", fuzz_escape(t, n));
        FUZZ_CHECK(dot == NULL || (n > int_end + 1u && t[n - 1u] != '0'),
                   "fraction malformed: \"%s\"", fuzz_escape(t, n));
        if (t[i] != '0') {
            k = (long)(int_end - i) - 1;
        } else {
            size_t j = int_end + 1u;
            while (j < n && t[j] == '0') {
                j++;
            }
            k = -(long)(j - int_end);
        }
        FUZZ_CHECK(k >= -5 && k <= 8, "positional for k = %ld: \"%s\"", k, fuzz_escape(t, n));
    }
    (void)v;
}

static size_t significant_digits(const char *t, size_t n)
{
    size_t first = n, last = 0;
    const char *e = memchr(t, 'e', n);
    size_t end = e != NULL ? (size_t)(e - t) : n;
    for (size_t j = 0; j < end; j++) {
        if (digit(t[j]) && t[j] != '0') {
            if (first == n) {
                first = j;
            }
            last = j;
        }
    }
    size_t count = 0;
    for (size_t j = first; j <= last && first != n; j++) {
        count += digit(t[j]) ? 1u : 0u;
    }
    return count;
}

/* True when some decimal of @p q significant digits near v reads back as v. */
static bool shorter_exists(float v, size_t q)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.*e", (int)q - 1, (double)v);
    /* buf: [-]d[.ddd]e[+-]XX */
    const char *s = buf[0] == '-' ? buf + 1 : buf;
    long long m = 0;
    const char *c = s;
    for (; *c != 'e'; c++) {
        if (digit(*c)) {
            m = m * 10 + (*c - '0');
        }
    }
    long ex = strtol(c + 1, NULL, 10) - (long)q + 1;
    for (long long d = m - 1; d <= m + 1; d++) {
        if (d <= 0) {
            continue;
        }
        char cand[64];
        snprintf(cand, sizeof cand, "%s%llde%ld", buf[0] == '-' ? "-" : "", d, ex);
        if (daran_bits_of(strtof(cand, NULL)) == daran_bits_of(v)) {
            return true;
        }
    }
    return false;
}

/* Still all 'Z': a printer given too little room wrote nothing. */
static bool untouched(const char *u, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        if (u[i] != 'Z') {
            return false;
        }
    }
    return true;
}

static void test_format_float(uint32_t b)
{
    float v = daran_float_of(b);
    char t[DARAN_F32_TEXT_MAX + 8];
    memset(t, 'Z', sizeof t);
    size_t n = daran_format_float(v, t, DARAN_F32_TEXT_MAX);
    FUZZ_CHECK(n >= 1u && n <= DARAN_F32_TEXT_MAX, "format_float(%08" PRIx32 ") wrote %zu bytes",
               b, n);
    FUZZ_CHECK(t[DARAN_F32_TEXT_MAX] == 'Z', "format_float wrote past DARAN_F32_TEXT_MAX");
    {
        char u[DARAN_F32_TEXT_MAX + 1];
        memset(u, 'Z', sizeof u);
        FUZZ_CHECK(daran_format_float(v, u, n - 1u) == 0 && untouched(u, sizeof u),
                   "format_float(%08" PRIx32 ") into %zu bytes wrote", b, n - 1u);
        FUZZ_CHECK(daran_format_float(v, u, n) == n && memcmp(u, t, n) == 0 && u[n] == 'Z',
                   "format_float(%08" PRIx32 ") into exactly %zu bytes", b, n);
    }
    if (isnan(v)) {
        FUZZ_CHECK(n == 3u && memcmp(t, "nan", 3) == 0, "nan printed \"%s\"", fuzz_escape(t, n));
        return;
    }
    if (isinf(v)) {
        const char *want = v > 0 ? "inf" : "-inf";
        FUZZ_CHECK(n == strlen(want) && memcmp(t, want, n) == 0, "inf printed \"%s\"",
                   fuzz_escape(t, n));
        return;
    }
    if (v == 0.0f) {
        const char *want = signbit(v) ? "-0" : "0";
        FUZZ_CHECK(n == strlen(want) && memcmp(t, want, n) == 0, "zero printed \"%s\"",
                   fuzz_escape(t, n));
        return;
    }
    FUZZ_CHECK((t[0] == '-') == (signbit(v) != 0), "sign wrong: \"%s\"", fuzz_escape(t, n));
    check_notation(t, n, v);

    float back = 0.0f;
    FUZZ_CHECK(daran_parse_f32(t, n, &back) == DARAN_OK && daran_bits_of(back) == b,
               "format_float(%08" PRIx32 ") = \"%s\" does not parse back", b, fuzz_escape(t, n));
    char z[DARAN_F32_TEXT_MAX + 1];
    memcpy(z, t, n);
    z[n] = '\0';
    FUZZ_CHECK(daran_bits_of(strtof(z, NULL)) == b, "strtof(\"%s\") is not %08" PRIx32, z, b);

    size_t digits = significant_digits(t, n);
    FUZZ_CHECK(digits >= 1u && digits <= 9u, "\"%s\" has %zu digits", z, digits);
    FUZZ_CHECK(digits == 1u || !shorter_exists(v, digits - 1u),
               "\"%s\" is not shortest: %zu digits would do", z, digits - 1u);
}

static void test_format_uint(uint64_t v)
{
    char t[DARAN_U64_TEXT_MAX + 4];
    memset(t, 'Z', sizeof t);
    size_t n = daran_format_uint(v, t, DARAN_U64_TEXT_MAX);
    char want[32];
    int wn = snprintf(want, sizeof want, "%" PRIu64, v);
    FUZZ_CHECK(n == (size_t)wn && memcmp(t, want, n) == 0 && t[DARAN_U64_TEXT_MAX] == 'Z',
               "format_uint(%s) = \"%s\"", want, fuzz_escape(t, n));
    {
        char u[DARAN_U64_TEXT_MAX + 1];
        memset(u, 'Z', sizeof u);
        FUZZ_CHECK(daran_format_uint(v, u, n - 1u) == 0 && untouched(u, sizeof u),
                   "format_uint(%s) into %zu bytes wrote", want, n - 1u);
        FUZZ_CHECK(daran_format_uint(v, u, n) == n && memcmp(u, want, n) == 0 && u[n] == 'Z',
                   "format_uint(%s) into exactly %zu bytes", want, n);
    }
    uint64_t back = 0;
    FUZZ_CHECK(daran_parse_u64(t, n, &back) == DARAN_OK && back == v,
               "parse_u64(format_uint(%s)) failed", want);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1u) {
        return 0;
    }
    const char *s = (const char *)data + 1;
    size_t n = size - 1u;
    switch (data[0] & 3u) {
    case 0:
        if (n <= TEXT_MAX) {
            test_parse_f32(s, n);
        }
        break;
    case 1:
        if (n <= TEXT_MAX) {
            test_parse_u64(s, n);
        }
        break;
    case 2:
        for (size_t i = 0; i + 4u <= n; i += 4u) {
            uint32_t b;
            memcpy(&b, s + i, 4);
            test_format_float(b);
        }
        break;
    default:
        for (size_t i = 0; i + 8u <= n; i += 8u) {
            uint64_t v;
            memcpy(&v, s + i, 8);
            test_format_uint(v);
        }
        break;
    }
    return 0;
}
