#!/usr/bin/env python3
"""Generates the power-of-ten table of src/number.c (exact integer arithmetic).

Entry q (q = -64..45) is floor(10^q * 2^(63 - floor(log2(10^q)))): the 64 leading
bits of 10^q, truncated, with bit 63 set. Parsing uses q = -64..38, printing uses
10^-k for k = -45..31. Also checks the integer log formulas number.c uses.
Run: python3 bench/number/gen_pow10_table.py"""
from fractions import Fraction

LO, HI = -64, 45


def floor_log2(x):
    n = x.numerator.bit_length() - x.denominator.bit_length()
    while Fraction(2) ** n > x:
        n -= 1
    while Fraction(2) ** (n + 1) <= x:
        n += 1
    return n


def entry(q):
    x = Fraction(10) ** q
    scaled = x * Fraction(2) ** (63 - floor_log2(x))
    t = scaled.numerator // scaled.denominator
    assert 2 ** 63 <= t < 2 ** 64 - 1
    return t


def floor_log10(x):
    n = 0
    while Fraction(10) ** (n + 1) <= x:
        n += 1
    while Fraction(10) ** n > x:
        n -= 1
    return n


def check_log_formulas():
    """The integer formulas of src/number.c, against exact values."""
    for x in range(-70, 71):
        assert (x * 1741647) >> 19 == floor_log2(Fraction(10) ** x), x
    for q in range(-149, 105):
        two_q = Fraction(2) ** q
        assert (q * 1262611) >> 22 == floor_log10(two_q), q
        assert (q * 1262611 - 524031) >> 22 == floor_log10(Fraction(3, 4) * two_q), q


def main():
    check_log_formulas()
    vals = [entry(q) for q in range(LO, HI + 1)]
    print("static const uint64_t daran_pow10_hi[%d] = {" % len(vals))
    for i in range(0, len(vals), 3):
        row = ", ".join("UINT64_C(0x%016X)" % v for v in vals[i:i + 3])
        print("    " + row + ",")
    print("};")


if __name__ == "__main__":
    main()
