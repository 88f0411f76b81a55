/* Text <-> numbers for the protocol: float32 and unsigned integers.
 * Pure functions: no state, no libc, no heap, bounded stack. */
#ifndef DARAN_NUMBER_H
#define DARAN_NUMBER_H

#include <stddef.h>
#include <stdint.h>

#include "daran_result.h"

/* Longest text daran_format_float() writes ("-0.0000123456789" is 16);
 * DARAN_FLOAT_TEXT_MAX in daran_port.h. */
#define DARAN_F32_TEXT_MAX 16
/* Longest text daran_format_uint() writes (18446744073709551615);
 * DARAN_UINT_TEXT_MAX in daran_port.h. */
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

/* The two printers, public in daran_port.h (same declarations). Each writes
 * its text into buf[0..size) only when the whole text fits (no NUL) and
 * returns its length; when it does not fit it writes nothing and returns 0
 * (never a cut number). A size of DARAN_F32_TEXT_MAX / DARAN_U64_TEXT_MAX
 * always fits; a smaller one fits whenever the text does. */

/* The shortest decimal that parses back to the same float32: positional when
 * its decimal exponent k (value = d.ddd x 10^k) is within -5..8, else
 * scientific "d.ddde+XX" with at least one digit after the point and a signed
 * exponent of two or more digits; "0"/"-0", "nan", "inf", "-inf". */
size_t daran_format_float(float value, char *buf, size_t size);

/* value in decimal, no leading zeros ("0" for 0). */
size_t daran_format_uint(uint64_t value, char *buf, size_t size);

/* The leading 64 bits of 10^q, truncated, for q = -64..45: the scale the
 * parser and the printer multiply by. Internal; exposed for its test. */
uint64_t daran_pow10_hi(int32_t q);

#endif /* DARAN_NUMBER_H */
