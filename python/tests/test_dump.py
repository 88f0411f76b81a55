"""dump()/restore() in the CLI's file format, read by the CLI's own reader."""
import subprocess

import pytest

import daran

def test_a_dump_restored_into_another_drive_copies_its_configuration(sim3, tmp_path):
    sim3.confirm = 0.002  # a pty answers a refusal within 0.1 ms
    one, two = sim3.drive(1), sim3.drive(2)
    one.props.axis.output_shaft.vel_limit = 450
    one.props.axis.controller.config.pos_gain = 33
    text = one.dump(tmp_path / "drive1.txt")
    assert text.startswith("# daran-python ") and "# firmware 100, hardware 3" in text
    assert "w axis1.output_shaft.vel_limit 450\n" in text
    assert "# node id 1 (not restored)" in text
    assert "# w axis1.requested_state 8  (not restored: the drive's state" in text
    assert "config.can_node_id" not in text.replace("# node id", "")
    assert two.restore(tmp_path / "drive1.txt") == []
    assert two.props.axis.output_shaft.vel_limit == 450.0
    assert two.props.axis.controller.config.pos_gain == 33.0
    assert two.props.axis.config.can_node_id == 2


def test_a_refused_line_puts_the_previous_values_back(sim3, tmp_path):
    sim3.confirm = 0.002
    drive = sim3.drive(3)
    sim3.confirm = 0  # the refusal then comes late: restore finds it at the read-back
    lines = drive.dump().splitlines()
    before = drive.props.axis.output_shaft.vel_limit
    for i, line in enumerate(lines):
        if line.startswith("w axis3.output_shaft.vel_limit "):
            lines[i] = "w axis3.output_shaft.vel_limit 123"
        if line.startswith("w axis3.telemetry.fields "):  # after vel_limit in the file
            lines[i] = "w axis3.telemetry.fields 9999"
    path = tmp_path / "bad.txt"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(daran.DriveRefused) as refused:
        drive.restore(path)
    assert refused.value.result == daran.Result.ERR_OUT_OF_RANGE
    assert drive.props.axis.output_shaft.vel_limit == before


def test_a_file_that_is_not_a_dump_is_refused_before_anything_is_sent(sim3, tmp_path):
    path = tmp_path / "not.txt"
    path.write_text("# firmware 100\nw axis1.output_shaft.vel_limit fast\n")
    with pytest.raises(ValueError, match="not.txt:2"):
        sim3.drive(1).restore(path)
    path.write_text("w axis1.output_shaft.vel_limit 100\n")
    with pytest.raises(ValueError, match="firmware"):
        sim3.drive(1).restore(path)
    path.write_text("# firmware 101\nw axis1.output_shaft.vel_limit 100\n")
    with pytest.raises(ValueError, match="firmware 101"):
        sim3.drive(1).restore(path)
    assert sim3.drive(1).restore(path, force=True) == []


def test_the_cli_restores_a_python_dump(sim3, tmp_path):
    import pathlib
    cli = pathlib.Path(__file__).resolve().parents[2] / "build/host/cli/daran"
    if not cli.exists():
        pytest.skip("no build/host/cli/daran")
    sim3.drive(1).props.axis.output_shaft.vel_limit = 321
    sim3.drive(1).dump(tmp_path / "d.txt")
    sim3.close()
    link = daran.sim(drives=2, timeout=1.0)
    try:
        done = subprocess.run([str(cli), "--port", link.sim.pty, "restore", "2", str(tmp_path / "d.txt")],
                              capture_output=True, text=True, timeout=30)
        assert done.returncode == 0, done.stderr + done.stdout
        assert link.drive(2).props.axis.output_shaft.vel_limit == 321.0
    finally:
        link.close()
