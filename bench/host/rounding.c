/* How often the hand-written yardstick's float conversion (grbl's read_float
 * style: bench/baseline/handwritten.c) rounds a decimal to another float32
 * than correct rounding does. The reference is glibc's strtof, which rounds
 * correctly (round to nearest, ties to even); the core's daran_parse_f32 is
 * checked against it on the same numbers too (it must never differ).
 *
 *   daran_rounding streams FILE...      every number of the streams (every
 *                                       field after the command word, before
 *                                       '*', that is a decimal of the grammar)
 *   daran_rounding random N SEED        N random decimals of each length 8..17
 *                                       significant digits (and 1..7 for
 *                                       comparison), in two spellings:
 *                                       positional, magnitude 1e-3..1e4 (how
 *                                       hosts spell positions, velocities,
 *                                       gains), and scientific over the whole
 *                                       normal float32 range (1e-37..3e38)
 *
 * Prints Markdown tables: numbers, how many the yardstick rounds to another
 * float, the rate, and how far off (ulps); and the core's count (0). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "handwritten.h"
#include "number.h"

typedef struct tally {
    unsigned long numbers;
    unsigned long wrong;      /* the yardstick's float != strtof's */
    unsigned long ulps[4];    /* 1, 2, 3, more */
    unsigned long core_wrong; /* daran_parse_f32's float != strtof's */
} tally_t;

static int32_t ordered(float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    return (bits & 0x80000000u) ? -(int32_t)(bits & 0x7FFFFFFFu) : (int32_t)bits;
}

static void check(const char *text, size_t len, tally_t *t)
{
    char buf[64];
    if (len >= sizeof buf) {
        return;
    }
    memcpy(buf, text, len);
    buf[len] = '\0';
    char *end;
    float right = strtof(buf, &end);
    float mine, core;
    if (*end != '\0' || handwritten_parse_f32(buf, len, &mine) != DARAN_OK) {
        return;
    }
    t->numbers++;
    if (memcmp(&mine, &right, sizeof mine) != 0) {
        int64_t d = (int64_t)ordered(mine) - (int64_t)ordered(right);
        d = d < 0 ? -d : d;
        t->wrong++;
        t->ulps[d >= 4 ? 3 : d - 1]++;
    }
    if (daran_parse_f32(buf, len, &core) != DARAN_OK || memcmp(&core, &right, sizeof core) != 0) {
        t->core_wrong++;
    }
}

static void row(const char *label, const tally_t *t)
{
    printf("| %s | %lu | %lu | %.2f%% | %lu | %lu | %lu | %lu | %lu |\n", label, t->numbers,
           t->wrong, t->numbers ? 100.0 * (double)t->wrong / (double)t->numbers : 0.0, t->ulps[0],
           t->ulps[1], t->ulps[2], t->ulps[3], t->core_wrong);
}

static void header(const char *first)
{
    printf("| %s | numbers | rounded to another float | rate | 1 ulp | 2 ulp | 3 ulp | 4+ ulp | "
           "core (daran_parse_f32) wrong |\n",
           first);
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
}

static int decimal(const char *p, size_t n)
{
    int digits = 0;
    for (size_t i = 0; i < n; i++) {
        char c = p[i];
        if (c >= '0' && c <= '9') {
            digits = 1;
        } else if (c != '.' && c != '-' && c != '+' && c != 'e' && c != 'E') {
            return 0;
        }
    }
    return digits;
}

static int streams(int argc, char **argv)
{
    tally_t all = {0};
    header("stream");
    for (int i = 0; i < argc; i++) {
        FILE *f = fopen(argv[i], "r");
        if (f == NULL) {
            perror(argv[i]);
            return 2;
        }
        tally_t t = {0};
        char line[512];
        while (fgets(line, sizeof line, f) != NULL) {
            char *star = strchr(line, '*');
            if (star != NULL) {
                *star = '\0';
            }
            int field = 0;
            for (char *p = line; *p != '\0';) {
                while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
                    p++;
                }
                char *q = p;
                while (*q != '\0' && *q != ' ' && *q != '\t' && *q != '\r' && *q != '\n') {
                    q++;
                }
                if (q > p && field++ > 0 && decimal(p, (size_t)(q - p))) {
                    check(p, (size_t)(q - p), &t);
                }
                p = q;
            }
        }
        fclose(f);
        const char *name = strrchr(argv[i], '/');
        row(name != NULL ? name + 1 : argv[i], &t);
        all.numbers += t.numbers;
        all.wrong += t.wrong;
        all.core_wrong += t.core_wrong;
        for (int k = 0; k < 4; k++) {
            all.ulps[k] += t.ulps[k];
        }
    }
    row("**all**", &all);
    return 0;
}

static uint64_t state;

static uint64_t next(void)
{
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 2685821657736338717ull;
}

static unsigned below(unsigned n)
{
    return (unsigned)(next() % n);
}

/* n significant digits, the first not 0; value d.ddd x 10^e. */
static size_t positional(char *out, int n, int e)
{
    char digits[32];
    size_t k = 0;
    digits[0] = (char)('1' + below(9));
    for (int i = 1; i < n; i++) {
        digits[i] = (char)('0' + below(10));
    }
    if (below(2)) {
        out[k++] = '-';
    }
    if (e >= 0) {
        for (int i = 0; i < n || i <= e; i++) {
            if (i == e + 1) {
                out[k++] = '.';
            }
            out[k++] = i < n ? digits[i] : '0';
        }
    } else {
        out[k++] = '0';
        out[k++] = '.';
        for (int i = 0; i < -e - 1; i++) {
            out[k++] = '0';
        }
        for (int i = 0; i < n; i++) {
            out[k++] = digits[i];
        }
    }
    return k;
}

static size_t scientific(char *out, int n, int e)
{
    size_t k = 0;
    if (below(2)) {
        out[k++] = '-';
    }
    out[k++] = (char)('1' + below(9));
    if (n > 1) {
        out[k++] = '.';
        for (int i = 1; i < n; i++) {
            out[k++] = (char)('0' + below(10));
        }
    }
    k += (size_t)sprintf(out + k, "e%d", e);
    return k;
}

static int random_sample(unsigned long count, unsigned long seed)
{
    state = seed * 0x9E3779B97F4A7C15ull + 1u;
    static const char *const kinds[2] = {
        "positional, |x| in [1e-3, 1e4)", "scientific, |x| in [1e-37, 1e38)"};
    for (int kind = 0; kind < 2; kind++) {
        tally_t long_digits = {0};
        printf("\n%s, %lu numbers per length, seed %lu:\n\n", kinds[kind], count, seed);
        header("significant digits");
        for (int n = 1; n <= 17; n++) {
            tally_t t = {0};
            for (unsigned long i = 0; i < count; i++) {
                char text[64];
                size_t len = kind == 0 ? positional(text, n, (int)below(7) - 3)
                                       : scientific(text, n, (int)below(75) - 37);
                check(text, len, &t);
            }
            char label[16];
            snprintf(label, sizeof label, "%d", n);
            row(label, &t);
            if (n >= 8) {
                long_digits.numbers += t.numbers;
                long_digits.wrong += t.wrong;
                long_digits.core_wrong += t.core_wrong;
                for (int k = 0; k < 4; k++) {
                    long_digits.ulps[k] += t.ulps[k];
                }
            }
        }
        row("**8 to 17**", &long_digits);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 3 && strcmp(argv[1], "streams") == 0) {
        return streams(argc - 2, argv + 2);
    }
    if (argc == 4 && strcmp(argv[1], "random") == 0) {
        return random_sample(strtoul(argv[2], NULL, 10), strtoul(argv[3], NULL, 10));
    }
    fprintf(stderr, "usage: daran_rounding streams FILE... | random N SEED\n");
    return 2;
}
