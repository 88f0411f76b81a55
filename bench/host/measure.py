#!/usr/bin/env python3
"""Every host figure of docs/performance.md, counted with callgrind.

    measure.py --driver BUILD/bench/host/daran_bench_driver --out DIR
               [--clang-driver PATH] [--reference bench/host/reference.txt]
               [--rounding BUILD/bench/host/daran_rounding]

Writes DIR/host.md (the tables), DIR/families.dat and DIR/lookup.dat (the
charts' data), with --rounding DIR/rounding.md (how often the hand-written
yardstick rounds a decimal to another float), and, with --reference, the
committed reference figure(s) of the CTest guard.

Three parsers, each counted at its entry point: the core on pre-framed lines
(daran_process_line) and on the byte path (daran_rx_write + daran_poll), the
hand-written yardstick (handwritten_process_line, bench/baseline/
handwritten.c) and the sscanf/strtof/printf yardstick (baseline_process_line,
bench/baseline/baseline.c).
Instruction counts (Ir) are deterministic: the same binary on the same stream
gives the same count on every run.

Definitions
  core          instructions inside the parser's entry point and everything it
                calls (HAL stubs and reply sink included), via callgrind
                --toggle-collect=daran_process_line / handwritten_process_line /
                baseline_process_line (ours-poll: daran_rx_write + daran_poll),
                divided by lines
  whole program (Ir of the whole driver run - Ir of the same run in mode
                `none`, which reads and splits the stream but parses nothing)
                / lines: what each line costs the program, libc included
"""
import argparse
import json
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
         "handwritten": ["handwritten_process_line"],
         "handwritten-bytes": ["handwritten_rx_write"], "baseline": ["baseline_process_line"]}
LOOKUP = {"ours": ["daran_find_property"], "handwritten": ["handwritten_find_property"],
          "baseline": ["baseline_find_property"]}
# issue 13 ("one pass per byte") host targets
TARGET_BYTE_PATH = 600    # reference.txt, daran_rx_write + daran_poll, per line
TARGET_PRE_FRAMED = 450   # reference.txt, daran_process_line, per line
TARGET_LOOKUP = 150       # every row of the property table, per lookup


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


def profile_pair(driver, md, left, right, names):
    path = os.path.join(STREAMS, "reference.txt")
    n = lines_in(path)
    a_rows = profile(driver, left, path)
    b_rows = profile(driver, right, path)
    md.append("| # | %s | per line | share | %s | per line | share |" % names)
    md.append("|---:|---|---:|---:|---|---:|---:|")
    for i in range(max(len(a_rows), len(b_rows))):
        a = a_rows[i] if i < len(a_rows) else (0, 0.0, "")
        b = b_rows[i] if i < len(b_rows) else (0, 0.0, "")
        md.append("| %d | %s | %s | %.1f%% | %s | %s | %.1f%% |" % (
            i + 1, a[2], fmt(a[0] / n), a[1], b[2], fmt(b[0] / n), b[1]))


def profile_table(driver, md):
    profile_pair(driver, md, "ours", "ours-poll",
                 ("core, pre-framed (daran_process_line)", "core, byte path (rx_write + poll)"))
    md.append("")
    profile_pair(driver, md, "handwritten", "baseline",
                 ("hand-written yardstick", "sscanf/printf yardstick"))


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


def met(measured, target):
    if measured <= target:
        return "**met** (%s, target <= %s)" % (fmt(measured), fmt(target))
    return "**missed** by %s (%s, target <= %s: %.0f%% over)" % (
        fmt(measured - target), fmt(measured), fmt(target), 100.0 * (measured - target) / target)


def verdicts(families, sessions, lookups):
    """The issue-13 host targets, met or missed, and by how much."""
    ref = sessions["reference"]
    rows = [("family %s" % label, v) for label, v in families]
    rows += [("%s.txt" % name, v) for name, v in sessions.items()]
    md = ["Targets (issue 13, host, gcc 12 -O2, callgrind):", ""]
    md.append("- reference.txt on the byte path (`daran_rx_write` + `daran_poll`), "
              "instructions per line: " + met(ref["poll"], TARGET_BYTE_PATH) + ".")
    md.append("- reference.txt pre-framed (`daran_process_line`), instructions per line: "
              + met(ref["ours"], TARGET_PRE_FRAMED) + ".")
    for key, hkey, what in (("ours", "hand", "both pre-framed"), ("poll", "handb", "both on the byte path")):
        worse = [(label, v) for label, v in rows if v[key] >= v[hkey]]
        if not worse:
            md.append("- fewer instructions than the hand-written yardstick on every stream and "
                      "family (%s): **met**." % what)
        else:
            shown = ", ".join("%s %s vs %s (%.2fx)" % (label, fmt(v[key]), fmt(v[hkey]),
                                                        v[key] / v[hkey]) for label, v in worse)
            md.append("- fewer instructions than the hand-written yardstick on every stream and "
                      "family (%s): **missed** on %d of %d: %s." % (what, len(worse),
                                                                       len(rows), shown))
    over = [r for r in lookups["ours"] if r > TARGET_LOOKUP]
    md.append("- property lookup <= %d instructions on every row (%d rows): %s; min %s, mean %s, "
              "max %s; rows above %d: %d." % (
                  TARGET_LOOKUP, len(lookups["ours"]),
                  "**met**" if not over else "**missed** (max %s, %.1fx the target)" % (
                      fmt(max(lookups["ours"])), max(lookups["ours"]) / TARGET_LOOKUP),
                  fmt(min(lookups["ours"])), fmt(sum(lookups["ours"]) / len(lookups["ours"])),
                  fmt(max(lookups["ours"])), TARGET_LOOKUP, len(over)))
    md.append("- for scale, the sscanf/printf yardstick on reference.txt: %s per line, %.1fx the "
              "core pre-framed, %.1fx the byte path." % (fmt(ref["base"]), ref["base"] / ref["ours"],
                                                        ref["base"] / ref["poll"]))
    return md


def families_table(driver, out, md):
    md.append("| family | lines | core: pre-framed | core: byte path | hand-written: pre-framed | "
              "hand-written: byte path | sscanf/printf | hand-written / core (pre-framed) | "
              "sscanf / core (pre-framed) |")
    md.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    data = []
    for name, label in FAMILIES:
        path = os.path.join(STREAMS, "families", name + ".txt")
        n = lines_in(path)
        v = {"ours": core(driver, "ours", [path]) / n,
             "poll": core(driver, "ours-poll", [path]) / n,
             "hand": core(driver, "handwritten", [path]) / n,
             "handb": core(driver, "handwritten-bytes", [path]) / n,
             "base": core(driver, "baseline", [path]) / n}
        md.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            label, n, fmt(v["ours"]), fmt(v["poll"]), fmt(v["hand"]), fmt(v["handb"]),
            fmt(v["base"]), ratio(v["ours"], v["hand"]), ratio(v["ours"], v["base"])))
        data.append((label, v))
        print("  family %-14s ours %6.0f poll %6.0f hand %6.0f baseline %6.0f" % (
            label, v["ours"], v["poll"], v["hand"], v["base"]), flush=True)
    with open(os.path.join(out, "families.dat"), "w") as f:
        f.write("# family  core-pre-framed  core-byte-path  hand-written-pre-framed  "
                "hand-written-byte-path  baseline   (instructions per line)\n")
        for label, v in data:
            f.write('"%s" %.0f %.0f %.0f %.0f %.0f\n' % (label, v["ours"], v["poll"], v["hand"],
                                                       v["handb"], v["base"]))
    return data


def sessions_table(driver, md):
    md.append("| stream | lines | core: pre-framed | core: byte path | hand-written: pre-framed | "
              "hand-written: byte path | sscanf/printf | hand-written / core (pre-framed) | "
              "sscanf / core (pre-framed) | whole program incl. start-up: core, hand-written, "
              "sscanf |")
    md.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    figures = {}
    values = {}
    for name in SESSIONS:
        path = os.path.join(STREAMS, name + ".txt")
        n = lines_in(path)
        ours_total = core(driver, "ours", [path])
        v = {"ours": ours_total / n,
             "poll": core(driver, "ours-poll", [path]) / n,
             "hand": core(driver, "handwritten", [path]) / n,
             "handb": core(driver, "handwritten-bytes", [path]) / n,
             "base": core(driver, "baseline", [path]) / n}
        whole = [callgrind(driver, [mode, path]) / n for mode in ("ours", "handwritten", "baseline")]
        figures[name] = ours_total
        values[name] = v
        md.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name + ".txt", n, fmt(v["ours"]), fmt(v["poll"]), fmt(v["hand"]), fmt(v["handb"]),
            fmt(v["base"]), ratio(v["ours"], v["hand"]), ratio(v["ours"], v["base"]),
            ", ".join(fmt(w) for w in whole)))
        print("  stream %-10s ours %6.0f poll %6.0f hand %6.0f baseline %6.0f" % (
            name, v["ours"], v["poll"], v["hand"], v["base"]), flush=True)
    return figures, values


def fit(xs, ys):
    """Least squares y = a + b x; returns a, b and the largest residual."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else 0.0
    a = my - b * mx
    return a, b, max(abs(y - a - b * x) for x, y in zip(xs, ys))


def lookup_table(driver, out, md):
    props = properties()
    axis = [p for p, s in props if s == "AXIS"]
    system = [p for p, s in props if s == "SYSTEM"]
    # Every property once, in list order (= table order of every parser).
    sweep = os.path.join(out, "lookup_lines.txt")
    with open(sweep, "w") as f:
        for path, scope in props:
            f.write("r axis1.%s\n" % path if scope == "AXIS" else "r %s 1\n" % path)
    per_row = {mode: per_call(driver, mode, sweep, LOOKUP[mode][0])
               for mode in ("ours", "handwritten", "baseline")}
    for mode, costs in per_row.items():
        if len(costs) != len(props):
            raise RuntimeError("lookup sweep: %d %s calls for %d properties"
                               % (len(costs), mode, len(props)))
    ours_all, hand_all, base_all = per_row["ours"], per_row["handwritten"], per_row["baseline"]
    with open(os.path.join(out, "lookup.dat"), "w") as f:
        f.write("# row  daran-ascii  hand-written  baseline  path-length  path"
                "   (instructions per lookup; the length is what is looked up, without axisN.)\n")
        for i, ((path, scope), a, h, b) in enumerate(zip(props, ours_all, hand_all, base_all)):
            f.write("%d %d %d %d %d %s%s\n" % (i + 1, a, h, b, len(path),
                                              "axisN." if scope == "AXIS" else "", path))
    index = {p: i for i, (p, _) in enumerate(props)}
    picks = [("system, first", system[0], "r %s 1" % system[0]),
             ("system, last", system[-1], "r %s 1" % system[-1]),
             ("axis, first", axis[0], "r axis1." + axis[0]),
             ("axis, middle", axis[len(axis) // 2], "r axis1." + axis[len(axis) // 2]),
             ("axis, last", axis[-1], "r axis1." + axis[-1]),
             ("axis, longest path", max(axis, key=len), "r axis1." + max(axis, key=len)),
             ("axis, unknown", "output_shaft.no_such_thing", "r axis1.output_shaft.no_such_thing")]
    repeat = 100
    md.append("Property table: %d rows (%d system, %d axis), in the order of "
              "include/daran_properties.h. Lookup = the table search alone, counted inside "
              "daran_find_property / handwritten_find_property / baseline_find_property while "
              "the `r` line is processed; line = the whole `r` request, pre-framed."
              % (len(props), len(system), len(axis)))
    md.append("")
    md.append("| property | row | path | lookup: core | lookup: hand-written | "
              "lookup: sscanf/printf | `r` line: core | `r` line: hand-written | "
              "`r` line: sscanf/printf |")
    md.append("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    for label, name, line in picks:
        args = ["--repeat", str(repeat), "--line", line]
        look = [core(driver, m, args, LOOKUP[m]) / repeat for m in ("ours", "handwritten", "baseline")]
        whole = [core(driver, m, args) / repeat for m in ("ours", "handwritten", "baseline")]
        row = str(index[name] + 1) if name in index else "-"
        md.append("| %s | %s | `%s` | %s |" % (label, row, name,
                                              " | ".join(fmt(x) for x in look + whole)))
        print("  lookup %-18s ours %5.0f hand %5.0f baseline %5.0f" % (label, *look), flush=True)
    md.append("")
    lengths = [len(p) for p, _ in props]

    def stats(name, costs):
        return "%s min %s, mean %s, max %s" % (name, fmt(min(costs)), fmt(sum(costs) / len(costs)),
                                             fmt(max(costs)))
    md.append("Over all %d rows, instructions per lookup: %s; %s; %s (every row: lookup.dat, "
              "chart docs/bench-host-lookup.png). Rows above %d for the core: %d." % (
                  len(props), stats("core", ours_all), stats("hand-written", hand_all),
                  stats("sscanf/printf", base_all), TARGET_LOOKUP,
                  sum(1 for c in ours_all if c > TARGET_LOOKUP)))
    md.append("")
    a, b, worst = fit(lengths, ours_all)
    ha, hb, hworst = fit(lengths, hand_all)
    md.append("What the cost follows: the length of the path looked up (%d to %d bytes), not the "
              "row or the size of the table. Least squares over the rows: core = %.0f + %.2f x "
              "length (largest residual %.0f); hand-written = %.0f + %.2f x length (largest "
              "residual %.0f). The sscanf/printf yardstick's strcmp walk grows with the row "
              "instead." % (min(lengths), max(lengths), a, b, worst, ha, hb, hworst))
    old = os.path.join(ROOT, "bench", "host", "lookup-1a9450a.dat")
    if os.path.exists(old):
        rows = [l.split() for l in open(old) if l.strip() and not l.startswith("#")]
        before = [int(r[1]) for r in rows]
        md.append("")
        md.append("Before the perfect hash (core of 1a9450a: %d rows, a packed segment index; "
                  "bench/host/lookup-1a9450a.dat, the grey line of the chart): min %s, mean %s, "
                  "max %s instructions per lookup." % (
                      len(before), fmt(min(before)), fmt(sum(before) / len(before)),
                      fmt(max(before))))
    return per_row


def length_table(driver, md):
    repeat = 100
    md.append("| line | length | core: pre-framed | core: byte path | hand-written: pre-framed | "
              "hand-written: byte path | sscanf/printf |")
    md.append("|---|---:|---:|---:|---:|---:|---:|")
    for kind in ("blanks", "digits"):
        for k in (0, 16, 32, 64, 96, 120):
            line = "t 1 10" + " " * k if kind == "blanks" else "t 1 10." + "0" * k
            args = ["--repeat", str(repeat), "--line", line]
            counts = [core(driver, m, args) / repeat
                      for m in ("ours", "ours-poll", "handwritten", "handwritten-bytes", "baseline")]
            shown = ("`t 1 10` + %d blanks" % k) if kind == "blanks" else ("`t 1 10.` + %d zeros" % k)
            md.append("| %s | %d | %s |" % (shown, len(line), " | ".join(fmt(c) for c in counts)))
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


def rounding(binary, driver, out):
    """DIR/rounding.md: the yardstick's float conversion against correct
    rounding, on the streams' numbers, on random decimals, and as HAL calls."""
    rel = os.path.relpath(STREAMS, ROOT)
    streams = [os.path.join(rel, n) for n in sorted(os.listdir(STREAMS)) if n.endswith(".txt")]
    families = [os.path.join(rel, "families", n)
                for n in sorted(os.listdir(os.path.join(STREAMS, "families")))]
    driver = os.path.abspath(driver)
    binary = os.path.abspath(binary)
    run = lambda cmd: subprocess.run(cmd, check=True, stdout=subprocess.PIPE,
                                     cwd=ROOT).stdout.decode()
    md = ["Every number of the streams (each field after the command word that is a decimal: "
          "values, ids, modes), parsed by the hand-written yardstick and by glibc's strtof "
          "(correctly rounded); `bench/host/rounding.c`, "
          "`build/bench/gcc/bench/host/daran_rounding streams bench/streams/*.txt "
          "bench/streams/families/*.txt`:", ""]
    md.append(run([binary, "streams"] + streams + families).strip())
    md.append("")
    md.append("Random decimals, 1,000,000 of each length (`daran_rounding random 1000000 "
              "20261123`):")
    md.append(run([binary, "random", "1000000", "20261123"]).rstrip())
    md.append("")
    md.append("As HAL calls (`python3 bench/host/compare_traces.py --yardstick handwritten "
              "build/bench/gcc/bench/host/daran_bench_driver bench/streams/*.txt "
              "bench/streams/families/*.txt`; CTest `bench_handwritten_same_up_to_rounding`):")
    md.append("")
    text = run([sys.executable, os.path.join(ROOT, "bench", "host", "compare_traces.py"),
                "--yardstick", "handwritten", driver] + streams + families)
    md.append("```")
    md += [l for l in text.splitlines()]
    md.append("```")
    with open(os.path.join(out, "rounding.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote", os.path.join(out, "rounding.md"))
    # the figures the summary quotes: rate over all the streams' numbers, over
    # the 8-to-17-digit random decimals of each spelling, and HAL calls
    figures = {}
    for line in "\n".join(md).splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if cells[0] == "**all**":
            figures["streams"] = [int(cells[1]), int(cells[2])]
        elif cells[0] == "**8 to 17**":
            figures.setdefault("random_8_17", []).append([int(cells[1]), int(cells[2])])
        elif line.startswith("handwritten vs core, all streams"):
            figures["hal"] = line
    with open(os.path.join(out, "rounding.json"), "w") as f:
        json.dump(figures, f, indent=1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--driver", required=True)
    ap.add_argument("--clang-driver")
    ap.add_argument("--out", required=True)
    ap.add_argument("--reference")
    ap.add_argument("--rounding")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.rounding:
        rounding(args.rounding, args.driver, args.out)
    md = ["Measured on %s." % provenance(args.driver), ""]
    body = []
    body.append("### Per command family (bench/streams/families/*.txt, 1000 lines each)")
    body.append("")
    body.append("Instructions per line, each parser counted at its entry point and everything it "
                "calls (trivial HAL and reply sink included). Ratios: the yardstick's count over "
                "the core's pre-framed count (below 1.0x: the yardstick takes fewer).")
    body.append("")
    families = families_table(args.driver, args.out, body)
    body.append("")
    body.append("### Recorded sessions (a third of the lines checksummed)")
    body.append("")
    figures, sessions = sessions_table(args.driver, body)
    body.append("")
    body.append("### Where the instructions go (reference.txt, exclusive, top ten)")
    body.append("")
    profile_table(args.driver, body)
    body.append("")
    body.append("### Scaling: property lookup")
    body.append("")
    lookups = lookup_table(args.driver, args.out, body)
    body.append("")
    body.append("### Scaling: line length (instructions per line)")
    body.append("")
    length_table(args.driver, body)
    body.append("")
    md += verdicts(families, sessions, lookups) + [""] + body
    refs = {compiler_key(args.driver): figures["reference"]}
    if args.clang_driver:
        n = lines_in(os.path.join(STREAMS, "reference.txt"))
        total = core(args.clang_driver, "ours", [os.path.join(STREAMS, "reference.txt")])
        refs[compiler_key(args.clang_driver)] = total
        md.append("clang-14 -O2 build of the same core on reference.txt (pre-framed): %s "
                  "instructions per line." % fmt(total / n))
        md.append("")
    if args.reference:
        write_reference(args.reference, refs)
    lookup_stats = {m: [min(c), sum(c) / len(c), max(c), sum(1 for x in c if x > TARGET_LOOKUP)]
                    for m, c in lookups.items()}
    with open(os.path.join(args.out, "host.json"), "w") as f:
        json.dump({"provenance": provenance(args.driver), "families": dict(families),
                   "sessions": sessions, "lookup": lookup_stats, "rows": len(lookups["ours"]),
                   "reference": refs,
                   "reference_lines": lines_in(os.path.join(STREAMS, "reference.txt"))},
                  f, indent=1)
    with open(os.path.join(args.out, "host.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote", os.path.join(args.out, "host.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
