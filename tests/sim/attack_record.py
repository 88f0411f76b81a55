#!/usr/bin/python3
"""Regression test: a line without a newline cannot make daran-sim grow
without limit (the old one buffered it whole: 100 MB of input, 104 MB RSS).
With --record, in lock-step and on --pty, 48 MB without a newline and then
the newline: the memory high-water mark grows by less than 8 MB, the drive
answers `line too long`, the recording holds the line's first
DARAN_LINE_MAX + 1 bytes after a comment saying how long it was, and
tools/replay-style parsing of it gives back a line a drive also finds too long.

usage: attack_record.py DARAN_SIM
"""
import os
import re
import select
import subprocess
import sys
import tempfile
import threading
import time
import tty

SIZE = 48 << 20
GROWTH_MAX_KB = 8 << 10
LINE_MAX = 128  # DARAN_LINE_MAX of the default build


def hwm_kb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return 0


def check_recording(path, failures, what):
    with open(path, "rb") as f:
        lines = f.read().split(b"\n")
    body = [x for x in lines if x and not x.startswith(b"# Protocol") and
            not x.startswith(b"# then") and not x.startswith(b"# daran-sim")]
    if len(body) != 3:
        failures.append("%s: recording has %d lines after the header: %r"
                        % (what, len(body), [x[:80] for x in body]))
        return
    comment, long_line, f1 = body
    if not comment.startswith(b"#") or str(SIZE).encode() not in comment:
        failures.append("%s: no comment saying the line had %d bytes: %r" % (what, SIZE, comment))
    stamp, tab, data = long_line.partition(b"\t")
    if not tab or not re.match(rb"^[0-9]+\.[0-9]+$", stamp):
        failures.append("%s: overlong line not recorded as SECONDS<TAB>bytes" % what)
    if data != b"x" * (LINE_MAX + 1):
        failures.append("%s: overlong line recorded as %d bytes, want its first %d"
                        % (what, len(data), LINE_MAX + 1))
    if f1.partition(b"\t")[2] != b"f 1":
        failures.append("%s: the line after it: %r" % (what, f1))


def lockstep(sim, tmp, failures):
    rec = os.path.join(tmp, "lock.txt")
    p = subprocess.Popen([sim, "--record", rec], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL)
    time.sleep(0.2)
    base = hwm_kb(p.pid)
    chunk = b"x" * (1 << 20)
    for _ in range(SIZE >> 20):
        p.stdin.write(chunk)
    p.stdin.write(b"\nf 1\n")
    p.stdin.flush()
    buf = b""
    deadline = time.time() + 20
    while buf.count(b"\n") < 2 and time.time() < deadline:
        ready, _, _ = select.select([p.stdout], [], [], 0.1)
        if ready:
            buf += os.read(p.stdout.fileno(), 4096)
    replies = buf.replace(b"\r", b"").split(b"\n")[:2]
    grew = hwm_kb(p.pid) - base
    p.stdin.close()
    p.wait(timeout=10)
    if replies != [b"error: line too long", b"0 0"]:
        failures.append("lock-step: replies %r" % replies)
    if grew > GROWTH_MAX_KB:
        failures.append("lock-step: memory grew by %d KB for one %d MB line"
                        % (grew, SIZE >> 20))
    check_recording(rec, failures, "lock-step")


def pty(sim, tmp, failures):
    rec = os.path.join(tmp, "pty.txt")
    p = subprocess.Popen([sim, "--pty", "--record", rec], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    ready, _, _ = select.select([p.stdout], [], [], 5)
    path = p.stdout.readline().decode().strip() if ready else ""
    if not path.startswith("/dev/"):
        failures.append("--pty: no path")
        p.kill()
        p.wait()
        return
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    time.sleep(0.2)
    base = hwm_kb(p.pid)
    got = []

    def reader():
        buf = b""
        deadline = time.time() + 25
        while buf.count(b"\n") < 2 and time.time() < deadline:
            r, _, _ = select.select([fd], [], [], 0.05)
            if r:
                buf += os.read(fd, 4096)
        got.append(buf)

    t = threading.Thread(target=reader)
    t.start()
    chunk = b"x" * (1 << 16)
    for _ in range(SIZE >> 16):
        os.write(fd, chunk)
    os.write(fd, b"\nf 1\n")
    t.join()
    grew = hwm_kb(p.pid) - base
    p.terminate()
    p.wait(timeout=10)
    os.close(fd)
    replies = got[0].replace(b"\r", b"").split(b"\n")[:2]
    if replies != [b"error: line too long", b"0 0"]:
        failures.append("--pty: replies %r" % replies)
    if grew > GROWTH_MAX_KB:
        failures.append("--pty: memory grew by %d KB for one %d MB line" % (grew, SIZE >> 20))
    check_recording(rec, failures, "--pty")


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        lockstep(sys.argv[1], tmp, failures)
        if os.path.exists("/dev/ptmx"):
            pty(sys.argv[1], tmp, failures)
    for f in failures:
        print("FAIL:", f)
    print("record bound: %s" % ("failed" if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
