/* Unit tests of the number module (src/number.h): the float grammar, correct
 * rounding at the hard places (exact halfway points, long tails, subnormals,
 * the overflow boundary, huge exponents), exact integers, and the printed
 * forms of spec section 4. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "number.h"

static uint32_t bits_of(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof b);
    return b;
}

static float float_of(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

/* Parses text, expects DARAN_OK and exactly these bits. */
static void expect_f32(const char *text, uint32_t want)
{
    float f = 12345.0f;
    daran_result_t rc = daran_parse_f32(text, strlen(text), &f);
    if (rc != DARAN_OK || bits_of(f) != want) {
        print_error("'%s': rc %d bits %08x, want %08x\n", text, (int)rc, (unsigned)bits_of(f), (unsigned)want);
        fail();
    }
}

/* Parses text, expects the error and *out untouched. */
static void expect_f32_error(const char *text, daran_result_t want)
{
    float f = 12345.0f;
    daran_result_t rc = daran_parse_f32(text, strlen(text), &f);
    if (rc != want || bits_of(f) != bits_of(12345.0f)) {
        print_error("'%s': rc %d, want %d\n", text, (int)rc, (int)want);
        fail();
    }
}

static void expect_u64(const char *text, uint64_t want)
{
    uint64_t v = 777;
    daran_result_t rc = daran_parse_u64(text, strlen(text), &v);
    if (rc != DARAN_OK || v != want) {
        print_error("'%s': rc %d value %llu\n", text, (int)rc, (unsigned long long)v);
        fail();
    }
}

static void expect_u64_error(const char *text, daran_result_t want)
{
    uint64_t v = 777;
    daran_result_t rc = daran_parse_u64(text, strlen(text), &v);
    if (rc != want || v != 777) {
        print_error("'%s': rc %d, want %d\n", text, (int)rc, (int)want);
        fail();
    }
}

static void expect_text(float value, const char *want)
{
    char buf[DARAN_F32_TEXT_MAX + 8];
    size_t n;
    memset(buf, 'x', sizeof buf);
    n = daran_format_f32(value, buf);
    assert_true(n <= DARAN_F32_TEXT_MAX);
    assert_int_equal(buf[DARAN_F32_TEXT_MAX], 'x'); /* nothing written past the limit */
    buf[n] = '\0';
    assert_string_equal(buf, want);
}

static void expect_u64_text(uint64_t value, const char *want)
{
    char buf[DARAN_U64_TEXT_MAX + 1];
    size_t n = daran_format_u64(value, buf);
    assert_true(n <= DARAN_U64_TEXT_MAX);
    buf[n] = '\0';
    assert_string_equal(buf, want);
}

/* ---- grammar ---- */

static void test_plain_integers_and_signs_are_accepted(void **state)
{
    (void)state;
    expect_f32("5", bits_of(5.0f));
    expect_f32("+5", bits_of(5.0f));
    expect_f32("-5", bits_of(-5.0f));
    expect_f32("000012", bits_of(12.0f));
}

static void test_point_forms_are_accepted(void **state)
{
    (void)state;
    expect_f32("5.", bits_of(5.0f));
    expect_f32(".5", bits_of(0.5f));
    expect_f32("-.5", bits_of(-0.5f));
    expect_f32("5.25", bits_of(5.25f));
    expect_f32("12.500000", bits_of(12.5f));
}

static void test_exponent_forms_are_accepted(void **state)
{
    (void)state;
    expect_f32("5e3", bits_of(5000.0f));
    expect_f32("5E3", bits_of(5000.0f));
    expect_f32("5e+3", bits_of(5000.0f));
    expect_f32("5e-3", bits_of(0.005f));
    expect_f32(".5e1", bits_of(5.0f));
    expect_f32("5.e1", bits_of(50.0f));
    expect_f32("1e0000000000000000000000000000001", bits_of(10.0f));
}

static void test_empty_and_lone_signs_are_invalid(void **state)
{
    (void)state;
    expect_f32_error("", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("+", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("-", DARAN_ERR_INVALID_VALUE);
    expect_f32_error(".", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("-.", DARAN_ERR_INVALID_VALUE);
}

static void test_broken_exponents_are_invalid(void **state)
{
    (void)state;
    expect_f32_error("e5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5e", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5e+", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5e-", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("1e5.5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error(".e1", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5ee1", DARAN_ERR_INVALID_VALUE);
}

static void test_words_and_hex_are_invalid(void **state)
{
    (void)state;
    expect_f32_error("nan", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("inf", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("-inf", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("infinity", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("0x10", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("0x1p3", DARAN_ERR_INVALID_VALUE);
}

static void test_stray_characters_are_invalid(void **state)
{
    (void)state;
    expect_f32_error("5 ", DARAN_ERR_INVALID_VALUE);
    expect_f32_error(" 5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5..1", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5.5.5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("++5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("+-5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("1,5", DARAN_ERR_INVALID_VALUE);
    expect_f32_error("5f", DARAN_ERR_INVALID_VALUE);
}

static void test_length_bounds_the_text_not_a_nul(void **state)
{
    float f = 0.0f;
    (void)state;
    assert_int_equal(daran_parse_f32("12345", 2, &f), DARAN_OK);
    assert_true(f == 12.0f);
    assert_int_equal(daran_parse_f32("1.5x", 3, &f), DARAN_OK);
    assert_true(f == 1.5f);
    assert_int_equal(daran_parse_f32("5", 0, &f), DARAN_ERR_INVALID_VALUE);
}

/* ---- correct rounding ---- */

static void test_common_values_take_the_exact_float(void **state)
{
    (void)state;
    expect_f32("100.5", bits_of(100.5f));
    expect_f32("-0.02", bits_of(-0.02f));
    expect_f32("12", bits_of(12.0f));
    expect_f32("0.1", 0x3DCCCCCDu);
    expect_f32("1.4142135623730951", bits_of(1.41421356f));
    expect_f32("90.000000", bits_of(90.0f));
    expect_f32("-359.9999", bits_of(-359.9999f));
}

static void test_integer_halfway_rounds_to_even(void **state)
{
    (void)state;
    expect_f32("16777217", 0x4B800000u);  /* between 2^24 and 2^24+2: even is 2^24 */
    expect_f32("16777219", 0x4B800002u);  /* between +2 (odd) and +4: up */
    expect_f32("8388608.5", 0x4B000000u); /* ulp 1 at 2^23 */
    expect_f32("8388609.5", 0x4B000002u);
}

static void test_fraction_halfway_rounds_to_even(void **state)
{
    (void)state;
    expect_f32("1.000000059604644775390625", 0x3F800000u);          /* 1 + 2^-24 */
    expect_f32("1.000000178813934326171875", 0x3F800002u);          /* 1 + 3 * 2^-24 */
    expect_f32("0.5000000298023223876953125", 0x3F000000u);         /* 0.5 + 2^-25 */
}

static void test_a_tail_just_above_halfway_rounds_up(void **state)
{
    (void)state;
    expect_f32("1.0000000596046447753906250000000000000000000000000001", 0x3F800001u);
    expect_f32("16777217.00000000000000000000000000000000000000000000001", 0x4B800001u);
    expect_f32("1.000000059604644775390625e0000000000000000000000000001", 0x41200001u); /* 10.0000006: 0.625 ulp up */
}

static void test_a_tail_just_below_halfway_rounds_down(void **state)
{
    (void)state;
    expect_f32("1.0000000596046447753906249999999999999999999999999999", 0x3F800000u);
    expect_f32("1.0000001788139343261718749999999999999999999999", 0x3F800001u);
    expect_f32("16777218.9999999999999999999999999999999999999999999", 0x4B800001u);
}

static void test_long_digit_strings_use_every_digit(void **state)
{
    (void)state;
    /* 120+ digits, the deciding one far beyond 19 */
    expect_f32("1.00000005960464477539062500000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001",
               0x3F800001u);
    expect_f32("0.00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001e122",
               bits_of(1.0f));
    expect_f32("1000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000e-105",
               bits_of(1.0f));
}

static void test_leading_zeros_do_not_count_as_digits(void **state)
{
    (void)state;
    expect_f32("0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000012.5",
               bits_of(12.5f));
    expect_f32("0.0000000000000000000000000000000000000000000000000001e60", bits_of(1e8f));
}

static void test_subnormals_round_correctly(void **state)
{
    (void)state;
    expect_f32("1e-45", 0x00000001u);
    expect_f32("1.401298464324817070923729583289916131280e-45", 0x00000001u);
    expect_f32("2.8e-45", 0x00000002u);
    expect_f32("1.1754942106924411e-38", 0x007FFFFFu); /* largest subnormal */
    expect_f32("1.17549435e-38", 0x00800000u);          /* FLT_MIN */
    expect_f32("-1e-45", 0x80000001u);
}

static void test_half_the_smallest_subnormal_is_a_tie_to_zero(void **state)
{
    (void)state;
    expect_f32("7.00649232162408535461864791644958065640130970938257885878534141944895541342930300743319094181060791015625e-46",
               0x00000000u);
    expect_f32("7.00649232162408535461864791644958065640130970938257885878534141944895541342930300743319094181060791015626e-46",
               0x00000001u);
    expect_f32("2.1019476964872256063855943749348741969203929128147736576356024258346866240287909022299572825431823730468750e-45",
               0x00000002u); /* 3 * 2^-150: tie between 1 (odd) and 2 */
}

static void test_underflow_gives_signed_zero(void **state)
{
    (void)state;
    expect_f32("1e-46", 0x00000000u);
    expect_f32("-1e-50", 0x80000000u);
    expect_f32("1e-999999999", 0x00000000u);
    expect_f32("-9.99e-999999999999999999999", 0x80000000u);
}

static void test_zero_in_all_its_forms(void **state)
{
    (void)state;
    expect_f32("0", 0x00000000u);
    expect_f32("-0", 0x80000000u);
    expect_f32("-0.0", 0x80000000u);
    expect_f32("0e99999", 0x00000000u);
    expect_f32("0.000e999999999999999999", 0x00000000u);
    expect_f32("+.0e-5", 0x00000000u);
}

static void test_flt_max_and_what_rounds_to_it_are_in_range(void **state)
{
    (void)state;
    expect_f32("3.4028235e38", 0x7F7FFFFFu);
    expect_f32("340282346638528859811704183484516925440", 0x7F7FFFFFu);
    expect_f32("3.40282356779733661637539395458142568447e38", 0x7F7FFFFFu);
    expect_f32("-3.4028235677973366e38", 0xFF7FFFFFu);
}

static void test_halfway_to_2_pow_128_is_out_of_range(void **state)
{
    (void)state;
    expect_f32_error("3.40282356779733661637539395458142568448e38", DARAN_ERR_OUT_OF_RANGE);
    expect_f32_error("-3.40282356779733661637539395458142568448e38", DARAN_ERR_OUT_OF_RANGE);
    expect_f32_error("3.5e38", DARAN_ERR_OUT_OF_RANGE);
    expect_f32_error("1e39", DARAN_ERR_OUT_OF_RANGE);
}

static void test_huge_exponents_saturate(void **state)
{
    (void)state;
    expect_f32_error("1e999999999", DARAN_ERR_OUT_OF_RANGE);
    expect_f32_error("1e2147483648", DARAN_ERR_OUT_OF_RANGE);
    expect_f32_error("1e99999999999999999999999999999999", DARAN_ERR_OUT_OF_RANGE);
    expect_f32("1e-2147483649", 0x00000000u);
    expect_f32_error("0.0000000000000000000000000000000000000000000001e999999999", DARAN_ERR_OUT_OF_RANGE);
    expect_f32("100000000000000000000000000000000000000000000000000e-999999999", 0x00000000u);
}

static void test_a_million_zeros_are_only_zeros(void **state)
{
    static char text[1000016];
    float f = 0.0f;
    uint64_t v = 0;
    size_t n;
    (void)state;
    memset(text, '0', 1000000);
    memcpy(text + 1000000, "1.5", 3);
    assert_int_equal(daran_parse_f32(text, 1000003, &f), DARAN_OK);
    assert_true(f == 1.5f);
    text[0] = '.';
    memcpy(text + 1000000, "15e1000000", 10);
    n = 1000010;
    assert_int_equal(daran_parse_f32(text, n, &f), DARAN_OK);
    assert_true(f == 1.5f);
    assert_int_equal(daran_parse_u64(text, n, &v), DARAN_ERR_INVALID_VALUE); /* 1.5 */
    memcpy(text + 1000000, "15e1000001", 10);
    assert_int_equal(daran_parse_u64(text, n, &v), DARAN_OK);
    assert_true(v == 15u);
}

/* ---- integers ---- */

static void test_integer_spellings_of_five(void **state)
{
    (void)state;
    expect_u64("5", 5);
    expect_u64("+5", 5);
    expect_u64("5.0", 5);
    expect_u64("5.", 5);
    expect_u64("05", 5);
    expect_u64("5e0", 5);
    expect_u64("50e-1", 5);
    expect_u64("0.5e1", 5);
    expect_u64("5.000000", 5);
}

static void test_negative_zero_is_zero(void **state)
{
    (void)state;
    expect_u64("-0", 0);
    expect_u64("-0.0", 0);
    expect_u64("0e999999999", 0);
    expect_u64("-0e-5", 0);
}

static void test_negative_integers_are_out_of_range(void **state)
{
    (void)state;
    expect_u64_error("-1", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("-1e30", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("-10e-1", DARAN_ERR_OUT_OF_RANGE);
}

static void test_fractions_are_invalid_values(void **state)
{
    (void)state;
    expect_u64_error("5.5", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("-5.5", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("1e-1", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("1e-999999999", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("18446744073709551615.5", DARAN_ERR_INVALID_VALUE);
}

static void test_uint64_max_is_the_limit(void **state)
{
    (void)state;
    expect_u64("18446744073709551615", UINT64_MAX);
    expect_u64("1.8446744073709551615e19", UINT64_MAX);
    expect_u64("0000018446744073709551615.000", UINT64_MAX);
    expect_u64_error("18446744073709551616", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("1.8446744073709551616e19", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("99999999999999999999", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("1e20", DARAN_ERR_OUT_OF_RANGE);
    expect_u64_error("1e999999999", DARAN_ERR_OUT_OF_RANGE);
    expect_u64("1e19", UINT64_C(10000000000000000000));
}

static void test_integer_grammar_matches_the_float_grammar(void **state)
{
    (void)state;
    expect_u64_error("", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("x", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("5x", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("0x5", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("5e", DARAN_ERR_INVALID_VALUE);
    expect_u64_error("nan", DARAN_ERR_INVALID_VALUE);
}

/* ---- printing ---- */

static void test_spec_examples_print_positionally(void **state)
{
    (void)state;
    expect_text(100.5f, "100.5");
    expect_text(160.0f, "160");
    expect_text(-3.0f, "-3");
    expect_text(0.02f, "0.02");
    expect_text(1e-5f, "0.00001");
}

static void test_spec_examples_print_scientifically(void **state)
{
    (void)state;
    expect_text(1e9f, "1.0e+09");
    expect_text(1.5e-7f, "1.5e-07");
    expect_text(3e12f, "3.0e+12");
}

static void test_positional_range_ends_at_exponents_minus_5_and_8(void **state)
{
    (void)state;
    expect_text(1e8f, "100000000");
    expect_text(999999936.0f, "999999940");
    expect_text(1e-6f, "1.0e-06");
    expect_text(9.99e-5f, "0.0000999");
    expect_text(9.99e-6f, "9.99e-06");
    expect_text(1.25e-6f, "1.25e-06");
}

static void test_the_shortest_text_that_round_trips_is_chosen(void **state)
{
    (void)state;
    expect_text(123456789.0f, "123456790"); /* the float is 123456792 */
    expect_text(0.1f, "0.1");
    expect_text(1.0f / 3.0f, "0.33333334");
    expect_text(16777216.0f, "16777216");
    expect_text(float_of(0x3F800001u), "1.0000001");
}

static void test_extremes_print(void **state)
{
    (void)state;
    expect_text(float_of(0x7F7FFFFFu), "3.4028235e+38");
    expect_text(float_of(0x00000001u), "1.0e-45");
    expect_text(float_of(0x00800000u), "1.1754944e-38");
    expect_text(float_of(0x007FFFFFu), "1.1754942e-38");
    expect_text(float_of(0x80000001u), "-1.0e-45");
}

static void test_powers_of_two_use_the_narrow_gap_below(void **state)
{
    (void)state;
    expect_text(float_of(0x4C800000u), "67108864");  /* 2^26 */
    expect_text(float_of(0x5F000000u), "9.223372e+18"); /* 2^63 */
    expect_text(float_of(0x3A800000u), "0.0009765625");
}

static void test_zero_nan_and_infinity_print_as_words(void **state)
{
    (void)state;
    expect_text(0.0f, "0");
    expect_text(-0.0f, "-0");
    expect_text(float_of(0x7FC00000u), "nan");
    expect_text(float_of(0xFFC00000u), "nan");
    expect_text(float_of(0x7F800001u), "nan");
    expect_text(float_of(0x7F800000u), "inf");
    expect_text(float_of(0xFF800000u), "-inf");
}

static void test_longest_text_fits_the_buffer(void **state)
{
    char buf[DARAN_F32_TEXT_MAX];
    uint32_t b;
    size_t longest = 0;
    (void)state;
    for (b = 0; b < 0xFF800000u; b += 0x00012345u) {
        size_t n = daran_format_f32(float_of(b), buf);
        longest = n > longest ? n : longest;
    }
    assert_true(longest <= DARAN_F32_TEXT_MAX);
    expect_text(float_of(0xB74F0000u), "-0.0000123381615"); /* 16 characters */
}

static void test_printed_text_parses_back_to_the_same_bits(void **state)
{
    char buf[DARAN_F32_TEXT_MAX];
    uint32_t b, seed = 1;
    int i;
    (void)state;
    for (i = 0; i < 100000; i++) {
        float f;
        size_t n;
        seed = seed * 1664525u + 1013904223u;
        b = seed;
        if ((b & 0x7F800000u) == 0x7F800000u) {
            continue;
        }
        n = daran_format_f32(float_of(b), buf);
        assert_int_equal(daran_parse_f32(buf, n, &f), DARAN_OK);
        assert_int_equal(bits_of(f), b);
    }
}

/* ---- integer printing ---- */

static void test_u64_prints_in_decimal(void **state)
{
    (void)state;
    expect_u64_text(0, "0");
    expect_u64_text(9, "9");
    expect_u64_text(10, "10");
    expect_u64_text(4294967295u, "4294967295");
    expect_u64_text(UINT64_C(4294967296), "4294967296");
    expect_u64_text(UINT64_C(9999999999999999999), "9999999999999999999");
    expect_u64_text(UINT64_C(10000000000000000000), "10000000000000000000");
    expect_u64_text(UINT64_MAX, "18446744073709551615");
}

static void test_u64_printing_agrees_with_snprintf(void **state)
{
    char ours[DARAN_U64_TEXT_MAX + 1], ref[32];
    uint64_t x = 88172645463325252u;
    int i;
    (void)state;
    for (i = 0; i < 200000; i++) {
        uint64_t v;
        size_t n;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        v = x >> (i % 64); /* every magnitude */
        n = daran_format_u64(v, ours);
        ours[n] = '\0';
        snprintf(ref, sizeof ref, "%llu", (unsigned long long)v);
        assert_string_equal(ours, ref);
    }
}

static void test_u64_text_parses_back(void **state)
{
    char buf[DARAN_U64_TEXT_MAX];
    uint64_t v = 1, back = 0;
    int i;
    (void)state;
    for (i = 0; i < 64; i++, v = v * 3u + 1u) {
        size_t n = daran_format_u64(v, buf);
        assert_int_equal(daran_parse_u64(buf, n, &back), DARAN_OK);
        assert_true(back == v);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plain_integers_and_signs_are_accepted),
        cmocka_unit_test(test_point_forms_are_accepted),
        cmocka_unit_test(test_exponent_forms_are_accepted),
        cmocka_unit_test(test_empty_and_lone_signs_are_invalid),
        cmocka_unit_test(test_broken_exponents_are_invalid),
        cmocka_unit_test(test_words_and_hex_are_invalid),
        cmocka_unit_test(test_stray_characters_are_invalid),
        cmocka_unit_test(test_length_bounds_the_text_not_a_nul),
        cmocka_unit_test(test_common_values_take_the_exact_float),
        cmocka_unit_test(test_integer_halfway_rounds_to_even),
        cmocka_unit_test(test_fraction_halfway_rounds_to_even),
        cmocka_unit_test(test_a_tail_just_above_halfway_rounds_up),
        cmocka_unit_test(test_a_tail_just_below_halfway_rounds_down),
        cmocka_unit_test(test_long_digit_strings_use_every_digit),
        cmocka_unit_test(test_leading_zeros_do_not_count_as_digits),
        cmocka_unit_test(test_subnormals_round_correctly),
        cmocka_unit_test(test_half_the_smallest_subnormal_is_a_tie_to_zero),
        cmocka_unit_test(test_underflow_gives_signed_zero),
        cmocka_unit_test(test_zero_in_all_its_forms),
        cmocka_unit_test(test_flt_max_and_what_rounds_to_it_are_in_range),
        cmocka_unit_test(test_halfway_to_2_pow_128_is_out_of_range),
        cmocka_unit_test(test_huge_exponents_saturate),
        cmocka_unit_test(test_a_million_zeros_are_only_zeros),
        cmocka_unit_test(test_integer_spellings_of_five),
        cmocka_unit_test(test_negative_zero_is_zero),
        cmocka_unit_test(test_negative_integers_are_out_of_range),
        cmocka_unit_test(test_fractions_are_invalid_values),
        cmocka_unit_test(test_uint64_max_is_the_limit),
        cmocka_unit_test(test_integer_grammar_matches_the_float_grammar),
        cmocka_unit_test(test_spec_examples_print_positionally),
        cmocka_unit_test(test_spec_examples_print_scientifically),
        cmocka_unit_test(test_positional_range_ends_at_exponents_minus_5_and_8),
        cmocka_unit_test(test_the_shortest_text_that_round_trips_is_chosen),
        cmocka_unit_test(test_extremes_print),
        cmocka_unit_test(test_powers_of_two_use_the_narrow_gap_below),
        cmocka_unit_test(test_zero_nan_and_infinity_print_as_words),
        cmocka_unit_test(test_longest_text_fits_the_buffer),
        cmocka_unit_test(test_printed_text_parses_back_to_the_same_bits),
        cmocka_unit_test(test_u64_prints_in_decimal),
        cmocka_unit_test(test_u64_printing_agrees_with_snprintf),
        cmocka_unit_test(test_u64_text_parses_back),
    };
    return cmocka_run_group_tests_name("number", tests, NULL, NULL);
}
