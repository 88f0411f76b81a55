"""`daran` through a CAN gateway: daran-sim --bridge --pty, drive 1 bridging
the lines for drives 2 and 3 (docs/cli.md). The gateway answers a query
whose drive stays silent with `error: no reply` (docs/can.md C32): that is
no reply (exit status 3), never a refusal, for every command; a `w` whose
read-back gets it went out and may have taken effect, so `restore` writes it
back too, and says "back" only of values read again as they were. A frame
the gateway cannot put on its bus is answered `error: bus error` (C33): the
drive did not get that line, so it is neither a refusal nor a reply (exit
status 5); a `w` the gateway could not send had no effect, one whose
read-back it could not send went out and may have. Faults come at an exact
request: a proxy between daran and the simulator injects `!fault 3 can-lose
N` (drive 3's next N frames are lost) or `!fault 1 can-bus-off` (the
gateway's controller leaves the bus) just before it passes that request on."""
import json
import os
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_support import Proxy, Sim, main  # noqa: E402
import cli_support  # noqa: E402

# A drive that does not answer is told by the gateway within 10 ms of the
# simulator's time; the link's own timeout only has to outlast a busy machine
# (a reply that comes after it could be taken for the next request's).
TIMEOUT = "2"


def daran(port, *args):
    return cli_support.daran(port, "--timeout", TIMEOUT, *args)

# a property drive 3 holds at 0 (the simulated drive's default), changed by
# the file, and an earlier line changed too, so that both need writing back
CHANGED = "encoder.config.use_index"
EARLIER = ("config.calibration_lockin.accel", "33")


class Bridge(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = Sim(drives=3, options=["--bridge"])
        # everything goes through the proxy: it alone reads the simulator's pty
        cls.proxy = Proxy(cls.sim.path)
        cls.port = cls.proxy.path
        cls.dir = tempfile.TemporaryDirectory()
        dump = daran(cls.port, "dump", 3)
        assert dump.returncode == 0, dump.stderr
        lines = [l for l in dump.stdout.splitlines() if l.startswith("w ")]
        firmware = [l for l in dump.stdout.splitlines() if l.startswith("# firmware ")]
        assert "w axis3.%s 0" % CHANGED in lines, lines
        # about 30 lines, the changed one last, an earlier one changed too
        kept = [l for l in lines if CHANGED not in l][:29]
        kept = ["w axis3.%s %s" % EARLIER if l.startswith("w axis3.%s " % EARLIER[0]) else l
                for l in kept]
        assert "w axis3.%s %s" % EARLIER in kept, kept
        cls.lines = kept + ["w axis3.%s 1" % CHANGED]
        cls.file = os.path.join(cls.dir.name, "drive3.txt")
        with open(cls.file, "w") as f:
            f.write("\n".join(firmware + cls.lines) + "\n")
        cls.paths = [l.split()[1] for l in cls.lines]
        cls.original = os.path.join(cls.dir.name, "original.txt")
        with open(cls.original, "w") as f:
            f.write("\n".join(firmware + [l for l in lines
                                          if l.split()[1] in cls.paths]) + "\n")

    @classmethod
    def tearDownClass(cls):
        cls.proxy.close()
        cls.sim.stop()
        cls.dir.cleanup()

    def tearDown(self):
        self.proxy.before_line(None, None)
        self.sim.directive_taken("!fault 0 can-recover")  # every node's faults, the bus's

    def values_before(self):
        """Drive 3 as it was at the start (the file's changes not in it)."""
        r = daran(self.port, "restore", 3, self.original)
        self.assertEqual(r.returncode, 0, r.stderr)
        values = self.values()
        self.assertIn("%s 0\n" % CHANGED, values)
        self.assertIn("%s 20\n" % EARLIER[0], values)
        return values

    def values(self):
        """What drive 3 holds of every line's property."""
        got = daran(self.port, "get", 3, *self.paths)
        self.assertEqual(got.returncode, 0, got.stderr)
        return got.stdout

    def fault_before(self, matches, directive):
        """`directive` on the simulator's stdin just before daran's first
        line for which matches(line) holds goes on to the drive."""
        self.proxy.before_line(matches, lambda: self.sim.directive_taken(directive))

    def nth(self, prefix, n):
        """A matches() for the n-th line starting with prefix."""
        seen = [0]

        def matches(line):
            if line.startswith(prefix):
                seen[0] += 1
            return seen[0] == n and line.startswith(prefix)
        return matches

    def bus_off_before(self, matches, recover_before=None, settle=0.0):
        """The gateway's controller goes bus-off just before daran's first
        line for which matches(line) holds reaches the simulator, `settle`
        seconds after the lines before it did (their frames on the bus);
        with recover_before, it is back on the bus just before the first
        line after that for which recover_before(line) holds."""
        def fault():
            time.sleep(settle)
            self.sim.directive_taken("!fault 1 can-bus-off")
            if recover_before is not None:
                self.proxy.before_line(
                    recover_before, lambda: self.sim.directive_taken("!fault 1 can-recover"))
        self.proxy.before_line(matches, fault)

    def not_sent(self, line, drive=3):
        return ('drive %d did not get "%s": the gateway on %s answered "error: bus error" (it '
                'could not send it on its CAN bus)' % (drive, line, self.port))

    def test_bus_error_is_neither_a_refusal_nor_a_reply(self):
        path = "output_shaft.homing_vel_limit"
        held = self.values_of(path)
        other = str(int(float(held)) + 11)
        # the gateway's controller off the bus, then the whole bus down
        for fault in ("!fault 1 can-bus-off", "!fault 0 can-bus-off"):
            self.sim.directive_taken(fault)
            for args, line in ((["get", 3, path], "r axis3." + path), (["errors", 3], "e 3"),
                               (["dump", 3], "i 3"),
                               (["set", 3, path, other], "w axis3.%s %s" % (path, other))):
                r = daran(self.port, *args)
                self.assertEqual(r.returncode, 5, (fault, args, r.stderr))
                self.assertEqual(r.stderr, "daran: %s\n" % self.not_sent(line), (fault, args))
            self.sim.directive_taken("!fault 0 can-recover")
            self.assertEqual(self.values_of(path), held)  # the write never reached it
        self.sim.directive_taken("!fault 1 can-bus-off")
        r = daran(self.port, "--json", "get", 3, path)
        self.assertEqual((r.returncode, json.loads(r.stdout)), (5, {"id": 3, "properties": []}))
        r = daran(self.port, "send", "r axis3." + path)
        self.assertEqual((r.returncode, r.stdout), (5, "error: bus error\n"), r.stderr)
        self.assertIn('"r axis3.%s": not sent: the gateway on %s answered "error: bus error"'
                      % (path, self.port), r.stderr)
        self.assertNotIn("drive answered", r.stderr)
        # drive 1 answers itself; drive 2 was not asked, nor any after it
        r = daran(self.port, "scan", "1-4")
        self.assertEqual(r.returncode, 5, r.stderr)
        self.assertEqual([l.split(":")[0] for l in r.stdout.splitlines()], ["drive 1"])
        self.assertEqual(r.stderr, "daran: %s; scan stopped at id 2\n" % self.not_sent("i 2", drive=2))
        r = daran(self.port, "--json", "scan", "1-4")
        self.assertEqual(r.returncode, 5, r.stderr)
        self.assertEqual([d["id"] for d in json.loads(r.stdout)["drives"]], [1])

    def values_of(self, path):
        got = daran(self.port, "get", 3, path)
        self.assertEqual(got.returncode, 0, got.stderr)
        return got.stdout.split()[1]

    def test_restore_line_the_gateway_could_not_send_had_no_effect(self):
        before = self.values_before()
        # the last line's `w` and read-back cannot be sent; the bus is back
        # for the write-backs
        self.bus_off_before(lambda line: line.startswith("w axis3.%s " % CHANGED),
                            recover_before=lambda line: line.startswith("w "))
        r = daran(self.port, "--json", "restore", 3, self.file)
        self.assertEqual(self.values(), before, r.stderr)
        self.assertEqual(r.returncode, 5, r.stderr)
        self.assertEqual(r.stderr, "daran: %s:%d: %s; drive 3's previous values are back (%d "
                         "lines written back, then all read again as they were)\n" %
                         (self.file, len(self.lines) + 1,
                          self.not_sent("w axis3.%s 1" % CHANGED), len(self.lines) - 1))
        doc = json.loads(r.stdout)
        self.assertEqual((doc["complete"], doc["rolled_back"], doc["written_back"]),
                         (False, True, len(self.lines) - 1))
        self.assertEqual((doc["failed"]["path"], doc["failed"]["error"]),
                         ("axis3." + CHANGED, "bus error"))

    def test_restore_writes_back_a_line_whose_read_back_could_not_be_sent(self):
        before = self.values_before()
        # the last line's `w` goes out; its read-back (the second `r` of that
        # path, after the one that reads what the drive had) cannot be sent
        self.bus_off_before(self.nth("r axis3.%s" % CHANGED, 2), settle=0.1,
                            recover_before=lambda line: line.startswith("w "))
        r = daran(self.port, "--json", "restore", 3, self.file)
        self.assertEqual(self.values(), before, r.stderr)  # the undo covers that line
        self.assertEqual(r.returncode, 5, r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertIn(self.not_sent("r axis3." + CHANGED) + '; "w axis3.%s 1" went out '
                      'before it and may have taken effect; drive 3\'s previous values are '
                      'back, that line\'s too (%d lines written back' % (CHANGED, len(self.lines)),
                      r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual((doc["rolled_back"], doc["written_back"], doc["failed"]["error"]),
                         (True, len(self.lines), "bus error"))

    def test_restore_never_says_back_while_the_gateway_cannot_send(self):
        before = self.values_before()
        self.bus_off_before(lambda line: line.startswith("w axis3.%s " % CHANGED))
        r = daran(self.port, "--json", "restore", 3, self.file)
        self.assertEqual(r.returncode, 5, r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertNotIn("back (", r.stderr)
        self.assertNotIn("refused", r.stderr)
        self.assertIn("drive 3 may be half-restored: 0 of %d lines written back, each read back "
                      "as it was; then drive 3 did not get \"w %s " %
                      (len(self.lines) - 1, self.paths[0]), r.stderr)
        self.assertIn('the gateway on %s answered "error: bus error"' % self.port, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual((doc["rolled_back"], doc["written_back"]), (False, 0))
        self.sim.directive_taken("!fault 1 can-recover")
        self.assertNotEqual(self.values(), before)  # as said: not back

    def test_no_reply_is_not_a_refusal(self):
        self.sim.directive_taken("!fault 3 can-mute")  # drive 3 obeys but sends nothing
        said = 'the gateway on %s answered "error: no reply"' % self.port
        for args in (["get", 3, "output_shaft.homing_vel_limit"], ["errors", 3], ["dump", 3],
                     ["set", 3, "output_shaft.homing_vel_limit", 77]):
            r = daran(self.port, *args)
            self.assertEqual(r.returncode, 3, (args, r.stderr))
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
            self.assertIn("daran: drive 3 did not answer", r.stderr)
            self.assertIn(said, r.stderr)
            self.assertNotIn("refused", r.stderr)
        # the write of `set` went out: it says so
        self.assertIn('"w axis3.output_shaft.homing_vel_limit 77" went out before it and may '
                      'have taken effect', r.stderr)
        r = daran(self.port, "send", "r axis3.output_shaft.homing_vel_limit")
        self.assertEqual((r.returncode, r.stdout), (3, "error: no reply\n"), r.stderr)
        self.assertIn("no reply: " + said, r.stderr)
        # a drive that does not answer is not one scan lists
        r = daran(self.port, "scan", "1-4")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual([l.split(":")[0] for l in r.stdout.splitlines()],
                         ["drive 1", "drive 2"])
        # a refusal is still one (drive 1 checks the value for the gateway)
        r = daran(self.port, "set", 3, "output_shaft.vel_limit", -5)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("refused", r.stderr)
        self.sim.directive_taken("!fault 3 can-recover")
        r = daran(self.port, "get", 3, "output_shaft.homing_vel_limit")
        self.assertEqual(r.stdout, "output_shaft.homing_vel_limit 77\n")  # it did take it

    def test_restore_writes_back_an_unanswered_line_too(self):
        before = self.values_before()
        # the reply to the read-back of the last line is lost: its `w` took effect
        self.fault_before(lambda line: line.startswith("w axis3.%s " % CHANGED),
                          "!fault 3 can-lose 1")
        r = daran(self.port, "--json", "restore", 3, self.file)
        self.assertEqual(self.values(), before, r.stderr)  # the undo covers that line
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertNotIn("refused", r.stderr)
        self.assertIn('"w axis3.%s 1" went out before it and may have taken effect' % CHANGED,
                      r.stderr)
        self.assertIn("previous values are back, that line's too (%d lines written back, then "
                      "all read again as they were)" % len(self.lines), r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual((doc["complete"], doc["rolled_back"], doc["written_back"]),
                         (False, True, len(self.lines)))
        self.assertEqual((doc["failed"]["path"], doc["failed"]["error"]),
                         ("axis3." + CHANGED, "no reply"))

    def test_restore_never_says_back_of_what_it_could_not_read_back(self):
        before = self.values_before()
        # lost: the read-back of the last line and that of the first write-back
        self.fault_before(lambda line: line.startswith("w axis3.%s " % CHANGED),
                          "!fault 3 can-lose 2")
        r = daran(self.port, "--json", "restore", 3, self.file)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertNotIn("back (", r.stderr)
        self.assertIn("drive 3 may be half-restored: 0 of %d lines written back, each read back "
                      "as it was; then drive 3 did not answer \"r %s\"" %
                      (len(self.lines), self.paths[0]), r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual((doc["rolled_back"], doc["written_back"]), (False, 0))
        self.assertNotEqual(self.values(), before)  # as said: not back

    def test_lost_reply_in_the_final_comparison(self):
        # the third `r` of the last line: before, its read-back, the comparison
        self.fault_before(self.nth("r axis3.%s" % CHANGED, 3), "!fault 3 can-lose 1")
        r = daran(self.port, "restore", 3, self.file)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(r.stdout, "")  # no "restored …, each kept as written"
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertIn("%s:%d: drive 3 did not answer \"r axis3.%s\"" %
                      (self.file, len(self.lines) + 1, CHANGED), r.stderr)
        self.assertIn("all %d lines were written and read back, but reading them again stopped "
                      "there: what drive 3 keeps from line %d on is unchecked" %
                      (len(self.lines), len(self.lines) + 1), r.stderr)
        self.fault_before(self.nth("r axis3.%s" % CHANGED, 3), "!fault 3 can-lose 1")
        doc = json.loads(daran(self.port, "--json", "restore", 3, self.file).stdout)
        self.assertEqual((doc["complete"], doc["compared"]), (True, len(self.lines) - 1))


if __name__ == "__main__":
    main()
