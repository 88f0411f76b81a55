/* Text <-> numbers for the protocol: float32 and unsigned integers.
 * Pure functions: no state, no libc, no heap, bounded stack. */
#ifndef DARAN_NUMBER_H
#define DARAN_NUMBER_H

#include <stddef.h>
#include <stdint.h>

#include "daran_result.h"

/* Longest text daran_format_f32() writes ("-0.0000123456789" is 16). */
#define DARAN_F32_TEXT_MAX 16
/* Longest text daran_format_u64() writes (18446744073709551615). */
#define DARAN_U64_TEXT_MAX 20

/* Parse text[0..len) as a float32, correctly rounded (round to nearest, ties
 * to even), grammar [+-]?(digits[.digits*]|.digits)([eE][+-]?digits)?, the
 * whole text and nothing else.
 * DARAN_OK: *out set. DARAN_ERR_INVALID_VALUE: not in the grammar (empty,
 * nan, inf, hex, stray characters). DARAN_ERR_OUT_OF_RANGE: the value rounds
 * beyond FLT_MAX. *out is untouched on error. */
daran_result_t daran_parse_f32(const char *text, size_t len, float *out);

/* Parse text[0..len) (same grammar) as an exact non-negative integer: "5",
 * "+5", "5.0", "5e0", "50e-1" and "-0" all give 5 or 0.
 * DARAN_OK: *out set. DARAN_ERR_INVALID_VALUE: not in the grammar, or not an
 * integer ("5.5"). DARAN_ERR_OUT_OF_RANGE: an integer below 0 or above
 * UINT64_MAX. *out is untouched on error. */
daran_result_t daran_parse_u64(const char *text, size_t len, uint64_t *out);

/* The public names of the two printers (daran_port.h): one function each. */
#define daran_format_f32 daran_format_float
#define daran_format_u64 daran_format_uint

/* Write the shortest decimal that parses back to the same float32 into
 * buf[0..DARAN_F32_TEXT_MAX): positional when its decimal exponent k (value =
 * d.ddd x 10^k) is within -5..8, else scientific "d.ddde+XX" with at least
 * one digit after the point and a signed exponent of two or more digits;
 * "0"/"-0", "nan", "inf", "-inf". No NUL. Returns the length. */
size_t daran_format_f32(float value, char *buf);

/* Write value in decimal into buf[0..DARAN_U64_TEXT_MAX). No NUL. Returns the
 * length. */
size_t daran_format_u64(uint64_t value, char *buf);

/* The leading 64 bits of 10^q, truncated, for q = -64..45: the scale the
 * parser and the printer multiply by. Internal; exposed for its test. */
uint64_t daran_pow10_hi(int32_t q);

#endif /* DARAN_NUMBER_H */
