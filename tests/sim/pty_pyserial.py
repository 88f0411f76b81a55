#!/usr/bin/python3
"""Talks to `daran-sim --pty` the way the vendor's Python library does:
pyserial, lines with a trailing space, optional checksums, replies split on
whitespace and read up to their '\\n'. Exits 77 (skipped) without pyserial.

usage: pty_pyserial.py DARAN_SIM
"""
import os
import subprocess
import sys
import time

try:
    import serial
except ImportError:
    print("python3-serial is not installed: skipped")
    sys.exit(77)


def xor(text):
    value = 0
    for byte in text.encode("ascii"):
        value ^= byte
    return value


def main():
    if not os.path.exists("/dev/ptmx"):
        print("no /dev/ptmx on this machine: skipped")
        return 77
    # stdin stays open: directives still work in --pty mode
    sim = subprocess.Popen([sys.argv[1], "--drives", "2", "--pty"], stdin=subprocess.PIPE,
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    failures = []
    try:
        path = sim.stdout.readline().decode().strip()
        if not path.startswith("/dev/"):
            print("no pty path on the first line: %r" % path)
            return 1
        port = serial.Serial(path, 115200, timeout=2)

        def ask(line, checksum=False):
            text = line + " "
            if checksum:
                text += "*%d" % xor(text)
            port.write((text + "\n").encode("ascii"))
            reply = port.readline().decode("ascii")
            if not reply.endswith("\n"):
                failures.append("no complete reply to %r (got %r)" % (line, reply))
                return []
            reply = reply.rstrip("\n")
            if checksum:
                payload, _, value = reply.rpartition(" *")
                if xor(payload + " ") != int(value):
                    failures.append("bad reply checksum %r" % reply)
                reply = payload
            return reply.split()

        def tell(line):
            port.write((line + " \n").encode("ascii"))

        if ask("r axis1.config.can_node_id") != ["1"]:
            failures.append("id of drive 1")
        if ask("f 2", checksum=True) != ["0", "0"]:
            failures.append("f 2 with checksum")
        vbus, iq = (float(x) for x in ask("g 1"))
        if abs(vbus - 24.0) > 0.1 or abs(iq) > 0.5:
            failures.append("g 1: %r %r" % (vbus, iq))
        # a real-time move: 90 deg triangle at 60 (r/min)/s takes 1 s
        tell("q 1 90 60 60")
        time.sleep(0.3)
        done = ask("r axis1.controller.trajectory_done")
        if done != ["0"]:
            failures.append("trajectory_done during the move: %r" % done)
        deadline = time.time() + 5
        while ask("r axis1.controller.trajectory_done") != ["1"] and time.time() < deadline:
            time.sleep(0.05)
        time.sleep(0.5)
        pos, vel = (float(x) for x in ask("f 1", checksum=True))
        if abs(pos - 90.0) > 0.5 or abs(vel) > 1.0:
            failures.append("f 1 after the move: %r %r" % (pos, vel))
        reply = ask("t 1 nan")
        if reply[:1] != ["error:"] or any(c.isdigit() for c in " ".join(reply)):
            failures.append("error reply %r" % reply)
        # directives still work on stdin in --pty mode
        sim.stdin.write(b"!fault 2 overtemp\n")
        sim.stdin.flush()
        time.sleep(0.2)
        if ask("r axis2.error") != ["262144"]:  # DARAN_FLAG_OVERTEMP
            failures.append("fault injected on stdin not seen")
        port.close()
        # a client may reopen the port
        port = serial.Serial(path, 115200, timeout=2)
        if ask("f 2") == []:
            failures.append("no reply after reopening the port")
        port.close()
    finally:
        sim.terminate()
        try:
            sim.wait(timeout=5)
        except subprocess.TimeoutExpired:
            sim.kill()
            sim.wait()
    for failure in failures:
        print("FAIL:", failure)
    if sim.returncode not in (-15, 143):  # killed by SIGTERM, as a signal ends it
        print("FAIL: daran-sim exit status %d after SIGTERM" % sim.returncode)
        return 1
    print("pyserial on --pty: %s" % ("all checks passed" if not failures else "failed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
