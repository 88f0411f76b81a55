/* Text <-> numbers for the protocol: float32 parsing correctly rounded, the
 * shortest float32 printing, exact unsigned integers (docs/numbers.md says why
 * each step is exact). Single-precision FPU only: no double, no libc number
 * functions, no heap; the one big scratch is ~120 bytes in the rare slow path. */
#include "number.h"

#include "compiler.h"
#include "text.h"

#include <float.h>
#include <stdint.h>
#include <string.h>

/* The fast path needs float operations rounded once, to float (not wider, as
 * on x87, and not reassociated, as under -ffast-math); elsewhere all is integer. */
#if FLT_EVAL_METHOD == 0 && !defined(__FAST_MATH__)
#define DARAN_NUM_FAST_PATH 1
#else
#define DARAN_NUM_FAST_PATH 0
#endif

#define DARAN_F32_INF 0x7F800000u
/* Digit counts and exponents saturate here: far beyond anything that changes a
 * float32 or a uint64, far from int32 overflow when three of them are added. */
#define DARAN_NUM_CAP 0x10000000L
/* Significant digits the exact path keeps: a float32 halfway point has at most
 * 113, so 120 decide every case; the rest only count as "non-zero". */
#define DARAN_BIG_DIGITS 120
/* 448 bits: D < 10^120 < 2^399 and M * 5^166 < 2^411 fit with room. */
#define DARAN_BIG_LIMBS 14

/* The leading 64 bits of 10^q, q = -64..45, truncated, are rebuilt from every
 * 14th of them rounded up (the anchors) times a power of 5 below 2^32, and a
 * 2-bit correction per entry: 92 bytes instead of 880
 * (bench/number/gen_pow10_table.py makes both and proves the rebuild exact;
 * tests/number checks it in C against all 110 exact values). */
static const uint64_t daran_pow10_anchor[8] = {
    UINT64_C(0xA87FEA27A539E9A6), UINT64_C(0xEF73D256A5C0F77D), UINT64_C(0xAA242499697392D3),
    UINT64_C(0xF1C90080BAF72CB2), UINT64_C(0xABCC77118461CEFD), UINT64_C(0xF424000000000000),
    UINT64_C(0xAD78EBC5AC620000), UINT64_C(0xF684DF56C3E01BC7),
};
static const uint8_t daran_pow10_correction[28] = {
    0x45, 0x55, 0x56, 0x55, 0x14, 0x00, 0x00, 0x41, 0x00, 0x00, 0x50, 0x01,
    0x00, 0x15, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x10, 0x00, 0x10, 0x05,
};

#define DARAN_POW10_MIN (-64)
#define DARAN_POW10_STRIDE 14u

/* What the scan found: the significand's first 19 digits gathered, and where
 * the text's digits are, for the exact comparison and the integer parser that
 * read them again. */
typedef struct {
    const char *mant; /* first mantissa character */
    size_t int_len;   /* digits before the point */
    size_t total;     /* digits of the mantissa, point excluded */
    size_t z;         /* index of the first non-zero digit */
    size_t end;       /* index after the last non-zero digit; 0: all zero */
    int32_t exp10;    /* explicit exponent, saturated */
    int negative;
    uint64_t w;       /* the first up to 19 digits from index z, as an integer */
    size_t w_len;     /* how many digits w holds */
    int truncated;    /* a non-zero digit follows the 19 in w (then w >= 10^18) */
} number_scan_t;

typedef struct {
    uint32_t w[DARAN_BIG_LIMBS]; /* little-endian limbs */
} number_big_t;

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* a - b as an int32, saturated at +-DARAN_NUM_CAP. */
static int32_t diff_saturated(size_t a, size_t b)
{
    size_t d = a >= b ? a - b : b - a;
#if SIZE_MAX > DARAN_NUM_CAP /* a 16-bit size_t cannot even hold the cap */
    if (d > (size_t)DARAN_NUM_CAP) {
        d = (size_t)DARAN_NUM_CAP;
    }
#endif
    int32_t v = (int32_t)d;
    return a >= b ? v : -v;
}

/* floor(x / 2^n) without relying on >> of a negative int (implementation
 * defined): x > -2^30 in every caller. */
static int32_t floor_shift(int32_t x, unsigned n)
{
    uint32_t biased = (uint32_t)(x + 0x40000000L) >> n;
    return (int32_t)biased - (int32_t)(0x40000000L >> n);
}

/* floor(log2(10^x)) for |x| <= 70 (bench/number/gen_pow10_table.py checks it). */
static int32_t floor_log2_pow10(int32_t x)
{
    return floor_shift(x * INT32_C(1741647), 19);
}

static unsigned clz64(uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
    return (unsigned)__builtin_clzll(x);
#else
    unsigned n = 0;
    while (!(x & (UINT64_C(1) << 63))) {
        x <<= 1;
        n++;
    }
    return n;
#endif
}

/* High 64 bits of a * b; *lo gets the low 64. */
static uint64_t mul_64x64(uint64_t a, uint64_t b, uint64_t *lo)
{
#if defined(__SIZEOF_INT128__)
    __extension__ typedef unsigned __int128 u128;
    u128 p = (u128)a * b;
    *lo = (uint64_t)p;
    return (uint64_t)(p >> 64);
#else
    uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32;
    uint64_t b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    *lo = (mid << 32) | (p00 & 0xFFFFFFFFu);
    return p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

/* Leading 64 bits of 10^q (q = -64..45), truncated: the top 64 bits of the
 * exact 96-bit product anchor * 5^r (10^r = 5^r * 2^r: the 2^r does not change
 * leading bits), less the stored correction (0..3). */
uint64_t daran_pow10_hi(int32_t q)
{
    uint32_t i = (uint32_t)(q - DARAN_POW10_MIN), scale = 1, r = i % DARAN_POW10_STRIDE, h1, h0, lz;
    uint64_t v = daran_pow10_anchor[i / DARAN_POW10_STRIDE], lo, hi;
    if (r) {
        for (; r > 0u; r--) {
            scale *= 5u;
        }
        /* v * scale = hi * 2^32 + (lo mod 2^32), 2^32 <= hi < 2^64: shift its
         * top 64 bits into place word by word (0 <= lz < 32). */
        lo = (v & 0xFFFFFFFFu) * scale;
        hi = (v >> 32) * scale + (lo >> 32);
        h1 = (uint32_t)(hi >> 32);
        h0 = (uint32_t)hi;
        lz = (uint32_t)clz64(hi);
        h1 = (h1 << lz) | (h0 >> 1 >> (31u - lz));
        h0 = (h0 << lz) | ((uint32_t)lo >> 1 >> (31u - lz));
        v = (uint64_t)h1 << 32 | h0;
    }
    return v - (((unsigned)daran_pow10_correction[i / 4u] >> (2u * (i % 4u))) & 3u);
}

/* The grammar [+-]?(digits[.digits*]|.digits)([eE][+-]?digits)?, all of it, in
 * one pass that counts and also gathers the significand: the first 19
 * significant digits as an integer, which is all the common path needs. The
 * counts stay in registers (stores through s could alias the text and cost
 * reloads). */
static int number_scan(const char *t, size_t len, number_scan_t *s)
{
    size_t i = 0, idx = 0, z, end = 0, int_len = (size_t)-1, e_start;
    int32_t e = 0;
    int eneg = 0, truncated = 0;
    uint64_t w = 0;
    size_t taken = 0;
    if (len == 0u) {
        return 0; /* empty (text may then be NULL: no pointer arithmetic on it) */
    }
    s->negative = 0;
    if (t[0] == '+' || t[0] == '-') {
        s->negative = t[0] == '-';
        i = 1;
    }
    s->mant = t + i;
    /* zeros (and the point) before the first non-zero digit */
    for (; i < len; i++) {
        if (t[i] == '0') {
            idx++;
        } else if (t[i] != '.' || int_len != (size_t)-1) {
            break;
        } else {
            int_len = idx;
        }
    }
    /* from the first non-zero digit: w takes 19 digits (trailing zeros
     * included: they only change the exponent) */
    z = idx;
    for (; i < len; i++) {
        uint32_t d = (uint32_t)(unsigned char)t[i] - (uint32_t)'0';
        if (d > 9u) {
            if (t[i] != '.' || int_len != (size_t)-1) {
                break;
            }
            int_len = idx; /* the first point */
            continue;
        }
        idx++; /* digit idx - 1 */
        if (taken < 19u) {
            w = w * 10u + d;
            taken++;
        } else if (d) {
            truncated = 1;
        }
        if (d) {
            end = idx;
        }
    }
    s->w = w;
    s->w_len = taken;
    s->truncated = truncated;
    s->int_len = int_len == (size_t)-1 ? idx : int_len;
    s->total = idx;
    s->z = z;
    s->end = end;
    if (idx == 0) {
        return 0;
    }
    if (i < len && (t[i] == 'e' || t[i] == 'E')) {
        i++;
        if (i < len && (t[i] == '+' || t[i] == '-')) {
            eneg = t[i] == '-';
            i++;
        }
        for (e_start = i; i < len && is_digit(t[i]); i++) {
            e = e < DARAN_NUM_CAP / 10 ? e * 10 + (t[i] - '0') : (int32_t)DARAN_NUM_CAP;
        }
        if (i == e_start) {
            return 0;
        }
    }
    s->exp10 = eneg ? -e : e;
    return i == len;
}

/* Digit i of the mantissa, the point skipped. */
static uint32_t digit_at(const number_scan_t *s, size_t i)
{
    return (uint32_t)(s->mant[i + (i >= s->int_len)] - '0');
}

/* Round (m + f) * 2^e, 0 <= f < 1 (f > 0 iff sticky), m >= 2^40, to float32
 * bits, ties to even; DARAN_F32_INF when it rounds beyond FLT_MAX. */
static uint32_t round_bits(uint64_t m, int sticky, int32_t e)
{
    int32_t hb = 63 - (int32_t)clz64(m);
    int32_t e2 = hb + e; /* value in [2^e2, 2^(e2+1)) */
    int32_t nbits = e2 >= -126 ? 24 : e2 + 150;
    unsigned below;
    uint64_t r, mant;
    if (e2 > 127) {
        return DARAN_F32_INF;
    }
    if (nbits < 0) {
        return 0; /* below 2^-150: under half the smallest subnormal */
    }
    below = (unsigned)(hb - nbits); /* bits under the round bit, 16..63 */
    m |= (uint64_t)(sticky != 0); /* a fraction: some bit under the round bit is set */
    r = m >> below;
    mant = r >> 1;
    if ((r & 1u) && ((m << (64u - below)) || (mant & 1u))) {
        mant++;
    }
    if (e2 < -126) {
        return (uint32_t)mant; /* a carry to 2^23 is exactly FLT_MIN's bits */
    }
    return ((uint32_t)(e2 + 126) << 23) + (uint32_t)mant; /* hidden bit bumps the exponent field */
}

static void big_muladd(number_big_t *b, uint32_t mul, uint32_t add)
{
    uint64_t carry = add;
    size_t i;
    for (i = 0; i < DARAN_BIG_LIMBS; i++) {
        carry += (uint64_t)b->w[i] * mul;
        b->w[i] = (uint32_t)carry;
        carry >>= 32;
    }
}

/* b *= base^n (base 2 or 5), by the largest powers of base below 2^32: a
 * shift is a multiplication too, and one loop is less code than two. */
static void big_mul_pow(number_big_t *b, uint32_t base, int32_t n)
{
    uint32_t p = 1, max = 0xFFFFFFFFu / base;
    for (; n > 0; n--) {
        if (p > max) {
            big_muladd(b, p, 0);
            p = 1;
        }
        p *= base;
    }
    big_muladd(b, p, 0);
}

static int big_cmp(const number_big_t *a, const number_big_t *b)
{
    int32_t i;
    for (i = DARAN_BIG_LIMBS - 1; i >= 0; i--) {
        if (a->w[i] != b->w[i]) {
            return a->w[i] > b->w[i] ? 1 : -1;
        }
    }
    return 0;
}

/* The exact decision between lo and lo + 1: compare the decimal (digits from
 * index z) with the halfway point between the two floats, in big integers.
 * Never inlined: its two big integers must not sit in the caller's frame on
 * the common path, where the stack budget is tightest. */
static DARAN_NOINLINE uint32_t big_decide(const number_scan_t *s, uint32_t lo)
{
    number_big_t x, y;
    uint32_t exf = lo >> 23, frac = lo & 0x7FFFFFu, chunk = 0, scale = 1;
    int32_t f, e, c;
    size_t i, z = s->z, take = s->total - z;
    int sticky = 0;
    if (take > DARAN_BIG_DIGITS) {
        take = DARAN_BIG_DIGITS;
    }
    for (i = 0; i < DARAN_BIG_LIMBS; i++) {
        x.w[i] = y.w[i] = 0; /* a loop, not memset: no call leaves the core's stack budget */
    }
    /* halfway = (2m + 1) * 2^f */
    y.w[0] = 2u * (exf ? (frac | 0x800000u) : frac) + 1u;
    f = exf ? (int32_t)exf - 151 : -150;
    for (i = 0; i < take; i++) {
        chunk = chunk * 10u + digit_at(s, z + i);
        scale *= 10u;
        if (scale == 1000000000u || i + 1 == take) {
            big_muladd(&x, scale, chunk);
            chunk = 0;
            scale = 1;
        }
    }
    for (i = z + take; i < s->total && !sticky; i++) {
        sticky = digit_at(s, i) != 0;
    }
    e = diff_saturated(s->int_len, z + take) + s->exp10;
    /* x * 10^e vs y * 2^f, i.e. (x * 5^e) * 2^e vs y * 2^f */
    big_mul_pow(e >= 0 ? &x : &y, 5u, e >= 0 ? e : -e);
    big_mul_pow(e > f ? &x : &y, 2u, e > f ? e - f : f - e);
    c = big_cmp(&x, &y);
    if (c > 0 || (c == 0 && (sticky || (lo & 1u)))) {
        return lo + 1u;
    }
    return lo;
}

/* |value| = w * 10^q to float32 bits, when 64 bits of 10^q decide it:
 * returns 1 with *bits set, or 0 when the exact decision between *bits and
 * *bits + 1 is needed (big_decide). w holds up to 19 significant digits;
 * truncated: a later digit is non-zero, and then w has all 19 (w >= 10^18). */
static int decimal_to_bits(uint64_t w, int32_t q, int truncated, uint32_t *bits)
{
    uint64_t hi, lo;
    uint32_t d;
    unsigned lz;
    int32_t e;
    if (DARAN_NUM_FAST_PATH && !truncated && w <= (UINT64_C(1) << 24) && q >= -10 && q <= 10) {
        /* Both operands exact in float32 (10^10 = 2^10 * 9765625, and every
         * product on the way is exact too): one IEEE operation rounds correctly. */
        float f = (float)(uint32_t)w, p = 1.0f;
        int32_t n;
        for (n = q < 0 ? -q : q; n > 0; n--) {
            p *= 10.0f;
        }
        f = q < 0 ? f / p : f * p;
        memcpy(bits, &f, sizeof *bits);
        return 1;
    }
    if (q < DARAN_POW10_MIN) {
        *bits = 0; /* < 2^64 * 10^-65 < 2^-150 */
        return 1;
    }
    if (q > 38) {
        *bits = DARAN_F32_INF; /* >= 10^39 */
        return 1;
    }
    lz = clz64(w);
    hi = mul_64x64(w << lz, daran_pow10_hi(q), &lo);
    /* value = (hi + lo / 2^64) * 2^e, within the bounds below */
    e = floor_log2_pow10(q) + 1 - (int32_t)lz;
    *bits = round_bits(hi, lo != 0, e);
    if (!truncated && q >= 0 && q <= 27) {
        return 1; /* 10^q is exact in the table: so is the product */
    }
    /* Truncated 10^q errs below by < 2^64 product units; truncated digits by
     * < 17 * 2^64 more (w >= 10^18 then, so lz <= 4). */
    d = truncated ? 19u : 2u;
    return hi <= UINT64_MAX - d && round_bits(hi + d, 0, e) == *bits;
}

/* 10^k for k = 0..10, every one exact in a float. */
static const float short_scale[11] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                      1e6f, 1e7f, 1e8f, 1e9f, 1e10f};

/* The digits from p on, gathered into *w: where they end, or NULL once the
 * significand passes 2^24 (a long number is the full road's, and *w never
 * wraps: 2^24 * 10 + 9 < 2^32). */
static DARAN_ALWAYS_INLINE const char *short_digits(const char *p, const char *end, uint32_t *w)
{
    uint32_t d;
    while (p != end && (d = (uint32_t)(unsigned char)*p - (uint32_t)'0') <= 9u) {
        *w = *w * 10u + d;
        if (*w > (UINT32_C(1) << 24)) {
            return NULL;
        }
        p++;
    }
    return p;
}

/* The number hosts send most: [+-]?digits[.digits] (or .digits) with at
 * most 9 digits, a significand of at most 2^24 and at most 10 digits after
 * the point. Both operands of w / 10^k are then exact floats and one IEEE
 * division rounds correctly (decimal_to_bits' fast path), with none of the
 * scan's bookkeeping. 0: not such a number, the full road decides. */
static DARAN_NOINLINE int short_decimal(const char *t, size_t len, float *out)
{
    /* a sign, 9 digits and a point at most: a longer text is the full
     * road's without a look (and an empty one may be NULL) */
    if (!DARAN_NUM_FAST_PATH || len == 0u || len > 11u) {
        return 0;
    }
    const char *p = t;
    const char *end = t + len;
    uint32_t w = 0;
    if (*p == '-' || *p == '+') {
        p++;
    }
    const char *digits = p;
    if ((p = short_digits(p, end, &w)) == NULL) {
        return 0;
    }
    size_t whole = (size_t)(p - digits);
    size_t fraction = 0;
    if (p != end && *p == '.') {
        const char *first = ++p;
        if ((p = short_digits(p, end, &w)) == NULL) {
            return 0;
        }
        fraction = (size_t)(p - first);
    }
    /* a digit, at most 10 of them after the point (10^k exact), then the end */
    if (p != end || whole + fraction == 0u || fraction > 10u) {
        return 0;
    }
    float f = (float)w;
    if (fraction != 0u) {
        f /= short_scale[fraction];
    }
    *out = *t == '-' ? -f : f;
    return 1;
}

/* Every other number: the full scan, then the exact decision. Kept apart so
 * that daran_parse_f32() itself has no frame to set up for a short one. */
static DARAN_NOINLINE daran_result_t parse_f32_full(const char *text, size_t len, float *out)
{
    number_scan_t s;
    uint32_t bits = 0;
    if (!number_scan(text, len, &s)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (s.end) {
        /* Up to 19 significant digits; truncated: a non-zero digit follows them,
         * and then all 19 are kept, so w >= 10^18 (see decimal_to_bits). */
        if (!decimal_to_bits(s.w, diff_saturated(s.int_len, s.z + s.w_len) + s.exp10,
                             s.truncated, &bits)) {
            bits = big_decide(&s, bits);
        }
        if (bits >= DARAN_F32_INF) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
    }
    bits |= (uint32_t)s.negative << 31;
    memcpy(out, &bits, sizeof bits);
    return DARAN_OK;
}

daran_result_t daran_parse_f32(const char *text, size_t len, float *out)
{
    if ((text == NULL && len != 0) || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (short_decimal(text, len, out)) {
        return DARAN_OK;
    }
    return parse_f32_full(text, len, out);
}

daran_result_t daran_parse_u64(const char *text, size_t len, uint64_t *out)
{
    number_scan_t s;
    uint64_t v = 0;
    int32_t e;
    size_t i;
    if ((text == NULL && len != 0) || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (!number_scan(text, len, &s)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (s.end) {
        /* value = digits[z, end) * 10^e: its digits, then e zeros */
        e = diff_saturated(s.int_len, s.end) + s.exp10;
        if (e < 0) {
            return DARAN_ERR_INVALID_VALUE; /* a non-zero digit after the point */
        }
        if (s.negative) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        for (i = s.z;; i++) {
            uint32_t d = 0;
            if (i < s.end) {
                d = digit_at(&s, i);
            } else if (e-- == 0) {
                break;
            }
            /* v * 10 + d > UINT64_MAX; a first digit is non-zero: at most 20 rounds */
            if (v > UINT64_MAX / 10u || (v == UINT64_MAX / 10u && d > UINT64_MAX % 10u)) {
                return DARAN_ERR_OUT_OF_RANGE;
            }
            v = v * 10u + d;
        }
    }
    *out = v;
    return DARAN_OK;
}

/* Round to odd of g * cp / 2^64: the integer part, its last bit forced to 1
 * when a fraction of 2^-32 or more remains. g errs by < cp / 2^64 < 2^-33, so an
 * integer stays exact; bench/number/f32_exhaustive.c checks for every float
 * that no non-integer lands within 2^-32 of an integer. */
static uint32_t round_odd(uint64_t g, uint32_t cp)
{
    uint64_t a = (g >> 32) * cp;
    uint64_t mid = a + (((g & 0xFFFFFFFFu) * cp) >> 32);
    return (uint32_t)(mid >> 32) | (uint32_t)((uint32_t)mid != 0u);
}

/* Shortest decimal s * 10^*k inside the rounding interval of c * 2^q,
 * closest to it, ties to even (the Schubfach method; docs/numbers.md). */
static uint32_t shortest_digits(uint32_t exf, uint32_t frac, int32_t *k_out)
{
    uint32_t c = exf ? frac | 0x800000u : frac;
    int32_t q = exf ? (int32_t)exf - 150 : -149;
    int irregular = frac == 0 && exf > 1; /* the gap below is half the gap above */
    /* floor(log10(2^q)), or floor(log10(3/4 * 2^q)): exact for q = -149..104 (checked
     * by bench/number/gen_pow10_table.py) */
    int32_t k = floor_shift(q * INT32_C(1262611) - (irregular ? INT32_C(524031) : 0), 22);
    unsigned h = (unsigned)(q + floor_log2_pow10(-k) + 1); /* 1..4 */
    uint64_t g = daran_pow10_hi(-k) + 1u;
    uint32_t cb = c << 2, out = c & 1u; /* odd: the interval is open */
    uint32_t vb = round_odd(g, cb << h);
    uint32_t vbl = round_odd(g, (cb - (irregular ? 1u : 2u)) << h);
    uint32_t vbr = round_odd(g, (cb + 2u) << h);
    uint32_t s = vb >> 2, t, step;
    int lower_in, upper_in;
    *k_out = k;
    /* First the multiples of 10 (the interval is narrower than 10 units: it
     * holds at most one), then the units. */
    for (step = s >= 10u ? 10u : 1u;; step = 1u) {
        t = s / step * step;
        lower_in = vbl + out <= t << 2;
        upper_in = ((t + step) << 2) + out <= vbr;
        if (lower_in != upper_in) {
            return lower_in ? t : t + step;
        }
        if (step == 1u) {
            break;
        }
    }
    t = (s << 2) + 2u; /* the midpoint of s and s + 1, scaled like vb */
    return vb < t || (vb == t && !(s & 1u)) ? s : s + 1u;
}

/* The decimal digits of hi * 2^32 + lo, written backwards ending at end; returns
 * where they start. Above 2^32 each digit is a long division by 10 of the 32-bit high
 * word and two 16-bit chunks: 32-bit hardware division only, never a 64-bit
 * division (a library call on Cortex-M). */
static char *put_digits(char *p, uint32_t hi, uint32_t lo)
{
    while (hi) {
        uint32_t t = ((hi % 10u) << 16) | (lo >> 16), up;
        hi /= 10u;
        up = t / 10u;
        t = ((t % 10u) << 16) | (lo & 0xFFFFu);
        lo = (up << 16) | (t / 10u);
        *--p = (char)('0' + t % 10u);
    }
    do {
        *--p = (char)('0' + lo % 10u);
        lo /= 10u;
    } while (lo);
    return p;
}

/* The text of daran_format_float() into buf[0..DARAN_F32_TEXT_MAX); returns
 * its length. Zero is the one digit "0"; the words "inf" and "nan" take the
 * same digit pass as every other value: their letters, no point, no
 * exponent. Writes through a moving pointer (indexing a stack buffer costs
 * more code on Cortex-M). */
static size_t float_text(float value, char *buf)
{
    uint32_t bits, s;
    char d[10], *p = buf;
    const char *dig;
    int32_t k, nd, pt, j, last, sci;
    memcpy(&bits, &value, sizeof bits);
    if (bits >> 31 && bits << 1 <= DARAN_F32_INF << 1) {
        *p++ = '-'; /* not for a NaN */
    }
    bits &= 0x7FFFFFFFu;
    if (bits == 0u) {
        *p++ = '0'; /* a drive at rest reports zeros: no digit pass for them */
        return (size_t)(p - buf);
    }
    if (bits >= DARAN_F32_INF) {
        dig = &"infnan"[bits > DARAN_F32_INF ? 3 : 0]; /* one literal for both words */
        nd = 3;
        k = 2; /* "d.dd x 10^2": positional, three digits, no point */
    } else {
        k = 0;
        s = shortest_digits(bits >> 23, bits & 0x7FFFFFu, &k);
        while (s % 10u == 0) {
            s /= 10u;
            k++;
        }
        dig = put_digits(d + sizeof d, 0, s);
        nd = (int32_t)(d + sizeof d - dig);
        k += nd - 1; /* value = d.ddd * 10^k */
    }
    sci = k < -5 || k > 8;
    /* One pass over the digit positions j: the point goes before position pt,
     * positions outside 0..nd-1 are zeros ("0.000d", "d000", "d.0e+XX"). */
    pt = sci ? 1 : k + 1;
    last = nd > pt + sci ? nd : pt + sci;
    for (j = pt > 0 ? 0 : pt - 1; j < last; j++) {
        if (j == pt) {
            *p++ = '.';
        }
        *p++ = j >= 0 && j < nd ? dig[j] : '0';
    }
    if (sci) {
        *p++ = 'e';
        *p++ = k < 0 ? '-' : '+';
        k = k < 0 ? -k : k; /* float32: at most 45, two digits */
        *p++ = (char)('0' + k / 10);
        *p++ = (char)('0' + k % 10);
    }
    return (size_t)(p - buf);
}

/* The printers' one size check: copy text[0..n) (n >= 1) to buf and return n
 * when it fits in size, else write nothing and return 0. */
static DARAN_NOINLINE size_t put_fit(size_t n, const char *text, char *buf, size_t size)
{
    size_t i;
    if (n > size) {
        return 0;
    }
    i = 0;
    do { /* never empty */
        buf[i] = text[i];
    } while (++i < n);
    return n;
}

/* Both printers build their text on the stack, then put_fit: the length is
 * known before the first byte reaches buf, and the check is written once. */
size_t daran_format_float(float value, char *buf, size_t size)
{
    char t[DARAN_F32_TEXT_MAX];
    return put_fit(float_text(value, t), t, buf, size);
}

size_t daran_format_uint(uint64_t value, char *buf, size_t size)
{
    if (value < 10u && size != 0u) {
        *buf = (char)('0' + (unsigned)value); /* the flags and counters replies carry most */
        return 1;
    }
    char d[DARAN_U64_TEXT_MAX];
    const char *p = put_digits(d + sizeof d, (uint32_t)(value >> 32), (uint32_t)value);
    return put_fit((size_t)(d + sizeof d - p), p, buf, size);
}
