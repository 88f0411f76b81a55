#!/usr/bin/python3
"""daran-record between a vendor-style pyserial client and `daran-sim --pty`,
and tools/replay of what it wrote. One check per MODE:

  session      a client session through the recorder (lines of
               examples/recordings/vendor-python-client.txt, one line split
               across two writes, the client closing and reopening the
               port), stopped by SIGINT: the header, every request byte for
               byte, every reply marked `<`, times monotonic, the bytes the
               client read unchanged; tools/replay --compare-recorded of the
               file against a fresh daran-sim (lock-step), against daran-sim
               as a port program and on a PTY finds no difference, and finds
               the one reply changed in a tampered copy
  missing      a device that does not exist, or is not a terminal: exit 1,
               one line on stderr, no recording
  vanishes     the device goes away (daran-sim killed): exit 1, one line on
               stderr, the file whole with what came before
  signals      SIGTERM and SIGHUP: exit 0, the file whole, an unfinished
               line kept in a comment
  overlong     a 10,000-byte line is recorded as its first 4096 bytes after a
               comment, and 16 MB without a newline leave the recorder's
               memory bounded
  vendor       the committed vendor-session.rec replays against a fresh
               daran-sim to its recorded replies (`f`, `g` and `r
               vbus_voltage`, which depend on real time, left out)

usage: record_link.py MODE DARAN_SIM DARAN_RECORD TOOLS_REPLAY WORK_DIR [REC]
Exit status: 0 pass, 1 fail, 77 skipped (no python3-serial or /dev/ptmx).
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import link_harness as h  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VENDOR = os.path.join(ROOT, "examples", "recordings", "vendor-python-client.txt")
STOP_WITHIN_S = 2.0


class Check:
    def __init__(self):
        self.failures = []

    def that(self, ok, what):
        if not ok:
            self.failures.append(what)
        return ok


def vendor_lines():
    """The vendor library's exact request bytes, by their text."""
    with open(VENDOR, "rb") as f:
        return {line.split(b"\t", 1)[1] for line in f.read().split(b"\n")
                if line and not line.startswith(b"#")}


def session(opt, check):
    serial = h.need_pyserial()
    vendor = vendor_lines()
    # (request bytes, reply lines): deterministic replies only, so that a
    # lock-step replay must give them back exactly
    plan = [
        (b"i 1 ", 1),
        (b"r axis0.config.can_node_id ", 1),
        (b"e 1 ", 7),
        (b"w axis1.controller.config.pos_gain 25 ", 0),
        (b"r axis1.controller.config.pos_gain ", 1),
        (b"x 1 ", 1),  # an unknown command: an error reply is recorded too
        (b"r config.uart_baudrate 1 ", 1),
        None,  # the client closes the port and opens it again
        (b"r axis0.config.can_node_id *42", 1),
        (b"w axis1.controller.config.pos_gain 25 *104", 0),
        (b"r axis1.controller.config.pos_gain *74", 1),
        (b"e 1 *84", 7),
    ]
    for step in plan:
        if step and step[0] not in (b"i 1 ", b"x 1 "):
            assert step[0] in vendor, step[0]
    out = os.path.join(opt.work, "session.rec")
    sim, sim_pty = h.start_sim(opt.sim)
    recorder, client_pty = h.start_recorder(opt.record, sim_pty, out)
    sent, replies = [], []
    try:
        client = h.Client(serial, client_pty)
        received = bytearray()
        for step in plan:
            if step is None:
                received += client.received
                client.close()
                cpu = cpu_seconds(recorder.pid)
                time.sleep(0.3)
                check.that(recorder.poll() is None, "the recorder ended when the client closed")
                busy = cpu_seconds(recorder.pid) - cpu
                check.that(busy < 0.1, f"with no client the recorder kept busy ({busy:.2f} s CPU "
                           "in 0.3 s): a hung-up port it polls")
                client = h.Client(serial, client_pty)
                continue
            line, n = step
            replies += client.ask(line, n)
            sent.append(line)
        # a line that reaches the recorder in two reads
        client.tell(b"r config.")
        time.sleep(0.1)
        replies += client.ask(b"uart_baudrate 1 ", 1)
        sent.append(b"r config.uart_baudrate 1 ")
        received += client.received
        client.close()
        status = h.stop(recorder, signal.SIGINT, STOP_WITHIN_S)
        check.that(status == 0, f"SIGINT: exit status {status}, want 0")
    finally:
        h.stop(recorder, signal.SIGKILL)
        h.stop(sim)

    comments, data, raw = h.read_recording(out)
    check.that(comments and comments[0] == b"# daran-record --device " + sim_pty.encode()
               + b" --baud 115200", f"header line: {comments[:1]!r}")
    check.that(any(re.match(rb"# started \d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", c) for c in comments),
               "no `# started DATE` header line")
    check.that(raw.endswith(b"\n") and comments[-1].startswith(b"# ended")
               and b"SIGINT" in comments[-1], f"the file does not end whole: {raw[-80:]!r}")
    requests = [line for is_reply, _, line in data if not is_reply]
    check.that(requests == sent, f"requests differ:\n  recorded {requests!r}\n  sent     {sent!r}")
    recorded_replies = [line for is_reply, _, line in data if is_reply]
    want = [r[:-2] if r.endswith(b"\r\n") else r[:-1] for r in replies]
    check.that(recorded_replies == want,
               f"replies differ:\n  recorded {recorded_replies!r}\n  read     {want!r}")
    times = [float(t) for _, t, _ in data]
    check.that(times == sorted(times), f"times go back: {times}")
    # each reply comes after the request it answers
    last_request = None
    for is_reply, t, line in data:
        if not is_reply:
            last_request = float(t)
        else:
            check.that(last_request is not None and float(t) >= last_request,
                       f"reply {line!r} at {t} before its request")

    # The client read the drive's bytes unchanged: what a lock-step replay
    # of the same lines gives.
    lockstep = subprocess.run([opt.replay, "--sim", opt.sim, out], stdout=subprocess.PIPE)
    check.that(lockstep.returncode == 0 and lockstep.stdout == bytes(received),
               f"the client read other bytes than the drive sent:\n  read {bytes(received)!r}\n"
               f"  sent {lockstep.stdout!r}")

    def replay(*args):
        return subprocess.run([opt.replay, "--compare-recorded", *args],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=30)

    for what, args in (("daran-sim", ["--sim", opt.sim, out]),
                       ("daran-sim as a port program",
                        ["--target", "program", "--program", opt.sim, "--no-pace", out])):
        r = replay(*args)
        check.that(r.returncode == 0, f"replay against {what}: status {r.returncode}\n"
                   + r.stdout.decode(errors="replace"))
    sim, sim_pty = h.start_sim(opt.sim)
    try:
        r = replay("--target", "serial", "--device", sim_pty, out)
        check.that(r.returncode == 0, f"replay on daran-sim's PTY: status {r.returncode}\n"
                   + r.stdout.decode(errors="replace"))
    finally:
        h.stop(sim)

    tampered = os.path.join(opt.work, "tampered.rec")
    with open(tampered, "wb") as f:
        f.write(re.sub(rb"(?m)^(<[0-9.]+\t)25$", rb"\g<1>26", raw, count=1))
    r = replay("--sim", opt.sim, tampered)
    text = r.stdout.decode(errors="replace")
    check.that(r.returncode == 1 and "\n-26\n+25\n" in text,
               f"a tampered reply: status {r.returncode}, want 1 and a diff\n{text}")


def missing(opt, check):
    h.need_pyserial()
    for device in ("/dev/daran-no-such-device", "/dev/null"):
        out = os.path.join(opt.work, "missing.rec")
        r = subprocess.run([opt.record, "--device", device, "--out", out],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=10)
        err = r.stderr.decode(errors="replace")
        check.that(r.returncode == 1, f"{device}: exit status {r.returncode}, want 1")
        check.that(err.count("\n") == 1 and err.startswith("daran-record: ")
                   and device in err, f"{device}: not a one-line error: {err!r}")
        check.that(r.stdout == b"", f"{device}: printed {r.stdout!r}")
        check.that(not os.path.exists(out), f"{device}: a recording was created")


def vanishes(opt, check):
    serial = h.need_pyserial()
    out = os.path.join(opt.work, "vanishes.rec")
    sim, sim_pty = h.start_sim(opt.sim)
    recorder, client_pty = h.start_recorder(opt.record, sim_pty, out)
    try:
        client = h.Client(serial, client_pty)
        info = client.ask(b"i 1 ", 1)[0].rstrip(b"\r\n")
        client.tell(b"r axis0.config")  # never ended: the device goes first
        time.sleep(0.3)
        sim.kill()
        sim.wait()
        t0 = time.monotonic()
        try:
            status = recorder.wait(timeout=5)
        except subprocess.TimeoutExpired:
            status = None
        check.that(status == 1, f"exit status {status} once the device went, want 1")
        check.that(time.monotonic() - t0 < STOP_WITHIN_S, "it took long to notice")
        client.close()
        err = recorder.stderr.read().decode(errors="replace")
        check.that(err.count("\n") == 1 and "went away" in err, f"not a one-line error: {err!r}")
    finally:
        h.stop(recorder, signal.SIGKILL)
        h.stop(sim, signal.SIGKILL)
    comments, data, raw = h.read_recording(out)
    check.that([line for _, _, line in data] == [b"i 1 ", info],
               f"the lines before: {data!r}")
    check.that(raw.endswith(b"\n") and comments[-1].startswith(b"# ended")
               and b"went away" in comments[-1], f"not whole: {raw[-120:]!r}")
    check.that(any(c.startswith(b"# unfinished request") and c.endswith(b"\tr axis0.config")
                   for c in comments), f"the unfinished line is not kept: {comments!r}")


def signals(opt, check):
    serial = h.need_pyserial()
    for sig in (signal.SIGTERM, signal.SIGHUP):
        name = signal.Signals(sig).name
        out = os.path.join(opt.work, f"{name}.rec")
        sim, sim_pty = h.start_sim(opt.sim)
        recorder, client_pty = h.start_recorder(opt.record, sim_pty, out)
        try:
            client = h.Client(serial, client_pty)
            client.ask(b"r axis0.config.can_node_id ", 1)
            client.tell(b"f 1")  # no \n yet
            time.sleep(0.3)
            t0 = time.monotonic()
            status = h.stop(recorder, sig, STOP_WITHIN_S)
            check.that(status == 0, f"{name}: exit status {status}, want 0")
            check.that(time.monotonic() - t0 < STOP_WITHIN_S, f"{name}: slow to stop")
            client.close()
        finally:
            h.stop(recorder, signal.SIGKILL)
            h.stop(sim)
        comments, data, raw = h.read_recording(out)
        check.that([line for _, _, line in data] == [b"r axis0.config.can_node_id ", b"1"],
                   f"{name}: lines {data!r}")
        check.that(raw.endswith(b"\n") and comments[-1].startswith(b"# ended")
                   and name.encode() in comments[-1], f"{name}: not whole: {raw[-120:]!r}")
        check.that(any(c.startswith(b"# unfinished request") and c.endswith(b"\tf 1")
                       for c in comments), f"{name}: the unfinished line is not kept")


def cpu_seconds(pid):
    """User + system CPU time of a process, from /proc."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def rss_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def overlong(opt, check):
    serial = h.need_pyserial()
    out = os.path.join(opt.work, "overlong.rec")
    sim, sim_pty = h.start_sim(opt.sim)
    recorder, client_pty = h.start_recorder(opt.record, sim_pty, out)
    try:
        client = h.Client(serial, client_pty, timeout=10)
        too_long = client.ask(b"x" * 10000, 1)
        check.that(too_long and too_long[0].startswith(b"error"), f"reply {too_long!r}")
        before = rss_kib(recorder.pid)
        chunk = b"y" * 65536
        for _ in range(256):  # 16 MiB, no newline
            client.port.write(chunk)
        client.ask(b"", 1)  # its end: the drive's one `line too long`
        grown = rss_kib(recorder.pid) - before
        check.that(grown < 8 * 1024, f"the recorder grew by {grown} KiB over a 16 MiB line")
        client.ask(b"i 1 ", 1)
        client.close()
        check.that(h.stop(recorder, signal.SIGINT, STOP_WITHIN_S) == 0, "SIGINT: not exit 0")
    finally:
        h.stop(recorder, signal.SIGKILL)
        h.stop(sim)
    comments, data, raw = h.read_recording(out)
    requests = [line for is_reply, _, line in data if not is_reply]
    check.that(requests == [b"x" * 4096, b"y" * 4096, b"i 1 "],
               f"requests {[(r[:8], len(r)) for r in requests]!r}")
    for total in (10000, 16 * 1024 * 1024):
        note = f"# overlong request line: {total} bytes before its \\n, the first 4096 recorded"
        check.that(note.encode() in comments, f"no comment {note!r}")
    r = subprocess.run([opt.replay, "--compare-recorded", "--sim", opt.sim, out],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=30)
    check.that(r.returncode == 0, "the cut lines do not replay to the same replies:\n"
               + r.stdout.decode(errors="replace"))


def vendor(opt, check):
    r = subprocess.run([opt.replay, "--compare-recorded", "--sim", opt.sim,
                        "--ignore-replies-to", r"^([fg] |r vbus_voltage)", opt.rec],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    sys.stdout.write(r.stdout.decode(errors="replace"))
    check.that(r.returncode == 0, f"{opt.rec}: status {r.returncode}")
    comments, data, _ = h.read_recording(opt.rec)
    check.that(comments[0].startswith(b"# ") and any(c.startswith(b"# daran-record --device")
                                                     for c in comments), "no daran-record header")
    check.that(sum(1 for is_reply, _, _ in data if is_reply) >= 20, "few recorded replies")


MODES = {"session": session, "missing": missing, "vanishes": vanishes, "signals": signals,
         "overlong": overlong, "vendor": vendor}


class Options:
    def __init__(self, argv):
        if len(argv) not in (6, 7) or argv[1] not in MODES:
            print(__doc__, file=sys.stderr)
            sys.exit(2)
        self.mode, self.sim, self.record, self.replay, self.work = argv[1:6]
        self.rec = argv[6] if len(argv) == 7 else None


def main():
    opt = Options(sys.argv)
    shutil.rmtree(opt.work, ignore_errors=True)
    os.makedirs(opt.work)
    check = Check()
    try:
        MODES[opt.mode](opt, check)
    except (RuntimeError, OSError, subprocess.TimeoutExpired) as e:
        check.failures.append(f"{type(e).__name__}: {e}")
    for f in check.failures:
        print(f"FAIL: {f}")
    if check.failures:
        return 1
    print(f"daran-record {opt.mode}: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
