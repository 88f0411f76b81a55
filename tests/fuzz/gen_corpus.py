#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz harnesses into tests/corpus/<harness>/.

Seeds come from the spec's worked examples, the vendor recordings (time column
stripped), the simulator transcripts, and generated sessions: a pick-and-place
arm streaming `t` at 500 Hz, a synchronised multi-drive move, an r/w tuning
session. Each harness has its own input layout (see the harness's first
comment); this script adds the setup bytes. Run from anywhere:
    python3 tests/fuzz/gen_corpus.py [--shared /work/shared] [--only NAME...]
then minimise with libFuzzer -merge=1 (tools/ci.d/40-fuzz.sh documents how).
--only writes the seeds of the named sessions alone (e.g. a new recording:
--only vendor-python-defaults), leaving the merged corpus as it is.
"""
import argparse
import hashlib
import math
import os
import random
import re
import struct
from decimal import Decimal
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def spec_examples(shared):
    text = open(os.path.join(shared, "spec", "protocol.md"), encoding="utf-8").read()
    block = text.split("## 9. Worked examples")[1].split("```")[1]
    lines = []
    for row in block.strip("\n").split("\n"):
        lines += [c.strip() for c in re.split(r" {2,}", row) if c.strip()]
    # "All must be accepted exactly as written": also with the vendor's trailing space.
    return lines + [l + " " for l in lines if "*" not in l]


def recordings(shared):
    out = {}
    d = os.path.join(shared, "recordings")
    for name in sorted(os.listdir(d)):
        lines = []
        for row in open(os.path.join(d, name), encoding="utf-8"):
            row = row.rstrip("\n")
            if row.startswith("#") or "\t" not in row:
                continue
            lines.append(row.split("\t", 1)[1])
        out[name.rsplit(".", 1)[0]] = lines
    return out


def transcripts():
    out = {}
    d = os.path.join(ROOT, "tests", "transcripts")
    if not os.path.isdir(d):
        return out
    for name in sorted(os.listdir(d)):
        if name.endswith(".txt"):
            out[name[:-4]] = open(os.path.join(d, name), "rb").read().decode("latin-1").split("\n")
    return out


def pick_and_place():
    """An arm: 3 joints streaming `t` at 500 Hz along a smooth path."""
    lines = ["w axis0.controller.config.input_filter_bandwidth 50"]
    for k in range(250):
        s = k / 250.0
        for j, amp in ((1, 90.0), (2, -45.0), (3, 30.0)):
            lines.append("t %d %.3f" % (j, amp * (0.5 - 0.5 * math.cos(math.pi * s))))
        lines.append("!advance 0.002")
    lines += ["f 1", "f 2", "f 3"]
    return lines


def synchronised_move():
    return ["ms 1 120 2.5 10", "ms 2 -100 2.5 10", "ms 3 30 2.5 10", "mq 0 0",
            "!advance 1", "r axis1.controller.trajectory_done", "!advance 1.6",
            "r axis1.controller.trajectory_done", "f 1", "f 2", "f 3",
            "ms 1 10 0 25", "ms 2 20 0 25", "mt 0 1", "!advance 0.5", "f 0"]


def tuning_session():
    lines = []
    for gain in ("20", "25", "30.5", "12.25"):
        lines += ["w axis1.controller.config.pos_gain " + gain,
                  "r axis1.controller.config.pos_gain",
                  "w axis1.controller.config.vel_gain 0.2",
                  "w axis1.controller.config.vel_integrator_gain 0.5",
                  "t 1 10", "!advance 0.3", "f 1", "t 1 0", "!advance 0.3", "f 1"]
    lines += ["r axis1.motor.config.current_lim", "w axis1.output_shaft.vel_limit 300",
              "r vbus_voltage 1", "r ibus 1", "ss 1", "e 1"]
    return lines


def f32_neighbours(bits):
    lo = struct.unpack("<f", struct.pack("<I", bits))[0]
    hi = struct.unpack("<f", struct.pack("<I", bits + 1))[0]
    return lo, hi


def hard_decimals():
    """Decimals at and next to the exact halfway point between two adjacent
    float32s, where a parser must decide with all the digits (the slow path)."""
    rnd = random.Random(6)
    bits = [0x3F800000, 0x4B800000, 0x00000000, 0x00000001, 0x007FFFFF, 0x00800000,
            0x7F7FFFFE, 0x3DCCCCCC, 0x42C80000]
    bits += [rnd.randrange(1, 0x7F7FFFFF) for _ in range(12)]
    out = []
    for b in bits:
        lo, hi = f32_neighbours(b)
        mid = (Fraction(lo) + Fraction(hi)) / 2
        d = Decimal(mid.numerator) / Decimal(mid.denominator)
        exact = format(d.normalize(), "f") if abs(d) > Decimal("1e-10") else "%se0" % d
        out.append(exact)
        out.append(exact + "0000000000000000000001")
        if len(exact) > 12:
            out.append(exact[:-1])
            out.append(exact[:40])
    # the overflow boundary: FLT_MAX + half an ulp rounds to infinity
    out += ["340282356779733661637539395458142568448", "340282356779733661637539395458142568447.9"]
    return out


def error_registers():
    """Every fault the simulator injects, read back through `e` (seven
    register lines), cleared with `sc`; zero rates and S-curve timing."""
    lines = ["w axis1.config.extra_setting.enable_stall_limit 1", "t 1 90 0 0", "!advance 0.5",
             "!fault 1 stall", "!advance 0.2", "e 1", "t 1 0", "sc 1", "e 1",
             "w axis1.requested_state 8",
             "w axis1.controller.config.enable_overspeed_error 1", "v 1 30 0 2", "v 1 30 50 2",
             "!advance 0.3", "!fault 1 overspeed", "!advance 0.2", "e 1", "sc 1",
             "w axis1.requested_state 8", "!fault 1 overtemp", "!advance 0.5", "e 1",
             "r axis1.fet_thermistor.error", "w axis1.fet_thermistor.error 0", "sc 1",
             "!fault 1 undervoltage", "!advance 0.2", "e 1", "!advance 2", "sc 1",
             "w axis1.requested_state 8", "t 1 0", "!advance 1",
             "w axis1.trap_traj.config.traj_mode 2",
             "ms 1 90 3 20", "mq 0 0", "!advance 1.5", "r axis1.controller.trajectory_done",
             "!advance 1.6", "r axis1.controller.trajectory_done", "q 1 0 30 0", "!advance 0.5",
             "c 1 0.2 0 6", "!advance 0.2", "!fault 1 nvm-corrupt", "!power-cycle 1",
             "r axis1.config_warnings", "e 1", "sc 1", "r axis1.config_warnings", "f 1"]
    return lines


def port_brake_session():
    """The example port (examples/port-brake): its command, its rows, the
    rows it left out, discovery; for fuzz_port."""
    lines = ["h 1", "h 1 properties axis0.brake", "h 1 properties axis0.encoder.",
             "h 1 properties", "sb 1 20000", "SB 1 50000", "sb 0 12000", "sb 1 2.5e3",
             "sb 1 0", "sb 1 -0", "sb 1 +50000.0", "sb 1 .5", "sb 1", "sb 1 1 2", "sb 1 x",
             "sb 1 nan", "sb 1 60000", "sb 1 50000.004", "sb 1 1.5e39", "sb 1 -1", "sb 64 1",
             "sb 2 1000", "sb 1.0 100", "r axis0.brake.temperature", "r axis1.brake.chopper_hz",
             "w axis0.brake.chopper_hz 1500", "w axis1.brake.chopper_hz -1",
             "w axis0.brake.temperature 20", "w axis0.brake.chopper_hz 60000",
             "r axis0.encoder.pos_abs", "r axis0.encoder.turn_abs", "r axis0.encoder.spi_buff_0",
             "r axis0.encoder.spi_buff_1", "w axis0.encoder.spi_buff_2 0",
             "r axis0.encoder.pos_estimate", "t 1 90", "f 1", "st 1", "sc 1"]
    return lines + with_checksums(lines[::3])


def telemetry_session():
    """Telemetry switched on, retuned and off between ordinary requests; for
    fuzz_telemetry (and the others)."""
    return ["w axis0.telemetry.period 0.005", "w axis0.telemetry.fields 511", "f 1", "t 1 90",
            "r axis0.telemetry.period", "q 1 45 30 60", "w axis0.telemetry.period 0.0001",
            "g 1", "w axis0.telemetry.fields 128", "e 1", "w axis0.telemetry.period 1e-9",
            "w axis0.telemetry.fields 0", "h 1", "w axis0.telemetry.period 0.0125",
            "w axis0.telemetry.fields 3", "w axis0.telemetry.period -1",
            "w axis0.telemetry.fields 512", "r axis0.telemetry.fields", "i 1",
            "w axis0.telemetry.period 0", "f 1"]


def with_checksums(lines):
    out = []
    for l in lines:
        if l.startswith("!") or "*" in l:
            out.append(l)
            continue
        x = 0
        for ch in (l + " ").encode("latin-1"):
            x ^= ch
        out.append("%s *%d" % (l, x))
    return out


def write(harness, data):
    d = os.path.join(ROOT, "tests", "corpus", harness)
    os.makedirs(d, exist_ok=True)
    name = hashlib.sha1(data).hexdigest()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def protocol_only(lines):
    return [l for l in lines if not l.startswith("!")]


# The sessions that also seed fuzz_port and fuzz_telemetry.
PORT_SESSIONS = {"port-brake", "spec", "tuning-checksum", "error-registers", "telemetry"}
TELEMETRY_SESSIONS = {"telemetry", "telemetry-checksum", "tuning", "sync-move", "port-brake"}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shared", default="/work/shared")
    ap.add_argument("--only", nargs="+", metavar="NAME",
                    help="write only these sessions' seeds (names as in recordings/, "
                         "without .txt; no number seeds)")
    args = ap.parse_args()

    sessions = {"spec": spec_examples(args.shared)}
    sessions.update(recordings(args.shared))
    sessions.update({"transcript-" + k: v for k, v in transcripts().items()})
    sessions["pick-and-place"] = pick_and_place()
    sessions["sync-move"] = synchronised_move()
    sessions["tuning"] = tuning_session()
    sessions["tuning-checksum"] = with_checksums(tuning_session())
    sessions["error-registers"] = error_registers()
    # relative starts from a setpoint near FLT_MAX must be refused, not overflow
    sessions["port-brake"] = port_brake_session()
    sessions["telemetry"] = telemetry_session()
    sessions["telemetry-checksum"] = with_checksums(telemetry_session())
    sessions["relative-overflow"] = ["w axis1.output_shaft.pos_setpoint 3e38", "ms 1 3e38 0 25",
                                     "mt 1 1", "mp 1 1", "ms 1 -3e38 1 1", "mq 1 1", "f 1"]

    if args.only:
        unknown = sorted(set(args.only) - set(sessions))
        if unknown:
            ap.error("no session named %s (there are: %s)" % (", ".join(unknown),
                                                             ", ".join(sorted(sessions))))
        sessions = {k: v for k, v in sessions.items() if k in args.only}

    for name, lines in sessions.items():
        proto = protocol_only(lines)
        body = "\n".join(proto).encode("latin-1") + b"\n"
        # line: id 1 closed loop; id 2 with the forward hook; id 1 in e-stop
        write("line", bytes([0, 0, 0, 0]) + body[:4000])
        write("line", bytes([1, 4, 0, 0]) + body[:4000])
        write("line", bytes([0, 2, 0x83, 5]) + body[:2000])
        write("line", bytes([0, 0, 0x60 | (len(name) & 7), 0]) + body[:2000])
        # stream: calm polling, and a rarely polled ring (overruns)
        write("stream", b"\x01\x02\x03\x04\x00" + body[:4000])
        write("stream", b"\x11\x22\x33\x44\x3e" + body[:4000])
        write("stream", b"\x05\x06\x07\x08\xe1" + body[:2000])
        # sim: the session on 3 drives, directives kept
        simbody = "\n".join(l for l in lines if not l.startswith("!#")).encode("latin-1")
        write("sim", bytes([2]) + simbody[:16000] + b"\n!advance 1\nf 0\n")
        # port: the line harness's layouts on the example port's drive
        if name in PORT_SESSIONS:
            write("port", bytes([0, 0, 0, 0]) + body[:4000])
            write("port", bytes([1, 4, 0, 0]) + body[:4000])
            write("port", bytes([0, 0, 0x81, 5]) + body[:2000])
            write("port", bytes([0, 3, 0x60, 0]) + body[:2000])
        # telemetry: 1 kHz from off, 8 kHz on from the start with every
        # field, odd values and getter faults, 1 Hz, 0 Hz, bytes during ticks
        if name in TELEMETRY_SESSIONS:
            for flags, tick in ((0x00, 0), (0x09, 5), (0x39, 1000), (0x03, 7), (0x04, 0),
                                (0xc0, 0xfffff000), (0x2e, 123456)):
                write("telemetry", bytes([0, flags]) + struct.pack("<I", tick) +
                      bytes([len(name), flags]) + body[:2000])

    if args.only:
        return

    numbers = ["0", "-0", "1", "100.5", "0.02", "160", "-3", "0.00001", "1.5e-07", "3.0e+12",
               "1.0e+09", "1.4142135623730951", "90.000000", "-45.500000", "1e39", "3.4028235e38",
               "3.4028236e38", "1e-46", "1.17549435e-38", "7.0064923e-46", ".5", "5.", "+5",
               "5e0", "50e-1", "99999999999999999999", "18446744073709551615",
               "18446744073709551616", "0.1e-0000000000000000000001", "1" + "0" * 60,
               "0." + "0" * 40 + "1", "4.9406564584124654e-324", "nan", "inf", "0x10", "1e",
               "--1", "1.5", "-1", "1.000000000000000000000000000001"]
    numbers += hard_decimals()
    for t in numbers:
        write("number", b"\x00" + t.encode())
        write("number", b"\x01" + t.encode())
    floats = [0.0, 1.0, 0.1, 100.5, 1e-5, 1.5e-7, 3e12, 1e9, 123456789.0, 1e8, 9.999999e8,
              1.17549435e-38, 1.4e-45, 3.4028235e38, 16777216.0, 0.3]
    write("number", b"\x02" + b"".join(struct.pack("<f", f) for f in floats))
    write("number", b"\x02" + struct.pack("<I", 0x7fc00000) + struct.pack("<I", 0xff800000))
    write("number", b"\x03" + struct.pack("<QQQ", 0, 18446744073709551615, 2026000001))


if __name__ == "__main__":
    main()
