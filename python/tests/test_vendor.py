"""daran.vendor against the vendor's own serial library: the same calls send
the same requests as /work/shared/recordings/vendor-python-client.txt (the
lines a script produced with DrEmpower_ascii.py v2.0), as daran-sim records
them, and the drive accepts every one of them."""
import struct

import pytest

import daran
import daran.vendor as dr
from conftest import RECORDINGS


def the_vendors_script():
    """The calls behind vendor-python-client.txt, in its order."""
    dr.get_id()
    dr.get_state(1)
    dr.get_volcur(1)
    dr.dump_error(1)
    dr.set_angle(1, 90, 0, 25, 0)
    dr.set_angle(1, -45.5, 30, 10, 1)
    dr.set_angle(1, 12.25, 5, 0.3, 2)
    dr.step_angle(1, 30, 10, 10, 1)
    dr.set_angles([1, 2, 3], [10, -20, 30], 10, 10, 0)
    dr.set_angles([1, 2, 3], [40, 50, -60], 10, 10, 1)
    dr.set_angles([1, 2, 3], [0, 0, 0], 5, 0.1, 2)
    dr.step_angles([1, 2], [15, -15], 10, 10, 1)
    dr.set_speed(1, 20, 0.5, 1)
    dr.set_speed(1, 12.5, 2.5, 2)
    dr.set_speeds([1, 2, 3], [10, 20, 30], 0, 1)
    dr.set_torque(1, 0.1, 0, 1)
    dr.set_torque(1, 0.1, 0.02, 6)
    dr.set_torques([1, 2, 3], [0.1, 0.2, 0.3], 0, 1)
    dr.impedance_control(1, 10, 0, 0.5, 0.1, 0.01)
    dr.estop(1)
    dr.clear_error(1)
    dr.set_mode(1, 2)
    dr.set_mode(1, 1)
    dr.set_mode(1, 2)
    dr.set_zero_position(1)
    dr.write_property(1, "axis0.controller.config.pos_gain", 25)
    assert dr.read_property(1, "axis0.controller.config.pos_gain") == 25
    assert dr.read_property(1, "config.uart_baudrate") == 115200
    assert dr.read_property(1, "vbus_voltage") == pytest.approx(24, abs=0.5)
    dr.position_done(1)
    assert dr.set_angle_range(1, -180, 180) is True
    dr.save_config(1)
    dr.positions_done([1])


def requests(lines):
    """Each line as (word, fields): numbers as the float32 a drive reads, the
    checksum's presence (its value is each end's own: the vendor sums the trailing space)."""
    out = []
    for line in lines:
        text, star, _ = line.rstrip().rpartition("*") if "*" in line else (line, "", "")
        fields = []
        for token in text.split():
            try:
                fields.append(struct.unpack("f", struct.pack("f", float(token)))[0])
            except ValueError:
                fields.append(token)
        out.append((tuple(fields), bool(star)))
    return out


def sections(path):
    """The recording's two sections (checksums off, on) as lists of lines."""
    parts, current = [], None
    for line in path.read_text().splitlines():
        if line.startswith("# checksums"):
            current = []
            parts.append(current)
        elif not line.startswith("#") and current is not None:
            current.append(line.split("\t", 1)[1])
    return parts


def test_the_vendors_script_sends_the_vendors_requests(tmp_path, capsys):
    record = tmp_path / "record.txt"
    link = daran.sim(drives=3, args=("--record", str(record)), confirm=0.005, timeout=1.0)
    late_errors = link.late_errors  # a refusal that came after its wait
    try:
        dr.connect(link)
        dr.CHECK_FLAG = 0
        dr.cur_angle_list = []
        the_vendors_script()
        dr.CHECK_FLAG = 1
        the_vendors_script()
    finally:
        dr.CHECK_FLAG = 0
        link.close()
    printed = capsys.readouterr().out
    assert "---error" not in printed and not late_errors  # the drive took every line
    sent = [line.split("\t", 1)[1] for line in record.read_text().splitlines()
            if not line.startswith("#")]
    off, on = sections(RECORDINGS / "vendor-python-client.txt")
    assert requests(sent) == requests(off) + requests(on)


def test_a_read_that_fails_returns_none_and_sets_read_flag(capsys):
    link = daran.sim(drives=1, timeout=0.05, confirm=1.0)
    try:
        dr.connect(link)
        assert dr.get_state(5) is None and dr.READ_FLAG == -1
        link.timeout = 1.0
        assert dr.get_state(1) == [0.0, 0.0] and dr.READ_FLAG == 1
        assert dr.read_property(1, "axis0.no_such") is None and dr.READ_FLAG == -1
        link.confirm = 0
        dr.estop(1)
        link.confirm = 1.0  # the refusal ends the wait
        assert dr.set_angle(1, 10, 10, 10, 1) is False  # refused: the vendor's returns True
        assert dr.send_command("x 1") is False  # unknown command: the refusal ends the wait
        link.confirm = 0.05
        assert dr.send_command("sc 1", 1) is True
    finally:
        link.close()
