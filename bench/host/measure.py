#!/usr/bin/env python3
"""Every host figure of docs/performance.md, counted with callgrind.

    measure.py --driver BUILD/bench/host/daran_bench_driver --out DIR
               [--clang-driver PATH] [--reference bench/host/reference.txt]

Writes DIR/host.md (the tables), DIR/families.dat (the chart's data) and,
with --reference, the committed reference figure(s) of the CTest guard.
Instruction counts (Ir) are deterministic: the same binary on the same stream
gives the same count on every run.

Definitions
  core          instructions inside the parser's entry point and everything it
                calls (HAL stubs and reply sink included), via callgrind
                --toggle-collect=daran_process_line / baseline_process_line
                (ours-poll: daran_rx_write + daran_poll), divided by lines
  whole program (Ir of the whole driver run - Ir of the same run in mode
                `none`, which reads and splits the stream but parses nothing)
                / lines: what each line costs the program, libc included
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
STREAMS = os.path.join(ROOT, "bench", "streams")
FAMILIES = [
    ("t", "t"), ("t_cs", "t + checksum"), ("q", "q"), ("p", "p"), ("v", "v"), ("c", "c"),
    ("d", "d"), ("ms_mq", "ms/mq"), ("r", "r"), ("w", "w"), ("f", "f"), ("g", "g"), ("e", "e"),
    ("errors", "errors"),
]
SESSIONS = ["reference", "tuning", "bus"]
ENTRY = {"ours": ["daran_process_line"], "ours-poll": ["daran_rx_write", "daran_poll"],
         "baseline": ["baseline_process_line"]}
LOOKUP = {"ours": ["daran_find_property"], "baseline": ["baseline_find_property"]}


def callgrind(driver, args, toggles=()):
    with tempfile.NamedTemporaryFile(prefix="cg.", delete=False) as f:
        out = f.name
    try:
        cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out]
        cmd += ["--toggle-collect=" + t for t in toggles]
        cmd += [driver] + args
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(out) as f:
            for line in f:
                if line.startswith("totals:"):
                    return int(line.split()[1])
        raise RuntimeError("no totals in callgrind output of %s" % " ".join(cmd))
    finally:
        os.unlink(out)


def per_call(driver, mode, stream, function):
    """Instructions inside each call of function, in call order (callgrind
    dumps a profile after every call; each holds the cost since the last)."""
    with tempfile.TemporaryDirectory(prefix="cg.") as tmp:
        base = os.path.join(tmp, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + base,
                        "--toggle-collect=" + function, "--dump-after=" + function,
                        driver, mode, stream],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        dumps = sorted((int(n.rsplit(".", 1)[1]), n) for n in os.listdir(tmp)
                       if re.match(r"cg\.out\.\d+$", n))
        costs = []
        for _, name in dumps:
            with open(os.path.join(tmp, name)) as f:
                costs.append(next(int(l.split()[1]) for l in f if l.startswith("totals:")))
        return costs


def profile(driver, mode, stream, top=10):
    """The functions the parser spends its instructions in (exclusive Ir),
    from callgrind_annotate over a run limited to the entry point."""
    with tempfile.TemporaryDirectory(prefix="cg.") as tmp:
        out = os.path.join(tmp, "cg.out")
        cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out]
        cmd += ["--toggle-collect=" + t for t in ENTRY[mode]] + [driver, mode, stream]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        text = subprocess.run(["callgrind_annotate", "--threshold=100", out], check=True,
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout.decode()
    rows = []
    for line in text.splitlines():
        m = re.match(r"^\s*([\d,]+) \(\s*([\d.]+)%\)\s+(\S+?):(\S+)", line)
        if m and "PROGRAM TOTALS" not in line:
            name = m.group(4)
            rows.append((int(m.group(1).replace(",", "")), float(m.group(2)), name))
    return rows[:top]


def profile_table(driver, md):
    path = os.path.join(STREAMS, "reference.txt")
    n = lines_in(path)
    ours = profile(driver, "ours", path)
    base = profile(driver, "baseline", path)
    md.append("| # | daran-ascii function | per line | share | baseline function | per line | share |")
    md.append("|---:|---|---:|---:|---|---:|---:|")
    for i in range(max(len(ours), len(base))):
        a = ours[i] if i < len(ours) else (0, 0.0, "")
        b = base[i] if i < len(base) else (0, 0.0, "")
        md.append("| %d | %s | %s | %.1f%% | %s | %s | %.1f%% |" % (
            i + 1, a[2], fmt(a[0] / n), a[1], b[2], fmt(b[0] / n), b[1]))


def core(driver, mode, args, toggles=None):
    return callgrind(driver, [mode] + args, toggles or ENTRY[mode])


def lines_in(path):
    with open(path, "rb") as f:
        return sum(1 for _ in f)


def fmt(x):
    return "{:,}".format(int(round(x)))


def ratio(a, b):
    return "%.1fx" % (b / a) if a else "-"


def properties():
    """(scope, path) in list order, from the X-macro list."""
    text = open(os.path.join(ROOT, "include", "daran_properties.h")).read()
    return re.findall(r'X\(\w+,\s*"([^"]+)",\s*(SYSTEM|AXIS)', text)


def verdict(families, sessions):
    """The 10x goal, met or missed, and by how much."""
    ours, base = sessions["reference"]
    worst = min(families, key=lambda f: f[2] / f[1])
    best = max(families, key=lambda f: f[2] / f[1])
    met = ours * 10 <= base
    text = ("**Goal: at least 10x fewer instructions per line than the baseline: %s.** "
            "reference.txt: %s against %s, %.1fx" % ("met" if met else "missed", fmt(ours),
                                                   fmt(base), base / ours))
    if not met:
        text += " (10x needs <= %s per line, %.0f%% fewer than now)" % (
            fmt(base / 10), 100 * (1 - base / 10 / ours))
    text += "; by family from %.1fx (%s) to %.1fx (%s)." % (
        worst[2] / worst[1], worst[0], best[2] / best[1], best[0])
    return text


def families_table(driver, out, md):
    md.append("| family | lines | core: daran-ascii | core: baseline | core ratio | "
              "whole program: daran-ascii | whole program: baseline | whole ratio |")
    md.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    data = []
    for name, label in FAMILIES:
        path = os.path.join(STREAMS, "families", name + ".txt")
        n = lines_in(path)
        ours = core(driver, "ours", [path]) / n
        base = core(driver, "baseline", [path]) / n
        none = callgrind(driver, ["none", path])
        ours_whole = (callgrind(driver, ["ours", path]) - none) / n
        base_whole = (callgrind(driver, ["baseline", path]) - none) / n
        md.append("| %s | %d | %s | %s | %s | %s | %s | %s |" % (
            label, n, fmt(ours), fmt(base), ratio(ours, base), fmt(ours_whole), fmt(base_whole),
            ratio(ours_whole, base_whole)))
        data.append((label, ours, base))
        print("  family %-14s ours %7.0f baseline %7.0f" % (label, ours, base), flush=True)
    with open(os.path.join(out, "families.dat"), "w") as f:
        f.write("# family  daran-ascii  baseline   (core instructions per line)\n")
        for label, ours, base in data:
            f.write('"%s" %.0f %.0f\n' % (label, ours, base))
    return data


def sessions_table(driver, md):
    md.append("| stream | lines | core: daran_process_line | core: byte path (rx_write + poll) | "
              "core: baseline | ratio | whole program incl. start-up: daran-ascii | baseline |")
    md.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    figures = {}
    pairs = {}
    for name in SESSIONS:
        path = os.path.join(STREAMS, name + ".txt")
        n = lines_in(path)
        ours_total = core(driver, "ours", [path])
        ours = ours_total / n
        poll = core(driver, "ours-poll", [path]) / n
        base = core(driver, "baseline", [path]) / n
        ours_whole = callgrind(driver, ["ours", path]) / n
        base_whole = callgrind(driver, ["baseline", path]) / n
        figures[name] = ours_total
        pairs[name] = (ours, base)
        md.append("| %s | %d | %s | %s | %s | %s | %s | %s |" % (
            name + ".txt", n, fmt(ours), fmt(poll), fmt(base), ratio(ours, base), fmt(ours_whole),
            fmt(base_whole)))
        print("  stream %-10s ours %7.0f poll %7.0f baseline %7.0f" % (name, ours, poll, base),
              flush=True)
    return figures, pairs


def lookup_table(driver, out, md):
    props = properties()
    axis = [p for p, s in props if s == "AXIS"]
    system = [p for p, s in props if s == "SYSTEM"]
    # Every property once, in list order (= table order of both parsers).
    sweep = os.path.join(out, "lookup_lines.txt")
    with open(sweep, "w") as f:
        for path, scope in props:
            f.write("r axis1.%s\n" % path if scope == "AXIS" else "r %s 1\n" % path)
    ours_all = per_call(driver, "ours", sweep, LOOKUP["ours"][0])
    base_all = per_call(driver, "baseline", sweep, LOOKUP["baseline"][0])
    if len(ours_all) != len(props) or len(base_all) != len(props):
        raise RuntimeError("lookup sweep: %d/%d calls for %d properties"
                           % (len(ours_all), len(base_all), len(props)))
    with open(os.path.join(out, "lookup.dat"), "w") as f:
        f.write("# row  daran-ascii  baseline  path   (instructions per lookup)\n")
        for i, ((path, scope), a, b) in enumerate(zip(props, ours_all, base_all)):
            f.write("%d %d %d %s%s\n" % (i + 1, a, b, "axisN." if scope == "AXIS" else "", path))
    index = {p: i for i, (p, _) in enumerate(props)}
    picks = [("system, first", system[0], "r %s 1" % system[0]),
             ("system, last", system[-1], "r %s 1" % system[-1]),
             ("axis, first", axis[0], "r axis1." + axis[0]),
             ("axis, middle", axis[len(axis) // 2], "r axis1." + axis[len(axis) // 2]),
             ("axis, last", axis[-1], "r axis1." + axis[-1]),
             ("axis, unknown", "output_shaft.no_such_thing", "r axis1.output_shaft.no_such_thing")]
    repeat = 100
    md.append("Property table: %d rows (%d system, %d axis), in the order of "
              "include/daran_properties.h. Lookup = the table search alone, counted inside "
              "daran_find_property / baseline_find_property while the `r` line is processed; "
              "line = the whole `r` request (core)." % (len(props), len(system), len(axis)))
    md.append("")
    md.append("| property | row | path | lookup: daran-ascii | lookup: baseline | "
              "`r` line: daran-ascii | `r` line: baseline |")
    md.append("|---|---:|---|---:|---:|---:|---:|")
    for label, name, line in picks:
        args = ["--repeat", str(repeat), "--line", line]
        ours = core(driver, "ours", args, LOOKUP["ours"]) / repeat
        base = core(driver, "baseline", args, LOOKUP["baseline"]) / repeat
        ours_line = core(driver, "ours", args) / repeat
        base_line = core(driver, "baseline", args) / repeat
        row = str(index[name] + 1) if name in index else "-"
        md.append("| %s | %s | `%s` | %s | %s | %s | %s |" % (
            label, row, name, fmt(ours), fmt(base), fmt(ours_line), fmt(base_line)))
        print("  lookup %-14s ours %5.0f baseline %5.0f" % (label, ours, base), flush=True)
    md.append("")
    md.append("Over all %d rows: daran-ascii min %s, mean %s, max %s instructions per lookup; "
              "baseline min %s, mean %s, max %s (every row: lookup.dat, chart "
              "docs/bench-host-lookup.png)." % (
                  len(props), fmt(min(ours_all)), fmt(sum(ours_all) / len(ours_all)),
                  fmt(max(ours_all)), fmt(min(base_all)), fmt(sum(base_all) / len(base_all)),
                  fmt(max(base_all))))
    old = os.path.join(ROOT, "bench", "host", "lookup-1a9450a.dat")
    if os.path.exists(old):
        rows = [l.split() for l in open(old) if l.strip() and not l.startswith("#")]
        before = [int(r[1]) for r in rows]
        md.append("")
        md.append("Before the perfect hash (core of 1a9450a: %d rows, a packed segment index; "
                  "bench/host/lookup-1a9450a.dat, the third line of the chart): min %s, mean %s, "
                  "max %s instructions per lookup." % (
                      len(before), fmt(min(before)), fmt(sum(before) / len(before)),
                      fmt(max(before))))


def length_table(driver, md):
    repeat = 100
    md.append("| line | length | daran-ascii | baseline |")
    md.append("|---|---:|---:|---:|")
    for kind in ("blanks", "digits"):
        for k in (0, 16, 32, 64, 96, 120):
            line = "t 1 10" + " " * k if kind == "blanks" else "t 1 10." + "0" * k
            ours = core(driver, "ours", ["--repeat", str(repeat), "--line", line]) / repeat
            base = core(driver, "baseline", ["--repeat", str(repeat), "--line", line]) / repeat
            shown = ("`t 1 10` + %d blanks" % k) if kind == "blanks" else ("`t 1 10.` + %d zeros" % k)
            md.append("| %s | %d | %s | %s |" % (shown, len(line), fmt(ours), fmt(base)))
        print("  length %-7s done" % kind, flush=True)


def write_reference(path, figures):
    lines = ["# Core instructions (callgrind Ir inside daran_process_line) for the whole of",
             "# bench/streams/reference.txt, per compiler (gcc/clang -O2, no sanitizers).",
             "# bench_core_instructions (CTest, label bench) fails above +10%.",
             "# Refresh with: bench/host/run_all.sh --reference"]
    for key, value in sorted(figures.items()):
        lines.append("%s %d" % (key, value))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", path)


def compiler_key(driver):
    """GNU-12 / Clang-14, read from the driver's .comment section."""
    text = subprocess.run(["readelf", "-p", ".comment", driver], stdout=subprocess.PIPE,
                          stderr=subprocess.DEVNULL).stdout.decode(errors="replace")
    m = re.search(r"clang version (\d+)", text)
    if m:
        return "Clang-" + m.group(1)
    m = re.search(r"GCC: \([^)]*\) (\d+)", text)
    return "GNU-" + m.group(1) if m else "unknown"


def provenance(driver):
    """Which core and which tools the figures belong to."""
    def run(cmd):
        return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              cwd=ROOT).stdout.decode().strip()
    commit = run(["git", "rev-parse", "--short", "HEAD"]) or "unknown commit"
    dirty = run(["git", "status", "--porcelain", "--", "src", "include"])
    valgrind = run(["valgrind", "--version"])
    libc = run(["ldd", "--version"]).splitlines()[0].split()[-1]
    return "commit %s%s, %s -O2 (no sanitizers), glibc %s, %s, x86-64" % (
        commit, " with uncommitted changes in src/ or include/" if dirty else "",
        compiler_key(driver).replace("GNU-", "gcc ").replace("Clang-", "clang "), libc, valgrind)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--driver", required=True)
    ap.add_argument("--clang-driver")
    ap.add_argument("--out", required=True)
    ap.add_argument("--reference")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    md = ["Measured on %s." % provenance(args.driver), ""]
    md.append("### Per command family (bench/streams/families/*.txt, 1000 lines each)")
    md.append("")
    md.append("Instructions per line. Core = the parser's entry point and all it calls; whole "
              "program = extra instructions the driver program executes per line (stream "
              "reading excluded).")
    md.append("")
    families = families_table(args.driver, args.out, md)
    md.append("")
    md.append("### Recorded sessions (a third of the lines checksummed)")
    md.append("")
    figures, pairs = sessions_table(args.driver, md)
    md.append("")
    md.insert(2, verdict(families, pairs))
    md.insert(3, "")
    md.append("### Where the instructions go (reference.txt, exclusive, top ten)")
    md.append("")
    profile_table(args.driver, md)
    md.append("")
    md.append("### Scaling: property lookup")
    md.append("")
    lookup_table(args.driver, args.out, md)
    md.append("")
    md.append("### Scaling: line length (core instructions per line)")
    md.append("")
    length_table(args.driver, md)
    md.append("")
    refs = {compiler_key(args.driver): figures["reference"]}
    if args.clang_driver:
        n = lines_in(os.path.join(STREAMS, "reference.txt"))
        total = core(args.clang_driver, "ours", [os.path.join(STREAMS, "reference.txt")])
        refs[compiler_key(args.clang_driver)] = total
        md.append("clang-14 -O2 build of the same core on reference.txt: %s instructions per line."
                  % fmt(total / n))
        md.append("")
    if args.reference:
        write_reference(args.reference, refs)
    with open(os.path.join(args.out, "host.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote", os.path.join(args.out, "host.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
