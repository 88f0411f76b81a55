"""The same API over both links: three simulated drives on a pty (ASCII lines)
and on the simulator's slcan adapter (the vendor's CAN protocol, python-can)."""
import time

import pytest

import daran


def wait_until(predicate, timeout=3.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.01)
    return False


@pytest.fixture(params=["line", "can"])
def link(request):
    link = daran.sim(drives=3, can=request.param == "can", timeout=1.0, confirm=0.05)
    yield link
    link.close()


def test_queries(link):
    drive = link.drive(2)
    assert drive.info() == (100, 3, 2026000002)
    assert drive.position_velocity() == (0.0, 0.0)
    voltage, current = drive.voltage_current()
    assert voltage == pytest.approx(24, abs=0.5) and current == pytest.approx(0, abs=0.5)
    assert drive.state() == daran.State(0.0, 0.0, 0.0, True, 0)
    assert link.scan(range(1, 6), timeout=0.3) == [1, 2, 3]


def test_properties_keep_their_types(link):
    drive = link.drive(1)
    drive.props.axis.output_shaft.vel_limit = 300
    assert drive.props.axis.output_shaft.vel_limit == 300.0
    assert drive.props.axis.config.can_node_id == 1
    assert drive.props.axis.controller.trajectory_done is True
    assert drive.props.vbus_voltage == pytest.approx(24, abs=0.5)
    assert drive.props.serial_number == 2026000001
    drive.props.axis.config.extra_setting.stored_turns_counts = -5
    assert drive.props.axis.config.extra_setting.stored_turns_counts == -5


def test_motion_and_state(link):
    drive = link.drive(1)
    drive.trapezoid(90, 120, 300)
    assert wait_until(lambda: not drive.state().done)
    assert wait_until(lambda: drive.state().done and abs(drive.state().position - 90) < 0.5)
    drive.move_to(45, 50)
    assert wait_until(lambda: abs(drive.position_velocity()[0] - 45) < 0.5)
    drive.position(30)
    assert wait_until(lambda: abs(drive.position_velocity()[0] - 30) < 0.5)
    drive.velocity(60)
    assert wait_until(lambda: abs(drive.position_velocity()[1] - 60) < 1)
    drive.velocity(0, 100, 2)
    assert wait_until(lambda: abs(drive.position_velocity()[1]) < 1)
    drive.torque(0.05)
    assert wait_until(lambda: drive.props.axis.output_shaft.input_torque == pytest.approx(0.05))
    drive.impedance(10, 0, 0, 0.5, 0.01)
    assert wait_until(lambda: drive.props.axis.controller.config.input_mode == 9)
    drive.trapezoid(0)  # velocity and acceleration: the drive's own
    assert wait_until(lambda: abs(drive.position_velocity()[0]) < 0.5)


def test_estop_errors_and_recovery(link):
    drive = link.drive(3)
    drive.estop()
    assert wait_until(lambda: drive.errors().names["axis"] == ["ESTOP_REQUESTED"])
    assert drive.errors().registers["axis"] == 1 << 14
    assert drive.state().error
    drive.clear_errors()
    assert wait_until(lambda: not drive.errors())
    drive.enable()
    drive.trapezoid(10, 60, 300)
    assert wait_until(lambda: abs(drive.position_velocity()[0] - 10) < 0.5)


def test_move_together(link):
    link.move_together("trapezoid", {1: (30, 0.5, 300), 2: (-20, 0.5, 300), 3: (10, 0.5, 300)})
    drives = [link.drive(i) for i in (1, 2, 3)]
    assert wait_until(lambda: [round(d.position_velocity()[0]) for d in drives] == [30, -20, 10])
    for d in drives:
        d.preset(5, 0, 1)  # a velocity preset of 5 r/min, mode 1
    link.start("velocity")
    assert wait_until(lambda: all(abs(d.position_velocity()[1] - 5) < 0.5 for d in drives))


def test_set_zero_save_and_reboot(link):
    drive = link.drive(2)
    drive.trapezoid(20, 120, 300)
    assert wait_until(lambda: abs(drive.position_velocity()[0] - 20) < 0.1 and drive.state().done)
    drive.set_zero()
    assert wait_until(lambda: abs(drive.position_velocity()[0]) < 0.1)
    drive.props.axis.output_shaft.vel_limit = 250
    drive.save()
    drive.props.axis.output_shaft.vel_limit = 100
    drive.reboot()
    assert wait_until(lambda: drive.props.axis.output_shaft.vel_limit == 250)


def test_a_missing_drive_is_no_reply(link):
    link.timeout = 0.05
    with pytest.raises(daran.NoReply) as silent:
        link.drive(9).position_velocity()
    assert silent.value.result == daran.Result.ERR_NO_REPLY
