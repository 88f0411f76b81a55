/* Unit tests of the number module (src/text/number.h): the float grammar, correct
 * rounding at the hard places (exact halfway points, long tails, subnormals,
 * the overflow boundary, huge exponents), exact integers, and the printed
 * forms of spec section 4. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"

#include "float_bits.h"

#include "number.h"

void setUp(void)
{
}

void tearDown(void)
{
}


/* The text in a heap block of exactly its length, no NUL after it, so a read
 * one byte past the end is a fault under AddressSanitizer. */
static char *exact_copy(const char *text)
{
    size_t len = strlen(text);
    char *copy = malloc(len != 0u ? len : 1u);
    TEST_ASSERT_NOT_NULL(copy);
    memcpy(copy, text, len);
    return copy;
}

/* The EXPECT_* checks are macros so that a failure names the line of the
 * test that made the check; the text under test is the failure message. */

/* Parses text, expects DARAN_OK and exactly these bits. */
#define EXPECT_F32(text, want) expect_f32_at(__LINE__, (text), (want))
static void expect_f32_at(UNITY_LINE_TYPE line, const char *text, uint32_t want)
{
    float f = 12345.0f;
    char *copy = exact_copy(text);
    daran_result_t rc = daran_parse_f32(copy, strlen(text), &f);
    free(copy);
    UNITY_TEST_ASSERT_EQUAL_INT(DARAN_OK, rc, line, text);
    UNITY_TEST_ASSERT_EQUAL_HEX32(want, daran_bits_of(f), line, text);
}

/* Parses text, expects the error and *out untouched. */
#define EXPECT_F32_ERROR(text, want) expect_f32_error_at(__LINE__, (text), (want))
static void expect_f32_error_at(UNITY_LINE_TYPE line, const char *text, daran_result_t want)
{
    float f = 12345.0f;
    char *copy = exact_copy(text);
    daran_result_t rc = daran_parse_f32(copy, strlen(text), &f);
    free(copy);
    UNITY_TEST_ASSERT_EQUAL_INT(want, rc, line, text);
    UNITY_TEST_ASSERT_EQUAL_HEX32(daran_bits_of(12345.0f), daran_bits_of(f), line, text);
}

#define EXPECT_U64(text, want) expect_u64_at(__LINE__, (text), (want))
static void expect_u64_at(UNITY_LINE_TYPE line, const char *text, uint64_t want)
{
    uint64_t v = 777;
    char *copy = exact_copy(text);
    daran_result_t rc = daran_parse_u64(copy, strlen(text), &v);
    free(copy);
    UNITY_TEST_ASSERT_EQUAL_INT(DARAN_OK, rc, line, text);
    UNITY_TEST_ASSERT_EQUAL_UINT64(want, v, line, text);
}

#define EXPECT_U64_ERROR(text, want) expect_u64_error_at(__LINE__, (text), (want))
static void expect_u64_error_at(UNITY_LINE_TYPE line, const char *text, daran_result_t want)
{
    uint64_t v = 777;
    char *copy = exact_copy(text);
    daran_result_t rc = daran_parse_u64(copy, strlen(text), &v);
    free(copy);
    UNITY_TEST_ASSERT_EQUAL_INT(want, rc, line, text);
    UNITY_TEST_ASSERT_EQUAL_UINT64(777, v, line, text);
}

/* Prints value, expects exactly the text, and nothing written past DARAN_F32_TEXT_MAX. */
#define EXPECT_TEXT(value, want) expect_text_at(__LINE__, (value), (want))
static void expect_text_at(UNITY_LINE_TYPE line, float value, const char *want)
{
    char buf[DARAN_F32_TEXT_MAX + 8];
    size_t n;
    memset(buf, 'x', sizeof buf);
    n = daran_format_float(value, buf, DARAN_F32_TEXT_MAX);
    UNITY_TEST_ASSERT_SMALLER_OR_EQUAL_UINT(DARAN_F32_TEXT_MAX, n, line, want);
    UNITY_TEST_ASSERT_EQUAL_INT('x', buf[DARAN_F32_TEXT_MAX], line, "written past the limit");
    buf[n] = '\0';
    UNITY_TEST_ASSERT_EQUAL_STRING(want, buf, line, NULL);
}

#define EXPECT_U64_TEXT(value, want) expect_u64_text_at(__LINE__, (value), (want))
static void expect_u64_text_at(UNITY_LINE_TYPE line, uint64_t value, const char *want)
{
    char buf[DARAN_U64_TEXT_MAX + 1];
    size_t n = daran_format_uint(value, buf, DARAN_U64_TEXT_MAX);
    UNITY_TEST_ASSERT_SMALLER_OR_EQUAL_UINT(DARAN_U64_TEXT_MAX, n, line, want);
    buf[n] = '\0';
    UNITY_TEST_ASSERT_EQUAL_STRING(want, buf, line, NULL);
}

/* ---- grammar ---- */

static void test_plain_integers_and_signs_are_accepted(void)
{
    EXPECT_F32("5", daran_bits_of(5.0f));
    EXPECT_F32("+5", daran_bits_of(5.0f));
    EXPECT_F32("-5", daran_bits_of(-5.0f));
    EXPECT_F32("000012", daran_bits_of(12.0f));
}

static void test_point_forms_are_accepted(void)
{
    EXPECT_F32("5.", daran_bits_of(5.0f));
    EXPECT_F32(".5", daran_bits_of(0.5f));
    EXPECT_F32("-.5", daran_bits_of(-0.5f));
    EXPECT_F32("5.25", daran_bits_of(5.25f));
    EXPECT_F32("12.500000", daran_bits_of(12.5f));
}

static void test_exponent_forms_are_accepted(void)
{
    EXPECT_F32("5e3", daran_bits_of(5000.0f));
    EXPECT_F32("5E3", daran_bits_of(5000.0f));
    EXPECT_F32("5e+3", daran_bits_of(5000.0f));
    EXPECT_F32("5e-3", daran_bits_of(0.005f));
    EXPECT_F32(".5e1", daran_bits_of(5.0f));
    EXPECT_F32("5.e1", daran_bits_of(50.0f));
    EXPECT_F32("1e0000000000000000000000000000001", daran_bits_of(10.0f));
}

static void test_empty_and_lone_signs_are_invalid(void)
{
    EXPECT_F32_ERROR("", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("+", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("-", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR(".", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("-.", DARAN_ERR_INVALID_VALUE);
}

static void test_missing_text_or_result_is_a_bad_argument(void)
{
    float f = 7.0f;
    uint64_t u = 7u;
    /* no text and no length is the empty field; no text with a length is a caller's bug */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_parse_f32(NULL, 0, &f));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_parse_u64(NULL, 0, &u));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_parse_f32(NULL, 3, &f));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_parse_u64(NULL, 3, &u));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_parse_f32("1", 1, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_parse_u64("1", 1, NULL));
    TEST_ASSERT_EQUAL_UINT32(daran_bits_of(7.0f), daran_bits_of(f)); /* refused: untouched */
    TEST_ASSERT_EQUAL_UINT64(7u, u);
}

static void test_broken_exponents_are_invalid(void)
{
    EXPECT_F32_ERROR("e5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5e", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5e+", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5e-", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("1e5.5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR(".e1", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5ee1", DARAN_ERR_INVALID_VALUE);
}

static void test_words_and_hex_are_invalid(void)
{
    EXPECT_F32_ERROR("nan", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("inf", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("-inf", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("infinity", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("0x10", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("0x1p3", DARAN_ERR_INVALID_VALUE);
}

static void test_stray_characters_are_invalid(void)
{
    EXPECT_F32_ERROR("5 ", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR(" 5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5..1", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5.5.5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("++5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("+-5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("1,5", DARAN_ERR_INVALID_VALUE);
    EXPECT_F32_ERROR("5f", DARAN_ERR_INVALID_VALUE);
}

static void test_length_bounds_the_text_not_a_nul(void)
{
    float f = 0.0f;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_f32("12345", 2, &f));
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(12.0f), daran_bits_of(f));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_f32("1.5x", 3, &f));
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(1.5f), daran_bits_of(f));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_parse_f32("5", 0, &f));
}

/* ---- correct rounding ---- */

static void test_common_values_take_the_exact_float(void)
{
    EXPECT_F32("100.5", daran_bits_of(100.5f));
    EXPECT_F32("-0.02", daran_bits_of(-0.02f));
    EXPECT_F32("12", daran_bits_of(12.0f));
    EXPECT_F32("0.1", 0x3DCCCCCDu);
    EXPECT_F32("1.4142135623730951", daran_bits_of(1.41421356f));
    EXPECT_F32("90.000000", daran_bits_of(90.0f));
    EXPECT_F32("-359.9999", daran_bits_of(-359.9999f));
}

static void test_integer_halfway_rounds_to_even(void)
{
    EXPECT_F32("16777217", 0x4B800000u);  /* between 2^24 and 2^24+2: even is 2^24 */
    EXPECT_F32("16777219", 0x4B800002u);  /* between +2 (odd) and +4: up */
    EXPECT_F32("8388608.5", 0x4B000000u); /* ulp 1 at 2^23 */
    EXPECT_F32("8388609.5", 0x4B000002u);
}

static void test_fraction_halfway_rounds_to_even(void)
{
    EXPECT_F32("1.000000059604644775390625", 0x3F800000u);          /* 1 + 2^-24 */
    EXPECT_F32("1.000000178813934326171875", 0x3F800002u);          /* 1 + 3 * 2^-24 */
    EXPECT_F32("0.5000000298023223876953125", 0x3F000000u);         /* 0.5 + 2^-25 */
}

static void test_a_tail_just_above_halfway_rounds_up(void)
{
    EXPECT_F32("1.0000000596046447753906250000000000000000000000000001", 0x3F800001u);
    EXPECT_F32("16777217.00000000000000000000000000000000000000000000001", 0x4B800001u);
    EXPECT_F32("1.000000059604644775390625e0000000000000000000000000001", 0x41200001u); /* 10.0000006: 0.625 ulp up */
}

static void test_a_tail_just_below_halfway_rounds_down(void)
{
    EXPECT_F32("1.0000000596046447753906249999999999999999999999999999", 0x3F800000u);
    EXPECT_F32("1.0000001788139343261718749999999999999999999999", 0x3F800001u);
    EXPECT_F32("16777218.9999999999999999999999999999999999999999999", 0x4B800001u);
}

static void test_long_digit_strings_use_every_digit(void)
{
    /* 120+ digits, the deciding one far beyond 19 */
    EXPECT_F32("1.00000005960464477539062500000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001",
               0x3F800001u);
    EXPECT_F32("0.00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001e122",
               daran_bits_of(1.0f));
    EXPECT_F32("1000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000e-105",
               daran_bits_of(1.0f));
}

static void test_leading_zeros_do_not_count_as_digits(void)
{
    EXPECT_F32("0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000012.5",
               daran_bits_of(12.5f));
    EXPECT_F32("0.0000000000000000000000000000000000000000000000000001e60", daran_bits_of(1e8f));
}

static void test_subnormals_round_correctly(void)
{
    EXPECT_F32("1e-45", 0x00000001u);
    EXPECT_F32("1.401298464324817070923729583289916131280e-45", 0x00000001u);
    EXPECT_F32("2.8e-45", 0x00000002u);
    EXPECT_F32("1.1754942106924411e-38", 0x007FFFFFu); /* largest subnormal */
    EXPECT_F32("1.17549435e-38", 0x00800000u);          /* FLT_MIN */
    EXPECT_F32("-1e-45", 0x80000001u);
}

static void test_half_the_smallest_subnormal_is_a_tie_to_zero(void)
{
    EXPECT_F32("7.00649232162408535461864791644958065640130970938257885878534141944895541342930300743319094181060791015625e-46",
               0x00000000u);
    EXPECT_F32("7.00649232162408535461864791644958065640130970938257885878534141944895541342930300743319094181060791015626e-46",
               0x00000001u);
    EXPECT_F32("2.1019476964872256063855943749348741969203929128147736576356024258346866240287909022299572825431823730468750e-45",
               0x00000002u); /* 3 * 2^-150: tie between 1 (odd) and 2 */
}

static void test_underflow_gives_signed_zero(void)
{
    EXPECT_F32("1e-46", 0x00000000u);
    EXPECT_F32("-1e-50", 0x80000000u);
    EXPECT_F32("1e-999999999", 0x00000000u);
    EXPECT_F32("-9.99e-999999999999999999999", 0x80000000u);
}

static void test_zero_in_all_its_forms(void)
{
    EXPECT_F32("0", 0x00000000u);
    EXPECT_F32("-0", 0x80000000u);
    EXPECT_F32("-0.0", 0x80000000u);
    EXPECT_F32("0e99999", 0x00000000u);
    EXPECT_F32("0.000e999999999999999999", 0x00000000u);
    EXPECT_F32("+.0e-5", 0x00000000u);
}

static void test_flt_max_and_what_rounds_to_it_are_in_range(void)
{
    EXPECT_F32("3.4028235e38", 0x7F7FFFFFu);
    EXPECT_F32("340282346638528859811704183484516925440", 0x7F7FFFFFu);
    EXPECT_F32("3.40282356779733661637539395458142568447e38", 0x7F7FFFFFu);
    EXPECT_F32("-3.4028235677973366e38", 0xFF7FFFFFu);
}

static void test_halfway_to_2_pow_128_is_out_of_range(void)
{
    EXPECT_F32_ERROR("3.40282356779733661637539395458142568448e38", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32_ERROR("-3.40282356779733661637539395458142568448e38", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32_ERROR("3.5e38", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32_ERROR("1e39", DARAN_ERR_OUT_OF_RANGE);
}

static void test_huge_exponents_saturate(void)
{
    EXPECT_F32_ERROR("1e999999999", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32_ERROR("1e2147483648", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32_ERROR("1e99999999999999999999999999999999", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32("1e-2147483649", 0x00000000u);
    EXPECT_F32_ERROR("0.0000000000000000000000000000000000000000000001e999999999", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_F32("100000000000000000000000000000000000000000000000000e-999999999", 0x00000000u);
}

static void test_a_million_zeros_are_only_zeros(void)
{
    static char text[1000016];
    float f = 0.0f;
    uint64_t v = 0;
    size_t n;
    memset(text, '0', 1000000);
    memcpy(text + 1000000, "1.5", 3);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_f32(text, 1000003, &f));
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(1.5f), daran_bits_of(f));
    text[0] = '.';
    memcpy(text + 1000000, "15e1000000", 10);
    n = 1000010;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_f32(text, n, &f));
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(1.5f), daran_bits_of(f));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, daran_parse_u64(text, n, &v)); /* 1.5 */
    memcpy(text + 1000000, "15e1000001", 10);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_u64(text, n, &v));
    TEST_ASSERT_EQUAL_UINT64(15u, v);
}

/* ---- integers ---- */

static void test_integer_spellings_of_five(void)
{
    EXPECT_U64("5", 5);
    EXPECT_U64("+5", 5);
    EXPECT_U64("5.0", 5);
    EXPECT_U64("5.", 5);
    EXPECT_U64("05", 5);
    EXPECT_U64("5e0", 5);
    EXPECT_U64("50e-1", 5);
    EXPECT_U64("0.5e1", 5);
    EXPECT_U64("5.000000", 5);
}

static void test_negative_zero_is_zero(void)
{
    EXPECT_U64("-0", 0);
    EXPECT_U64("-0.0", 0);
    EXPECT_U64("0e999999999", 0);
    EXPECT_U64("-0e-5", 0);
}

static void test_negative_integers_are_out_of_range(void)
{
    EXPECT_U64_ERROR("-1", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("-1e30", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("-10e-1", DARAN_ERR_OUT_OF_RANGE);
}

static void test_fractions_are_invalid_values(void)
{
    EXPECT_U64_ERROR("5.5", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("-5.5", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("1e-1", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("1e-999999999", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("18446744073709551615.5", DARAN_ERR_INVALID_VALUE);
}

static void test_uint64_max_is_the_limit(void)
{
    EXPECT_U64("18446744073709551615", UINT64_MAX);
    EXPECT_U64("1.8446744073709551615e19", UINT64_MAX);
    EXPECT_U64("0000018446744073709551615.000", UINT64_MAX);
    EXPECT_U64_ERROR("18446744073709551616", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("1.8446744073709551616e19", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("99999999999999999999", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("1e20", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64_ERROR("1e999999999", DARAN_ERR_OUT_OF_RANGE);
    EXPECT_U64("1e19", UINT64_C(10000000000000000000));
}

static void test_integer_grammar_matches_the_float_grammar(void)
{
    EXPECT_U64_ERROR("", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("x", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("5x", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("0x5", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("5e", DARAN_ERR_INVALID_VALUE);
    EXPECT_U64_ERROR("nan", DARAN_ERR_INVALID_VALUE);
}

/* ---- printing ---- */

static void test_spec_examples_print_positionally(void)
{
    EXPECT_TEXT(100.5f, "100.5");
    EXPECT_TEXT(160.0f, "160");
    EXPECT_TEXT(-3.0f, "-3");
    EXPECT_TEXT(0.02f, "0.02");
    EXPECT_TEXT(1e-5f, "0.00001");
}

static void test_spec_examples_print_scientifically(void)
{
    EXPECT_TEXT(1e9f, "1.0e+09");
    EXPECT_TEXT(1.5e-7f, "1.5e-07");
    EXPECT_TEXT(3e12f, "3.0e+12");
}

static void test_positional_range_ends_at_exponents_minus_5_and_8(void)
{
    EXPECT_TEXT(1e8f, "100000000");
    EXPECT_TEXT(999999936.0f, "999999940");
    EXPECT_TEXT(1e-6f, "1.0e-06");
    EXPECT_TEXT(9.99e-5f, "0.0000999");
    EXPECT_TEXT(9.99e-6f, "9.99e-06");
    EXPECT_TEXT(1.25e-6f, "1.25e-06");
}

static void test_the_shortest_text_that_round_trips_is_chosen(void)
{
    EXPECT_TEXT(123456789.0f, "123456790"); /* the float is 123456792 */
    EXPECT_TEXT(0.1f, "0.1");
    EXPECT_TEXT(1.0f / 3.0f, "0.33333334");
    EXPECT_TEXT(16777216.0f, "16777216");
    EXPECT_TEXT(daran_float_of(0x3F800001u), "1.0000001");
}

/* 0.00146484375 is exactly halfway between the 8-digit texts ...437 and
 * ...438: the tie goes to the even last digit (docs/numbers.md). */
static void test_a_tie_between_two_shortest_texts_goes_to_the_even_digit(void)
{
    EXPECT_TEXT(daran_float_of(0x3AC00000u), "0.0014648438");
    EXPECT_TEXT(daran_float_of(0x3B600000u), "0.0034179688");
    EXPECT_TEXT(daran_float_of(0x3C980000u), "0.018554688");
}

static void test_extremes_print(void)
{
    EXPECT_TEXT(daran_float_of(0x7F7FFFFFu), "3.4028235e+38");
    EXPECT_TEXT(daran_float_of(0x00000001u), "1.0e-45");
    EXPECT_TEXT(daran_float_of(0x00800000u), "1.1754944e-38");
    EXPECT_TEXT(daran_float_of(0x007FFFFFu), "1.1754942e-38");
    EXPECT_TEXT(daran_float_of(0x80000001u), "-1.0e-45");
}

static void test_powers_of_two_use_the_narrow_gap_below(void)
{
    EXPECT_TEXT(daran_float_of(0x4C800000u), "67108864");  /* 2^26 */
    EXPECT_TEXT(daran_float_of(0x5F000000u), "9.223372e+18"); /* 2^63 */
    EXPECT_TEXT(daran_float_of(0x3A800000u), "0.0009765625");
}

static void test_zero_nan_and_infinity_print_as_words(void)
{
    EXPECT_TEXT(0.0f, "0");
    EXPECT_TEXT(-0.0f, "-0");
    EXPECT_TEXT(daran_float_of(0x7FC00000u), "nan");
    EXPECT_TEXT(daran_float_of(0xFFC00000u), "nan");
    EXPECT_TEXT(daran_float_of(0x7F800001u), "nan");
    EXPECT_TEXT(daran_float_of(0x7F800000u), "inf");
    EXPECT_TEXT(daran_float_of(0xFF800000u), "-inf");
}

static void test_longest_text_fits_the_buffer(void)
{
    char buf[DARAN_F32_TEXT_MAX];
    uint32_t b;
    size_t longest = 0;
    for (b = 0; b < 0xFF800000u; b += 0x00012345u) {
        size_t n = daran_format_float(daran_float_of(b), buf, sizeof buf);
        longest = n > longest ? n : longest;
    }
    TEST_ASSERT_LESS_OR_EQUAL_UINT(DARAN_F32_TEXT_MAX, longest);
    EXPECT_TEXT(daran_float_of(0xB74F0000u), "-0.0000123381615"); /* 16 characters */
}

static void test_printed_text_parses_back_to_the_same_bits(void)
{
    char buf[DARAN_F32_TEXT_MAX];
    uint32_t b, seed = 1;
    int i;
    for (i = 0; i < 100000; i++) {
        float f;
        size_t n;
        seed = seed * 1664525u + 1013904223u;
        b = seed;
        if ((b & 0x7F800000u) == 0x7F800000u) {
            continue;
        }
        n = daran_format_float(daran_float_of(b), buf, sizeof buf);
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_f32(buf, n, &f));
        TEST_ASSERT_EQUAL_HEX32(b, daran_bits_of(f));
    }
}

/* ---- integer printing ---- */

static void test_u64_prints_in_decimal(void)
{
    EXPECT_U64_TEXT(0, "0");
    EXPECT_U64_TEXT(9, "9");
    EXPECT_U64_TEXT(10, "10");
    EXPECT_U64_TEXT(4294967295u, "4294967295");
    EXPECT_U64_TEXT(UINT64_C(4294967296), "4294967296");
    EXPECT_U64_TEXT(UINT64_C(9999999999999999999), "9999999999999999999");
    EXPECT_U64_TEXT(UINT64_C(10000000000000000000), "10000000000000000000");
    EXPECT_U64_TEXT(UINT64_MAX, "18446744073709551615");
}

static void test_u64_printing_agrees_with_snprintf(void)
{
    char ours[DARAN_U64_TEXT_MAX + 1], ref[32];
    uint64_t x = 88172645463325252u;
    int i;
    for (i = 0; i < 200000; i++) {
        uint64_t v;
        size_t n;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        v = x >> (i % 64); /* every magnitude */
        n = daran_format_uint(v, ours, DARAN_U64_TEXT_MAX);
        ours[n] = '\0';
        snprintf(ref, sizeof ref, "%llu", (unsigned long long)v);
        TEST_ASSERT_EQUAL_STRING(ref, ours);
    }
}

static void test_u64_text_parses_back(void)
{
    char buf[DARAN_U64_TEXT_MAX];
    uint64_t v = 1, back = 0;
    int i;
    for (i = 0; i < 64; i++, v = v * 3u + 1u) {
        size_t n = daran_format_uint(v, buf, sizeof buf);
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_parse_u64(buf, n, &back));
        TEST_ASSERT_EQUAL_UINT64(v, back);
    }
}

/* ---- the size rule: the whole text when it fits in size, else nothing and 0 ---- */

/* The printer under test: both have the same shape but for the value's type. */
typedef size_t (*printer_t)(const void *value, char *buf, size_t size);

static size_t print_float(const void *value, char *buf, size_t size)
{
    return daran_format_float(*(const float *)value, buf, size);
}

static size_t print_uint(const void *value, char *buf, size_t size)
{
    return daran_format_uint(*(const uint64_t *)value, buf, size);
}

/* Is buf[0..len) still all 'x'? */
static int untouched(const char *buf, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++) {
        if (buf[i] != 'x') {
            return 0;
        }
    }
    return 1;
}

/* Every size from 0 to 8 past the text: below its length, 0 and the buffer
 * untouched; from its length on, the text and not a byte past it. */
#define EXPECT_SIZE_RULE(print, value, want) expect_size_rule_at(__LINE__, (print), (value), (want))
static void expect_size_rule_at(UNITY_LINE_TYPE line, printer_t print, const void *value,
                                const char *want)
{
    char buf[DARAN_U64_TEXT_MAX + 8];
    size_t len = strlen(want), size;
    for (size = 0; size <= len + 8u; size++) {
        size_t n;
        memset(buf, 'x', sizeof buf);
        n = print(value, buf, size);
        if (size < len) {
            UNITY_TEST_ASSERT_EQUAL_UINT(0, n, line, want);
            UNITY_TEST_ASSERT(untouched(buf, sizeof buf), line, "written into too small a buffer");
        } else {
            UNITY_TEST_ASSERT_EQUAL_UINT(len, n, line, want);
            UNITY_TEST_ASSERT_EQUAL_MEMORY(want, buf, len, line, want);
            UNITY_TEST_ASSERT(untouched(buf + len, sizeof buf - len), line, "written past the text");
        }
    }
}

static void test_float_text_exactly_fits_its_length_and_not_one_byte_less(void)
{
    static const struct {
        uint32_t bits;
        const char *text;
    } cases[] = {
        {0x00000000u, "0"},          {0x80000000u, "-0"},      {0x7FC00000u, "nan"},
        {0x7F800000u, "inf"},        {0xFF800000u, "-inf"},    {0x3FC00000u, "1.5"},
        {0x41200000u, "10"},         {0xBF800000u, "-1"},      {0x4CBEBC20u, "100000000"},
        {0x501502F9u, "1.0e+10"},    {0x3727C5ACu, "0.00001"}, {0x358637BDu, "1.0e-06"}, {0x7F7FFFFFu, "3.4028235e+38"},
        {0x00000001u, "1.0e-45"},    {0xB74F0000u, "-0.0000123381615"}, /* 16: the longest */
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        float value = daran_float_of(cases[i].bits);
        EXPECT_TEXT(value, cases[i].text); /* the table is right */
        EXPECT_SIZE_RULE(print_float, &value, cases[i].text);
    }
}

static void test_uint_text_exactly_fits_its_length_and_not_one_byte_less(void)
{
    static const struct {
        uint64_t value;
        const char *text;
    } cases[] = {
        {0u, "0"},
        {7u, "7"},
        {255u, "255"}, /* the checksum: 3 bytes are enough */
        {4294967296u, "4294967296"},
        {UINT64_MAX, "18446744073709551615"}, /* 20: the longest */
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        EXPECT_SIZE_RULE(print_uint, &cases[i].value, cases[i].text);
    }
}

static void test_size_0_writes_nothing(void)
{
    char buf[4];
    float f = 1.0f;
    memset(buf, 'x', sizeof buf);
    TEST_ASSERT_EQUAL_UINT(0, daran_format_float(f, buf, 0));
    TEST_ASSERT_EQUAL_UINT(0, daran_format_float(-0.0f, buf, 0));
    TEST_ASSERT_EQUAL_UINT(0, daran_format_float(daran_float_of(0x7FC00000u), buf, 0));
    TEST_ASSERT_EQUAL_UINT(0, daran_format_uint(0u, buf, 0));
    TEST_ASSERT_EQUAL_UINT(0, daran_format_uint(UINT64_MAX, buf, 0));
    TEST_ASSERT_TRUE(untouched(buf, sizeof buf));
}

/* Over many values, every size: the length is the same whatever the room,
 * and a short buffer is never written. */
static void test_every_size_below_the_text_writes_nothing(void)
{
    uint32_t seed = 7;
    int i;
    for (i = 0; i < 2000; i++) {
        char full[DARAN_U64_TEXT_MAX], want[DARAN_U64_TEXT_MAX + 1];
        uint64_t u;
        float f;
        size_t n;
        seed = seed * 1664525u + 1013904223u;
        f = daran_float_of(seed);
        n = daran_format_float(f, full, sizeof full);
        memcpy(want, full, n);
        want[n] = '\0';
        EXPECT_SIZE_RULE(print_float, &f, want);
        u = ((uint64_t)seed << 32 | (seed ^ 0x9E3779B9u)) >> (i % 64);
        n = daran_format_uint(u, full, sizeof full);
        memcpy(want, full, n);
        want[n] = '\0';
        EXPECT_SIZE_RULE(print_uint, &u, want);
    }
}

/* A halfway case longer than the exact comparison takes (DARAN_BIG_DIGITS,
 * 120 digits): a nonzero digit past the 120th breaks the tie upwards, all
 * zeros past it leave it to round-half-even. 16777217 is halfway between the
 * floats 16777216 (0x4B800000) and 16777218 (0x4B800001). */
static void test_digits_past_the_exact_window_break_a_tie(void)
{
    char text[160];
    memset(text, '0', sizeof text);
    memcpy(text, "16777217", 8);
    text[120] = '1'; /* the 121st significant digit */
    text[121] = '\0';
    /* 16777217 followed by 112 zeros and a 1: an integer 10^113 times the
     * halfway value and a hair: above it, so it rounds up */
    char scaled[200];
    snprintf(scaled, sizeof scaled, "%.8s.%se-0", text, text + 8);
    EXPECT_F32(scaled, 0x4B800001u);
    text[120] = '0';
    snprintf(scaled, sizeof scaled, "%.8s.%s", text, text + 8);
    EXPECT_F32(scaled, 0x4B800000u); /* exactly halfway: to even */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_plain_integers_and_signs_are_accepted);
    RUN_TEST(test_point_forms_are_accepted);
    RUN_TEST(test_exponent_forms_are_accepted);
    RUN_TEST(test_empty_and_lone_signs_are_invalid);
    RUN_TEST(test_missing_text_or_result_is_a_bad_argument);
    RUN_TEST(test_broken_exponents_are_invalid);
    RUN_TEST(test_words_and_hex_are_invalid);
    RUN_TEST(test_stray_characters_are_invalid);
    RUN_TEST(test_length_bounds_the_text_not_a_nul);
    RUN_TEST(test_common_values_take_the_exact_float);
    RUN_TEST(test_integer_halfway_rounds_to_even);
    RUN_TEST(test_fraction_halfway_rounds_to_even);
    RUN_TEST(test_a_tail_just_above_halfway_rounds_up);
    RUN_TEST(test_a_tail_just_below_halfway_rounds_down);
    RUN_TEST(test_long_digit_strings_use_every_digit);
    RUN_TEST(test_leading_zeros_do_not_count_as_digits);
    RUN_TEST(test_subnormals_round_correctly);
    RUN_TEST(test_half_the_smallest_subnormal_is_a_tie_to_zero);
    RUN_TEST(test_underflow_gives_signed_zero);
    RUN_TEST(test_zero_in_all_its_forms);
    RUN_TEST(test_flt_max_and_what_rounds_to_it_are_in_range);
    RUN_TEST(test_halfway_to_2_pow_128_is_out_of_range);
    RUN_TEST(test_huge_exponents_saturate);
    RUN_TEST(test_a_million_zeros_are_only_zeros);
    RUN_TEST(test_integer_spellings_of_five);
    RUN_TEST(test_negative_zero_is_zero);
    RUN_TEST(test_negative_integers_are_out_of_range);
    RUN_TEST(test_fractions_are_invalid_values);
    RUN_TEST(test_uint64_max_is_the_limit);
    RUN_TEST(test_integer_grammar_matches_the_float_grammar);
    RUN_TEST(test_spec_examples_print_positionally);
    RUN_TEST(test_spec_examples_print_scientifically);
    RUN_TEST(test_positional_range_ends_at_exponents_minus_5_and_8);
    RUN_TEST(test_the_shortest_text_that_round_trips_is_chosen);
    RUN_TEST(test_a_tie_between_two_shortest_texts_goes_to_the_even_digit);
    RUN_TEST(test_extremes_print);
    RUN_TEST(test_powers_of_two_use_the_narrow_gap_below);
    RUN_TEST(test_zero_nan_and_infinity_print_as_words);
    RUN_TEST(test_longest_text_fits_the_buffer);
    RUN_TEST(test_printed_text_parses_back_to_the_same_bits);
    RUN_TEST(test_u64_prints_in_decimal);
    RUN_TEST(test_u64_printing_agrees_with_snprintf);
    RUN_TEST(test_u64_text_parses_back);
    RUN_TEST(test_float_text_exactly_fits_its_length_and_not_one_byte_less);
    RUN_TEST(test_uint_text_exactly_fits_its_length_and_not_one_byte_less);
    RUN_TEST(test_size_0_writes_nothing);
    RUN_TEST(test_every_size_below_the_text_writes_nothing);
    RUN_TEST(test_digits_past_the_exact_window_break_a_tie);
    return UNITY_END();
}
