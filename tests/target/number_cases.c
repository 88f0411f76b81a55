/* The number sample of the on-target self-test: text -> float32 and
 * float32 -> shortest text through the core's number code, against values
 * computed exactly on the host (number_samples.h, generated at build time by
 * gen_number_samples.py). Soft-float helpers, FPU flags and libgcc division
 * differ between host and target; this shows the core does not care. */
#include "selftest.h"

#include <string.h>

#include "number.h"
#include "number_samples.h"

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static float float_of(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void report_bits(const char *what, const char *text, uint32_t got, uint32_t want)
{
    static const char hex[] = "0123456789abcdef";
    char buf[8];
    selftest_print("FAIL ");
    selftest_print(what);
    selftest_print(" \"");
    selftest_print_escaped(text);
    selftest_print("\": got 0x");
    for (int i = 0; i < 8; i++) {
        buf[i] = hex[(got >> (28 - 4 * i)) & 15u];
    }
    selftest_write(buf, 8u);
    selftest_print(" want 0x");
    for (int i = 0; i < 8; i++) {
        buf[i] = hex[(want >> (28 - 4 * i)) & 15u];
    }
    selftest_write(buf, 8u);
    selftest_print("\n");
}

void selftest_number_cases(selftest_tally_t *tally)
{
    for (size_t i = 0; i < sizeof number_parse_samples / sizeof number_parse_samples[0]; i++) {
        const char *text = number_parse_samples[i].text;
        float got = 0.0f;
        daran_result_t r = daran_parse_f32(text, strlen(text), &got);
        bool ok;
        if (number_parse_samples[i].out_of_range) {
            ok = r == DARAN_ERR_OUT_OF_RANGE;
        } else {
            ok = r == DARAN_OK && bits_of(got) == number_parse_samples[i].bits;
        }
        if (ok) {
            tally->passed++;
        } else {
            tally->failed++;
            report_bits("parse", text, r == DARAN_OK ? bits_of(got) : 0xFFFFFFFFu,
                        number_parse_samples[i].bits);
        }
    }
    for (size_t i = 0; i < sizeof number_format_samples / sizeof number_format_samples[0]; i++) {
        char buf[DARAN_F32_TEXT_MAX + 1];
        size_t len = daran_format_f32(float_of(number_format_samples[i].bits), buf);
        const char *want = number_format_samples[i].text;
        if (len <= DARAN_F32_TEXT_MAX && len == strlen(want) && memcmp(buf, want, len) == 0) {
            tally->passed++;
        } else {
            tally->failed++;
            if (len > DARAN_F32_TEXT_MAX) {
                len = DARAN_F32_TEXT_MAX;
            }
            buf[len] = '\0';
            selftest_print("FAIL format 0x");
            {
                static const char hex[] = "0123456789abcdef";
                char hb[8];
                for (int k = 0; k < 8; k++) {
                    hb[k] = hex[(number_format_samples[i].bits >> (28 - 4 * k)) & 15u];
                }
                selftest_write(hb, 8u);
            }
            selftest_print(": got \"");
            selftest_print(buf);
            selftest_print("\" want \"");
            selftest_print(want);
            selftest_print("\"\n");
        }
    }
}
