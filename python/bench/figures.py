#!/usr/bin/python3
"""docs/python.md's figures, on one daran-sim --pty (drives 1..3):

  get      a `get` of one property: drive.get() against the C client doing the
           same (c_get.c, daran_client_transact), microseconds per call
  state    drive.state() calls per second, beside daran.vendor.get_state (the
           vendor's get_state: `f`, two values) on the same drive
  import   `import daran` in a fresh interpreter, milliseconds (the median of 15,
           less an interpreter that imports nothing)

Run with the package installed (docs/python.md) and the host build (build/host):
  V/bin/python python/bench/figures.py [--n N]"""
import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
os.environ.setdefault("DARAN_SIM", str(ROOT / "build/host/port/sim/daran-sim"))

import daran  # noqa: E402
import daran.vendor  # noqa: E402


def c_client(work):
    """c_get.c with the C sources the extension compiles, at the extension's -O2 (the
    host build's libraries carry ASan and UBSan)."""
    sys.path.insert(0, str(ROOT / "python"))
    from daran_build import INCLUDE_DIRS, SOURCES
    exe = pathlib.Path(work) / "c_get"
    subprocess.run(["gcc", "-O2", "-std=c11", "-D_DEFAULT_SOURCE", "-fno-math-errno",
                    *[f"-I{ROOT / d}" for d in INCLUDE_DIRS],
                    str(pathlib.Path(__file__).with_name("c_get.c")),
                    *[str(ROOT / s) for s in SOURCES if not s.startswith("cli/")],
                    "-lm", "-o", str(exe)], check=True)
    return exe


ROUNDS = 7


def per_call(function, n):
    for _ in range(100):
        function()
    start = time.perf_counter()
    for _ in range(n):
        function()
    return (time.perf_counter() - start) / n


def import_ms():
    def run(code):
        times = []
        for _ in range(15):
            start = time.perf_counter()
            subprocess.run([sys.executable, "-P", "-c", code], check=True)
            times.append(time.perf_counter() - start)
        return statistics.median(times)
    return (run("import daran") - run("pass")) * 1000


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=2000, help="calls per round")
    n = parser.parse_args().n
    with tempfile.TemporaryDirectory() as work:
        exe = c_client(work)
        link = daran.sim(drives=3, timeout=1.0)
        try:
            drive = link.drive(1)
            # alternated, medians of the rounds: the machine is shared
            c_rounds, py_rounds = [], []
            for _ in range(ROUNDS):
                c_rounds.append(float(subprocess.run(
                    [str(exe), link.sim.pty, str(n)], check=True, capture_output=True,
                    text=True).stdout))
                py_rounds.append(
                    per_call(lambda: drive.get("axis1.output_shaft.vel_limit"), n) * 1e6)
            c_us, py_us = statistics.median(c_rounds), statistics.median(py_rounds)
            state = 1 / per_call(drive.state, n)
            daran.vendor.connect(link)
            vendor = 1 / per_call(lambda: daran.vendor.get_state(1), n)
        finally:
            link.close()
    print(f"get: python {py_us:.1f} us, C client {c_us:.1f} us, ratio {py_us / c_us:.2f}")
    print(f"state(): {state:,.0f} calls/s (position, velocity, torque, done, error); "
          f"daran.vendor.get_state: {vendor:,.0f} calls/s (position, velocity)")
    print(f"import daran: {import_ms():.1f} ms")


if __name__ == "__main__":
    main()
