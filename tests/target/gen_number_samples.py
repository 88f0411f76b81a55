#!/usr/bin/env python3
"""Write number_samples.h for the on-target self-test: decimal texts with the
float32 a correct strtof gives (round to nearest, ties to even), and float32
bit patterns with their shortest round-trip text in the protocol's format.

The expected values come from exact rational arithmetic (fractions), not from
the host's C library, so the test is an independent oracle for the core's
number code. The sample is pseudo-random with a fixed seed, plus hand-picked
edges; the output is the same on every run.

Usage: gen_number_samples.py OUTPUT.h [COUNT]
"""
import math
import random
import sys
from fractions import Fraction

OK, OUT_OF_RANGE = 0, 1


def round_to_f32(value):
    """Exact rational -> (bits without sign, overflowed)."""
    if value == 0:
        return 0, False
    exp = value.numerator.bit_length() - value.denominator.bit_length()
    if Fraction(2) ** exp > value:
        exp -= 1
    while Fraction(2) ** (exp + 1) <= value:
        exp += 1
    exp = max(exp, -126)
    scaled = value / Fraction(2) ** (exp - 23)
    mant = math.floor(scaled)
    rem = scaled - mant
    if rem > Fraction(1, 2) or (rem == Fraction(1, 2) and mant % 2 == 1):
        mant += 1
    if mant == 1 << 24:
        mant >>= 1
        exp += 1
    if exp > 127:
        return 0x7F800000, True
    if mant < (1 << 23):
        return mant, False
    return ((exp + 127) << 23) | (mant - (1 << 23)), False


def parse_text(text):
    neg = text.startswith("-")
    value = Fraction(text.lstrip("+-"))
    bits, over = round_to_f32(value)
    return (bits | (0x80000000 if neg else 0)), over


def f32_value(bits):
    exp = (bits >> 23) & 0xFF
    mant = bits & 0x7FFFFF
    if exp == 0:
        v = Fraction(mant) * Fraction(2) ** -149
    else:
        v = Fraction(mant | 0x800000) * Fraction(2) ** (exp - 150)
    return -v if bits & 0x80000000 else v


def shortest_digits(v):
    """v > 0 exact value of a float32 -> (digits, k) with v ~ d.ddd x 10^k."""
    target, _ = round_to_f32(v)
    k = len(str(v.numerator)) - len(str(v.denominator))
    while Fraction(10) ** k > v:
        k -= 1
    while Fraction(10) ** (k + 1) <= v:
        k += 1
    for n in range(1, 10):
        scale = Fraction(10) ** (k - n + 1)
        lo = math.floor(v / scale)
        best = None
        for d in (lo, lo + 1):
            if d <= 0:
                continue
            if round_to_f32(d * scale)[0] == target:
                dist = abs(d * scale - v)
                if best is None or dist < best[0] or (dist == best[0] and d % 2 == 0):
                    best = (dist, d)
        if best is not None:
            d = best[1]
            digits = str(d)
            kk = k + len(digits) - n  # d may have gained a digit (999 -> 1000)
            return digits.rstrip("0") or "0", kk
    raise AssertionError("no shortest form")


def format_bits(bits):
    exp = (bits >> 23) & 0xFF
    neg = bits & 0x80000000
    sign = "-" if neg else ""
    if exp == 0xFF:
        if bits & 0x7FFFFF:
            return "nan"
        return sign + "inf"
    v = abs(f32_value(bits))
    if v == 0:
        return sign + "0"
    digits, k = shortest_digits(v)
    if -5 <= k <= 8:
        if k >= 0:
            whole = digits[:k + 1].ljust(k + 1, "0")
            frac = digits[k + 1:]
            return sign + whole + ("." + frac if frac else "")
        return sign + "0." + "0" * (-k - 1) + digits
    mant = digits[0] + "." + (digits[1:] or "0")
    return sign + mant + "e" + ("-" if k < 0 else "+") + "%02d" % abs(k)


PARSE_EDGES = [
    "0", "-0", "1", "+1", "100.5", "0.02", ".5", "5.", "1e-5", "3.4028235e38",
    "3.4028235677973366e38", "3.4028235677973367e38", "3.5e38", "1e39",
    "1e-45", "7e-46", "7.1e-46", "1.17549435e-38", "1.1754942e-38",
    "16777217", "16777217.000000000000000000001", "16777219",
    "0.000000000000000000000000000000000000000000001401298464324817070923729583289916131280",
    "123456789012345678901234567890", "9.999999e-39", "2.5e-07", "-273.15",
    "0.1", "0.3", "3.0e+12", "1.0e+09", "1E2", "4.7e-1", "33554431",
]

FORMAT_EDGES = [
    0x00000000, 0x80000000, 0x7F800000, 0xFF800000, 0x7FC00000, 0x00000001,
    0x007FFFFF, 0x00800000, 0x7F7FFFFF, 0x3F800000, 0xBF800000, 0x42C90000,
    0x3CA3D70A, 0x3727C5AC, 0x43200000, 0xC0400000, 0x3424B4B5, 0x4E6E6B28,
    0x54AE9F7B, 0x4CBEBC20, 0x4CBEBC1F, 0x3DCCCCCD, 0x3E99999A,
]


def random_text(rng):
    ndig = rng.choice([1, 2, 3, 5, 7, 8, 9, 10, 12, 17, 20, 25])
    digits = "".join(rng.choice("0123456789") for _ in range(ndig))
    point = rng.randint(0, ndig)
    text = digits[:point] + ("." if point < ndig or rng.random() < 0.3 else "") + digits[point:]
    if text.startswith("."):
        text = "0" + text if rng.random() < 0.5 else text
    if rng.random() < 0.6:
        text += "e%d" % rng.randint(-50, 40)
    if rng.random() < 0.3:
        text = "-" + text
    return text


def c_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main():
    out = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    rng = random.Random(20261122)
    texts = PARSE_EDGES + [random_text(rng) for _ in range(count)]
    bits_list = FORMAT_EDGES + [rng.getrandbits(32) for _ in range(count)]
    # also bit patterns of ordinary magnitudes, which replies mostly carry
    for _ in range(count // 2):
        e = rng.randint(127 - 20, 127 + 26)
        bits_list.append((rng.getrandbits(1) << 31) | (e << 23) | rng.getrandbits(23))

    lines = [
        "/* Generated by tests/target/gen_number_samples.py: do not edit. */",
        "#ifndef DARAN_TARGET_NUMBER_SAMPLES_H",
        "#define DARAN_TARGET_NUMBER_SAMPLES_H",
        "#include <stdint.h>",
        "",
        "/* text -> float32 bits; out_of_range: the value rounds beyond FLT_MAX */",
        "static const struct { const char *text; uint32_t bits; uint8_t out_of_range; }",
        "number_parse_samples[] = {",
    ]
    for t in texts:
        bits, over = parse_text(t)
        lines.append("    {%s, 0x%08Xu, %d}," % (c_string(t), 0 if over else bits, 1 if over else 0))
    lines += ["};", "", "/* float32 bits -> shortest text in the protocol's format */",
              "static const struct { uint32_t bits; const char *text; }",
              "number_format_samples[] = {"]
    for b in bits_list:
        lines.append("    {0x%08Xu, %s}," % (b, c_string(format_bits(b))))
    lines += ["};", "", "#endif", ""]
    with open(out, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
