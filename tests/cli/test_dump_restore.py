"""`daran dump` and `daran restore` against daran-sim --pty (docs/cli.md,
"dump, restore"): a dump of one drive restored into another gives the same
read-write values except the node id; a refused line leaves the drive as it
was; a file from another firmware needs --force; --save survives a power
cycle; a drive that does not answer is exit status 3."""
import json
import os
import re
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_support import Sim, daran, main  # noqa: E402

# Settings of drive 1 that differ from the simulated drive's defaults:
# axis and system rows, floats, integers, a bool, a signed value.
SETTINGS = [
    ("output_shaft.vel_limit", "450"),
    ("controller.config.pos_gain", "31.25"),
    ("motor.config.pole_pairs", "12"),
    ("motor.config.direction", "-1"),
    ("config.extra_setting.enable_stall_limit", "1"),
    ("fet_thermistor.config.temp_limit_upper", "95.5"),
    ("config.dc_bus_overvoltage_trip_level", "48"),
    ("config.uart_baudrate", "57600"),
]


def rw_values(port, drive):
    """Every read-write property of `drive`, as `h ID properties` lists it,
    read with `r`: {discovery path: value text}."""
    listing = daran(port, "send", "h %d properties" % drive)
    assert listing.returncode == 0, listing.stderr
    paths = [f[0] for f in (line.split() for line in listing.stdout.splitlines())
             if len(f) >= 4 and f[2] == "rw"]
    assert len(paths) > 50, listing.stdout
    got = daran(port, "get", drive, *paths)
    assert got.returncode == 0, got.stderr
    values = dict(line.split(" ", 1) for line in got.stdout.splitlines())
    assert sorted(values) == sorted(paths)
    return values


def write_lines(text):
    return [line for line in text.splitlines() if line.startswith("w ")]


class DumpRestore(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = Sim(drives=3)
        cls.port = cls.sim.path
        cls.dir = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.sim.stop()
        cls.dir.cleanup()

    def file(self, name, text=None):
        path = os.path.join(self.dir.name, name)
        if text is not None:
            with open(path, "w") as f:
                f.write(text)
        return path

    def run_ok(self, *args):
        r = daran(self.port, *args)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")
        return r

    def dump(self, drive, name):
        path = self.file(name)
        self.run_ok("dump", drive, "--out", path)
        with open(path) as f:
            return path, f.read()

    def test_dump_of_drive_1_restored_into_drive_2(self):
        settings = [a for pair in SETTINGS for a in pair]
        self.run_ok("set", 1, *settings)
        before_2 = rw_values(self.port, 2)
        path, text = self.dump(1, "drive1.txt")

        # The header: tool, drive, its `i` line, the date, the node id.
        version = self.run_ok("send", "i 1").stdout.split()
        head = [line for line in text.splitlines() if line.startswith("#")][:5]
        self.assertRegex(head[0], r"^# daran \d+\.\d+\.\d+: dump of drive 1$")
        self.assertEqual(head[1], "# firmware %s, hardware %s, serial number %s" % tuple(version))
        self.assertRegex(head[2], r"^# date \d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$")
        self.assertEqual(head[3], "# node id 1 (not restored)")
        self.assertNotIn("can_node_id", text)
        # Literal lines for drive 1: the id in axisN. or last.
        lines = write_lines(text)
        self.assertIn("w axis1.output_shaft.vel_limit 450", lines)
        self.assertIn("w axis1.motor.config.direction -1", lines)
        self.assertIn("w config.dc_bus_overvoltage_trip_level 48 1", lines)
        self.assertIn("w config.uart_baudrate 57600 1", lines)
        # State and setpoints are comments saying why, never `w` lines.
        for path_ in ("output_shaft.input_pos", "requested_state", "controller.error",
                      "controller.config.control_mode", "telemetry.period"):
            self.assertFalse([l for l in lines if (".%s " % path_) in l], path_)
            self.assertRegex(text, r"(?m)^# w axis1\.%s \S+  \(not restored: .+\)$"
                             % re.escape(path_))

        restore = self.run_ok("restore", 2, path)
        self.assertIn("drive 2: %d properties restored" % len(lines), restore.stdout)

        after_1 = rw_values(self.port, 1)
        after_2 = rw_values(self.port, 2)
        node = "axis0.config.can_node_id"
        self.assertEqual((after_1.pop(node), after_2.pop(node)), ("1", "2"))
        before_2.pop(node)
        self.assertEqual(after_1, after_2)
        # the restore did something: drive 2 had other values before
        for name, value in SETTINGS:
            key = name if name in ("config.dc_bus_overvoltage_trip_level",
                                   "config.uart_baudrate") else "axis0." + name
            self.assertNotEqual(before_2[key], value, key)
            self.assertEqual(after_2[key], value, key)
        self.assertEqual(len(self.run_ok("send", "i 2").stdout.split()), 3)  # still drive 2

    def test_json_dump_holds_the_same_lines(self):
        text = self.run_ok("dump", 3).stdout
        doc = json.loads(self.run_ok("--json", "dump", 3).stdout)
        version = self.run_ok("send", "i 3").stdout.split()
        self.assertEqual([str(doc["firmware"]), str(doc["hardware"]), str(doc["serial_number"])],
                         version)
        self.assertEqual((doc["id"], doc["node_id"], doc["source"]), (3, 3, "discovery"))
        restored = [p["line"] for p in doc["properties"] if "not_restored" not in p]
        self.assertEqual(restored, write_lines(text))
        kept_out = {p["path"]: p["not_restored"] for p in doc["properties"]
                    if "not_restored" in p}
        self.assertIn("setpoint", kept_out["axis0.output_shaft.input_pos"])
        self.assertIn("error register", kept_out["can.error"])

    def test_dump_with_checksums_while_telemetry_streams(self):
        plain = write_lines(self.run_ok("dump", 1).stdout)
        self.run_ok("set", 1, "telemetry.period", "0.01")
        try:
            time.sleep(0.05)  # reports are on the line
            r = daran(self.port, "--checksum", "dump", 1)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(write_lines(r.stdout), plain)
            self.assertIn("# w axis1.telemetry.period 0.01  (not restored:", r.stdout)
        finally:
            self.run_ok("set", 1, "telemetry.period", "0")

    def test_refused_line_leaves_the_drive_as_it_was(self):
        before = rw_values(self.port, 3)
        _, text = self.dump(3, "drive3.txt")
        lines = text.splitlines()
        # change values early in the file (written, then taken back) and
        # put an out-of-range value in the middle
        edits = {"w axis3.config.calibration_lockin.accel ": "33",
                 "w axis3.controller.config.vel_gain ": "0.75",
                 "w axis3.motor.config.current_lim ": "-5"}
        refused_at = None
        for i, line in enumerate(lines):
            for head, value in edits.items():
                if line.startswith(head):
                    lines[i] = head + value
                    if value == "-5":
                        refused_at = i + 1
        self.assertIsNotNone(refused_at)
        self.assertGreater(refused_at, len(lines) // 3)
        bad = self.file("refused.txt", "\n".join(lines) + "\n")

        r = daran(self.port, "--json", "restore", 3, bad)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertIn("%s:%d: drive 3 refused `w axis3.motor.config.current_lim -5`: value out "
                      "of range" % (bad, refused_at), r.stderr)
        self.assertIn("previous values are back", r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual((doc["complete"], doc["rolled_back"]), (False, True))
        self.assertEqual(doc["failed"]["line"], refused_at)
        self.assertGreater(doc["written"], 10)  # the early lines did go out
        self.assertEqual(rw_values(self.port, 3), before)

    def test_file_from_another_firmware(self):
        _, text = self.dump(3, "firmware.txt")
        firmware = re.search(r"(?m)^# firmware (\d+),", text).group(1)
        other = str(int(firmware) + 1)
        changed = text.replace("# firmware %s," % firmware, "# firmware %s," % other)
        changed = re.sub(r"(?m)^w axis3\.output_shaft\.torque_lim .*$",
                         "w axis3.output_shaft.torque_lim 7.5", changed)
        path = self.file("other-firmware.txt", changed)
        old = self.run_ok("get", 3, "output_shaft.torque_lim").stdout
        self.assertNotEqual(old, "output_shaft.torque_lim 7.5\n")

        r = daran(self.port, "restore", 3, path)
        self.assertEqual(r.returncode, 1)
        self.assertIn("dumped from firmware %s; drive 3 runs firmware %s" % (other, firmware),
                      r.stderr)
        self.assertEqual(self.run_ok("get", 3, "output_shaft.torque_lim").stdout, old)

        self.run_ok("restore", 3, path, "--force")
        self.assertEqual(self.run_ok("get", 3, "output_shaft.torque_lim").stdout,
                         "output_shaft.torque_lim 7.5\n")
        self.run_ok("restore", 3, self.file("firmware.txt"))
        self.assertEqual(self.run_ok("get", 3, "output_shaft.torque_lim").stdout, old)

    def test_every_difference_is_reported(self):
        # two views of one value (turn/s and r/min): the later line wins, and
        # the restore says what the drive kept of the earlier one
        original, _ = self.dump(3, "views-before.txt")
        path = self.file("views.txt", "# firmware %s, hardware 3, serial number 1\n"
                         "w axis3.output_shaft.trap_traj_vel_limit 300\n"
                         "w axis3.trap_traj.config.vel_limit 10\n"
                         % self.run_ok("send", "i 3").stdout.split()[0])
        r = self.run_ok("restore", 3, path)
        self.assertEqual(r.stdout.splitlines()[0], "%s:2: axis3.output_shaft.trap_traj_vel_limit: "
                         "drive 3 keeps 600 (the file has 300)" % path)
        self.assertIn("1 kept otherwise", r.stdout)
        doc = json.loads(self.run_ok("--json", "restore", 3, path).stdout)
        self.assertEqual(doc["differences"], [{"line": 2, "file": 300, "kept": 600,
                                               "path": "axis3.output_shaft.trap_traj_vel_limit"}])
        self.run_ok("restore", 3, original)

    def test_paths_are_named_as_sent(self):
        # drive 2's lines restored into drive 3: every message names axis3., the path sent
        original, _ = self.dump(3, "as-sent-before.txt")
        firmware = self.run_ok("send", "i 3").stdout.split()[0]
        head = "# firmware %s, hardware 3, serial number 1\n" % firmware
        views = self.file("as-sent-views.txt", head +
                          "w axis2.output_shaft.trap_traj_vel_limit 300\n"
                          "w axis2.trap_traj.config.vel_limit 10\n")
        doc = json.loads(self.run_ok("--json", "restore", 3, views).stdout)
        self.assertEqual([d["path"] for d in doc["differences"]],
                         ["axis3.output_shaft.trap_traj_vel_limit"])
        self.assertIn(":2: axis3.output_shaft.trap_traj_vel_limit: drive 3 keeps 600",
                      self.run_ok("restore", 3, views).stdout)
        refused = self.file("as-sent-refused.txt", head + "w axis2.output_shaft.vel_limit 450\n"
                            "w axis2.motor.config.current_lim -5\n")
        r = daran(self.port, "--json", "restore", 3, refused)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertEqual(json.loads(r.stdout)["failed"]["path"], "axis3.motor.config.current_lim")
        self.assertNotIn("axis2.", r.stdout + r.stderr)
        self.run_ok("restore", 3, original)

    def test_file_errors_before_the_port_is_opened(self):
        header = "# firmware 100, hardware 3, serial number 1\n"
        cases = [
            ("node.txt", header + "w axis1.config.can_node_id 5\n", ":2: ", "never restored"),
            ("setpoint.txt", header + "w axis1.output_shaft.input_pos 10\n", ":2: ",
             "moves the motor"),
            ("state.txt", header + "w axis1.requested_state 1\n", ":2: ", "never restored"),
            ("other.txt", header + "w axis1.output_shaft.vel_limit 300\nss 1\n", ":3: ",
             "only `w` lines"),
            ("value.txt", header + "w axis1.output_shaft.vel_limit fast\n", ":2: ",
             "not a value"),
            ("id.txt", header + "w axis1.output_shaft.vel_limit 300 1\n", ":2: ", "no id"),
            ("nofirmware.txt", "w axis1.output_shaft.vel_limit 300\n", "", "--force"),
        ]
        for name, text, where, what in cases:
            path = self.file(name, text)
            r = daran("/nonexistent/port", "restore", 1, path)
            self.assertEqual(r.returncode, 2, (name, r.stderr))
            self.assertIn(path + where, r.stderr)
            self.assertIn(what, r.stderr)
        r = daran("/nonexistent/port", "restore", 1, self.file("missing.txt"))
        self.assertEqual(r.returncode, 2)
        for args in (["dump"], ["dump", "1", "2"], ["dump", "64"], ["dump", "1", "--bogus"],
                     ["dump", "1", "--out"], ["restore", "1"], ["restore", "1", "f", "--save2"]):
            r = daran("/nonexistent/port", *args)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)

    def test_drive_that_does_not_answer(self):
        out = self.file("absent.txt")
        r = daran(self.port, "--timeout", "0.05", "dump", 9, "--out", out)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("drive 9", r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1)
        self.assertFalse([n for n in os.listdir(self.dir.name) if n.startswith("absent")])
        path = self.file("for9.txt", "# firmware 100, hardware 3, serial number 1\n"
                         "w axis9.output_shaft.vel_limit 300\n")
        r = daran(self.port, "--timeout", "0.05", "restore", 9, path)
        self.assertEqual(r.returncode, 3, r.stderr)


class SaveAndPowerCycle(unittest.TestCase):
    def test_restore_save_survives_a_power_cycle(self):
        with tempfile.TemporaryDirectory() as nvm, Sim(drives=2, options=["--nvm", nvm]) as sim:
            port = sim.path
            r = daran(port, "set", 1, "output_shaft.vel_limit", "321", "motor.config.pole_pairs", "9")
            self.assertEqual(r.returncode, 0, r.stderr)
            path = os.path.join(nvm, "drive1.txt")
            self.assertEqual(daran(port, "dump", 1, "--out", path).returncode, 0)
            r = daran(port, "restore", 2, path, "--save")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("saved", r.stdout)
            # an unsaved change, which the power cycle must drop
            self.assertEqual(daran(port, "set", 2, "output_shaft.vel_limit", "100").returncode, 0)
            sim.directive("!power-cycle 2")
            deadline = time.monotonic() + 3
            while True:
                r = daran(port, "get", 2, "output_shaft.vel_limit", "motor.config.pole_pairs",
                          "config.can_node_id")
                if r.stdout.startswith("output_shaft.vel_limit 321") or time.monotonic() > deadline:
                    break
                time.sleep(0.05)
            self.assertEqual(r.stdout, "output_shaft.vel_limit 321\nmotor.config.pole_pairs 9\n"
                             "config.can_node_id 2\n")


if __name__ == "__main__":
    main()
