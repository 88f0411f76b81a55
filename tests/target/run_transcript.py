#!/usr/bin/env python3
"""Feed a daran-sim transcript to the example firmware under QEMU and check
that its UART replies equal the host simulator's, byte for byte.

Usage: run_transcript.py --qemu "QEMU ARGS..." --elf daran-fw-lockstep.elf
                         [--tick-hz 1000] TRANSCRIPT.txt [EXPECTED]

EXPECTED defaults to TRANSCRIPT with .txt replaced by .expected.
Protocol lines go to the UART unchanged. daran-sim directives become the
firmware's lock-step directives (port/mps2-an386/lockstep.c), which the
firmware takes off the line before the core sees it:

  --tick-hz HZ      -> !h HZ  (first line)
  !advance S        -> !t N   (N = S x tick rate, rounded half away from
                               zero like daran-sim's llround)
  !power-cycle [ID] -> !p ID
  !fault ID KIND    -> !f ID o|u|s|v|n  (overtemp, undervoltage, stall,
                               overspeed, nvm-corrupt)
  !load ID NM       -> !l ID <float32 bits in hex>
  !# ...            -> (comment, dropped)

Exit status: 0 pass, 1 mismatch, 77 skipped (a transcript this firmware,
one drive on one UART, cannot run, such as a multi-drive bus).
"""
import argparse
import difflib
import math
import os
import shlex
import struct
import subprocess
import sys
from fractions import Fraction

SKIP = 77


def float32_bits(text):
    """Correctly rounded float32 of a decimal text (as strtof does)."""
    value = Fraction(text)  # exact
    if value == 0:
        return 0x80000000 if text.strip().startswith("-") else 0
    sign = 0x80000000 if value < 0 else 0
    value = abs(value)
    exp = value.numerator.bit_length() - value.denominator.bit_length()
    if Fraction(2) ** exp > value:
        exp -= 1
    exp = max(exp, -126)
    # 24 significant bits at exponent exp (subnormals keep exp = -126)
    scaled = value / (Fraction(2) ** (exp - 23))
    mant = math.floor(scaled)
    rem = scaled - mant
    if rem > Fraction(1, 2) or (rem == Fraction(1, 2) and mant % 2 == 1):
        mant += 1
    if mant == 1 << 24:
        mant >>= 1
        exp += 1
    if exp > 127:
        raise ValueError("overflow")
    if mant < (1 << 23):  # subnormal
        return sign | mant
    return sign | ((exp + 127) << 23) | (mant - (1 << 23))


def ticks_for(seconds_text, tick_hz):
    x = float(seconds_text) * float(tick_hz)
    whole = math.floor(x)
    return whole + 1 if x - whole >= 0.5 else whole


def translate(data, tick_hz):
    """Transcript bytes -> bytes for the firmware's UART, or None to skip."""
    out = bytearray()
    lines = data.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    for raw in lines:
        if not raw.startswith(b"!"):
            out += raw + b"\n"
            continue
        words = raw[1:].decode("ascii", "replace").split()
        if not words or raw.startswith(b"!#"):
            continue
        cmd, args = words[0], words[1:]
        if cmd == "advance" and len(args) == 1:
            out += b"!t %d\n" % ticks_for(args[0], tick_hz)
        elif cmd == "power-cycle" and len(args) <= 1:
            out += b"!p %d\n" % int(args[0] if args else "0")
        elif cmd == "fault" and len(args) == 2:
            kind = {"overtemp": b"o", "undervoltage": b"u", "stall": b"s", "overspeed": b"v",
                    "nvm-corrupt": b"n"}.get(args[1])
            if kind is None:
                return None
            out += b"!f %d %s\n" % (int(args[0]), kind)
        elif cmd == "load" and len(args) == 2:
            out += b"!l %d %x\n" % (int(args[0]), float32_bits(args[1]))
        else:
            return None
    return bytes(out) + b"!x\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--qemu", required=True, help="QEMU command line before -kernel")
    ap.add_argument("--elf", required=True)
    ap.add_argument("--tick-hz", type=int, default=1000)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("transcript")
    ap.add_argument("expected", nargs="?")
    opt = ap.parse_args()

    expected_path = opt.expected or os.path.splitext(opt.transcript)[0] + ".expected"
    with open(opt.transcript, "rb") as f:
        data = f.read()
    tick_hz_line = b""
    options_path = os.path.splitext(opt.transcript)[0] + ".args"
    if os.path.exists(options_path):
        with open(options_path) as f:
            sim_args = shlex.split(f.read())
        # --nvm DIR: a fresh store that lives across !power-cycle, which is
        # what the firmware's RAM store is within one run. --tick-hz HZ: the
        # firmware restarts its drive at that rate. Anything else (--drives
        # N: a bus of drives, --echo) the firmware, one drive on one UART,
        # does not model.
        other = []
        i = 0
        while i < len(sim_args):
            a = sim_args[i]
            if a == "--nvm" or a == "--tick-hz":
                if i + 1 < len(sim_args) and a == "--tick-hz":
                    opt.tick_hz = int(sim_args[i + 1])
                    tick_hz_line = b"!h %d\n" % opt.tick_hz
                i += 2
                continue
            if a.startswith("--tick-hz="):
                opt.tick_hz = int(a.split("=", 1)[1])
                tick_hz_line = b"!h %d\n" % opt.tick_hz
            elif not a.startswith("--nvm="):
                other.append(a)
            i += 1
        if other:
            print(f"SKIP {opt.transcript}: daran-sim options {other} are not modelled "
                  "by the firmware (one drive on one UART)")
            return SKIP
    feed = translate(data, opt.tick_hz)
    if feed is None:
        print(f"SKIP {opt.transcript}: a directive the firmware does not model")
        return SKIP
    feed = tick_hz_line + feed
    with open(expected_path, "rb") as f:
        expected = f.read()

    cmd = shlex.split(opt.qemu) + ["-kernel", opt.elf]
    try:
        proc = subprocess.run(cmd, input=feed, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, timeout=opt.timeout)
    except subprocess.TimeoutExpired:
        print(f"FAIL {opt.transcript}: QEMU did not finish in {opt.timeout} s")
        return 1
    got = proc.stdout
    if proc.returncode != 0:
        print(f"FAIL {opt.transcript}: QEMU exit status {proc.returncode}")
        sys.stdout.write(proc.stderr.decode("utf-8", "replace"))
        return 1
    if got != expected:
        print(f"FAIL {opt.transcript}: firmware replies differ from daran-sim's")
        diff = difflib.unified_diff(
            expected.decode("latin-1").splitlines(keepends=True),
            got.decode("latin-1").splitlines(keepends=True),
            "daran-sim (expected)", "firmware on QEMU")
        sys.stdout.writelines(list(diff)[:80])
        return 1
    print(f"PASS {opt.transcript}: {len(got)} reply bytes identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
