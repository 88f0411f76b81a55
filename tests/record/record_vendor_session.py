#!/usr/bin/python3
"""Records tests/record/vendor-session.rec: daran-record between `daran-sim
--pty` (one drive, real time) and a vendor-style Python client, the way a
drive maker records a real client against a real drive.

The client plays the request lines of examples/recordings/vendor-python-client.txt
(the drive maker's own Python library calling its public functions, checksums
off then on) that concern drive 1 or every drive, at the times the library
sent them, and reads back the replies each call reads (r, f, g, i: one line;
e: seven), as the library does, before its next call.

usage: record_vendor_session.py DARAN_SIM DARAN_RECORD OUT
       (from the repository: build/host/port/sim/daran-sim tools/daran-record
        tests/record/vendor-session.rec)
Exits 1 if a reply is an error or missing: the vendor's session runs cleanly.
"""
import os
import re
import signal
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import link_harness as h  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VENDOR = os.path.join(ROOT, "examples", "recordings", "vendor-python-client.txt")
OTHER_DRIVE = re.compile(rb"^[a-z]+ [23]( |\*|$)|axis[23]\.")
REPLY_LINES = {b"r": 1, b"f": 1, b"g": 1, b"i": 1, b"e": 7}  # what the library reads back

DESCRIPTION = (
    "A vendor-style Python client (pyserial) and daran-sim --pty, one drive, recorded "
    "with daran-record: the requests of examples/recordings/vendor-python-client.txt for "
    "drive 1 or every drive, at the library's times, checksums off then on; the replies "
    "as the drive sent them. Positions, velocities and voltages (`f`, `g`, `r "
    "vbus_voltage`) depend on real time; the other replies are the same on every run "
    "and in a lock-step replay. Recorded by "
    "tests/record/record_vendor_session.py.")


def vendor_requests():
    """[(seconds, request bytes)] for drive 1 and broadcasts."""
    out = []
    with open(VENDOR, "rb") as f:
        for line in f.read().split(b"\n"):
            if not line or line.startswith(b"#"):
                continue
            stamp, _, request = line.partition(b"\t")
            if not OTHER_DRIVE.search(request):
                out.append((float(stamp), request))
    return out


def describe(text):
    lines, line = [], "#"
    for word in text.split(" "):
        if len(line) + 1 + len(word) > 88:
            lines.append(line)
            line = "#"
        line += " " + word
    lines.append(line)
    return "\n".join(lines).encode() + b"\n"


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    sim_path, record, out = sys.argv[1:]
    serial = h.need_pyserial()
    raw_out = out + ".part"
    sim, sim_pty = h.start_sim(sim_path)
    recorder, client_pty = h.start_recorder(record, sim_pty, raw_out)
    errors = []
    try:
        client = h.Client(serial, client_pty)
        start = time.monotonic()
        for seconds, request in vendor_requests():
            delay = start + seconds - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            for reply in client.ask(request, REPLY_LINES.get(request[:1], 0)):
                if reply.startswith(b"error"):
                    errors.append(f"{request!r} -> {reply!r}")
        time.sleep(0.2)
        client.close()
        status = h.stop(recorder, signal.SIGINT)
        if status != 0:
            errors.append(f"daran-record exit status {status}")
    finally:
        h.stop(recorder, signal.SIGKILL)
        h.stop(sim)
    with open(raw_out, "rb") as f:
        recorded = f.read()
    os.remove(raw_out)
    with open(out, "wb") as f:
        f.write(describe(DESCRIPTION) + recorded)
    for e in errors:
        print(f"record_vendor_session: {e}", file=sys.stderr)
    requests = sum(1 for line in recorded.split(b"\n") if line[:1].isdigit())
    replies = recorded.count(b"\n<")
    print(f"{out}: {requests} requests, {replies} replies")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
