"""`daran.sim()`: the simulated drives (daran-sim) on a pseudo-terminal, for
tests without hardware. The program is $DARAN_SIM, else `daran-sim` on the
PATH, else the host build of the checkout the package was built from."""
import collections
import os
import pathlib
import shutil
import subprocess
import threading
import weakref

_CHECKOUT_SIM = pathlib.Path(__file__).resolve().parents[2] / "build/host/port/sim/daran-sim"


def _stop(process):
    if process.poll() is None:
        process.terminate()  # with --pty it runs until a signal, as a drive would
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
    process.stdin.close()


def _drain(stream, lines):
    for line in iter(stream.readline, b""):
        lines.append(line.decode(errors="replace").rstrip("\n"))


def sim_program():
    """The daran-sim program to run."""
    for candidate in (os.environ.get("DARAN_SIM"), shutil.which("daran-sim"), _CHECKOUT_SIM):
        if candidate and os.access(candidate, os.X_OK):
            return str(candidate)
    raise FileNotFoundError("daran-sim not found: set DARAN_SIM, or put it on the PATH")


class Sim:
    """A running daran-sim: `.pty` (the line's port), `.slcan` (the CAN adapter's
    port, with can=True); directives go to its stdin (`fault`, `directive`)."""

    def __init__(self, drives=3, can=False, args=()):
        command = [sim_program(), "--drives", str(drives), "--pty"]
        if can:
            command.append("--slcan")
        command += list(args)
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE)
        # a simulator outlives no script: stopped at exit when nobody closed it
        self._finalizer = weakref.finalize(self, _stop, self.process)
        self.pty = self._path_line()
        self.slcan = self._path_line() if can else None
        #: the simulator's last output lines (with --can it prints every frame on the bus)
        self.output = collections.deque(maxlen=1000)
        self.errors = collections.deque(maxlen=1000)
        # read both pipes all the time: a full pipe would stop the simulator
        for stream, lines in ((self.process.stdout, self.output), (self.process.stderr, self.errors)):
            threading.Thread(target=_drain, args=(stream, lines), daemon=True).start()

    def _path_line(self):
        line = self.process.stdout.readline().decode().strip()
        if not line.startswith("/dev/"):
            self.close()
            raise RuntimeError(f"daran-sim did not start: {line!r} "
                               f"{self.process.stderr.read().decode()!r}")
        return line

    def directive(self, text):
        """Send a line to the simulator's console (`!fault 2 can-mute`, `!load 1 0.2`)."""
        self.process.stdin.write(text.encode() + b"\n")
        self.process.stdin.flush()

    def fault(self, drive_id, kind, *args):
        """`!fault ID KIND [ARGS]` (docs/simulator.md): stall, overtemp, can-lose N, ..."""
        self.directive(" ".join(["!fault", str(drive_id), kind, *map(str, args)]))

    def close(self):
        self._finalizer()


def sim(drives=3, can=False, args=(), **link_options):
    """Start daran-sim with `drives` drives and return an open link to them: over
    the pty, or with can=True over its slcan adapter (python-can). The link's
    `.sim` is the Sim; closing the link stops it."""
    from . import open as open_serial, open_can

    simulator = Sim(drives, can, args)
    try:
        if can:
            import can as python_can
            bus = python_can.Bus(interface="slcan", channel=simulator.slcan, bitrate=1000000,
                                 sleep_after_open=0)
            link = open_can(bus, **link_options)
        else:
            link = open_serial(simulator.pty, **link_options)
    except BaseException:
        simulator.close()
        raise
    link.sim = simulator
    return link
