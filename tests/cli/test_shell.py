"""`daran shell` (docs/cli.md, "shell") against daran-sim --pty: typed
through a pseudo-terminal (pty.fork: the shell's controlling terminal, so
Ctrl-C is a signal), the screen rebuilt from what the shell wrote (a small
terminal: carriage return, column moves, erase to the end of the row), so
completion and reports are checked as a user would see them; and piped, with
no terminal at all."""
import fcntl
import os
import pty
import re
import select
import shutil
import signal
import struct
import subprocess
import tempfile
import termios
import time
import unittest

from cli_support import DARAN, Sim, Proxy, main

PROMPT = "daran> "
ESCAPE = re.compile(r"\x1b\[([0-9;?]*)([A-Za-z])")


def render(raw):
    """The rows a terminal shows after `raw` (enough of one for libedit's
    output with TERM=xterm: \\r, \\n, \\b, ESC[nG/C/D/A/K; others ignored)."""
    rows = [""]
    row = col = 0
    i = 0
    while i < len(raw):
        ch = raw[i]
        m = ESCAPE.match(raw, i) if ch == "\x1b" else None
        if m:
            n = int(m.group(1)) if m.group(1).isdigit() else 1
            op = m.group(2)
            if op == "G":
                col = n - 1
            elif op == "C":
                col += n
            elif op == "D":
                col = max(0, col - n)
            elif op == "A":
                row = max(0, row - n)
            elif op == "K":
                rows[row] = rows[row][:col]
            i = m.end()
            continue
        if ch == "\r":
            col = 0
        elif ch == "\n":
            row += 1
            if row == len(rows):
                rows.append("")
        elif ch == "\b":
            col = max(0, col - 1)
        elif ch >= " ":
            line = rows[row].ljust(col)
            rows[row] = line[:col] + ch + line[col + 1:]
            col += 1
        i += 1
    return rows


class Session:
    """`daran --port PORT shell ARGS` on a pseudo-terminal of its own."""

    def __init__(self, port, *args, env=None):
        environment = dict(os.environ, TERM="xterm")
        environment.pop("DARAN_PORT", None)
        environment.update(env or {})
        argv = [DARAN, "--port", port, "shell"] + [str(a) for a in args]
        self.pid, self.fd = pty.fork()
        if self.pid == 0:
            try:
                fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 100, 0, 0))
                os.execve(DARAN, argv, environment)
            finally:
                os._exit(127)
        self.raw = ""
        self.status = None

    def read(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            ready, _, _ = select.select([self.fd], [], [], 0.02)
            if ready:
                try:
                    data = os.read(self.fd, 65536)
                except OSError:
                    return
                if not data:
                    return
                self.raw += data.decode(errors="replace")

    def screen(self):
        return render(self.raw)

    def expect(self, pattern, timeout=3.0, since=0):
        """Wait until a shown row (from row `since` on) matches: the match."""
        regex = re.compile(pattern)
        end = time.monotonic() + timeout
        while True:
            for row in self.screen()[since:]:
                m = regex.search(row)
                if m:
                    return m
            if time.monotonic() > end:
                raise AssertionError("no row matches %r; the screen:\n%s"
                                     % (pattern, "\n".join(self.screen()[-30:])))
            self.read(0.05)

    def rows(self):
        return len(self.screen())

    def type(self, keys, settle=0.0):
        os.write(self.fd, keys.encode())
        if settle:
            self.read(settle)

    def line(self, text, pattern, timeout=3.0):
        """Type a line and Enter; wait for a row below it matching pattern."""
        since = self.rows() - 1
        self.type(text + "\r")
        return self.expect(pattern, timeout, since)

    def prompt_row(self, timeout=2.0):
        """The last row once it shows the prompt (what is being typed)."""
        end = time.monotonic() + timeout
        while True:
            self.read(0.05)
            last = self.screen()[-1]
            if last.startswith(PROMPT) or time.monotonic() > end:
                return last

    def last_row(self, expected, timeout=2.0):
        """The last row once it equals `expected` (or when the time is up):
        a report may be on its way to the screen, with the prompt drawn
        again only after it, at the moment one looks."""
        end = time.monotonic() + timeout
        while True:
            self.read(0.02)
            last = self.screen()[-1]
            if last == expected or time.monotonic() > end:
                return last

    def end(self, timeout=5.0):
        """Ctrl-U (drop the line), Ctrl-D; the exit status."""
        self.type("\x15\x04")
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            self.read(0.05)
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self.status = os.waitstatus_to_exitcode(status)
                break
        else:
            os.kill(self.pid, signal.SIGKILL)
            os.waitpid(self.pid, 0)
        os.close(self.fd)
        return self.status

    def kill(self):
        if self.status is None:
            try:
                os.kill(self.pid, signal.SIGKILL)
                os.waitpid(self.pid, 0)
            except OSError:
                pass
            try:
                os.close(self.fd)
            except OSError:
                pass


class ShellTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = Sim(drives=1)
        cls.dir = tempfile.mkdtemp(prefix="daran-shell-")
        cls.env = {"HOME": cls.dir, "DARAN_HISTORY": os.path.join(cls.dir, "history")}

    @classmethod
    def tearDownClass(cls):
        cls.sim.stop()
        shutil.rmtree(cls.dir, ignore_errors=True)

    def session(self, *args):
        s = Session(self.sim.path, *args, env=self.env)
        self.addCleanup(s.kill)
        s.expect("^" + PROMPT)
        return s

    def test_protocol_lines_and_commands_print_their_replies(self):
        s = self.session()
        s.line("f 1", r"^-?[0-9.e+-]+ -?[0-9.e+-]+$")
        s.line("get 1 vbus_voltage", r"^vbus_voltage 24$")
        s.line("r vbus_voltage 1", r"^24$")
        s.line("r axis1.no_such_thing", r"^error: invalid property$")
        since = s.rows() - 1
        s.line("e 1", r"^can: 0$")
        self.assertIn("axis: 0", s.screen()[since:])
        s.line("errors 1", r"no error flag set")
        self.assertEqual(s.end(), 0)

    def test_tab_completes_a_property_path_and_the_line_runs(self):
        s = self.session(1)
        s.line("get 1 output_shaft.vel_limit", r"^output_shaft\.vel_limit \S+$")
        limit = s.screen()[-2].split()[1]
        s.type("r axis1.output_shaft.vel_l\t")
        self.assertEqual(s.prompt_row(), PROMPT + "r axis1.output_shaft.vel_limit ")
        s.line("", "^%s$" % re.escape(limit))
        # the path without axisN. after get, one dotted part at a time
        s.type("get 1 outp\t")
        self.assertEqual(s.prompt_row(), PROMPT + "get 1 output_shaft.")
        s.type("vel_l\t")
        self.assertEqual(s.prompt_row(), PROMPT + "get 1 output_shaft.vel_limit ")
        s.line("", r"^output_shaft\.vel_limit %s$" % re.escape(limit))
        self.assertEqual(s.end(), 0)

    def test_tab_completes_a_command_word(self):
        s = self.session()
        s.type("ge\t")
        self.assertEqual(s.prompt_row(), PROMPT + "get ")
        s.line("1 vbus_voltage", r"^vbus_voltage 24$")
        self.assertEqual(s.end(), 0)

    def test_tab_lists_the_candidates_of_an_ambiguous_prefix(self):
        s = self.session()
        since = s.rows() - 1
        s.type("se\t")
        s.expect(r"^se +send +set$", since=since)
        self.assertEqual(s.prompt_row(), PROMPT + "se")  # the line is drawn again
        s.type("\x15s\t")
        row = s.expect(r"^sc +scan ", since=since).string
        self.assertNotIn("shell", row)  # not inside itself
        s.type("\x15r axis1.output_shaft.vel_\t")
        s.expect(r"axis1\.output_shaft\.vel_estimate +axis1\.output_shaft\.vel_limit",
                 since=since)
        self.assertEqual(s.end(), 0)

    def test_telemetry_reports_are_shown_apart_from_replies(self):
        s = self.session()
        self.addCleanup(lambda: subprocess.run(
            [DARAN, "--port", self.sim.path, "send", "w axis1.telemetry.period 0"],
            capture_output=True, timeout=10))
        s.line("w axis1.telemetry.period 0.05", r"^@1 t=[0-9.]+ pos=\S+ vel=\S+$")
        # while nothing is typed, reports keep coming, above the prompt
        shown = sum(row.startswith("@1 ") for row in s.screen())
        s.read(0.4)
        self.assertGreater(sum(row.startswith("@1 ") for row in s.screen()), shown + 3)
        self.assertEqual(s.last_row(PROMPT), PROMPT)
        # a half-typed line survives a report: it is drawn again below it
        s.type("get 1 vbus")
        s.read(0.2)
        self.assertEqual(s.last_row(PROMPT + "get 1 vbus"), PROMPT + "get 1 vbus")
        since = s.rows() - 1
        s.line("_voltage", r"^vbus_voltage 24$")
        s.line("r vbus_voltage 1", r"^24$")
        for row in s.screen()[since:]:
            if "@" in row:  # every report is a row of its own, whole
                self.assertRegex(row, r"^@1 t=[0-9.]+ pos=\S+ vel=\S+$")
        s.line("w axis1.telemetry.period 0", "^" + PROMPT + "$")
        s.read(0.2)
        quiet = s.rows()
        s.read(0.3)
        self.assertEqual(s.rows(), quiet)  # streaming is off again
        self.assertEqual(s.end(), 0)

    def test_history_is_saved_at_exit_and_loaded_at_start(self):
        s = self.session()
        s.line("get 1 vbus_voltage", r"^vbus_voltage 24$")
        s.line("r vbus_voltage 1", r"^24$")
        self.assertEqual(s.end(), 0)
        with open(self.env["DARAN_HISTORY"]) as f:
            saved = [line.replace("\\040", " ") for line in f.read().splitlines()]
        self.assertEqual(saved[-2:], ["get 1 vbus_voltage", "r vbus_voltage 1"])
        s = self.session()
        s.type("\x1b[A\x1b[A")  # up, up: the lines of the last session
        self.assertEqual(s.prompt_row(), PROMPT + "get 1 vbus_voltage")
        s.line("", r"^vbus_voltage 24$")
        self.assertEqual(s.end(), 0)

    def test_ctrl_c_drops_the_line_and_the_shell_goes_on(self):
        s = self.session()
        s.type("f 1")
        s.read(0.1)
        s.type("\x03")
        s.expect("^" + PROMPT + r"f 1\^C$")  # the line typed is dropped
        self.assertEqual(s.prompt_row(), PROMPT)
        s.line("get 1 vbus_voltage", r"^vbus_voltage 24$")
        s.line("quit", r".*")
        s.read(0.5)
        pid, status = os.waitpid(s.pid, 0)
        s.status = os.waitstatus_to_exitcode(status)
        self.assertEqual(s.status, 0)

    def test_piped_lines_run_without_a_prompt(self):
        script = "f 1\nget 1 vbus_voltage\nr axis1.no_such_thing\nfoo 1\nhelp\n"
        env = dict(os.environ, **self.env)
        env.pop("DARAN_PORT", None)
        done = subprocess.run([DARAN, "--port", self.sim.path, "shell"], input=script,
                              capture_output=True, text=True, timeout=20, env=env)
        self.assertEqual(done.returncode, 0, done.stderr)
        lines = done.stdout.splitlines()
        self.assertRegex(lines[0], r"^-?[0-9.e+-]+ -?[0-9.e+-]+$")
        self.assertEqual(lines[1:4], ["vbus_voltage 24", "error: invalid property",
                                      "error: unknown command"])
        self.assertIn("protocol", done.stdout)  # help
        self.assertNotIn(PROMPT, done.stdout)

    def test_a_port_that_fails_ends_the_shell_with_status_4(self):
        with Proxy(self.sim.path) as proxy:
            shell = subprocess.Popen([DARAN, "--port", proxy.path, "shell"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
            try:
                shell.stdin.write("get 1 vbus_voltage\n")
                shell.stdin.flush()
                time.sleep(0.5)
                proxy.close()  # the port's other end goes away while the shell waits
                out, err = shell.communicate(timeout=10)
            finally:
                if shell.poll() is None:
                    shell.kill()
                    shell.wait()
        self.assertEqual(shell.returncode, 4, err)
        self.assertIn("vbus_voltage 24", out)
        self.assertRegex(err, r"daran: %s: read failed" % re.escape(proxy.path))

    def test_a_bad_id_is_a_usage_error_before_the_port(self):
        done = subprocess.run([DARAN, "--port", "/nonexistent", "shell", "64"],
                              capture_output=True, text=True, timeout=10)
        self.assertEqual(done.returncode, 2)
        self.assertIn("not a motor id", done.stderr)


if __name__ == "__main__":
    main()
