"""What the tests of `daran` (the CLI) share: daran-sim on a pseudo-terminal
(--pty, one or more drives, --nvm when asked), running `daran` against it,
and a man in the middle that can cut the link. Paths come from the
environment CTest sets: DARAN_CLI (the tool), DARAN_SIM (daran-sim).
stdlib only; run by /usr/bin/python3."""
import os
import pty
import re
import sys
import select
import subprocess
import threading
import time
import tty
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "sim"))
import can_pty_support  # noqa: E402  (the simulator's pty tests' Sim and end_process)

DARAN = os.environ.get("DARAN_CLI", "daran")
SIM = os.environ.get("DARAN_SIM", "daran-sim")


class Sim(can_pty_support.Sim):
    """daran-sim --pty with @drives drives (and @options); .path is its
    pseudo-terminal. Its stdout (replies to lines typed on its stdin) and
    stderr are read in the background so it never blocks; directive()
    types a line on its stdin (`!fault 1 overtemp`)."""

    def __init__(self, drives=1, options=()):
        super().__init__(SIM, ["--pty", "--drives", str(drives)] + list(options), 1)
        self.path = self.paths[0]
        if not self.path.startswith("/dev/"):
            self.stop()
            raise RuntimeError("daran-sim printed no pty path: %r" % self.path)

    def directive_taken(self, line, timeout=10):
        """directive(line), and wait until daran-sim has taken it: `i 1`
        typed after it (drive 1's own query) is answered on stdout only once
        every line before it was."""
        seen = len(self.console)
        self.directive(line)
        self.directive("i 1")
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if any(re.match(r"^\d+ \d+ \d+\s*$", l) for l in self.console[seen:]):
                return
            time.sleep(0.005)
        raise AssertionError("daran-sim did not take %r within %s s" % (line, timeout))

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()


def daran(port, *args, stdin=None, timeout=60, env=None):
    """Run `daran --port PORT ARGS...`; the CompletedProcess (text)."""
    environment = dict(os.environ)
    environment.pop("DARAN_PORT", None)
    if env:
        environment.update(env)
    command = [DARAN] + (["--port", port] if port else []) + [str(a) for a in args]
    return subprocess.run(command, input=stdin, capture_output=True, text=True, timeout=timeout,
                          env=environment)


class Proxy:
    """A pseudo-terminal of our own between `daran` and the drive's: .path
    is what daran opens. Bytes flow both ways, daran's a whole line at a
    time; `cut_after(n)` lets n more bytes of the drive's side through, then
    closes daran's side (the link drops mid-reply); `drop_replies()` stops
    passing the drive's bytes (a drive that went silent); `before_line(
    matches, action)` calls action() before passing on the first line of
    daran's for which matches(text) is true (a fault at an exact request;
    matches None: none)."""

    def __init__(self, drive_path):
        self.master, slave = pty.openpty()
        tty.setraw(slave)
        self.path = os.ttyname(slave)
        self._slave = slave
        self.drive = os.open(drive_path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.drive)
        self.budget = None
        self.silent = False
        self._hook = None
        self._pending = b""
        self.closed = False
        self._stop = False
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def cut_after(self, n):
        self.budget = n

    def drop_replies(self):
        self.silent = True

    def before_line(self, matches, action):
        self._hook = (matches, action) if matches is not None else None

    def _pass_lines(self, data):
        self._pending += data
        *lines, self._pending = self._pending.split(b"\n")
        for line in lines:
            hook = self._hook
            if hook is not None and hook[0](line.decode("ascii", "replace")):
                self._hook = None
                hook[1]()
            os.write(self.drive, line + b"\n")

    def _run(self):
        while not self._stop and not self.closed:
            ready, _, _ = select.select([self.master, self.drive], [], [], 0.05)
            for fd in ready:
                try:
                    data = os.read(fd, 4096)
                except OSError:
                    continue
                if fd == self.master:
                    self._pass_lines(data)
                    continue
                if self.silent:
                    continue
                if self.budget is not None:
                    data = data[:self.budget]
                    self.budget -= len(data)
                os.write(self.master, data)
                if self.budget == 0:
                    time.sleep(0.05)
                    os.close(self.master)
                    os.close(self._slave)
                    self.closed = True
                    break

    def close(self):
        self._stop = True
        self.thread.join(timeout=2)
        for fd in ([] if self.closed else [self.master, self._slave]) + [self.drive]:
            try:
                os.close(fd)
            except OSError:
                pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def main():
    unittest.main(verbosity=2)
