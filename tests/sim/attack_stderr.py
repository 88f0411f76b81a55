#!/usr/bin/python3
"""Regression test: diagnostics on stderr never block the drives. Every
garbage line on a bus of two drives is a collision (both answer it); with
stderr a pipe nobody reads, daran-sim must keep serving (the old one stopped
after about 64 KB of messages). Afterwards stderr holds a bounded number of
messages and says how many it suppressed.

usage: attack_stderr.py DARAN_SIM
"""
import os
import select
import subprocess
import sys
import threading
import time
import tty

GARBAGE = 20000  # x 70 bytes of collision message each: 1.4 MB, 20 pipe buffers


def run(sim, args, failures, what):
    p = subprocess.Popen([sim, *args], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)  # stderr: nobody reads it until the end
    out = []

    def reader():
        out.append(p.stdout.read())

    t = threading.Thread(target=reader, daemon=True)
    t.start()

    def writer():
        try:
            p.stdin.write(b"xyz\n" * GARBAGE + b"!bogus\nf 2\n")
            p.stdin.close()
        except BrokenPipeError:
            pass

    w = threading.Thread(target=writer, daemon=True)
    w.start()
    t.join(timeout=8)
    if t.is_alive():
        failures.append("%s: daran-sim stopped serving (stderr not read)" % what)
        p.kill()
        p.wait()
        return
    rc = p.wait(timeout=5)
    err = p.stderr.read().decode("utf-8", "replace")
    lines = out[0].replace(b"\r", b"").decode().split("\n")
    if lines[-2:] != ["0 0", ""] or len(lines) != 2 * GARBAGE + 2:
        failures.append("%s: %d reply lines, last %r" % (what, len(lines) - 1, lines[-2:]))
    if rc != 1:
        failures.append("%s: exit status %d (a bad directive: want 1)" % (what, rc))
    messages = err.splitlines()
    if len(messages) > 200:
        failures.append("%s: %d lines on stderr: not rate-limited" % (what, len(messages)))
    if not any("suppressed" in m for m in messages):
        failures.append("%s: stderr does not say how many messages were suppressed: %r"
                        % (what, messages[-3:]))
    if not any("collision" in m for m in messages):
        failures.append("%s: no collision message at all" % what)


def run_pty(sim, failures):
    """The same on --pty: garbage from a serial client, stderr unread."""
    p = subprocess.Popen([sim, "--pty", "--drives", "2"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    ready, _, _ = select.select([p.stdout], [], [], 5)
    path = p.stdout.readline().decode().strip() if ready else ""
    if not path.startswith("/dev/"):
        failures.append("--pty: no path")
        p.kill()
        p.wait()
        return
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    got = []

    def reader():
        buf = b""
        deadline = time.time() + 8
        while not buf.endswith(b"0 0\r\n") and time.time() < deadline:
            r, _, _ = select.select([fd], [], [], 0.05)
            if r:
                buf += os.read(fd, 65536)
        got.append(buf)

    t = threading.Thread(target=reader)
    t.start()
    os.write(fd, b"xyz\n" * GARBAGE + b"f 2\n")
    t.join()
    os.close(fd)
    p.terminate()
    try:
        p.wait(timeout=5)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        failures.append("--pty: did not stop on SIGTERM (blocked on stderr?)")
    lines = got[0].replace(b"\r", b"").decode().split("\n")
    if lines[-2:] != ["0 0", ""] or len(lines) != 2 * GARBAGE + 2:
        failures.append("--pty: %d reply lines, last %r: stopped serving (stderr not read)"
                        % (len(lines) - 1, lines[-2:]))
    err = p.stderr.read().decode("utf-8", "replace").splitlines()
    if len(err) > 300 or not any("suppressed" in m for m in err):
        failures.append("--pty: %d lines on stderr, last %r" % (len(err), err[-2:]))


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    failures = []
    run(sys.argv[1], ["--drives", "2"], failures, "lock-step")
    if os.path.exists("/dev/ptmx"):
        run_pty(sys.argv[1], failures)
    for f in failures:
        print("FAIL:", f)
    print("stderr back-pressure: %s" % ("failed" if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
