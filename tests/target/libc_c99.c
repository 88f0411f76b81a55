/* Two gaps of the target's C library that the tests would otherwise trip
 * over, filled for the Unity test images only (they link with
 * -Wl,--wrap=snprintf,--wrap=vsnprintf,--wrap=strtof; the core never calls
 * either function, the firmware does not link this file).
 *
 * 1. printf's C99 conversions. newlib as Debian builds it
 *    (libnewlib-arm-none-eabi, without --enable-newlib-io-c99-formats) prints
 *    %zu, %td, %jd, %hhd and %a as plain text and does not take their
 *    argument, so every conversion after one reads the wrong argument. The
 *    tests use %zu and %a in case names and failure messages. The wrappers
 *    below split a format into its conversions, take each argument with the
 *    C99 type, and let newlib format each one with a spec it knows (the
 *    length modifier rewritten); %a/%A are written here, as glibc writes them
 *    ("0x1.8p+0"), flags, width and precision of %a are not supported.
 *
 * 2. strtof's rounding. The tests take the C library's strtof as the
 *    reference for correctly rounded float32 results. newlib's strtof is
 *    (float)strtod(): a second rounding, wrong when the double lands exactly
 *    on the midpoint between two floats while the decimal is not the
 *    midpoint (e.g. "1.000000059604644775390625000000000000000000000000001"
 *    reads as 1 instead of 1 + 2^-23). The wrapper keeps newlib's strtod (a
 *    correctly rounded double) and settles exactly that case by comparing the
 *    decimal text with the midpoint's exact decimal expansion (which newlib's
 *    printf writes digit for digit). Everywhere else one rounding of the
 *    correct double to float is the correct float. */
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int __real_snprintf(char *buf, size_t size, const char *fmt, ...);
int __wrap_snprintf(char *buf, size_t size, const char *fmt, ...);
int __wrap_vsnprintf(char *buf, size_t size, const char *fmt, va_list ap);
float __wrap_strtof(const char *text, char **end);

/* ---- printf ---------------------------------------------------------------- */

typedef struct out {
    char *buf;
    size_t size;
    size_t len; /* what the whole output needs, as vsnprintf returns it */
} out_t;

static char *out_at(const out_t *o)
{
    return o->len < o->size ? o->buf + o->len : NULL;
}

static size_t out_room(const out_t *o)
{
    return o->len < o->size ? o->size - o->len : 0u;
}

static void out_char(out_t *o, char c)
{
    if (o->len + 1u < o->size) {
        o->buf[o->len] = c;
    }
    o->len++;
}

static void out_count(out_t *o, int n)
{
    if (n > 0) {
        o->len += (size_t)n;
    }
}

/* glibc's %a: 0x1.<hex digits, trailing zeros dropped>p<+-exponent>. */
static void out_hexfloat(out_t *o, double v, bool upper)
{
    static const char lower_digits[] = "0123456789abcdef";
    static const char upper_digits[] = "0123456789ABCDEF";
    const char *hex = upper ? upper_digits : lower_digits;
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    bool neg = (bits >> 63) != 0u;
    int exp = (int)((bits >> 52) & 0x7FFu);
    uint64_t mant = bits & ((UINT64_C(1) << 52) - 1u);
    char text[40];
    size_t k = 0;
    if (neg) {
        text[k++] = '-';
    }
    if (exp == 0x7FF) {
        const char *word = mant != 0u ? (upper ? "NAN" : "nan") : (upper ? "INF" : "inf");
        memcpy(text + k, word, 3u);
        k += 3u;
    } else {
        text[k++] = '0';
        text[k++] = upper ? 'X' : 'x';
        text[k++] = exp == 0 ? '0' : '1';
        int e = exp == 0 ? (mant == 0u ? 0 : -1022) : exp - 1023;
        if (mant != 0u) {
            text[k++] = '.';
            int last = 12;
            while (((mant >> (4 * (12 - last))) & 0xFu) == 0u) {
                last--;
            }
            for (int i = 0; i <= last; i++) {
                text[k++] = hex[(mant >> (4 * (12 - i))) & 0xFu];
            }
        }
        text[k++] = upper ? 'P' : 'p';
        text[k++] = e < 0 ? '-' : '+';
        unsigned ue = (unsigned)(e < 0 ? -e : e);
        char digits[8];
        size_t n = 0;
        do {
            digits[n++] = (char)('0' + ue % 10u);
            ue /= 10u;
        } while (ue != 0u);
        while (n > 0u) {
            text[k++] = digits[--n];
        }
    }
    for (size_t i = 0; i < k; i++) {
        out_char(o, text[i]);
    }
}

typedef enum length { LEN_NONE, LEN_HH, LEN_H, LEN_L, LEN_LL, LEN_Z, LEN_J, LEN_T, LEN_BIG_L } length_t;

int __wrap_vsnprintf(char *buf, size_t size, const char *fmt, va_list ap)
{
    out_t o = {buf, size, 0u};
    const char *p = fmt;
    while (*p != '\0') {
        if (*p != '%') {
            out_char(&o, *p++);
            continue;
        }
        p++;
        if (*p == '%') {
            out_char(&o, *p++);
            continue;
        }
        /* the spec as newlib will see it: flags, width and precision (a '*'
         * replaced by its argument), then a length it knows */
        char spec[48];
        size_t k = 0;
        spec[k++] = '%';
        while (*p != '\0' && strchr("-+ #0", *p) != NULL && k < 8u) {
            spec[k++] = *p++;
        }
        if (*p == '*') {
            k += (size_t)__real_snprintf(spec + k, sizeof spec - k, "%d", va_arg(ap, int));
            p++;
        } else {
            while (*p >= '0' && *p <= '9' && k < 20u) {
                spec[k++] = *p++;
            }
        }
        if (*p == '.') {
            spec[k++] = *p++;
            if (*p == '*') {
                k += (size_t)__real_snprintf(spec + k, sizeof spec - k, "%d", va_arg(ap, int));
                p++;
            } else {
                while (*p >= '0' && *p <= '9' && k < 36u) {
                    spec[k++] = *p++;
                }
            }
        }
        length_t len = LEN_NONE;
        if (p[0] == 'h' && p[1] == 'h') {
            len = LEN_HH;
            p += 2;
        } else if (p[0] == 'l' && p[1] == 'l') {
            len = LEN_LL;
            p += 2;
        } else if (*p == 'h') {
            len = LEN_H;
            p++;
        } else if (*p == 'l') {
            len = LEN_L;
            p++;
        } else if (*p == 'z') {
            len = LEN_Z;
            p++;
        } else if (*p == 'j') {
            len = LEN_J;
            p++;
        } else if (*p == 't') {
            len = LEN_T;
            p++;
        } else if (*p == 'L') {
            len = LEN_BIG_L;
            p++;
        }
        char conv = *p;
        if (conv == '\0') {
            break;
        }
        p++;
        switch (conv) {
        case 'd':
        case 'i': {
            long long v;
            switch (len) {
            case LEN_HH: v = (signed char)va_arg(ap, int); break;
            case LEN_H: v = (short)va_arg(ap, int); break;
            case LEN_L: v = va_arg(ap, long); break;
            case LEN_LL:
            case LEN_J: v = va_arg(ap, long long); break;
            case LEN_Z: v = (long long)(ptrdiff_t)va_arg(ap, size_t); break;
            case LEN_T: v = va_arg(ap, ptrdiff_t); break;
            default: v = va_arg(ap, int); break;
            }
            spec[k++] = 'l';
            spec[k++] = 'l';
            spec[k++] = conv;
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, v));
            break;
        }
        case 'u':
        case 'o':
        case 'x':
        case 'X': {
            unsigned long long v;
            switch (len) {
            case LEN_HH: v = (unsigned char)va_arg(ap, unsigned); break;
            case LEN_H: v = (unsigned short)va_arg(ap, unsigned); break;
            case LEN_L: v = va_arg(ap, unsigned long); break;
            case LEN_LL:
            case LEN_J: v = va_arg(ap, unsigned long long); break;
            case LEN_Z: v = va_arg(ap, size_t); break;
            case LEN_T: v = (unsigned long long)va_arg(ap, ptrdiff_t); break;
            default: v = va_arg(ap, unsigned); break;
            }
            spec[k++] = 'l';
            spec[k++] = 'l';
            spec[k++] = conv;
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, v));
            break;
        }
        case 'e':
        case 'E':
        case 'f':
        case 'F':
        case 'g':
        case 'G': {
            /* long double is double on this target */
            double v = va_arg(ap, double);
            spec[k++] = conv;
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, v));
            break;
        }
        case 'a':
        case 'A':
            out_hexfloat(&o, va_arg(ap, double), conv == 'A');
            break;
        case 'c':
            spec[k++] = 'c';
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, va_arg(ap, int)));
            break;
        case 's':
            spec[k++] = 's';
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, va_arg(ap, const char *)));
            break;
        case 'p':
            spec[k++] = 'p';
            spec[k] = '\0';
            out_count(&o, __real_snprintf(out_at(&o), out_room(&o), spec, va_arg(ap, void *)));
            break;
        case 'n':
            *va_arg(ap, int *) = (int)o.len;
            break;
        default:
            /* not a conversion: written as it stands */
            out_char(&o, '%');
            out_char(&o, conv);
            break;
        }
    }
    if (size > 0u) {
        buf[o.len < size ? o.len : size - 1u] = '\0';
    }
    return (int)o.len;
}

int __wrap_snprintf(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = __wrap_vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

/* ---- strtof ---------------------------------------------------------------- */

/* A decimal's magnitude as 0.<digits> x 10^exp10, digits without leading or
 * trailing zeros (none at all for zero). */
typedef struct decimal {
    char digits[420];
    size_t n;
    long exp10;
} decimal_t;

/* Reads what strtod reads of a decimal (after white space and the sign):
 * digits with an optional point, an optional exponent. */
static void decimal_read(const char *s, decimal_t *d)
{
    long int_digits = 0;
    bool point = false;
    d->n = 0u;
    while ((*s >= '0' && *s <= '9') || (*s == '.' && !point)) {
        if (*s == '.') {
            point = true;
        } else {
            if (!point) {
                int_digits++;
            }
            if (d->n == 0u && *s == '0') {
                int_digits--; /* a leading zero: nothing before the point, a shift after it */
            } else if (d->n < sizeof d->digits) {
                d->digits[d->n++] = *s;
            }
        }
        s++;
    }
    long e = 0;
    if (*s == 'e' || *s == 'E') {
        const char *q = s + 1;
        bool neg = false;
        if (*q == '+' || *q == '-') {
            neg = *q == '-';
            q++;
        }
        if (*q >= '0' && *q <= '9') {
            while (*q >= '0' && *q <= '9') {
                if (e < 100000) {
                    e = e * 10 + (*q - '0');
                }
                q++;
            }
            e = neg ? -e : e;
        }
    }
    while (d->n > 0u && d->digits[d->n - 1u] == '0') {
        d->n--;
    }
    d->exp10 = int_digits + e;
}

/* Sign of |a| - |b|. */
static int decimal_compare(const decimal_t *a, const decimal_t *b)
{
    if (a->n == 0u || b->n == 0u) {
        return (a->n != 0u) - (b->n != 0u);
    }
    if (a->exp10 != b->exp10) {
        return a->exp10 > b->exp10 ? 1 : -1;
    }
    size_t n = a->n < b->n ? a->n : b->n;
    for (size_t i = 0; i < n; i++) {
        if (a->digits[i] != b->digits[i]) {
            return a->digits[i] > b->digits[i] ? 1 : -1;
        }
    }
    return (a->n > n) - (b->n > n);
}

/* Sign of |text| - |value|, exactly; 0 for what is not a plain decimal. */
static int compare_text_with(const char *text, double value)
{
    static decimal_t a, b;
    static char exact[460];
    while (*text == ' ' || (*text >= '\t' && *text <= '\r')) {
        text++;
    }
    if (*text == '+' || *text == '-') {
        text++;
    }
    if ((text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) ||
        !((*text >= '0' && *text <= '9') || *text == '.')) {
        return 0;
    }
    decimal_read(text, &a);
    /* a float midpoint has at most ~115 significant digits; newlib's printf
     * writes every one of them */
    __real_snprintf(exact, sizeof exact, "%.400e", fabs(value));
    decimal_read(exact, &b);
    return decimal_compare(&a, &b);
}

float __wrap_strtof(const char *text, char **end)
{
    double d = strtod(text, end);
    float f = (float)d;
    if (d != d || d == (double)f) {
        return f; /* NaN, or the double is a float: nothing was rounded twice */
    }
    /* the overflow threshold (FLT_MAX + half an ulp): a tie goes to infinity */
    const double threshold = 0x1.ffffffp127;
    if (isinf(f)) {
        if (fabs(d) != threshold) {
            return f;
        }
        return compare_text_with(text, d) < 0 ? copysignf(0x1.fffffep127f, f) : f;
    }
    float below = (double)f < d ? f : nextafterf(f, -INFINITY);
    float above = (double)f < d ? nextafterf(f, INFINITY) : f;
    if (isinf(below) || isinf(above)) {
        return f;
    }
    double mid = ((double)below + (double)above) / 2.0; /* exact */
    if (d != mid) {
        return f; /* off the midpoint: the float nearest d is the float nearest the text */
    }
    int c = compare_text_with(text, mid);
    if (c == 0) {
        return f; /* exactly the midpoint: the cast's ties-to-even is right */
    }
    /* c compares magnitudes */
    bool up = d > 0.0 ? c > 0 : c < 0;
    return up ? above : below;
}
