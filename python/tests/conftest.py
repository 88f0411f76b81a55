"""The package's tests run against the host build's daran-sim (DARAN_SIM, or
the checkout's build/host) through the installed package."""
import os
import pathlib

import pytest

SIM = pathlib.Path(__file__).resolve().parents[2] / "build/host/port/sim/daran-sim"
os.environ.setdefault("DARAN_SIM", str(SIM))
RECORDINGS = pathlib.Path(os.environ.get(
    "DARAN_RECORDINGS", pathlib.Path(__file__).resolve().parents[2] / "examples/recordings"))


@pytest.fixture
def sim3(daran_sim):
    """Three simulated drives on a pty (the package's own fixture)."""
    return daran_sim


class ScriptedTransport:
    """A transport in memory: records each write, answers with `reply(line)`."""

    def __init__(self, reply):
        self.reply = reply
        self.writes = []
        self.pending = b""
        self.closed = False

    def write(self, data):
        self.writes.append(bytes(data))
        for line in bytes(data).splitlines():
            self.pending += self.reply(line.decode())
        return True

    def read(self, size, timeout_ms):
        data, self.pending = self.pending[:size], self.pending[size:]
        return data

    def wait(self, seconds):
        pass

    def close(self):
        self.closed = True
