"""What every link offers beside its transport: drives, synchronised starts,
telemetry, scan."""
import time

from ._link import LineLink
from .drive import STARTS, Drive
from .errors import NoReply


class LinkAPI:
    """Mixed into each link class (a line link, a CAN link)."""

    sim = None  # the Sim of daran.sim()

    def drive(self, drive_id):
        """Drive `drive_id` (1..63; 0 addresses every drive, for commands)."""
        return Drive(self, drive_id)

    def start(self, kind, relative=False, *, wait=None):
        """Start the presets of every drive at once (a broadcast start) as `kind`:
        filtered, trapezoid, passthrough, velocity, torque."""
        self.drive(0).start(kind, relative, wait=wait)

    def move_together(self, kind, presets, relative=False, *, wait=None):
        """Preset each drive of `presets` ({id: (p1, p2, p3)}) and start them in one
        broadcast, so they move together. p1..p3 as `ms` takes them for the start kind
        (trapezoid: position, duration s, acceleration)."""
        if kind not in STARTS:
            raise ValueError(f"{kind!r}: one of {', '.join(STARTS)}")
        for drive_id, values in presets.items():
            self.drive(drive_id).preset(*values, wait=wait)
        self.start(kind, relative, wait=wait)

    def scan(self, ids=range(1, 64), timeout=0.02):
        """The ids that answer `f` within `timeout` s each."""
        found = []
        saved, self.timeout = self.timeout, timeout
        try:
            for drive_id in ids:
                try:
                    self.query("F", drive_id, 2, None)
                    found.append(drive_id)
                except NoReply:
                    pass
        finally:
            self.timeout = saved
        return found

    def telemetry(self, timeout=None):
        """Telemetry reports as they come (a drive's `axis0.telemetry.*` settings
        start them); ends after `timeout` s without one (None: never)."""
        last = time.monotonic()
        while True:
            if self.reports:
                last = time.monotonic()
                yield self.reports.popleft()
                continue
            if timeout is not None and time.monotonic() - last > timeout:
                return
            self.wait_input(0.01)
            self.service()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        super().close()
        if self.sim is not None:
            self.sim.close()


class Link(LinkAPI, LineLink):
    """Drives on a line (a serial port, a bridge's line): `daran.open()`."""

    def wait_input(self, seconds):
        """Wait until bytes arrive or `seconds` pass (telemetry)."""
        self._transport.wait(seconds)
