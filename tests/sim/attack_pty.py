#!/usr/bin/python3
"""Regression tests for `daran-sim --pty` under attack (stdlib only: the pty
is opened with os/termios, no pyserial needed).

  order   replies leave in the order the requests arrived, line by line, even
          when the requests for several drives come in one write; a collision
          is reported only for a line that several drives answered
  slow    20,000 `i 1` written without reading, then read slowly: every
          reply line arrives whole, none is cut or lost
  flood   2,000 `h 1` with a reader running: all 52,000 reply lines arrive
          (back-pressure, not loss), nothing reported as dropped; then 2.4 MB
          of `h 1 properties` replies for a reader slower than the simulator

usage: attack_pty.py DARAN_SIM order|slow|flood
Exit 0 pass, 1 fail, 77 skipped (no /dev/ptmx).
"""
import errno
import fcntl
import os
import select
import subprocess
import sys
import tempfile
import threading
import time
import tty

import can_pty_support


class Sim:
    """daran-sim --pty, its port opened raw, stderr kept in a file."""

    def __init__(self, sim, *args):
        self.err = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([sim, "--pty", *args], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=self.err)
        ready, _, _ = select.select([self.proc.stdout], [], [], 5)
        path = self.proc.stdout.readline().decode().strip() if ready else ""
        if not path.startswith("/dev/"):
            self.close()
            raise SystemExit("FAIL: no pty path on the first line: %r" % path)
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)

    def write(self, data):
        while data:
            n = os.write(self.fd, data)
            data = data[n:]

    def read_lines(self, count, timeout=5.0):
        buf = b""
        deadline = time.time() + timeout
        while buf.count(b"\n") < count and time.time() < deadline:
            ready, _, _ = select.select([self.fd], [], [], 0.05)
            if ready:
                buf += os.read(self.fd, 65536)
        return buf

    def stderr(self):
        self.err.seek(0)
        return self.err.read().decode("utf-8", "replace")

    def close(self):
        if getattr(self, "fd", None) is not None:
            os.close(self.fd)
            self.fd = None
        can_pty_support.end_process(self.proc)


def lines_of(buf):
    return [x.rstrip(b"\r").decode("ascii", "replace") for x in buf.split(b"\n")[:-1]]


def lockstep(sim, text, *args):
    out = subprocess.run([sim, *args], input=text.encode(), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=10)
    return lines_of(out.stdout), out.stderr.decode()


def test_order(sim, failures):
    setup = ("w axis1.output_shaft.circular_setpoint_max 111\n"
             "w axis2.output_shaft.circular_setpoint_max 222\n")
    reads = ("r axis2.output_shaft.circular_setpoint_max\n"
             "r axis1.output_shaft.circular_setpoint_max\n")
    ids = ("r axis2.config.can_node_id\nr axis1.config.can_node_id\n"
           "r axis3.config.can_node_id\nr axis1.config.can_node_id\n")
    mixed = "r axis3.config.can_node_id\nr axis0.config.can_node_id\nr axis2.config.can_node_id\n"
    s = Sim(sim, "--drives", "3")
    try:
        s.write(setup.encode())
        time.sleep(0.2)
        s.write(reads.encode())  # one write: both requests in one read of the sim
        got = lines_of(s.read_lines(2))
        if got != ["222", "111"]:
            failures.append("pipelined reads for drives 2 then 1 came back %r" % got)
        s.write(ids.encode())
        got = lines_of(s.read_lines(4))
        if got != ["2", "1", "3", "1"]:
            failures.append("can_node_id for drives 2 1 3 1 came back %r" % got)
        # a line cut between two writes is still one line, in its place
        s.write(b"r axis2.config.can")
        time.sleep(0.1)
        s.write(b"_node_id\nr axis1.config.can_node_id\n")
        got = lines_of(s.read_lines(2))
        if got != ["2", "1"]:
            failures.append("a request split over two writes: %r" % got)
        # a broadcast read in the middle: its three replies in id order, in its place
        s.write(mixed.encode())
        got = lines_of(s.read_lines(5))
        if got != ["3", "1", "2", "3", "2"]:
            failures.append("broadcast between two reads: %r" % got)
        time.sleep(0.2)
    finally:
        s.close()
    collisions = [x for x in s.stderr().splitlines() if "collision" in x]
    if len(collisions) != 1 or "(ids 1 2 3)" not in collisions[0] or "axis0" not in collisions[0]:
        failures.append("want exactly one collision (the broadcast line), got %r" % collisions)
    # lock-step mode: the same order (stdin is read line by line)
    got, err = lockstep(sim, setup + reads + ids + mixed, "--drives", "3")
    if got != ["222", "111", "2", "1", "3", "1", "3", "1", "2", "3", "2"]:
        failures.append("lock-step order: %r" % got)
    if err.count("collision") != 1:
        failures.append("lock-step collisions: %r" % err)


def i_reply(sim):
    got, _ = lockstep(sim, "i 1\n")
    return got[0]


def test_slow(sim, failures):
    want = i_reply(sim)
    total = 20000
    s = Sim(sim)
    received = b""
    try:
        fl = fcntl.fcntl(s.fd, fcntl.F_GETFL)
        fcntl.fcntl(s.fd, fcntl.F_SETFL, fl | os.O_NONBLOCK)
        pending = b"i 1\n" * total
        # write all of it without reading a byte: 360 KB of replies, which
        # the simulator queues (up to 1 MiB) while it waits for the reader
        deadline = time.time() + 5
        while pending and time.time() < deadline:
            select.select([], [s.fd], [], 0.05)
            try:
                n = os.write(s.fd, pending)
            except OSError as e:
                if e.errno != errno.EAGAIN:
                    raise
                continue
            pending = pending[n:]
        if pending:
            failures.append("the port stopped taking requests after %d of %d without a reader"
                            % (total - len(pending) // 4, total))
        time.sleep(0.5)  # the replies pile up against a reader that does not read
        deadline = time.time() + 8
        while received.count(b"\n") < total and time.time() < deadline:
            if pending:
                try:
                    n = os.write(s.fd, pending)
                    pending = pending[n:]
                except OSError as e:
                    if e.errno != errno.EAGAIN:
                        raise
            ready, _, _ = select.select([s.fd], [], [], 0.02)
            if ready:
                try:
                    received += os.read(s.fd, 4096)  # a slow reader: small reads
                except OSError as e:
                    if e.errno != errno.EAGAIN:
                        raise
    finally:
        s.close()
    got = lines_of(received)
    bad = [(k, x) for k, x in enumerate(got) if x != want]
    if bad:
        failures.append("%d of %d reply lines are not `%s` (first: line %d %r)"
                        % (len(bad), len(got), want, bad[0][0], bad[0][1]))
    if len(got) != total:
        failures.append("%d replies to %d requests" % (len(got), total))
    if "drop" in s.stderr():
        failures.append("stderr reports dropped output: %r" % s.stderr()[:200])


STALL_S = 5


def test_flood(sim, failures):
    want, _ = lockstep(sim, "h 1\n")
    total = 2000
    s = Sim(sim)
    received = []

    def reader():
        buf = b""
        # every line must arrive, however loaded the machine: the reader
        # gives up only when nothing came for STALL_S seconds
        last = time.time()
        while buf.count(b"\n") < total * len(want) and time.time() - last < STALL_S:
            ready, _, _ = select.select([s.fd], [], [], 0.05)
            if ready:
                buf += os.read(s.fd, 65536)
                last = time.time()
        received.append(buf)

    try:
        t = threading.Thread(target=reader)
        t.start()
        s.write(b"h 1\n" * total)
        t.join()
    finally:
        s.close()
    got = lines_of(received[0])
    if len(got) != total * len(want):
        failures.append("%d of %d reply lines arrived" % (len(got), total * len(want)))
    elif got != want * total:
        failures.append("the replies are not %d copies of the `h 1` reply" % total)
    if "drop" in s.stderr() or "lost" in s.stderr():
        failures.append("stderr reports lost output: %r" % s.stderr()[:200])

    # More than the simulator queues (1 MiB) for a reader slower than it:
    # 300 x `h 1 properties` (8 KB each) read 4 KB at a time with pauses.
    want, _ = lockstep(sim, "h 1 properties\n")
    total = 300
    s = Sim(sim)
    received = []

    def slow_reader():
        buf = b""
        # every line must arrive, however loaded the machine: the reader
        # gives up only when nothing came for STALL_S seconds
        last = time.time()
        while buf.count(b"\n") < total * len(want) and time.time() - last < STALL_S:
            ready, _, _ = select.select([s.fd], [], [], 0.05)
            if ready:
                buf += os.read(s.fd, 4096)
                last = time.time()
                time.sleep(0.0005)
        received.append(buf)

    try:
        t = threading.Thread(target=slow_reader)
        t.start()
        s.write(b"h 1 properties\n" * total)
        t.join()
    finally:
        s.close()
    got = lines_of(received[0])
    if len(got) != total * len(want):
        failures.append("h 1 properties: %d of %d reply lines arrived"
                        % (len(got), total * len(want)))
    elif got != want * total:
        failures.append("the replies are not %d copies of the `h 1 properties` reply" % total)
    if "drop" in s.stderr() or "lost" in s.stderr():
        failures.append("stderr reports lost output: %r" % s.stderr()[:200])


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in ("order", "slow", "flood"):
        print(__doc__)
        return 2
    if not os.path.exists("/dev/ptmx"):
        print("no /dev/ptmx on this machine: skipped")
        return 77
    failures = []
    {"order": test_order, "slow": test_slow, "flood": test_flood}[sys.argv[2]](
        sys.argv[1], failures)
    for f in failures:
        print("FAIL:", f)
    print("attack_pty %s: %s" % (sys.argv[2], "failed" if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
