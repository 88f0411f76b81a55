"""The pytest fixtures of the package (registered through the `pytest11`
entry point when daran is installed):

    def test_my_script(daran_sim):           # three simulated drives on a pty
        drive = daran_sim.drive(1)
        drive.trapezoid(90, 60, 120)

`daran_sim_can` is the same on the simulator's slcan adapter (python-can).
Their replies may wait a second: a simulator on a loaded CI machine can be
slow to answer, and a drive that answers ends the wait at once (only a test
of silence pays it: give that link a short `timeout` of its own)."""
import pytest


@pytest.fixture
def daran_sim():
    """A link to three simulated drives (daran-sim --drives 3 --pty)."""
    import daran
    link = daran.sim(drives=3, timeout=1.0, confirm=0.05)
    yield link
    link.close()


@pytest.fixture
def daran_sim_can():
    """A CAN link to three simulated drives (daran-sim --drives 3 --slcan)."""
    import daran
    link = daran.sim(drives=3, can=True, timeout=1.0)
    yield link
    link.close()
