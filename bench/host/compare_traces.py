#!/usr/bin/env python3
"""Check that daran-ascii and the baseline yardstick did the same thing on a
stream: the same HAL set/move/action calls (floats within a relative 1e-6),
the same error replies, and the same values in query replies (the baseline
prints "%f", six decimals, so values are compared within 1e-6 absolute plus
the float's own rounding).

    compare_traces.py BENCH_DRIVER STREAM...   exit 0 when every stream agrees
"""
import subprocess
import sys


def trace(driver, mode, stream):
    out = subprocess.run([driver, mode, "--trace", stream], check=True,
                         stdout=subprocess.PIPE).stdout.decode("ascii")
    return out.splitlines()


def close(a, b, rel, absolute):
    if a == b:
        return True  # also "nan": an integer's bits seen as a float
    try:
        x, y = float(a), float(b)
    except ValueError:
        return a == b
    return abs(x - y) <= absolute + rel * max(abs(x), abs(y))


def same(ours, base):
    a, b = ours.split(" "), base.split(" ")
    if a[:2] != b[:2] or len(a) != len(b):
        return False
    kind = a[1]
    if kind in ("set", "move", "action"):
        return all(close(x, y, 1e-6, 0.0) for x, y in zip(a[2:], b[2:]))
    # replies: error phrases and checksums exact ... except the checksum of a
    # value reply, which differs with the number's spelling.
    if a[2:3] == ["error:"]:
        return a == b
    nums_a = [t for t in a[2:] if not t.startswith("*")]
    nums_b = [t for t in b[2:] if not t.startswith("*")]
    return len(nums_a) == len(nums_b) and all(close(x, y, 1e-6, 1e-6)
                                              for x, y in zip(nums_a, nums_b))


def main():
    driver, streams = sys.argv[1], sys.argv[2:]
    bad = 0
    for stream in streams:
        ours, base = trace(driver, "ours", stream), trace(driver, "baseline", stream)
        mismatches = 0
        if len(ours) != len(base):
            print("%s: %d events from daran-ascii, %d from the baseline" %
                  (stream, len(ours), len(base)))
        for x, y in zip(ours, base):
            if not same(x, y):
                if mismatches < 10:
                    print("%s:\n  ours:     %s\n  baseline: %s" % (stream, x, y))
                mismatches += 1
        calls = sum(1 for x in ours if x.split(" ")[1] in ("set", "move", "action"))
        replies = len(ours) - calls
        status = "same" if mismatches == 0 and len(ours) == len(base) else "DIFFERENT"
        print("%-40s %s: %d HAL calls, %d replies, %d mismatches" %
              (stream, status, calls, replies, mismatches))
        bad += status != "same"
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
