"""`daran scan/get/set/send` (docs/cli.md) against daran-sim --pty with one
and three drives: text and --json output, checksums on the wire (read back
from daran-sim's --record file), the port from --port, DARAN_PORT or
nowhere, usage errors before any port, a drive that does not answer, a
link that drops mid-reply, and `get` while telemetry streams."""
import glob
import json
import os
import re
import tempfile
import time
import unittest

from cli_support import Proxy, Sim, daran, main

COMMANDS = ["scan", "get", "set", "send", "errors", "clear", "dump", "restore", "watch",
            "shell"]


def checksum(payload):
    """protocol.md 2: the XOR of every byte before `*`, the blank included."""
    value = 0
    for byte in (payload + " ").encode():
        value ^= byte
    return value


class OneDriveTest(unittest.TestCase):
    def test_scan_one_drive(self):
        with Sim(drives=1) as sim:
            r = daran(sim.path, "--timeout", "0.01", "scan")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(r.stdout.splitlines(),
                             ["drive 1: firmware 100, hardware 3, serial number 2026000001"])
            doc = json.loads(daran(sim.path, "--json", "scan", "1-4").stdout)
            self.assertEqual(doc, {"drives": [{"id": 1, "firmware": 100, "hardware": 3,
                                               "serial_number": 2026000001}],
                                   "port": sim.path})

    def test_scan_no_drive(self):
        with Sim(drives=1) as sim, Proxy(sim.path) as proxy:
            proxy.drop_replies()  # the drive hears, nobody answers
            r = daran(proxy.path, "--timeout", "0.01", "scan")
            self.assertEqual(r.returncode, 3, r.stderr)
            self.assertIn("no drive answered on %s (ids 1..63)" % proxy.path, r.stdout)
            r = daran(proxy.path, "--timeout", "0.01", "--json", "scan", "1-3")
            self.assertEqual(r.returncode, 3)
            self.assertEqual(json.loads(r.stdout)["drives"], [])


class ThreeDrivesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.record = tempfile.NamedTemporaryFile(prefix="daran-basic-", suffix=".txt",
                                                 delete=False).name
        cls.sim = Sim(drives=3, options=["--record", cls.record])

    @classmethod
    def tearDownClass(cls):
        cls.sim.stop()
        os.unlink(cls.record)

    def run_daran(self, *args, status=0, port=None):
        r = daran(port or self.sim.path, *args)
        self.assertEqual(r.returncode, status, "daran %s:\n%s%s" % (args, r.stdout, r.stderr))
        if status != 0:
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)  # one line a failure
        return r

    def wire_lines(self, *args, status=0):
        """Run daran; the lines daran-sim received meanwhile (its --record file)."""
        before = os.path.getsize(self.record)
        r = self.run_daran(*args, status=status)
        time.sleep(0.05)
        with open(self.record) as f:
            f.seek(before)
            lines = [line.split("\t", 1)[1] for line in f.read().splitlines() if "\t" in line]
        return r, lines

    def assert_checksummed(self, lines):
        self.assertTrue(lines)
        for line in lines:
            m = re.fullmatch(r"(.*) \*(\d{1,3})", line)
            self.assertIsNotNone(m, "no checksum on the wire: %r" % line)
            self.assertEqual(int(m.group(2)), checksum(m.group(1)), line)

    # ------------------------------------------------------------ scan

    def test_scan(self):
        r = self.run_daran("--timeout", "0.01", "scan")
        self.assertEqual(r.stdout.splitlines(),
                         ["drive %d: firmware 100, hardware 3, serial number %d" % (i, 2026000000 + i)
                          for i in (1, 2, 3)])
        r = self.run_daran("scan", "2-3")
        self.assertEqual([line.split(":")[0] for line in r.stdout.splitlines()],
                         ["drive 2", "drive 3"])
        doc = json.loads(self.run_daran("--json", "scan", "2-5").stdout)
        self.assertEqual([(d["id"], d["serial_number"]) for d in doc["drives"]],
                         [(2, 2026000002), (3, 2026000003)])
        r, wire = self.wire_lines("--checksum", "scan", "1-3")
        self.assertEqual(len(r.stdout.splitlines()), 3)
        self.assert_checksummed(wire)
        self.assertEqual([line.split(" *")[0] for line in wire], ["i 1", "i 2", "i 3"])

    # ------------------------------------------------------------ get

    def test_get_axis_and_system_paths(self):
        self.run_daran("set", 2, "output_shaft.vel_limit", 450)
        r = self.run_daran("get", 1, "output_shaft.vel_limit", "vbus_voltage")
        self.assertEqual(r.stdout.splitlines(), ["output_shaft.vel_limit 600", "vbus_voltage 24"])
        r, wire = self.wire_lines("get", 2, "axis2.output_shaft.vel_limit", "vbus_voltage",
                                  "config.can_node_id")
        self.assertEqual(r.stdout.splitlines(), ["axis2.output_shaft.vel_limit 450",
                                                 "vbus_voltage 24", "config.can_node_id 2"])
        # the id goes where the protocol wants it: axisN. or last
        self.assertEqual(wire, ["r axis2.output_shaft.vel_limit", "r vbus_voltage 2",
                                "r axis2.config.can_node_id"])
        doc = json.loads(self.run_daran("--json", "get", 2, "output_shaft.vel_limit").stdout)
        self.assertEqual(doc, {"id": 2, "properties": [{"path": "output_shaft.vel_limit",
                                                        "value": 450}]})
        r, wire = self.wire_lines("--checksum", "get", 1, "output_shaft.vel_limit",
                                  "vbus_voltage")
        self.assertEqual(r.stdout.splitlines(), ["output_shaft.vel_limit 600", "vbus_voltage 24"])
        self.assert_checksummed(wire)
        self.run_daran("set", 2, "output_shaft.vel_limit", 600)

    def test_get_refused_path(self):
        for extra in ([], ["--checksum"]):
            r = self.run_daran(*extra, "get", 1, "output_shaft.vel_limit", "output_shaft.nope",
                               "vbus_voltage", status=1)
            self.assertEqual(r.stdout.splitlines(), ["output_shaft.vel_limit 600",
                                                     "vbus_voltage 24"])
            self.assertIn("drive 1 refused \"r axis1.output_shaft.nope\": invalid property",
                          r.stderr)
        r = self.run_daran("--json", "get", 1, "output_shaft.nope", "vbus_voltage", status=1)
        self.assertEqual(json.loads(r.stdout)["properties"],
                         [{"path": "output_shaft.nope", "error": "invalid property"},
                          {"path": "vbus_voltage", "value": 24}])

    # ------------------------------------------------------------ set

    def test_set_reads_back(self):
        r, wire = self.wire_lines("set", 3, "output_shaft.vel_limit", "1e3",
                                  "controller.config.control_mode", "2")
        # 1e3 goes out as the drive prints it and comes back as 1000: the same number
        self.assertEqual(r.stdout.splitlines(), ["output_shaft.vel_limit 1000",
                                                 "controller.config.control_mode 2"])
        self.assertEqual(wire, ["w axis3.output_shaft.vel_limit 1000",
                                "r axis3.output_shaft.vel_limit",
                                "w axis3.controller.config.control_mode 2",
                                "r axis3.controller.config.control_mode"])
        self.assertEqual(self.run_daran("get", 3, "output_shaft.vel_limit").stdout,
                         "output_shaft.vel_limit 1000\n")

        r = self.run_daran("set", 3, "output_shaft.vel_limit", "-5",
                           "controller.config.control_mode", "3", status=1)
        self.assertIn("drive 3 refused output_shaft.vel_limit = -5: value out of range "
                      "(it keeps 1000)", r.stderr)
        self.assertEqual(r.stdout, "controller.config.control_mode 3\n")  # the other pair
        r = self.run_daran("--json", "set", 3, "output_shaft.vel_limit", "-5",
                           "output_shaft.vel_limit", "2.5e2", status=1)
        self.assertEqual(json.loads(r.stdout)["properties"],
                         [{"path": "output_shaft.vel_limit", "asked": "-5", "kept": 1000,
                           "error": "value out of range"},
                          {"path": "output_shaft.vel_limit", "asked": "2.5e2", "kept": 250}])

        r, wire = self.wire_lines("--checksum", "set", 3, "output_shaft.vel_limit", "600",
                                  "output_shaft.vel_limit", "-1", status=1)
        self.assertEqual(r.stdout, "output_shaft.vel_limit 600\n")
        self.assertIn("it keeps 600", r.stderr)
        self.assert_checksummed(wire)

    # ------------------------------------------------------------ send

    def test_send(self):
        r = self.run_daran("--timeout", "2", "send", "i 2", "f 1",
                           "h 1 properties axis0.telemetry")
        self.assertEqual(r.stdout.splitlines(),
                         ["100 3 2026000002", "0 0",
                          "axis0.telemetry.fields u32 rw flags 0..511",
                          "axis0.telemetry.period f32 rw s >=0"])
        # discovery ends at `end`, not after the 2 s a silent command would wait
        start = time.monotonic()
        self.run_daran("--timeout", "2", "send", "h 1 properties axis0.telemetry")
        self.assertLess(time.monotonic() - start, 1.5)

        r = self.run_daran("send", "zz 1", "i 1", status=1)
        self.assertEqual(r.stdout.splitlines(), ["error: unknown command", "100 3 2026000001"])
        self.assertIn("\"zz 1\": the drive answered error: unknown command", r.stderr)

        r = self.run_daran("--timeout", "0.05", "send", "i 5", status=3)
        self.assertIn("\"i 5\": no reply within 50 ms", r.stderr)

        r = daran(self.sim.path, "send", stdin="i 3\nf 3\n")  # lines from standard input
        self.assertEqual((r.returncode, r.stdout), (0, "100 3 2026000003\n0 0\n"), r.stderr)

        doc = json.loads(self.run_daran("--json", "send", "i 1", "zz 1", status=1).stdout)
        self.assertEqual(doc["lines"], [{"line": "i 1", "reply": ["100 3 2026000001"]},
                                        {"line": "zz 1", "reply": [],
                                         "error": "unknown command"}])

        r, wire = self.wire_lines("--checksum", "send", "i 1", "h 1 properties axis0.telemetry",
                                  "w axis1.output_shaft.vel_limit 600", "zz 1", status=1)
        self.assertEqual(r.stdout.splitlines(),
                         ["100 3 2026000001", "axis0.telemetry.fields u32 rw flags 0..511",
                          "axis0.telemetry.period f32 rw s >=0", "error: unknown command"])
        self.assert_checksummed(wire)

    # ------------------------------------------------------------ failures

    def test_drive_that_does_not_answer(self):
        for args in (["get", 5, "vbus_voltage"], ["get", 5, "output_shaft.vel_limit"],
                     ["set", 5, "output_shaft.vel_limit", 3], ["--checksum", "get", 5, "pos"]):
            start = time.monotonic()
            r = self.run_daran("--timeout", "0.05", *args, status=3)
            self.assertLess(time.monotonic() - start, 2)
            # a set's write went out: said, since the drive may have taken it
            tail = ("; \"w axis5.output_shaft.vel_limit 3\" went out before it and may have "
                    "taken effect") if args[0] == "set" else ""
            self.assertRegex(r.stderr, r"^daran: drive 5 did not answer \"r [^\"]+\" within 50 "
                                       r"ms on %s%s\n$" % (re.escape(self.sim.path),
                                                           re.escape(tail)))
            self.assertEqual(r.stdout, "")

    def test_link_drops_mid_reply(self):
        with Proxy(self.sim.path) as proxy:
            proxy.cut_after(300)  # a few lines of discovery, then the link is gone
            r = daran(proxy.path, "send", "h 1 properties")
        self.assertEqual(r.returncode, 4, r.stdout + r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertIn(proxy.path, r.stderr)
        self.assertTrue(r.stdout.startswith("axis0."), r.stdout)  # what came before the cut
        with Proxy(self.sim.path) as proxy:
            proxy.cut_after(300)
            r = daran(proxy.path, "--json", "send", "h 1 properties")
        self.assertEqual(r.returncode, 4)
        doc = json.loads(r.stdout)  # still one whole document
        self.assertIn("error", doc["lines"][0])

    def test_get_while_telemetry_streams(self):
        self.run_daran("set", 1, "telemetry.fields", 3, "telemetry.period", "0.01")
        try:
            time.sleep(0.1)  # reports pile up unread
            for extra in ([], ["--checksum"]):
                r = self.run_daran(*extra, "get", 1, "output_shaft.vel_limit", "vbus_voltage",
                                   "telemetry.period", "config.can_node_id")
                self.assertEqual(r.stdout.splitlines(),
                                 ["output_shaft.vel_limit 600", "vbus_voltage 24",
                                  "telemetry.period 0.01", "config.can_node_id 1"])
            r = self.run_daran("send", "i 1", "f 1")
            lines = r.stdout.splitlines()
            self.assertEqual(lines[0], "100 3 2026000001")
            self.assertFalse(any(line.startswith("@") for line in lines), lines)
        finally:
            self.run_daran("set", 1, "telemetry.period", 0)

    # ------------------------------------------------------------ the port

    def test_port_from_environment(self):
        r = daran(None, "get", 1, "vbus_voltage", env={"DARAN_PORT": self.sim.path})
        self.assertEqual((r.returncode, r.stdout), (0, "vbus_voltage 24\n"), r.stderr)
        # --port wins over DARAN_PORT
        r = daran(self.sim.path, "get", 1, "vbus_voltage", env={"DARAN_PORT": "/nonexistent"})
        self.assertEqual(r.returncode, 0, r.stderr)
        r = daran(None, "get", 1, "vbus_voltage", env={"DARAN_PORT": "/nonexistent/tty"})
        self.assertEqual(r.returncode, 4)
        self.assertIn("/nonexistent/tty", r.stderr)

    def test_no_port(self):
        r = daran("/nonexistent/tty", "get", 1, "vbus_voltage")
        self.assertEqual(r.returncode, 4)
        self.assertEqual(r.stderr.splitlines(),
                         ["daran: /nonexistent/tty: cannot open: No such file or directory"])
        if glob.glob("/dev/ttyACM*") or glob.glob("/dev/ttyUSB*"):
            self.skipTest("this machine has a serial port the tool would take")
        r = daran(None, "scan")
        self.assertEqual(r.returncode, 4)
        self.assertIn("no /dev/ttyACM* or /dev/ttyUSB* found", r.stderr)

    def test_usage_before_any_port(self):
        for args in (["get"], ["get", "x", "y"], ["get", "1"], ["set", "1", "a"],
                     ["set", "1", "a", "b"], ["scan", "5-2"], ["--baud", "7", "scan"],
                     ["frobnicate"], ["--timeout", "x", "get", "1", "a"], []):
            for port in (None, "/nonexistent/tty"):
                r = daran(port, *args)
                self.assertEqual(r.returncode, 2, (args, port, r.stderr))
                if args:
                    self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertNotIn("nonexistent", r.stderr)

    @staticmethod
    def help_commands():
        """The lines of `daran --help` under "Commands:"."""
        out = daran(None, "--help").stdout.split("Commands:\n", 1)[1]
        return out.split("\n\n", 1)[0].splitlines()

    def test_help_lists_every_command(self):
        r = daran(None, "--help")
        self.assertEqual(r.returncode, 0)
        # a line a command (a deeper indent continues the one above)
        self.assertEqual([line.split()[0] for line in self.help_commands()
                          if not line.startswith("   ")], COMMANDS)
        for command in COMMANDS:
            r = daran(None, command, "--help")
            self.assertEqual(r.returncode, 0, command)
            self.assertIn("daran [OPTIONS] %s" % command, r.stdout)

    def test_help_shows_each_synopsis_whole(self):
        listing = "\n".join(self.help_commands())
        for command in COMMANDS:
            usage = daran(None, command, "--help").stdout.splitlines()[0]
            synopsis = usage.split("daran [OPTIONS] ", 1)[1]
            self.assertIn(synopsis, listing)

if __name__ == "__main__":
    main()
