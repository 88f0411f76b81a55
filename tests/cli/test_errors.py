"""`daran errors` and `daran clear` (docs/cli.md, "errors, clear") against
daran-sim --pty: each fault the simulator can raise, decoded into the
vendor's bit names; sc and what remains; --enable; --json; --checksum; and,
through a scripted drive of our own, bits without a name and a reply that
is not the seven registers."""
import json
import os
import pty
import threading
import time
import tty
import unittest

from cli_support import Sim, daran, main

# The drives of the shared simulator, one per fault, so that no test
# depends on another's leftovers.
ESTOP, OVERTEMP, STALL, UNDERVOLTAGE, OVERSPEED, CLEAN = 1, 2, 3, 4, 5, 6
REGISTERS = ["axis", "motor", "encoder", "controller", "fet_thermistor", "motor_thermistor",
             "can"]


def registers_text(stdout):
    """{register: (value, [names])} from the text output."""
    out = {}
    for line in stdout.splitlines():
        fields = line.split()
        if fields and fields[0] in REGISTERS:
            out[fields[0]] = (int(fields[1], 16), fields[2:])
    return out


class ScriptedDrive:
    """A pseudo-terminal that answers every `e N` with the lines given
    (a drive whose registers the simulator cannot produce)."""

    def __init__(self, lines):
        self.master, self.slave = pty.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.reply = "".join(line + "\r\n" for line in lines).encode()
        self.stop = False
        threading.Thread(target=self._run, daemon=True).start()

    def _run(self):
        pending = b""
        while not self.stop:
            try:
                pending += os.read(self.master, 256)
            except OSError:
                return
            while b"\n" in pending:
                line, pending = pending.split(b"\n", 1)
                if line.strip().startswith(b"e "):
                    os.write(self.master, self.reply)

    def close(self):
        self.stop = True
        os.close(self.slave)
        os.close(self.master)


class ErrorsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = Sim(drives=6)

    @classmethod
    def tearDownClass(cls):
        cls.sim.stop()

    def run_ok(self, *args, status=0):
        r = daran(self.sim.path, *args)
        self.assertEqual(r.returncode, status, r.stdout + r.stderr)
        return r

    def wait_for_flag(self, drive, register, names, seconds=2.0):
        """The fault takes a tick or two to trip: ask until it shows."""
        deadline = time.monotonic() + seconds
        while True:
            regs = registers_text(self.run_ok("errors", drive).stdout)
            if all(n in regs[register][1] for n in names) or time.monotonic() > deadline:
                return regs
            time.sleep(0.02)

    def state(self, drive):
        r = self.run_ok("--json", "get", drive, "current_state")
        return json.loads(r.stdout)["properties"][0]["value"]

    def test_all_clear(self):
        r = self.run_ok("errors", CLEAN)
        regs = registers_text(r.stdout)
        self.assertEqual(list(regs), REGISTERS)
        self.assertTrue(all(value == 0 and names == [] for value, names in regs.values()))
        self.assertIn("drive %d: all clear" % CLEAN, r.stdout)
        doc = json.loads(self.run_ok("--json", "errors", CLEAN).stdout)
        self.assertEqual(doc["id"], CLEAN)
        self.assertTrue(doc["clear"])
        self.assertEqual([reg["name"] for reg in doc["registers"]], REGISTERS)

    def test_estop_then_clear_then_enable(self):
        self.run_ok("send", "st %d" % ESTOP)
        r = self.run_ok("errors", ESTOP)  # flags set: the command still worked
        self.assertIn("axis             0x00004000 ESTOP_REQUESTED", r.stdout)
        self.assertEqual(registers_text(r.stdout)["motor"], (0, []))
        self.assertNotIn("all clear", r.stdout)
        doc = json.loads(self.run_ok("--json", "errors", ESTOP).stdout)
        self.assertFalse(doc["clear"])
        self.assertEqual(doc["registers"][0],
                         {"name": "axis", "value": 0x4000,
                          "bits": [{"bit": 14, "name": "ESTOP_REQUESTED"}]})
        # motion is refused until clear and enable
        self.run_ok("send", "v %d 10" % ESTOP, status=1)

        r = self.run_ok("clear", ESTOP)
        self.assertTrue(all(v == 0 for v, _ in registers_text(r.stdout).values()))
        self.assertIn("stays idle (current_state 1) until `daran set %d requested_state 8`"
                      % ESTOP, r.stdout)
        self.assertEqual(self.state(ESTOP), 1)
        self.assertIn("all clear", self.run_ok("errors", ESTOP).stdout)

        r = self.run_ok("clear", ESTOP, "--enable")
        self.assertIn("in closed-loop control (current_state 8)", r.stdout)
        self.assertEqual(self.state(ESTOP), 8)
        self.run_ok("send", "v %d 0" % ESTOP)  # motion accepted again

        # st again; --json clear --enable in one go, with checksums on the wire
        self.run_ok("send", "st %d" % ESTOP)
        doc = json.loads(self.run_ok("--checksum", "--json", "clear", "--enable", ESTOP).stdout)
        self.assertTrue(doc["clear"])
        self.assertTrue(doc["enabled"])
        self.assertEqual(doc["current_state"], 8)
        self.assertEqual(doc["requested_state"], 8)

    def test_overtemp_remains_after_clear(self):
        self.sim.directive("!fault %d overtemp" % OVERTEMP)
        regs = self.wait_for_flag(OVERTEMP, "axis", ["OVER_TEMP"])
        self.assertEqual(regs["axis"], (0x40000, ["OVER_TEMP"]))
        self.assertEqual(regs["fet_thermistor"], (1, ["OVER_TEMP"]))
        self.assertEqual(regs["motor_thermistor"], (1, ["OVER_TEMP"]))
        doc = json.loads(self.run_ok("--checksum", "--json", "errors", OVERTEMP).stdout)
        by_name = {reg["name"]: reg for reg in doc["registers"]}
        self.assertEqual(by_name["axis"]["bits"], [{"bit": 18, "name": "OVER_TEMP"}])
        self.assertEqual(by_name["fet_thermistor"]["bits"], [{"bit": 0, "name": "OVER_TEMP"}])

        # the shaft is still hot: sc clears, the next tick sets them again
        r = self.run_ok("clear", OVERTEMP, status=1)
        self.assertIn("OVER_TEMP", registers_text(r.stdout)["axis"][1])
        lines = r.stderr.splitlines()
        self.assertEqual(len(lines), 1, r.stderr)
        self.assertIn("drive %d: still set after \"sc %d\"" % (OVERTEMP, OVERTEMP), lines[0])
        self.assertIn("axis OVER_TEMP", lines[0])
        r = self.run_ok("clear", OVERTEMP, "--enable", status=1)
        self.assertIn("not enabled", r.stderr)
        self.assertEqual(self.state(OVERTEMP), 1)
        doc = json.loads(self.run_ok("--json", "clear", OVERTEMP, status=1).stdout)
        self.assertFalse(doc["clear"])
        self.assertFalse(doc["enabled"])

    def test_stall(self):
        self.sim.directive("!fault %d stall" % STALL)
        regs = self.wait_for_flag(STALL, "motor", ["STALL"])
        self.assertEqual(regs["axis"], (0x40, ["MOTOR_FAILED"]))
        self.assertEqual(regs["motor"], (0x10000, ["STALL"]))
        # a stall is over once tripped: clear takes it away
        self.run_ok("clear", STALL, "--enable")
        self.assertEqual(self.state(STALL), 8)

    def test_undervoltage_passes(self):
        self.sim.directive("!fault %d undervoltage" % UNDERVOLTAGE)
        regs = self.wait_for_flag(UNDERVOLTAGE, "axis", ["DC_BUS_UNDER_VOLTAGE"])
        self.assertEqual(regs["axis"], (0x2, ["DC_BUS_UNDER_VOLTAGE"]))
        time.sleep(0.15)  # the sag lasts 0.1 s
        r = self.run_ok("clear", UNDERVOLTAGE)
        self.assertIn("stays idle", r.stdout)

    def test_overspeed(self):
        self.run_ok("set", OVERSPEED, "controller.config.enable_overspeed_error", "1")
        self.sim.directive("!fault %d overspeed" % OVERSPEED)
        regs = self.wait_for_flag(OVERSPEED, "controller", ["OVERSPEED"])
        self.assertEqual(regs["controller"], (1, ["OVERSPEED"]))
        self.assertIn("CONTROLLER_FAILED", regs["axis"][1])

    def test_usage_before_port(self):
        for args in (["errors"], ["errors", "0"], ["errors", "1", "2"], ["errors", "x"],
                     ["clear"], ["clear", "64"], ["clear", "1", "2"], ["clear", "1", "--bogus"]):
            r = daran("/nonexistent/port", *args)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
            self.assertIn("usage: daran %s" % args[0], r.stderr)

    def test_no_reply(self):
        for command in ("errors", "clear"):
            r = daran(self.sim.path, "--timeout", "0.05", command, "9")
            self.assertEqual(r.returncode, 3, r.stderr)
            self.assertEqual(r.stdout, "")
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
            self.assertIn("drive 9", r.stderr)
        self.assertIn("\"e 9\"", daran(self.sim.path, "--timeout", "0.05", "errors", "9").stderr)

    def test_missing_port(self):
        r = daran("/nonexistent/port", "errors", "1")
        self.assertEqual(r.returncode, 4)
        self.assertIn("/nonexistent/port", r.stderr)


class ScriptedTest(unittest.TestCase):
    """Registers the simulator never sets: every name of the tables, the gaps."""

    def decode(self, values):
        drive = ScriptedDrive(["%s: %d" % (name, v) for name, v in zip(REGISTERS, values)])
        try:
            return daran(drive.path, "errors", "1"), daran(drive.path, "--json", "errors", "1")
        finally:
            drive.close()

    def test_names_and_gaps(self):
        axis = (1 << 15) | (1 << 16) | (1 << 17) | (1 << 31) | 1
        text, js = self.decode([axis, 1 << 11 | 1 << 15, 1 << 8, 1 << 5, 0, 0, 1])
        self.assertEqual(text.returncode, 0, text.stderr)
        regs = registers_text(text.stdout.replace("bit ", "bit_"))
        self.assertEqual(regs["axis"], (axis, ["INVALID_STATE", "bit_15", "bit_16",
                                               "HOMING_WITHOUT_ENDSTOP", "bit_31"]))
        self.assertEqual(regs["motor"], (0x8800, ["bit_11", "DC_BUS_OVER_CURRENT"]))
        self.assertEqual(regs["encoder"], (0x100, ["ABS_SPI_NOT_READY"]))
        self.assertEqual(regs["controller"], (0x20, ["INVALID_ESTIMATE"]))
        self.assertEqual(regs["can"], (1, ["DUPLICATE_CAN_IDS"]))
        doc = json.loads(js.stdout)
        self.assertEqual(doc["registers"][0]["value"], axis)
        self.assertEqual(doc["registers"][0]["bits"][1], {"bit": 15, "name": None})
        self.assertEqual(doc["registers"][0]["bits"][-1], {"bit": 31, "name": None})

    def test_not_the_registers(self):
        drive = ScriptedDrive(["axis: 0", "motor: 0", "encoder: 0", "controller: 0",
                               "fet_thermistor: 0", "can: 0", "motor_thermistor: 0"])
        try:
            r = daran(drive.path, "errors", "1")
        finally:
            drive.close()
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertEqual(len(r.stderr.splitlines()), 1)
        self.assertIn("not its error registers (line 6: \"can: 0\")", r.stderr)


if __name__ == "__main__":
    main()
