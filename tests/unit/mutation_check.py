#!/usr/bin/env python3
"""Mutation check of the core against tests/unit: does every one-operator
change in src/*.c make at least one unit test fail?

Copies the source tree (without build/ and .git/) to a scratch directory,
builds the unit test programs there (gcc, Debug, ASan + UBSan, so a mutant
that only writes out of bounds is caught too), then for a random sample of
mutants changes one operator (== != < <= > >= && || and +1u/-1u), runs the
unit programs (tests/unit's, tests/number's and the bridge's) until one fails
and restores the file. Each program is rebuilt only when its turn comes, and
the program that last killed a mutant of a file runs first for that file's
next mutant, so a killed mutant costs one link and one run, not fifteen; a
survivor has passed every program. A program that outlives 20 times its
unmutated run (at least 60 s; a mutant that loops) counts as a kill, and the
summary says how many kills were timeouts, so a loaded machine cannot pass
off a slow run as a kill unnoticed.

A survivor is a gap in the tests unless it is an equivalent mutant listed,
with the reason, in mutation_equivalent.txt (one "file: before -> after" per
line, text as printed). Exit status 1 when an unlisted mutant survives, or
when a listed one of the files checked is no longer a mutant of the source
(stale: its line changed, and the reason may no longer hold).

Usage: tests/unit/mutation_check.py [--count N] [--seed S] [--files a.c,b.c]
  --count  mutants to run (default 120; 0: every mutant, about an hour on a
           busy 2-core machine)
  --seed   sample seed (default 1)
  --files  restrict to these src/ files (default: all but version.c)
Run by CTest as `mutation_unit` (label mutation, left out of the default
test presets): ctest --preset mutation.
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

OPS = [(r"(?<![<>=!])==(?!=)", "!="), (r"!=", "=="), (r"(?<![<-])<=", "<"),
       (r"(?<![<>-])<(?![<=])", "<="), (r"(?<![->])>=", ">"), (r"(?<![->])>(?![>=])", ">="),
       (r"&&", "||"), (r"\|\|", "&&"), (r"\+ 1u\b", "+ 0u"), (r"- 1u\b", "- 0u")]


def test_programs(repo):
    """Every unit program: the areas of tests/unit/areas.cmake (so a new suite
    counts at once), the number module's own unit suites and the float
    interval suite."""
    text = open(os.path.join(repo, "tests", "unit", "areas.cmake")).read()
    block = re.search(r"set\(DARAN_UNIT_AREAS(.*?)\)", text, re.S)
    # porting_float_intervals: a core whose float rows have interval ranges,
    # the only build that compiles the interval check (DARAN_F32_INTERVALS)
    # test_bridge: the CAN bridge's own suite (can_bridge.c, and the scaled
    # writer's refusals, which only the bridge asks for)
    return (["tests/unit/unit_" + a for a in block.group(1).split()]
            + ["tests/number/number_unit", "tests/number/number_pow10",
               "tests/porting/porting_float_intervals", "tests/bridge/test_bridge"])


def equivalent_mutants(repo):
    """The survivors accepted as equivalent: "file: before -> after" keys."""
    keys = set()
    for line in open(os.path.join(repo, "tests", "unit", "mutation_equivalent.txt")):
        line = line.split("  #")[0].strip()
        if line and not line.startswith("#"):
            keys.add(line)
    return keys


def mutant_key(f, line, a, b, rep):
    """How a mutant is printed and listed: "file: before -> after"."""
    return f"{f}: {line.strip()} -> {(line[:a] + rep + line[b:]).strip()}"


def code_lines(text):
    """Yield (index, code part) of lines that are not comments or directives."""
    in_comment = False
    for i, line in enumerate(text.split("\n")):
        s = line.strip()
        if in_comment:
            in_comment = "*/" not in s
            continue
        if s.startswith("/*"):
            in_comment = "*/" not in s
            continue
        if not s or s[0] == "#" or s.startswith("//"):
            continue
        yield i, line.split("/*")[0]


def run_times(build, programs):
    """Wall time of each program's unmutated run, or None when one fails."""
    times = {}
    for program in programs:
        start = time.monotonic()
        if subprocess.run([os.path.join(build, program)], capture_output=True).returncode:
            return None
        times[program] = time.monotonic() - start
    return times


def verdict(build, programs, timeouts):
    """Build and run the programs in turn: (outcome, the program that failed,
    whether it timed out), outcome "broken" when one does not build, "killed"
    when one fails, else "survived"."""
    for program in programs:
        if subprocess.run(["ninja", "-C", build, program], capture_output=True).returncode:
            return "broken", None, False
        try:
            r = subprocess.run([os.path.join(build, program)], capture_output=True,
                               timeout=timeouts[program])
            if r.returncode != 0:
                return "killed", program, False
        except subprocess.TimeoutExpired:
            return "killed", program, True
    return "survived", None, False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--count", type=int, default=120)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--files", default="")
    args = ap.parse_args()
    only = args.files.split(",") if args.files else None
    repo = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    targets = test_programs(repo)
    accepted = equivalent_mutants(repo)
    started = time.monotonic()
    work = tempfile.mkdtemp(prefix="daran-mutation-")
    tree, build = os.path.join(work, "tree"), os.path.join(work, "build")
    shutil.copytree(repo, tree, ignore=shutil.ignore_patterns("build", ".git"))
    subprocess.run(["cmake", "-S", tree, "-B", build, "-G", "Ninja", "-DCMAKE_C_COMPILER=gcc",
                    "-DCMAKE_BUILD_TYPE=Debug", "-DDARAN_SANITIZE=ON", "-DDARAN_BUILD_SIM=OFF",
                    "-DDARAN_BUILD_DEMO=OFF"], check=True, capture_output=True)
    subprocess.run(["ninja", "-C", build] + targets, check=True, capture_output=True)
    baseline = run_times(build, targets)
    if baseline is None:
        print("the unmutated core fails its unit tests")
        return 1
    timeouts = {p: max(60.0, 20.0 * t) for p, t in baseline.items()}

    src = os.path.join(tree, "src")
    # each file by its path under src/ (a room's folder and its name)
    files = sorted(os.path.relpath(os.path.join(d, f), src)
                   for d, _, names in os.walk(src) for f in names
                   if f.endswith(".c") and f != "version.c")
    files = [f for f in files if only is None or f in only or os.path.basename(f) in only]
    mutants = []
    keys = set()
    for f in files:
        text = open(os.path.join(src, f)).read()
        lines = text.split("\n")
        for i, code in code_lines(text):
            for pat, rep in OPS:
                for m in re.finditer(pat, code):
                    mutants.append((f, i, m.start(), m.end(), rep))
                    keys.add(mutant_key(f, lines[i], m.start(), m.end(), rep))
    stale = sorted(k for k in accepted if k.split(":")[0] in files and k not in keys)
    for key in stale:
        print(f"STALE (listed, no longer a mutant): {key}", flush=True)
    random.seed(args.seed)
    sample = mutants if args.count <= 0 else random.sample(mutants, min(args.count, len(mutants)))
    print(f"{len(mutants)} possible mutants in {len(files)} files, running {len(sample)} "
          f"against {len(targets)} unit programs", flush=True)

    killed = equivalent = broken = timed_out = 0
    gaps = []
    order = {f: list(targets) for f in files}  # the last killer of each file first
    for f, i, a, b, rep in sample:
        path = os.path.join(src, f)
        original = open(path).read()
        lines = original.split("\n")
        before = lines[i]
        lines[i] = before[:a] + rep + before[b:]
        open(path, "w").write("\n".join(lines))
        try:
            outcome, killer, timeout = verdict(build, order[f], timeouts)
            if outcome == "broken":
                broken += 1
            elif outcome == "killed":
                killed += 1
                timed_out += timeout
                order[f].remove(killer)
                order[f].insert(0, killer)
            else:
                key = mutant_key(f, before, a, b, rep)
                if key in accepted:
                    equivalent += 1
                else:
                    gaps.append(key)
                    print(f"SURVIVED {f}:{i + 1}: {key}", flush=True)
        finally:
            open(path, "w").write(original)
    print(f"killed {killed} ({timed_out} by a timeout), equivalent {equivalent}, "
          f"survived {len(gaps)}, did not build {broken}, stale entries {len(stale)}; "
          f"{time.monotonic() - started:.0f} s", flush=True)
    shutil.rmtree(work)
    return 0 if not gaps and not stale else 1


if __name__ == "__main__":
    sys.exit(main())
