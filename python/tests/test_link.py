"""What the line link adds (test_common.py has what both links do): the
drive's refusals as DriveRefused, discovery, raw lines, checksums."""
import time

import pytest

import daran
from daran import Result


def wait_until(predicate, timeout=3.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.01)
    return False


def test_props_read_and_write_each_as_its_type(sim3):
    drive = sim3.drive(1)
    drive.props.axis.output_shaft.vel_limit = 300
    assert drive.props.axis.output_shaft.vel_limit == 300.0
    assert type(drive.props.axis.output_shaft.vel_limit) is float
    assert drive.props.axis.config.can_node_id == 1 and type(drive.props.axis.config.can_node_id) is int
    assert drive.props.axis.controller.trajectory_done is True
    assert drive.props.vbus_voltage == pytest.approx(24, abs=0.5)  # a system property: the id goes last
    assert drive.props.serial_number == 2026000001  # u64
    drive.props.axis.config.extra_setting.enable_reply_state = True
    assert drive.props.axis.config.extra_setting.enable_reply_state is True
    drive.props.axis.config.extra_setting.stored_turns_counts = -5  # s32 keeps its sign
    assert drive.props.axis.config.extra_setting.stored_turns_counts == -5
    assert "output_shaft" in dir(drive.props.axis)
    with pytest.raises(AttributeError):
        drive.props.axis.output_shaft.no_such_thing
    with pytest.raises(AttributeError):
        drive.props.axis.output_shaft = 1  # a group, not a property


def test_a_refused_write_raises_with_the_drives_result(sim3):
    drive = sim3.drive(1)
    # a refusal ends the wait at once; a generous one keeps a loaded machine from
    # turning a late refusal into a silent success
    sim3.confirm = 2.0
    with pytest.raises(daran.DriveRefused) as refused:
        drive.props.vbus_voltage = 12
    assert refused.value.result == Result.ERR_READ_ONLY
    with pytest.raises(daran.DriveRefused) as refused:
        drive.props.axis.config.can_node_id = 0
    assert refused.value.result == Result.ERR_OUT_OF_RANGE
    with pytest.raises(daran.DriveRefused) as refused:
        drive.get("axis1.no.such.property")
    assert refused.value.result == Result.ERR_INVALID_PROPERTY
    with pytest.raises(ValueError):
        drive.set("axis1.config.can_node_id", 1.5)  # not an integer: refused before sending


def test_the_property_table_is_the_c_librarys():
    prop = daran.PROPERTIES["output_shaft.vel_limit"]
    assert (prop.type, prop.writable, prop.system, prop.unit) == (float, True, False, "r/min")
    assert daran.PROPERTIES["vbus_voltage"].system
    assert daran.PROPERTIES["config.can_node_id"].can == 31001


def test_refused_motion_raises_and_clear_errors_recovers(sim3):
    drive = sim3.drive(3)
    drive.estop(wait=0)
    errors = drive.errors()
    assert errors and errors.names["axis"] == ["ESTOP_REQUESTED"]
    assert errors.registers["axis"] == 1 << 14
    with pytest.raises(daran.DriveRefused) as refused:
        drive.trapezoid(10, 60, 60, wait=2.0)
    assert refused.value.result == Result.ERR_ESTOP_ACTIVE
    drive.clear_errors()
    assert not drive.errors()
    with pytest.raises(daran.DriveRefused) as refused:
        drive.trapezoid(10, 60, 60, wait=2.0)
    assert refused.value.result == Result.ERR_MOTOR_IDLE
    drive.enable()
    drive.trapezoid(10, 60, 600)
    assert wait_until(lambda: abs(drive.position_velocity()[0] - 10) < 0.5)


def test_move_together_starts_every_preset_at_once(sim3):
    sim3.move_together("trapezoid", {1: (30, 0.5, 600), 2: (-20, 0.5, 600), 3: (10, 0.5, 600)})
    drives = [sim3.drive(i) for i in (1, 2, 3)]
    assert wait_until(lambda: all(d.state().done for d in drives) and
                      abs(drives[0].position_velocity()[0] - 30) < 0.5)
    assert [round(d.position_velocity()[0]) for d in drives] == [30, -20, 10]
    with pytest.raises(daran.DriveRefused) as refused:
        sim3.drive(1).start("trapezoid", wait=2.0)  # the preset was consumed
    assert refused.value.result == Result.ERR_NO_PRESET




def test_discovery_gives_the_drives_own_table(sim3):
    drive = sim3.drive(1)
    table = drive.discover()
    assert table["output_shaft.vel_limit"].type is float
    assert set(table) == set(daran.PROPERTIES)
    assert drive.props.axis.output_shaft.vel_limit == drive.get("axis1.output_shaft.vel_limit")


def test_send_line_and_checksums():
    link = daran.sim(drives=1, checksum=True, timeout=1.0)
    try:
        assert link.send_line("f 1") == ["0 0"]
        assert link.drive(1).info()[0] == 100
    finally:
        link.close()


def test_a_closed_link_is_a_link_error(sim3):
    sim3.close()
    with pytest.raises(daran.LinkError):
        sim3.drive(1).position_velocity()


def test_drives_behind_a_gateway_work_as_on_a_direct_link():
    link = daran.sim(drives=3, args=("--bridge",), timeout=1.0)  # the line reaches drive 1 only
    try:
        behind = link.drive(3)
        assert behind.info() == (100, 3, 2026000003)
        behind.props.axis.output_shaft.vel_limit = 200
        assert behind.props.axis.output_shaft.vel_limit == 200.0
        behind.trapezoid(20, 60, 300)
        assert wait_until(lambda: behind.state().done
                          and abs(behind.position_velocity()[0] - 20) < 0.5)
        assert behind.errors().registers["axis"] == 0
    finally:
        link.close()


def test_scan_finds_the_drives_on_each_port():
    from daran._sim import Sim
    simulator = Sim(drives=2)
    try:
        assert daran.scan([simulator.pty], ids=range(1, 5), timeout=0.3) == {simulator.pty: [1, 2]}
    finally:
        simulator.close()
