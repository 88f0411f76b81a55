/* Differential test of daran_parse_f32 against glibc strtof (the reference for
 * correct rounding on the host), plus a print sample checked for round trip,
 * shortness and closeness by brute force with snprintf. Families: exact
 * halfway points between adjacent floats written out in full, the same with
 * ...0001 and ...9999 tails, truncated prefixes of them, random digit strings
 * (1..40 digits, exponents -70..+50), the FLT_MAX and subnormal boundaries.
 * Usage: number_diff_strtof [parse count] [print count]; exit status 1 on any
 * mismatch. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "number.h"

static unsigned long g_fail, g_checked, g_printed;
static uint64_t g_rng = 0x9E3779B97F4A7C15u;

static uint64_t rnd64(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 7;
    g_rng ^= g_rng << 17;
    return g_rng;
}

static uint32_t rnd(uint32_t n)
{
    return (uint32_t)(rnd64() % n);
}

static uint32_t f2b(float f)
{
    uint32_t b;
    memcpy(&b, &f, 4);
    return b;
}

static float b2f(uint32_t b)
{
    float f;
    memcpy(&f, &b, 4);
    return f;
}

/* Our parse vs strtof on text (NUL-terminated). */
static void check_parse(const char *text)
{
    float ours = 0.0f, ref;
    daran_result_t rc = daran_parse_f32(text, strlen(text), &ours);
    int ref_out = 0;
    ref = strtof(text, NULL);
    if (isinf(ref)) {
        ref_out = 1;
    }
    g_checked++;
    if (ref_out ? rc != DARAN_ERR_OUT_OF_RANGE : (rc != DARAN_OK || f2b(ours) != f2b(ref))) {
        if (g_fail++ < 20) {
            fprintf(stderr, "parse mismatch '%s': rc %d ours %08x strtof %08x\n", text, (int)rc,
                    (unsigned)f2b(ours), (unsigned)f2b(ref));
        }
    }
}

/* Exact decimal of (2m+1) * 2^f: the halfway point above the float with
 * significand m and exponent f+1, as digits and a point position. */
static size_t halfway_text(uint32_t bits, char *out, size_t cap)
{
    uint32_t limbs[40]; /* base 1e9, little-endian */
    size_t n = 1, i, len = 0, nd;
    uint32_t exf = bits >> 23, frac = bits & 0x7FFFFFu;
    int f = exf ? (int)exf - 151 : -150, point;
    char digits[400];
    uint64_t carry;
    limbs[0] = 2u * (exf ? (frac | 0x800000u) : frac) + 1u;
    /* times 2^f (f >= 0) or 5^-f (f < 0, the point then moves -f places) */
    for (i = 0; i < (size_t)(f >= 0 ? f : -f); i++) {
        uint32_t mul = f >= 0 ? 2u : 5u;
        size_t j;
        carry = 0;
        for (j = 0; j < n; j++) {
            carry += (uint64_t)limbs[j] * mul;
            limbs[j] = (uint32_t)(carry % 1000000000u);
            carry /= 1000000000u;
        }
        if (carry) {
            limbs[n++] = (uint32_t)carry;
        }
    }
    nd = (size_t)sprintf(digits, "%u", limbs[n - 1]);
    for (i = n - 1; i-- > 0;) {
        nd += (size_t)sprintf(digits + nd, "%09u", limbs[i]);
    }
    point = f >= 0 ? (int)nd : (int)nd + f; /* digits before the point */
    if (point <= 0) {
        len += (size_t)snprintf(out, cap, "0.%0*d%s", -point, 0, digits);
        if (point == 0) { /* "%0*d" with 0 width still prints one 0 */
            len = (size_t)snprintf(out, cap, "0.%s", digits);
        }
    } else if ((size_t)point >= nd) {
        len = (size_t)snprintf(out, cap, "%s", digits);
    } else {
        len = (size_t)snprintf(out, cap, "%.*s.%s", point, digits, digits + point);
    }
    return len;
}

/* text minus one unit in its last digit (text has a non-zero digit). */
static void decrement_last(char *text, size_t len)
{
    size_t i = len;
    while (i-- > 0) {
        if (text[i] == '.') {
            continue;
        }
        if (text[i] > '0') {
            text[i]--;
            return;
        }
        text[i] = '9';
    }
}

static uint32_t random_finite_bits(void)
{
    uint32_t b;
    do {
        b = (uint32_t)rnd64() & 0x7FFFFFFFu;
    } while (b >= 0x7F7FFFFFu); /* the halfway above FLT_MAX is tested on its own */
    return b;
}

static void midpoint_family(uint32_t bits)
{
    char text[512];
    size_t len = halfway_text(bits, text, sizeof text - 32), cut;
    check_parse(text); /* exact tie: to even */
    strcpy(text + len, "0000000001");
    check_parse(text); /* just above */
    text[len] = '\0';
    decrement_last(text, len);
    strcpy(text + len, "99999999");
    check_parse(text); /* just below */
    text[len] = '\0';
    /* a truncated prefix (plus an exponent, sometimes) */
    len = halfway_text(bits, text, sizeof text - 32);
    cut = 1 + rnd((uint32_t)len);
    text[cut] = '\0';
    if (strcmp(text, "0") && strcmp(text, "0.") && text[cut - 1] != '.') {
        check_parse(text);
    }
}

static void random_digits(void)
{
    char text[128];
    size_t n = 0, nd = 1 + rnd(40), i, point = rnd((uint32_t)nd + 1);
    if (rnd(2)) {
        text[n++] = rnd(2) ? '-' : '+';
    }
    for (i = 0; i < nd; i++) {
        if (i == point && rnd(2)) {
            text[n++] = '.';
        }
        text[n++] = (char)('0' + (i == 0 && rnd(4) ? 1 + rnd(9) : rnd(10)));
    }
    n += (size_t)sprintf(text + n, "e%d", (int)rnd(121) - 70);
    text[n] = '\0';
    check_parse(text);
}

static void boundary_cases(void)
{
    char text[128];
    /* near FLT_MAX and the overflow threshold */
    sprintf(text, "3.40282%0*u%s", 1 + (int)rnd(30), (unsigned)rnd(1000000000u), rnd(2) ? "e38" : "e+38");
    check_parse(text);
    sprintf(text, "340282%uE33", (unsigned)rnd(1000000000u));
    check_parse(text);
    /* FLT_MIN and the subnormals, down to below half the smallest */
    sprintf(text, "%u.%ue-%u", 1 + (unsigned)rnd(9), (unsigned)rnd(1000000000u), 37 + (unsigned)rnd(10));
    check_parse(text);
    sprintf(text, "7.00649%u%ue-46", (unsigned)rnd(1000000000u), (unsigned)rnd(1000000000u));
    check_parse(text);
}

/* Print: our text parses back (ours and strtof), has the fewest digits any
 * round-tripping decimal has, and is the correctly rounded one of that length
 * when that one round-trips. */
static void check_print(uint32_t bits)
{
    char ours[DARAN_F32_TEXT_MAX + 1], ref[48], mant[48];
    float v = b2f(bits), back = 0.0f;
    size_t n = daran_format_float(v, ours, sizeof ours);
    int nd = 0, best = 0, digits;
    const char *p;
    ours[n] = '\0';
    g_printed++;
    if (n > DARAN_F32_TEXT_MAX || daran_parse_f32(ours, n, &back) != DARAN_OK || f2b(back) != bits ||
        f2b(strtof(ours, NULL)) != bits) {
        if (g_fail++ < 20) {
            fprintf(stderr, "print %08x -> '%s' does not parse back\n", (unsigned)bits, ours);
        }
        return;
    }
    /* significant digits of ours */
    for (p = ours; *p && *p != 'e'; p++) {
        if (*p >= '1' && *p <= '9') {
            nd = (int)(p - ours) + 1;
        }
    }
    for (p = ours, digits = 0; *p && *p != 'e'; p++) {
        if (*p >= '0' && *p <= '9' && (digits || *p != '0')) {
            digits++;
        }
        if (p - ours + 1 == nd) {
            break;
        }
    }
    for (best = 1; best <= 9; best++) {
        /* the nearest, and its neighbours (for the uneven gaps at powers of 2) */
        int k;
        sprintf(ref, "%.*e", best - 1, (double)v);
        if (f2b(strtof(ref, NULL)) == bits) {
            break;
        }
        for (k = -1; k <= 1; k += 2) {
            double step;
            char *e = strchr(ref, 'e');
            int ex = atoi(e + 1);
            memcpy(mant, ref, (size_t)(e - ref));
            mant[e - ref] = '\0';
            step = pow(10.0, ex - (best - 1));
            sprintf(mant, "%.*e", best - 1, atof(mant) * pow(10.0, ex) + k * step);
            if (f2b(strtof(mant, NULL)) == bits) {
                goto found;
            }
        }
    }
found:
    if (digits != best) {
        if (g_fail++ < 20) {
            fprintf(stderr, "print %08x -> '%s': %d digits, %d suffice (%s)\n", (unsigned)bits, ours, digits, best,
                    ref);
        }
    } else if (f2b(strtof(ref, NULL)) == bits && strtod(ref, NULL) != strtod(ours, NULL)) {
        if (g_fail++ < 20) {
            fprintf(stderr, "print %08x -> '%s', closer: %s\n", (unsigned)bits, ours, ref);
        }
    }
}

int main(int argc, char **argv)
{
    unsigned long parse_rounds = argc > 1 ? strtoul(argv[1], NULL, 0) : 260000ul;
    unsigned long print_count = argc > 2 ? strtoul(argv[2], NULL, 0) : 100000ul;
    unsigned long i;
    static const char *fixed[] = {"3.40282356779733661637539395458142568448e38",
                                  "3.40282356779733661637539395458142568447e38", "3.4028235e38",
                                  "3.4028235677973366e38", "1e39", "1e-46", "1e-45", "7.006492321624085354618e-46",
                                  "1.1754943508222875e-38", "1.1754942e-38", "0.000000000000000000000000000000000000000000001401298464324817070923729583289916131280"};
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        check_parse(fixed[i]);
    }
    for (i = 0; i < parse_rounds; i++) {
        uint32_t b = random_finite_bits();
        switch (i % 4) {
        case 0:
            midpoint_family(b);
            break;
        case 1: /* boundary regions: top and bottom of the range */
            midpoint_family(rnd(2) ? 0x7F000000u + rnd(0x7FFFFF) : rnd(0x01000000u));
            boundary_cases();
            break;
        default:
            random_digits();
            random_digits();
            break;
        }
    }
    for (i = 0; i < print_count; i++) {
        uint32_t b = (uint32_t)rnd64();
        if ((b & 0x7F800000u) != 0x7F800000u) {
            check_print(b);
        }
    }
    printf("%lu parse checks, %lu print checks, %lu failures\n", g_checked, g_printed, g_fail);
    return g_fail ? 1 : 0;
}
