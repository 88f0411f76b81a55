"""Pieces shared by the daran-record tests and the vendor-session generator:
daran-sim on a PTY, daran-record in front of it, a pyserial client on the
recorder's PTY, and a reader of the recordings format."""
import os
import re
import select
import signal
import subprocess
import sys
import time

SKIP = 77
START_TIMEOUT_S = 5.0

# A data line of a recording: an optional `<` (a reply), SECONDS with 4
# decimals, a tab, the line's bytes.
DATA_LINE = re.compile(rb"^(<?)(\d+\.\d{4})\t(.*)$", re.DOTALL)


def need_pyserial():
    """The serial module, or exit 77 (skipped) when python3-serial or
    /dev/ptmx is missing."""
    try:
        import serial
    except ImportError:
        print("python3-serial is not installed: skipped")
        sys.exit(SKIP)
    if not os.path.exists("/dev/ptmx"):
        print("no /dev/ptmx on this machine: skipped")
        sys.exit(SKIP)
    return serial


def first_line(proc, what):
    """The first line of a child's stdout, within START_TIMEOUT_S."""
    ready, _, _ = select.select([proc.stdout], [], [], START_TIMEOUT_S)
    if not ready:
        raise RuntimeError(f"{what} printed no first line in {START_TIMEOUT_S} s")
    return proc.stdout.readline().decode().strip()


def start_sim(sim, drives=1):
    """daran-sim --pty in real time: (process, its PTY path). Its stdin stays
    open (closing it does not stop it, but keeps it idle)."""
    proc = subprocess.Popen([sim, "--drives", str(drives), "--pty"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    path = first_line(proc, "daran-sim --pty")
    if not path.startswith("/dev/"):
        raise RuntimeError(f"daran-sim --pty: no PTY path on the first line: {path!r}")
    return proc, path


def start_recorder(record, device, out, *options):
    """daran-record between `device` and a new PTY: (process, the client's PTY path)."""
    proc = subprocess.Popen([record, "--device", device, "--out", out, *options],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    path = first_line(proc, "daran-record")
    if not path.startswith("/dev/"):
        raise RuntimeError(f"daran-record: no PTY path on the first line: {path!r}")
    return proc, path


def stop(proc, sig=signal.SIGTERM, timeout=5.0):
    """Send `sig` and wait: the exit status, or None if it did not end."""
    if proc.poll() is None:
        proc.send_signal(sig)
    try:
        return proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        return None


class Client:
    """A vendor-style client: pyserial, whole lines out, the replies it
    expects read line by line up to their \\n."""

    def __init__(self, serial, path, timeout=2.0):
        self.port = serial.Serial(path, 115200, timeout=timeout)
        self.received = bytearray()  # every byte the client read, unchanged

    def ask(self, line, replies):
        """Send `line` (bytes, without \\n); read `replies` lines; returns them
        as read (with their line end)."""
        self.port.write(line + b"\n")
        return [self.read_line() for _ in range(replies)]

    def tell(self, data):
        self.port.write(data)
        self.port.flush()

    def read_line(self):
        reply = self.port.readline()
        self.received += reply
        if not reply.endswith(b"\n"):
            raise RuntimeError(f"no whole reply line in time (got {reply!r})")
        return reply

    def close(self):
        self.port.close()


def read_recording(path):
    """(comment lines, data lines [(is_reply, seconds text, bytes)], raw bytes)."""
    with open(path, "rb") as f:
        raw = f.read()
    comments, data = [], []
    for line in raw.split(b"\n")[:-1] if raw.endswith(b"\n") else raw.split(b"\n"):
        if line.startswith(b"#"):
            comments.append(line)
            continue
        m = DATA_LINE.match(line)
        if m is None:
            raise RuntimeError(f"{path}: not a recording line: {line[:80]!r}")
        data.append((m.group(1) == b"<", m.group(2).decode(), m.group(3)))
    return comments, data, raw


def wait_for(predicate, timeout):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.02)
    return predicate()
