/* Exhaustive check of the float32 printer and parser over bit patterns
 * [--from, --to] (default: all 2^32). For every pattern: the text parses back to
 * the same bits with our parser and with glibc strtof; NaNs print "nan". For
 * every positive finite pattern also: the round-to-odd step of the printer never
 * met a non-integer within 2^-32 of an integer (the premise of its exactness).
 * With --shortest (about 3x slower) also: no decimal one digit shorter parses
 * back (shortest), and a neighbour of the same length that parses back is not
 * closer (closest).
 * Includes number.c to reach its internal helpers. Release build only. */
#define _POSIX_C_SOURCE 200809L
#include "../../src/text/number.c"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long g_fail;

static void report(uint32_t bits, const char *what, const char *text)
{
    if (g_fail++ < 50) {
        fprintf(stderr, "FAIL %08" PRIx32 " %s: '%s'\n", bits, what, text);
    }
}

/* "<m>e<e>" without snprintf (too slow for 2^32 rounds). */
static size_t sci_text(char *buf, uint64_t m, int32_t e)
{
    size_t n = daran_format_uint(m, buf, DARAN_U64_TEXT_MAX);
    buf[n++] = 'e';
    if (e < 0) {
        buf[n++] = '-';
        e = -e;
    }
    n += daran_format_uint((uint64_t)e, buf + n, DARAN_U64_TEXT_MAX);
    buf[n] = '\0';
    return n;
}

static uint32_t parse_bits(const char *text, size_t len)
{
    float f;
    uint32_t b;
    if (daran_parse_f32(text, len, &f) != DARAN_OK) {
        return 0xFFFFFFFFu;
    }
    memcpy(&b, &f, 4);
    return b;
}

/* Sign of m * 10^e - c * 2^q, exactly. */
static int cmp_dec_bin(uint64_t m, int32_t e, uint32_t c, int32_t q)
{
    number_big_t x, y;
    memset(&x, 0, sizeof x);
    memset(&y, 0, sizeof y);
    x.w[0] = (uint32_t)m;
    x.w[1] = (uint32_t)(m >> 32);
    y.w[0] = c;
    if (e >= 0) {
        big_mul_pow(&x, 5u, e);
    } else {
        big_mul_pow(&y, 5u, -e);
    }
    if (e > q) {
        big_mul_pow(&x, 2u, e - q);
    } else {
        big_mul_pow(&y, 2u, q - e);
    }
    return big_cmp(&x, &y);
}

/* Is cb * 2^q * 10^-k an integer equal to n? */
static int exact_is(uint32_t cb, int32_t q, int32_t k, uint32_t n)
{
    uint64_t v = cb;
    int32_t i, sh;
    if (k >= 0) {
        for (i = 0; i < k; i++) {
            if (v % 5u) {
                return 0;
            }
            v /= 5u;
        }
        sh = q - k;
    } else {
        sh = q - k; /* * 5^-k * 2^-k */
    }
    if (sh < 0) {
        if (-sh >= 64 || (v & ((UINT64_C(1) << -sh) - 1u))) {
            return 0;
        }
        v >>= -sh;
    } else {
        if (sh >= 32 || v >= (UINT64_C(1) << (63 - sh))) {
            return 0;
        }
        v <<= sh;
    }
    for (i = k; i < 0; i++) {
        if (v > UINT64_C(0xFFFFFFFF)) {
            return 0;
        }
        v *= 5u;
    }
    return v == n;
}

static void check_round_odd(uint32_t bits)
{
    uint32_t exf = bits >> 23, frac = bits & 0x7FFFFFu;
    uint32_t c = exf ? frac | 0x800000u : frac;
    int32_t q = exf ? (int32_t)exf - 150 : -149;
    int irregular = frac == 0 && exf > 1;
    int32_t k = floor_shift(q * INT32_C(1262611) - (irregular ? INT32_C(524031) : 0), 22);
    int32_t h = q + floor_log2_pow10(-k) + 1;
    uint64_t g = daran_pow10_hi(-k) + 1u;
    uint32_t cbs[3];
    int i;
    if (h < 1 || h > 4) {
        report(bits, "h out of 1..4", "");
        return;
    }
    cbs[0] = c << 2;
    cbs[1] = (c << 2) - (irregular ? 1u : 2u);
    cbs[2] = (c << 2) + 2u;
    for (i = 0; i < 3; i++) {
        uint32_t cp = cbs[i] << h;
        uint64_t mid = (g >> 32) * cp + (((g & 0xFFFFFFFFu) * cp) >> 32);
        if ((uint32_t)mid == 0u && !exact_is(cbs[i], q, k, (uint32_t)(mid >> 32))) {
            report(bits, "round_odd premise", "");
        }
    }
}

static void check_shortest(uint32_t bits)
{
    uint32_t exf = bits >> 23, frac = bits & 0x7FFFFFu;
    uint32_t c = exf ? frac | 0x800000u : frac;
    int32_t q = exf ? (int32_t)exf - 150 : -149;
    int32_t k;
    uint32_t s = shortest_digits(exf, frac, &k), nd = 0, t;
    char buf[48];
    size_t n;
    while (s % 10u == 0) {
        s /= 10u;
        k++;
    }
    for (t = s; t; t /= 10u) {
        nd++;
    }
    if (nd >= 2) {
        n = sci_text(buf, s / 10u, k + 1);
        if (parse_bits(buf, n) == bits) {
            report(bits, "shorter (down) parses back", buf);
        }
        n = sci_text(buf, s / 10u + 1u, k + 1);
        if (parse_bits(buf, n) == bits) {
            report(bits, "shorter (up) parses back", buf);
        }
    }
    /* A same-length neighbour that parses back must not be closer. */
    n = sci_text(buf, (uint64_t)s - 1u, k);
    if (s > 1u && parse_bits(buf, n) == bits) {
        int side = cmp_dec_bin((uint64_t)s * 10u - 5u, k - 1, c, q); /* midpoint vs value */
        if (side > 0) {
            report(bits, "s-1 closer", buf);
        }
    }
    n = sci_text(buf, (uint64_t)s + 1u, k);
    if (parse_bits(buf, n) == bits) {
        int side = cmp_dec_bin((uint64_t)s * 10u + 5u, k - 1, c, q);
        if (side < 0) {
            report(bits, "s+1 closer", buf);
        }
    }
}

int main(int argc, char **argv)
{
    uint64_t from = 0, to = 0xFFFFFFFFu, b;
    unsigned long long count = 0;
    int i, shortest = 0;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--shortest")) {
            shortest = 1;
        } else if (!strcmp(argv[i], "--from") && i + 1 < argc) {
            from = strtoull(argv[++i], NULL, 0);
        } else if (!strcmp(argv[i], "--to") && i + 1 < argc) {
            to = strtoull(argv[++i], NULL, 0);
        } else {
            fprintf(stderr, "usage: f32_exhaustive [--from BITS] [--to BITS] [--shortest]\n");
            return 2;
        }
    }
    for (b = from; b <= to; b++) {
        uint32_t bits = (uint32_t)b;
        float f, g;
        char buf[DARAN_F32_TEXT_MAX + 1];
        size_t n;
        memcpy(&f, &bits, 4);
        n = daran_format_float(f, buf, DARAN_F32_TEXT_MAX);
        buf[n] = '\0';
        count++;
        if ((bits & 0x7FFFFFFFu) > 0x7F800000u) {
            if (strcmp(buf, "nan")) {
                report(bits, "nan text", buf);
            }
            continue;
        }
        if ((bits & 0x7FFFFFFFu) == 0x7F800000u) {
            if (strcmp(buf, bits >> 31 ? "-inf" : "inf")) {
                report(bits, "inf text", buf);
            }
            continue;
        }
        if (parse_bits(buf, n) != bits) {
            report(bits, "our parse", buf);
        }
        g = strtof(buf, NULL);
        if (memcmp(&g, &bits, 4)) {
            report(bits, "strtof", buf);
        }
        if (!(bits >> 31) && bits) {
            check_round_odd(bits);
            if (shortest) {
                check_shortest(bits);
            }
        }
        if ((b & 0x3FFFFFFu) == 0x3FFFFFFu) {
            fprintf(stderr, "at %08" PRIx32 " failures %llu\n", bits, g_fail);
        }
    }
    printf("checked %llu patterns [0x%08" PRIx64 ", 0x%08" PRIx64 "]%s, failures %llu\n", count, from, to,
           shortest ? " with --shortest" : "", g_fail);
    return g_fail ? 1 : 0;
}
