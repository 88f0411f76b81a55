#!/usr/bin/env python3
"""Check that daran-ascii and a yardstick did the same thing on a stream: the
same HAL set/move/action calls, the same error replies, and the same values
in query replies (the yardsticks print six decimals, "%f" or fixed point, so
reply values are compared within 1e-6 absolute plus 1e-6 relative).

    compare_traces.py [--yardstick baseline|handwritten] BENCH_DRIVER STREAM...

baseline (default): the sscanf/strtof/printf yardstick. strtof rounds
    correctly, as the core does, so HAL floats must agree within 1e-6
    relative (in practice they are identical).
handwritten: the hand-written yardstick, whose float conversion is not
    correctly rounded. A difference counts as rounding only when it is
    proven to be: the driver respells every number the yardstick rounds
    differently as the float the yardstick got (bench_driver respell), and
    the core run on that stream must then make exactly the yardstick's HAL
    calls and replies. Every line where the yardstick's calls differ from
    the core's on the original stream is counted and reported: HAL floats
    that differ (with their distance in float32 ulps) and lines whose
    outcome changed (another error, no move, ...), never hidden.

Exit 0 when every stream agrees (rounding differences allowed for the
hand-written yardstick), 1 otherwise.
"""
import argparse
import os
import struct
import subprocess
import sys
import tempfile


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


def ordered(text):
    """A float32's bits as an integer that grows with the value (so the
    difference of two is their distance in ulps); None if not a number."""
    try:
        bits = struct.unpack("<I", struct.pack("<f", float(text)))[0]
    except (ValueError, OverflowError):
        return None
    return -(bits & 0x7FFFFFFF) if bits & 0x80000000 else bits


def ulps(a, b):
    """Distance of two float32 texts in ulps (0 when equal, -0 == 0)."""
    if a == b:
        return 0
    x, y = ordered(a), ordered(b)
    if x is None or y is None:
        return None
    return abs(x - y)


def same_reply(a, b):
    # error phrases and checksums exact ... except the checksum of a value
    # reply, which differs with the number's spelling.
    if a[2:3] == ["error:"] or b[2:3] == ["error:"]:
        return a == b
    nums_a = [t for t in a[2:] if not t.startswith("*")]
    nums_b = [t for t in b[2:] if not t.startswith("*")]
    return len(nums_a) == len(nums_b) and all(close(x, y, 1e-6, 1e-6)
                                              for x, y in zip(nums_a, nums_b))


def same_baseline(ours, other):
    a, b = ours.split(" "), other.split(" ")
    if a[:2] != b[:2] or len(a) != len(b):
        return False, []
    if a[1] in ("set", "move", "action"):
        return all(close(x, y, 1e-6, 0.0) for x, y in zip(a[2:], b[2:])), []
    return same_reply(a, b), []


def same_rounding(ours, other, max_ulps):
    """(agrees, [ulp distance of every float that differs])."""
    a, b = ours.split(" "), other.split(" ")
    if a[:2] != b[:2] or len(a) != len(b):
        return False, []
    kind = a[1]
    if kind == "set":
        # "<line> set <prop> <f32 view> <u64 view>": the same value, or a
        # float that differs by rounding (then its bits differ too)
        if a[2] != b[2]:
            return False, []
        if a[4] == b[4]:
            return True, []
        d = ulps(a[3], b[3])
        return (d is not None and d <= max_ulps), [d]
    if kind == "move":
        # "<line> move <kind> <given> pos vel torque rate kp kd"
        if a[2:4] != b[2:4]:
            return False, []
        diffs = []
        for x, y in zip(a[4:], b[4:]):
            d = ulps(x, y)
            if d is None or d > max_ulps:
                return False, []
            if d:
                diffs.append(d)
        return True, diffs
    if kind == "action":
        return a == b, []
    return same_reply(a, b), []


def same_shape(x, y):
    """The same event but for HAL float values: same kind, property, move
    kind and flags, action; replies as same_reply."""
    a, b = x.split(" "), y.split(" ")
    if a[:2] != b[:2] or len(a) != len(b):
        return False
    if a[1] == "set":
        return a[2] == b[2] and (a[4] == b[4] or (ulps(a[3], b[3]) or 0) > 0)
    if a[1] == "move":
        return a[2:4] == b[2:4]
    if a[1] == "action":
        return a == b
    return same_reply(a, b)


def by_line(events):
    lines = {}
    for e in events:
        lines.setdefault(int(e.split(" ", 1)[0]), []).append(e)
    return lines


def respelled(driver, stream):
    out = subprocess.run([driver, "respell", stream], check=True, stdout=subprocess.PIPE).stdout
    f = tempfile.NamedTemporaryFile(prefix="respelled.", suffix=".txt", delete=False)
    f.write(out)
    f.close()
    return f.name


def exact_event(x, y):
    """HAL calls bit for bit; replies as same_reply (the yardstick prints
    fixed point)."""
    a, b = x.split(" "), y.split(" ")
    if a[1] in ("set", "move", "action"):
        return a == b or same_rounding(x, y, 0)[0]
    return a[:2] == b[:2] and same_reply(a, b)


def check_handwritten(driver, stream, totals):
    ours = by_line(trace(driver, "ours", stream))
    hand = by_line(trace(driver, "handwritten", stream))
    path = respelled(driver, stream)
    try:
        control = by_line(trace(driver, "ours", path))
    finally:
        os.unlink(path)
    mismatches = 0
    rounded_lines = rounded_values = changed = 0
    for line in sorted(set(ours) | set(hand) | set(control)):
        o, h, c = ours.get(line, []), hand.get(line, []), control.get(line, [])
        if len(h) != len(c) or not all(exact_event(x, y) for x, y in zip(h, c)):
            if mismatches < 10:
                print("%s line %d: not explained by rounding\n  core on the respelled line: %s"
                      "\n  handwritten:                %s" % (stream, line, c, h))
            mismatches += 1
            continue
        if len(o) == len(h) and all(same_shape(x, y) for x, y in zip(o, h)):
            diffs = []
            for x, y in zip(o, h):
                diffs += [d for d in same_rounding(x, y, 1 << 30)[1] if d]
            if diffs:
                rounded_lines += 1
                rounded_values += len(diffs)
                for d in diffs:
                    key = d if d <= 4 else ">4"
                    totals["histogram"][key] = totals["histogram"].get(key, 0) + 1
            continue
        # the yardstick's rounding changed what the line did (another error,
        # no move, another integer)
        changed += 1
        if totals["changed_shown"] < 5:
            print("%s line %d: the yardstick's rounding changed the outcome\n  core:        %s"
                  "\n  handwritten: %s" % (stream, line, o, h))
            totals["changed_shown"] += 1
    totals["lines"] += rounded_lines
    totals["values"] += rounded_values
    totals["changed"] += changed
    return mismatches, rounded_lines, rounded_values, changed


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--yardstick", choices=("baseline", "handwritten"), default="baseline")
    ap.add_argument("driver")
    ap.add_argument("streams", nargs="+")
    opt = ap.parse_args()
    bad = 0
    totals = {"lines": 0, "values": 0, "changed": 0, "histogram": {}, "changed_shown": 0,
              "stream_lines": 0}
    for stream in opt.streams:
        if opt.yardstick == "handwritten":
            with open(stream, "rb") as f:
                n = sum(1 for _ in f)
            totals["stream_lines"] += n
            mismatches, lines, values, changed = check_handwritten(opt.driver, stream, totals)
            status = "same" if mismatches == 0 else "DIFFERENT"
            print("%-40s %s up to rounding: %d lines, %d not explained by rounding; rounding "
                  "differences on %d lines (%d HAL floats), outcome changed on %d" %
                  (stream, status, n, mismatches, lines, values, changed))
            bad += status != "same"
            continue
        ours, other = trace(opt.driver, "ours", stream), trace(opt.driver, opt.yardstick, stream)
        mismatches = 0
        if len(ours) != len(other):
            print("%s: %d events from daran-ascii, %d from the %s yardstick" %
                  (stream, len(ours), len(other), opt.yardstick))
        for x, y in zip(ours, other):
            if not same_baseline(x, y)[0]:
                if mismatches < 10:
                    print("%s:\n  ours:     %s\n  %-9s %s" % (stream, x, opt.yardstick + ":", y))
                mismatches += 1
        calls = sum(1 for x in ours if x.split(" ")[1] in ("set", "move", "action"))
        replies = len(ours) - calls
        status = "same" if mismatches == 0 and len(ours) == len(other) else "DIFFERENT"
        print("%-40s %s: %d HAL calls, %d replies, %d mismatches" %
              (stream, status, calls, replies, mismatches))
        bad += status != "same"
    if opt.yardstick == "handwritten":
        shown = ", ".join("%s ulp: %d" % (d, n) for d, n in
                          sorted(totals["histogram"].items(), key=lambda kv: (str(kv[0]) == ">4", kv[0] if kv[0] != ">4" else 0)))
        print("handwritten vs core, all streams (%d lines): %d lines with HAL floats rounded "
              "differently (%d floats%s), %d lines whose outcome the rounding changed" %
              (totals["stream_lines"], totals["lines"], totals["values"],
               ": " + shown if shown else "", totals["changed"]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
