"""The retry rule over an in-memory transport: a query is sent again after a
damaged reply, a command that moves never is."""
import pytest

import daran
from daran.link import Link
from conftest import ScriptedTransport


def damaged(line):
    return b"12 *1\n"  # a wrong checksum on every reply


def test_a_query_is_retried_after_a_damaged_reply():
    transport = ScriptedTransport(damaged)
    link = Link(transport, checksum=True, retries=2, quiet=0.001, timeout=0.01)
    with pytest.raises(daran.LinkError) as damage:
        link.drive(1).position_velocity()
    assert damage.value.result == daran.Result.ERR_CHECKSUM_MISMATCH
    assert len(transport.writes) == 3


@pytest.mark.parametrize("move", [
    lambda d: d.trapezoid(10, 20, 30), lambda d: d.move_to(1), lambda d: d.velocity(5),
    lambda d: d.torque(0.1), lambda d: d.impedance(1, 2, 3, 4, 5), lambda d: d.set_zero(),
    lambda d: d.start("trapezoid", True)])
def test_a_command_that_moves_is_sent_once(move):
    transport = ScriptedTransport(damaged)
    link = Link(transport, checksum=True, retries=2, quiet=0.001, confirm=0.01)
    with pytest.raises(daran.LinkError):
        move(link.drive(1))
    assert len(transport.writes) == 1


def test_a_port_that_cannot_write_is_a_link_error():
    class Refusing(ScriptedTransport):
        def write(self, data):
            raise OSError("unplugged")
    link = Link(Refusing(damaged))
    with pytest.raises(daran.LinkError) as failed:
        link.drive(1).trapezoid(1)
    assert "unplugged" in str(failed.value)


def test_requests_are_built_by_the_c_client():
    transport = ScriptedTransport(lambda line: b"")
    link = Link(transport, checksum=True, confirm=0)
    link.drive(1).move_to(10, 25)
    link.drive(1).set("axis1.config.can_node_id", 5)
    assert transport.writes == [b"t 1 10 0 25 *83\n", b"w axis1.config.can_node_id 5 *59\n"]
