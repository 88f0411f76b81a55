#!/usr/bin/env python3
"""One row of docs/targets.md's table from a finished CTest run of a target
preset (its Testing/Temporary/LastTest.log): the Unity cases run and passed
by the target_* images (or, in a host-style build such as the big-endian
preset, the unit_* and number_* programs), their run time under QEMU, the
core's flash (core_flash or budget_core_flash) and the instructions of
`t 1 10 0 25 *83` (perf_insns_per_line), where the build has them.

  target_summary.py BUILD_DIR [--label TEXT]
"""
import argparse
import os
import re
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir")
    ap.add_argument("--label", default=None)
    opt = ap.parse_args()
    log_path = os.path.join(opt.build_dir, "Testing", "Temporary", "LastTest.log")
    with open(log_path, errors="replace") as f:
        log = f.read()
    # one block per test: "N/M Testing: name" ... "Test time = X sec"
    blocks = re.split(r"^\d+/\d+ Testing: ", log, flags=re.M)[1:]
    run = passed = 0
    qemu_time = 0.0
    flash = insns = None
    suites = 0
    for block in blocks:
        name = block.split("\n", 1)[0].strip()
        time_match = re.search(r"^Test time =\s*([0-9.]+) sec", block, flags=re.M)
        if re.match(r"(target_)?(unit|number)_", name):
            summary = re.findall(r"^(\d+) Tests (\d+) Failures (\d+) Ignored", block, flags=re.M)
            if summary:
                tests, failures, ignored = (int(x) for x in summary[-1])
                run += tests
                passed += tests - failures - ignored
                suites += 1
            if time_match:
                qemu_time += float(time_match.group(1))
        elif name in ("core_flash", "budget_core_flash"):
            totals = re.search(r"^\s*(\d+)\s+(\d+)\s+\d+\s+\d+\s+[0-9a-f]+\s+\(TOTALS\)", block, flags=re.M)
            budget = re.search(r"core flash \(text \+ data\)[^:]*: (\d+) bytes", block)
            if totals:
                flash = int(totals.group(1)) + int(totals.group(2))
            elif budget:
                flash = int(budget.group(1))
        elif name == "perf_insns_per_line":
            m = re.search(r"^\| t with checksum \| `[^`]*` \| (\d+) \|", block, flags=re.M)
            if m:
                insns = int(m.group(1))
    label = opt.label or os.path.basename(os.path.normpath(opt.build_dir))
    line = f"{label}: {suites} suites, {passed}/{run} Unity cases passed, QEMU {qemu_time:.1f} s"
    if flash is not None:
        line += f"; core flash {flash} bytes"
    if insns is not None:
        line += f"; t 1 10 0 25 *83: {insns} instructions"
    print(line)
    return 0 if suites > 0 and passed == run else 1


if __name__ == "__main__":
    sys.exit(main())
