#!/usr/bin/python3
"""In real time, the drives answer in bus time, not at the control tick:
daran-sim --tick-hz 1 (a tick a second) with --slcan, --usbcan and
--pty --bridge at once. 20 fast reads of drive 2 on the slcan pty, 20 on
the usbcan pty and 10 `f 2` lines through drive 1's bridge are each
answered within BUDGET_S. A drive that waited for its tick would answer in
half a second on average (and the bridge, whose timeout is 10 ms, not at
all); the bus takes about 0.3 ms. The budget is wide so that a loaded
machine (two tests at a time on two cores) does not fail it; the figures
on an idle one are in docs/simulator.md (tools/sim-round-trip measures
them). Stdlib only; exits 77 (skipped) without ptys.

usage: pty_bus_time.py DARAN_SIM
"""
import os
import select
import sys
import time
import tty

from can_pty_support import FAST_READ, run

BUDGET_S = 0.2
STATUS_OF_2 = 0x043  # the status frame of node 2, a fast read's answer


def raw(path):
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    return fd


def drain(fd):
    """What waits on @fd is dropped: every adapter hears every frame on the
    bus, the other links' requests and answers too."""
    while select.select([fd], [], [], 0.05)[0]:
        os.read(fd, 4096)


def answered_within(fd, request, done, count, label, failures):
    """@count times: @request written, then bytes read until done(buf)
    gives the end of its answer; a failure when one is slower than
    BUDGET_S (or unanswered)."""
    drain(fd)
    buf = bytearray()
    slowest = 0.0
    for _ in range(count):
        t0 = time.monotonic()
        os.write(fd, request)
        while True:
            end = done(buf)
            if end is not None:
                del buf[:end]
                break
            left = t0 + 1.5 - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                failures.append("%s: no answer within 1.5 s" % label)
                return
            buf += os.read(fd, 4096)
        slowest = max(slowest, time.monotonic() - t0)
    if slowest > BUDGET_S:
        failures.append("%s: slowest answer %.3f s (budget %.1f s)" % (label, slowest, BUDGET_S))
    print("%s: %d answers, the slowest in %.2f ms" % (label, count, slowest * 1000.0))


def slcan_status(buf):
    at = buf.find(b"t%03X8" % STATUS_OF_2)
    end = buf.find(b"\r", at) if at >= 0 else -1
    return end + 1 if end >= 0 else None


def usbcan_status(buf):
    while len(buf) >= 16:
        if buf[0] == 0xAA and buf[6:8] == STATUS_OF_2.to_bytes(2, "big"):
            return 16
        del buf[:16 if buf[0] == 0xAA else 1]
    return None


def bridged_answer(buf):
    end = buf.find(b"\n")
    if end < 0:
        return None
    if buf.startswith(b"error"):
        raise AssertionError("f 2 through the bridge: %r" % bytes(buf[:end]))
    return end + 1


def checks(sim, failures):
    pty, slcan, usbcan = (raw(p) for p in sim.paths)
    try:
        os.write(slcan, b"O\r")
        time.sleep(0.1)
        answered_within(slcan, b"t%03X8%s\r" % (2 << 5 | 0x1E, FAST_READ.hex().encode()),
                        slcan_status, 20, "--slcan fast read", failures)
        packet = bytes([0xAA, 0, 0, 8]) + (2 << 5 | 0x1E).to_bytes(4, "big") + FAST_READ
        answered_within(usbcan, packet, usbcan_status, 20, "--usbcan fast read", failures)
        try:
            answered_within(pty, b"f 2\n", bridged_answer, 10, "--bridge f 2", failures)
        except AssertionError as e:
            failures.append(str(e))
    finally:
        for fd in (pty, slcan, usbcan):
            os.close(fd)


if __name__ == "__main__":
    sys.exit(run("pty_bus_time", ["--drives", "3", "--tick-hz", "1", "--pty", "--bridge",
                                  "--slcan", "--usbcan"], 3, checks))
