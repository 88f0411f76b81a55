"""What is the CAN link's own: replies matched by node, code and address;
bus faults give NoReply for exactly the lost requests; values that do not fit
a frame's field are refused before anything is sent."""
import time

import pytest

import daran


@pytest.fixture
def can_link():
    link = daran.sim(drives=3, can=True, retries=0, timeout=1.0)
    yield link
    link.close()


def settle(link):
    time.sleep(0.05)  # a directive on the simulator's stdin is taken between two ticks


def test_lost_frames_are_no_reply_for_exactly_those_requests(can_link):
    drive = can_link.drive(2)
    can_link.sim.fault(2, "can-lose", 2)
    settle(can_link)
    outcomes = []
    for _ in range(5):
        try:
            outcomes.append(drive.get("config.can_node_id"))
        except daran.NoReply:
            outcomes.append("no reply")
    assert outcomes == ["no reply", "no reply", 2, 2, 2]


def test_a_mute_drive_is_no_reply_until_it_recovers(can_link):
    can_link.sim.fault(3, "can-mute")
    settle(can_link)
    with pytest.raises(daran.NoReply):
        can_link.drive(3).state()
    assert can_link.drive(1).state().done  # the others answer
    can_link.sim.fault(3, "can-recover")
    settle(can_link)
    assert can_link.drive(3).position_velocity() == (0.0, 0.0)


def test_a_query_is_retried_after_a_lost_reply_a_command_is_not():
    link = daran.sim(drives=2, can=True, retries=1, timeout=1.0)
    try:
        link.sim.fault(1, "can-lose", 1)
        settle(link)
        assert link.drive(1).get("config.can_node_id") == 1  # the second attempt
    finally:
        link.close()


def test_replies_are_matched_not_taken_because_they_came_next(can_link):
    drive = can_link.drive(2)
    drive.props.axis.config.extra_setting.enable_reply_state = True
    for position in range(5):
        drive.move_to(position)  # each answered by a status frame nobody asked for
        assert drive.get("config.can_node_id") == 2
        assert drive.props.vbus_voltage == pytest.approx(24, abs=0.5)
    assert can_link.unmatched > 0


def test_values_beyond_a_frames_field_are_refused_before_sending(can_link):
    drive = can_link.drive(1)
    with pytest.raises(daran.DaranError) as refused:
        drive.trapezoid(10, 400, 60)  # 400 r/min is beyond s16 x 100
    assert refused.value.result == daran.Result.ERR_OUT_OF_RANGE
    with pytest.raises(daran.DaranError) as refused:
        drive.move_to(float("nan"))
    assert refused.value.result == daran.Result.ERR_INVALID_VALUE
    assert drive.state().done and drive.position_velocity() == (0.0, 0.0)
    with pytest.raises(ValueError):
        can_link.drive(0).position_velocity()  # every drive would answer
