#!/usr/bin/python3
"""tools/plot_telemetry against `daran-sim --pty`: a short recording while
the simulated shaft moves, then the CSV is read back: a row per report at the
requested period on the drive's clock (every interval exactly one period),
as many rows as the duration allows (with slack for a loaded machine), the
fields asked for, a position that moved, a PNG written. Exits 77 (skipped)
without pyserial or /dev/ptmx.

usage: pty_telemetry.py DARAN_SIM PLOT_TELEMETRY WORK_DIR
"""
import csv
import os
import subprocess
import sys

PERIOD = 0.01
DURATION = 1.5


def main():
    sim_path, tool, work = sys.argv[1:4]
    try:
        import serial  # noqa: F401  (the tool needs it)
    except ImportError:
        print("python3-serial is not installed: skipped")
        return 77
    if not os.path.exists("/dev/ptmx"):
        print("no /dev/ptmx on this machine: skipped")
        return 77
    os.makedirs(work, exist_ok=True)
    out_csv = os.path.join(work, "telemetry.csv")
    out_png = os.path.join(work, "telemetry.png")
    for f in (out_csv, out_png):
        if os.path.exists(f):
            os.remove(f)

    # stdin stays open: protocol lines typed there reach the drive too
    sim = subprocess.Popen([sim_path, "--pty"], stdin=subprocess.PIPE,
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    failures = []
    try:
        path = sim.stdout.readline().decode().strip()
        if not path.startswith("/dev/"):
            print("no pty path on the first line: %r" % path)
            return 1
        # a slow move (90 deg at 60 (r/min)/s takes 1 s) under way while it records
        sim.stdin.write(b"q 1 90 60 60\n")
        sim.stdin.flush()
        tool_run = subprocess.run(
            [sys.executable, tool, "--period", str(PERIOD), "--fields", "pos,vel,vbus,traj_done",
             "--duration", str(DURATION), "--csv", out_csv, "--png", out_png, path],
            capture_output=True, text=True, timeout=30)
        sys.stdout.write(tool_run.stdout)
        sys.stdout.write(tool_run.stderr)
        if tool_run.returncode != 0:
            failures.append("plot_telemetry exited %d" % tool_run.returncode)
    finally:
        sim.terminate()
        try:
            sim.wait(timeout=5)
        except subprocess.TimeoutExpired:
            sim.kill()
            sim.wait()

    if not failures:
        with open(out_csv, newline="") as f:
            rows = list(csv.reader(f))
        header, rows = rows[0], rows[1:]
        want = ["time_s", "host_s", "pos_deg", "vel_rpm", "vbus_v", "trajectory_done"]
        if header != want:
            failures.append("CSV header %r, not %r" % (header, want))
        expected = DURATION / PERIOD
        if not 0.5 * expected <= len(rows) <= 1.3 * expected:
            failures.append("%d rows for %g s at %g s (about %d expected)"
                            % (len(rows), DURATION, PERIOD, expected))
        times = [float(r[0]) for r in rows]
        gaps = [b - a for a, b in zip(times, times[1:])]
        off = [g for g in gaps if abs(g - PERIOD) > 1e-4]
        if off:
            failures.append("%d of %d intervals are not %g s on the drive's clock: %r"
                            % (len(off), len(gaps), PERIOD, off[:5]))
        if rows and not all(abs(float(r[4]) - 24.0) < 1.0 for r in rows):
            failures.append("vbus_v is not about 24 V")
        positions = [float(r[2]) for r in rows]
        if rows and not max(positions) - min(positions) > 10.0:
            failures.append("the position did not move: %g..%g" % (min(positions), max(positions)))
        if not (os.path.exists(out_png) and os.path.getsize(out_png) > 1000):
            failures.append("no PNG written")

    for failure in failures:
        print("FAIL:", failure)
    if sim.returncode not in (-15, 143):  # killed by SIGTERM, as a signal ends it
        print("FAIL: daran-sim exit status %d after SIGTERM" % sim.returncode)
        return 1
    print("plot_telemetry on --pty: %s" % ("all checks passed" if not failures else "failed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
