#!/usr/bin/env python3
"""Light mutation check of the core against tests/unit: how many one-operator
changes in src/*.c make at least one unit test fail.

Copies the source tree (without build/ and .git/) to a scratch directory,
builds only the unit test programs there (gcc, Debug, no sanitizers, so each
mutant builds fast), then for a random sample of mutants changes one operator
(== != < <= > >= && || and +1u/-1u), rebuilds, runs the nine programs and
restores the file. Prints every surviving mutant and the totals.

Usage: tests/unit/mutation_check.py [COUNT] [SEED] [FILE,FILE...]
  COUNT  mutants to run (default 60), SEED  sample seed (default 1),
  FILES  restrict to these src/ files (default: all but version.c).
Some survivors are equivalent mutants (e.g. a bound in a loop over a bit set
whose extra bit is never set); read each one before calling it a gap.
"""
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

AREAS = ["framing", "checksum_and_words", "numbers_in_fields", "commands", "errors",
         "properties", "addressing", "states_and_queries", "api"]
OPS = [(r"(?<![<>=!])==(?!=)", "!="), (r"!=", "=="), (r"(?<![<-])<=", "<"),
       (r"(?<![<>-])<(?![<=])", "<="), (r"(?<![->])>=", ">"), (r"(?<![->])>(?![>=])", ">="),
       (r"&&", "||"), (r"\|\|", "&&"), (r"\+ 1u\b", "+ 0u"), (r"- 1u\b", "- 0u")]


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
        if not s or s[0] in "#*" or s.startswith("//"):
            continue
        yield i, line.split("/*")[0]


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 60
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    only = sys.argv[3].split(",") if len(sys.argv) > 3 else None
    repo = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    work = tempfile.mkdtemp(prefix="daran-mutation-")
    tree, build = os.path.join(work, "tree"), os.path.join(work, "build")
    shutil.copytree(repo, tree, ignore=shutil.ignore_patterns("build", ".git"))
    subprocess.run(["cmake", "-S", tree, "-B", build, "-G", "Ninja", "-DCMAKE_C_COMPILER=gcc",
                    "-DCMAKE_BUILD_TYPE=Debug", "-DDARAN_BUILD_SIM=OFF", "-DDARAN_BUILD_DEMO=OFF"],
                   check=True, capture_output=True)
    targets = ["tests/unit/unit_" + a for a in AREAS]
    subprocess.run(["ninja", "-C", build] + targets, check=True, capture_output=True)

    src = os.path.join(tree, "src")
    files = [f for f in sorted(os.listdir(src)) if f.endswith(".c") and f != "version.c"
             and (only is None or f in only)]
    mutants = []
    for f in files:
        text = open(os.path.join(src, f)).read()
        for i, code in code_lines(text):
            for pat, rep in OPS:
                for m in re.finditer(pat, code):
                    mutants.append((f, i, m.start(), m.end(), rep))
    random.seed(seed)
    sample = random.sample(mutants, min(count, len(mutants)))
    print(f"{len(mutants)} possible mutants in {len(files)} files, running {len(sample)}",
          flush=True)

    killed = survived = broken = 0
    for f, i, a, b, rep in sample:
        path = os.path.join(src, f)
        original = open(path).read()
        lines = original.split("\n")
        before = lines[i]
        lines[i] = before[:a] + rep + before[b:]
        open(path, "w").write("\n".join(lines))
        try:
            if subprocess.run(["ninja", "-C", build] + targets, capture_output=True).returncode:
                broken += 1
                continue
            dead = False
            for area in AREAS:
                try:
                    r = subprocess.run([os.path.join(build, "tests", "unit", "unit_" + area)],
                                       capture_output=True, timeout=30)
                    dead = r.returncode != 0
                except subprocess.TimeoutExpired:
                    dead = True
                if dead:
                    break
            if dead:
                killed += 1
            else:
                survived += 1
                print(f"SURVIVED {f}:{i + 1}: {before.strip()}  ->  {lines[i].strip()}", flush=True)
        finally:
            open(path, "w").write(original)
    print(f"killed {killed} survived {survived} did-not-build {broken}", flush=True)
    shutil.rmtree(work)
    return 0 if survived == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
