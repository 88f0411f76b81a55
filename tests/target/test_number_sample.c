/* The number sample on the target: decimal text -> float32 and float32 ->
 * shortest text through the core's number code, against values computed with
 * exact rational arithmetic on the build machine (number_samples.h, written
 * at build time by gen_number_samples.py from Python's fractions, not from
 * any C library). One Unity case per sample.
 *
 * The unit suites' own number checks run on the target too, but several of
 * them take the C library's strtof as their reference, and newlib's strtof
 * rounds twice (strtod, then a cast to float); this sample does not depend
 * on the C library, so it stays an independent oracle on the target, edge
 * cases first (FLT_MAX and the overflow boundary, subnormals, ties, 17+
 * digit inputs). Soft-float helpers, FPU flags and libgcc division differ
 * between host and target; this shows the core does not care. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"

#include "number.h"
#include "number_samples.h"

void setUp(void)
{
}

void tearDown(void)
{
}

static size_t sample;

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

static void parse_sample(void)
{
    const char *text = number_parse_samples[sample].text;
    float got = 0.0f;
    daran_result_t r = daran_parse_f32(text, strlen(text), &got);
    if (number_parse_samples[sample].out_of_range) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_OUT_OF_RANGE, r, "beyond FLT_MAX: out of range");
    } else {
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, r, "a valid number");
        TEST_ASSERT_EQUAL_HEX32(number_parse_samples[sample].bits, bits_of(got));
    }
}

static void format_sample(void)
{
    char buf[DARAN_F32_TEXT_MAX + 1];
    size_t len = daran_format_float(float_of(number_format_samples[sample].bits), buf, sizeof buf);
    TEST_ASSERT_TRUE_MESSAGE(len <= DARAN_F32_TEXT_MAX, "text within DARAN_F32_TEXT_MAX");
    buf[len] = '\0';
    TEST_ASSERT_EQUAL_STRING(number_format_samples[sample].text, buf);
}

int main(void)
{
    static char name[160];
    UNITY_BEGIN();
    for (sample = 0; sample < sizeof number_parse_samples / sizeof number_parse_samples[0];
         sample++) {
        snprintf(name, sizeof name, "parse_\"%s\"", number_parse_samples[sample].text);
        UnityDefaultTestRun(parse_sample, name, __LINE__);
    }
    for (sample = 0; sample < sizeof number_format_samples / sizeof number_format_samples[0];
         sample++) {
        snprintf(name, sizeof name, "format_0x%08lX", (unsigned long)number_format_samples[sample].bits);
        UnityDefaultTestRun(format_sample, name, __LINE__);
    }
    return UNITY_END();
}
