"""`daran watch` against daran-sim --pty (docs/cli.md, "watch"): telemetry
streaming with the drive's settings written back however the run ends
(duration, SIGINT, SIGTERM), polling (forced, and for a drive without
telemetry), the live terminal view, CSV, JSON lines, the gnuplot picture,
a drive that does not answer and usage errors."""
import csv
import json
import os
import pty
import select
import shutil
import signal
import subprocess
import tempfile
import threading
import time
import tty
import unittest

from cli_support import DARAN, Proxy, Sim, daran, main


class HiddenTelemetry:
    """A pseudo-terminal between daran and the drive that renames
    `telemetry.` in every request line, so the drive answers `error:
    invalid property` to it: a drive without telemetry, as a port that
    leaves it out would be. .path is what daran opens."""

    def __init__(self, drive_path):
        self.master, self._slave = pty.openpty()
        tty.setraw(self._slave)
        self.path = os.ttyname(self._slave)
        self.drive = os.open(drive_path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.drive)
        self._stop = False
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self):
        pending = b""
        while not self._stop:
            ready, _, _ = select.select([self.master, self.drive], [], [], 0.05)
            if self.drive in ready:
                os.write(self.master, os.read(self.drive, 4096))
            if self.master in ready:
                pending += os.read(self.master, 4096)
                lines = pending.split(b"\n")
                pending = lines.pop()
                for line in lines:
                    os.write(self.drive, line.replace(b"telemetry.", b"no_telemetry.") + b"\n")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self._stop = True
        self._thread.join(timeout=2)
        for fd in (self.master, self._slave, self.drive):
            os.close(fd)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in row] for row in rows[1:]]


class Watch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = Sim(drives=1)
        cls.tmp = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.sim.stop()
        cls.tmp.cleanup()

    def file(self, name):
        return os.path.join(self.tmp.name, name)

    def telemetry_settings(self):
        r = daran(self.sim.path, "get", "1", "telemetry.period", "telemetry.fields")
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout.split()[1::2]

    def assert_increasing(self, times):
        self.assertTrue(all(a < b for a, b in zip(times, times[1:])), times)

    def test_telemetry_csv_and_settings_written_back(self):
        self.assertEqual(self.telemetry_settings(), ["0", "3"])
        out = self.file("stream.csv")
        # torque cannot be polled: rows with it come from the stream
        r = daran(self.sim.path, "watch", "1", "pos", "torque", "vbus", "--duration", "0.5",
                  "--csv", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")
        header, rows = read_csv(out)
        self.assertEqual(header, ["time_s", "pos", "torque", "vbus"])
        self.assertGreaterEqual(len(rows), 6)
        times = [row[0] for row in rows]
        self.assert_increasing(times)
        # the drive's clock, a report every 0.05 s
        for a, b in zip(times, times[1:]):
            self.assertAlmostEqual(b - a, 0.05, delta=0.002)
        self.assertTrue(all(row[3] == 24 for row in rows), rows)
        # stdout (a pipe): one line per sample, as in the CSV
        lines = r.stdout.splitlines()
        self.assertEqual(len(lines), len(rows))
        self.assertEqual([float(v) for v in lines[0].split()], rows[0])
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_a_running_stream_is_put_back_as_it_was(self):
        r = daran(self.sim.path, "set", "1", "telemetry.fields", "17", "telemetry.period", "0.2")
        self.assertEqual(r.returncode, 0, r.stderr)
        try:
            # the drive may finish its old period (0.2 s) before the new one starts
            r = daran(self.sim.path, "watch", "1", "vel", "--period", "0.02", "--duration", "0.6")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertGreaterEqual(len(r.stdout.splitlines()), 10)
            self.assertEqual(self.telemetry_settings(), ["0.2", "17"])
        finally:
            daran(self.sim.path, "set", "1", "telemetry.period", "0", "telemetry.fields", "3")

    def test_a_signal_ends_the_watch_and_the_stream(self):
        for signo in (signal.SIGINT, signal.SIGTERM):
            with self.subTest(signal=signo):
                env = dict(os.environ)
                env.pop("DARAN_PORT", None)
                p = subprocess.Popen([DARAN, "--port", self.sim.path, "watch", "1", "pos"],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     env=env)
                first = p.stdout.readline()  # streaming
                time.sleep(0.25)
                p.send_signal(signo)
                out, err = p.communicate(timeout=10)
                self.assertEqual(p.returncode, 0, err)
                self.assertEqual(err, "")
                self.assertGreaterEqual(len((first + out).splitlines()), 3)
                self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_a_reader_that_goes_away_ends_the_watch(self):
        # `daran watch 1 | head -2`: the pipe breaks, the stream still stops
        env = dict(os.environ)
        env.pop("DARAN_PORT", None)
        p = subprocess.Popen([DARAN, "--port", self.sim.path, "watch", "1", "--period", "0.01"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
        p.stdout.readline()
        p.stdout.readline()
        p.stdout.close()
        err = p.stderr.read().decode()
        p.stderr.close()
        p.wait(timeout=10)
        self.assertEqual(p.returncode, 0, err)
        self.assertEqual(err, "")
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_a_stream_that_stops(self):
        # the drive goes silent mid-stream: exit 3 after 1 s without a report; the
        # settings are still written (the drive hears them; their read-backs are lost)
        with Proxy(self.sim.path) as link:
            env = dict(os.environ)
            env.pop("DARAN_PORT", None)
            p = subprocess.Popen([DARAN, "--port", link.path, "--timeout", "0.05", "watch", "1"],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                 env=env)
            first = p.stdout.readline()
            link.drop_replies()
            out, err = p.communicate(timeout=10)
        self.assertEqual(p.returncode, 3, err)
        self.assertTrue(first)
        messages = err.splitlines()
        self.assertIn("drive 1 sent no telemetry report for 1000 ms", messages[0])
        self.assertTrue(all("drive 1 did not answer" in m for m in messages[1:]), messages)
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_poll_gives_rows(self):
        out = self.file("poll.csv")
        r = daran(self.sim.path, "watch", "1", "vbus", "pos", "--poll", "--period", "0.04",
                  "--duration", "0.3", "--csv", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(out)
        self.assertEqual(header, ["time_s", "vbus", "pos"])
        self.assertGreaterEqual(len(rows), 5)
        self.assertEqual(rows[0][0], 0.0)  # the host's clock, from the start
        self.assert_increasing([row[0] for row in rows])
        self.assertTrue(all(row[1] == 24 for row in rows), rows)
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_checksums(self):
        for mode in ([], ["--poll"]):
            with self.subTest(mode=mode):
                r = daran(self.sim.path, "--checksum", "watch", "1", "pos", "vbus", *mode,
                          "--duration", "0.2")
                self.assertEqual(r.returncode, 0, r.stderr)
                lines = r.stdout.splitlines()
                self.assertGreaterEqual(len(lines), 2)
                self.assertTrue(all(line.split()[2] == "24" for line in lines), lines)
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    def test_json_lines(self):
        r = daran(self.sim.path, "--json", "watch", "1", "trajectory_done", "error",
                  "--duration", "0.2")
        self.assertEqual(r.returncode, 0, r.stderr)
        samples = [json.loads(line) for line in r.stdout.splitlines()]
        self.assertGreaterEqual(len(samples), 3)
        self.assertEqual(list(samples[0]), ["time_s", "trajectory_done", "error"])
        self.assertTrue(all(s["error"] == 0 for s in samples), samples)

    def test_the_motor_moves_under_watch(self):
        for mode in ([], ["--poll"]):
            with self.subTest(mode=mode):
                r = daran(self.sim.path, "send", "f 1")
                start = float(r.stdout.split()[0])
                target = round(start) + 180
                # a trapezoid of about 0.5 s: 60 r/min = 360 deg/s, reached in 0.02 s
                r = daran(self.sim.path, "--timeout", "0.05", "send", "q 1 %d 60 3000" % target)
                self.assertEqual(r.returncode, 0, r.stderr)
                r = daran(self.sim.path, "--json", "watch", "1", "pos", "vel", *mode,
                          "--period", "0.02", "--duration", "0.8")
                self.assertEqual(r.returncode, 0, r.stderr)
                samples = [json.loads(line) for line in r.stdout.splitlines()]
                pos = [s["pos"] for s in samples]
                self.assertLess(pos[0], target - 30, pos)
                self.assertAlmostEqual(pos[-1], target, delta=0.5)
                self.assertGreater(max(s["vel"] for s in samples), 10)

    def test_terminal_view(self):
        master, slave = pty.openpty()
        p = subprocess.Popen([DARAN, "--port", self.sim.path, "watch", "1", "pos", "vbus",
                              "--period", "0.01", "--duration", "0.6"],
                             stdout=slave, stderr=subprocess.PIPE)
        os.close(slave)
        out = b""
        while True:
            try:
                data = os.read(master, 4096)
            except OSError:  # the last writer closed
                break
            if not data:
                break
            out += data
        p.wait(timeout=10)
        os.close(master)
        errors = p.stderr.read()
        p.stderr.close()
        self.assertEqual(p.returncode, 0, errors)
        text = out.decode()
        self.assertIn("(Ctrl-C ends)", text)
        redraws = text.count("\r") - text.count("\r\n")
        # 60 samples in 0.6 s, at most ~10 redraws a second
        self.assertGreaterEqual(redraws, 3)
        self.assertLessEqual(redraws, 9)
        self.assertRegex(text, r"\rt [0-9.]+ s   pos [-0-9.e]+ deg   vbus 24 V\x1b\[K")
        self.assertRegex(text, r"\r\n[0-9]+ samples\r\n$")
        self.assertEqual(self.telemetry_settings(), ["0", "3"])

    @unittest.skipIf(shutil.which("gnuplot") is None, "gnuplot is not installed")
    def test_plot(self):
        png = self.file("watch.png")
        r = daran(self.sim.path, "watch", "1", "pos", "vel", "iq", "--duration", "0.3",
                  "--plot", png)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(png, "rb") as f:
            picture = f.read()
        self.assertTrue(picture.startswith(b"\x89PNG\r\n\x1a\n"))
        self.assertGreater(len(picture), 1000)

    def test_plot_without_gnuplot(self):
        r = daran("/dev/null-no-port", "watch", "1", "--plot", self.file("x.png"),
                  env={"PATH": self.tmp.name})
        self.assertEqual(r.returncode, 2)
        self.assertIn("gnuplot", r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1)

    def test_a_drive_without_telemetry_is_polled(self):
        with HiddenTelemetry(self.sim.path) as link:
            out = self.file("hidden.csv")
            r = daran(link.path, "watch", "1", "--duration", "0.3", "--csv", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            header, rows = read_csv(out)
            self.assertEqual(header, ["time_s", "pos", "vel"])
            self.assertGreaterEqual(len(rows), 4)
            self.assertEqual(rows[0][0], 0.0)
            r = daran(link.path, "watch", "1", "pos", "torque", "--duration", "0.3")
            self.assertEqual(r.returncode, 2)
            self.assertIn("drive 1 has no telemetry", r.stderr)
            self.assertEqual(len(r.stderr.splitlines()), 1)

    def test_a_drive_that_does_not_answer(self):
        for mode in ([], ["--poll"]):
            with self.subTest(mode=mode):
                r = daran(self.sim.path, "--timeout", "0.05", "watch", "5", *mode,
                          "--duration", "1", "--csv", self.file("none.csv"))
                self.assertEqual(r.returncode, 3)
                self.assertEqual(r.stdout, "")
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn("drive 5 did not answer", r.stderr)
                self.assertFalse(os.path.exists(self.file("none.csv")))

    def test_usage_errors_come_before_the_port(self):
        for args in (["watch"], ["watch", "64"], ["watch", "1", "speed"],
                     ["watch", "1", "pos", "pos"], ["watch", "1", "--period", "0"],
                     ["watch", "1", "--duration", "-1"], ["watch", "1", "--period"],
                     ["watch", "1", "--poll", "torque"], ["watch", "1", "--frequency", "9"],
                     ["watch", "1", "--csv", "/no/such/dir/x.csv"]):
            with self.subTest(args=args):
                r = daran("/dev/null-no-port", *args)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertTrue(r.stderr.startswith("daran: watch: "), r.stderr)


if __name__ == "__main__":
    main()
