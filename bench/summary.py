#!/usr/bin/env python3
"""The summary of docs/performance.md: every issue-13 target against what was
measured, and the standing budgets, from the results the measuring scripts
leave in build/bench/results:

  host.json, rounding.json, lookup.dat, m4.md   bench/host/run_all.sh
  m4insns.json, m4insns.md, m4budgets.txt,      bench/target_insns.sh
  m0.json, m0.md

    bench/summary.py [RESULTS_DIR]     prints the Markdown block

Both scripts call it when the other's results are there and rewrite the
generated block `summary` of docs/performance.md with it."""
import json
import os
import re
import sys

TARGETS = {"m4_t_checksum": 600, "m4_t_checksum_stretch": 400, "byte_path": 600,
           "pre_framed": 450, "lookup": 150, "flash": 14336}
# issue 20's per-line budgets on the Cortex-M4 (the perf_insns_per_line names)
M4_LINES = (("blank line", "a blank line", 40), ("r longest path", "`r` of the longest path", 1200),
            ("e (seven lines)", "`e 1`", 2000), ("f", "`f 1`", 350))
# issue 20's lookup budget: 150 + 4 per byte of the path, on every row
LOOKUP_BASE, LOOKUP_PER_BYTE = 150, 4


def fmt(x):
    return "{:,}".format(int(round(x)))


def verdict(measured, goal):
    if measured <= goal:
        return "met (%s to spare)" % fmt(goal - measured)
    if measured < 1.5 * goal:
        return "**missed** by %s (%.1f%% over)" % (fmt(measured - goal),
                                                   100.0 * (measured - goal) / goal)
    return "**missed** by %s (%.1fx the goal)" % (fmt(measured - goal), measured / goal)


def fit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else 0.0
    return my - b * mx, b


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "build/bench/results"
    load = lambda name: json.load(open(os.path.join(out, name)))
    read = lambda name: open(os.path.join(out, name)).read()
    host, rounding = load("host.json"), load("rounding.json")
    m4, m0 = load("m4insns.json"), load("m0.json")
    m4md, m0md, m4size, budgets = read("m4insns.md"), read("m0.md"), read("m4.md"), \
        read("m4budgets.txt")

    commit = re.search(r"commit (\w+)", host["provenance"]).group(1)
    target_commit = re.search(r"commit (\w+)", m4md).group(1)
    md = []
    if commit != target_commit:
        md.append("**The host figures (commit %s) and the target figures (commit %s) are of "
                  "different commits.**" % (commit, target_commit))
        md.append("")
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    try:
        import subprocess
        core = subprocess.run(["git", "log", "-1", "--format=%h", commit, "--", "src", "include"],
                              cwd=root, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              check=True).stdout.decode().strip()
    except (OSError, subprocess.CalledProcessError):
        core = ""
    md.append("Measured at commit %s%s. Host: %s. Targets: arm-none-eabi-gcc 12.2.1 `-Os`, "
              "QEMU 7.2 (`mps2-an386` Cortex-M4F, `microbit` Cortex-M0)." % (
                  commit, " (its `src/` and `include/` last changed in %s)" % core if core else "",
                  host["provenance"].split(", ", 1)[1]))
    md.append("")
    md.append("| target (issues 13 and 20) | goal | measured | verdict |")
    md.append("|---|---:|---:|---|")

    t = m4["counts"]["t with checksum"]
    v = verdict(t, TARGETS["m4_t_checksum"])
    v += "; stretch <= %d: %s" % (TARGETS["m4_t_checksum_stretch"],
                                   "met" if t <= TARGETS["m4_t_checksum_stretch"] else "missed")
    md.append("| Cortex-M4, `t 1 10 0 25 *83`, bytes in to HAL call (QEMU instructions) | "
              "<= 600 (stretch 400) | %s | %s |" % (fmt(t), v))

    for name, what, goal in M4_LINES:
        n = m4["counts"][name]
        md.append("| Cortex-M4, %s (QEMU instructions) | <= %s | %s | %s |" % (
            what, fmt(goal), fmt(n), verdict(n, goal)))

    for budget in m4.get("budgets", []):
        if budget["figure"].startswith("bytes:"):
            md.append("| Cortex-M4, framing and the ring per byte, the longest `r` line (QEMU "
                      "instructions; enforced by `perf_insns_per_line`) | <= %g | %.1f | %s |" % (
                          budget["budget"], budget["measured"],
                          "met" if budget["met"] else "**missed**"))

    ref = host["sessions"]["reference"]
    md.append("| host, reference.txt, byte path (`daran_rx_write` + `daran_poll`), per line | "
              "<= 600 | %s | %s |" % (fmt(ref["poll"]), verdict(ref["poll"], TARGETS["byte_path"])))
    md.append("| host, reference.txt, pre-framed (`daran_process_line`), per line | <= 450 | %s | "
              "%s |" % (fmt(ref["ours"]), verdict(ref["ours"], TARGETS["pre_framed"])))

    rows = [("family " + k, v) for k, v in host["families"].items()]
    rows += [(k + ".txt", v) for k, v in host["sessions"].items()]
    for key, hkey, what in (("ours", "hand", "both pre-framed"), ("poll", "handb", "both on the byte path")):
        ratios = sorted((v[key] / v[hkey], label) for label, v in rows)
        worse = [r for r in ratios if r[0] >= 1.0]
        measured = "core / hand-written %.2fx (%s) to %.2fx (%s)" % (
            ratios[0][0], ratios[0][1], ratios[-1][0], ratios[-1][1])
        md.append("| host, fewer instructions than the hand-written yardstick on every stream "
                  "and family (%s) | below on all %d | %s | %s |" % (
                      what, len(rows), measured,
                      "met" if not worse else "**missed** on %d of %d; reference.txt %s vs %s" % (
                          len(worse), len(rows), fmt(ref[key]), fmt(ref[hkey]))))

    look = host["lookup"]["ours"]
    lookup_rows = [l.split() for l in open(os.path.join(out, "lookup.dat"))
                   if l.strip() and not l.startswith("#")]
    lengths = [int(r[4]) for r in lookup_rows]
    a, b = fit(lengths, [int(r[1]) for r in lookup_rows])
    md.append("| host, property lookup, every row, flat in the number of rows | <= 150 | "
              "min %s, mean %s, max %s over %d rows | %s; rows above 150: %d of %d; flat in "
              "the rows (cost = %.0f + %.1f x path length) |" % (
                  fmt(look[0]), fmt(look[1]), fmt(look[2]), host["rows"],
                  verdict(look[2], TARGETS["lookup"]), look[3], host["rows"], a, b))
    over = sum(1 for r in lookup_rows if int(r[1]) > LOOKUP_BASE + LOOKUP_PER_BYTE * int(r[4]))
    md.append("| host, property lookup, every row: <= %d + %d per path byte (issue 20) | every row "
              "| rows over it: %d of %d | %s |" % (LOOKUP_BASE, LOOKUP_PER_BYTE, over, len(lookup_rows),
                                               "met" if over == 0 else "**missed**"))

    m = re.search(r"core flash \(text \+ data\)[^:]*: (\d+) bytes, budget (\d+)", budgets)
    if m:
        flash, budget = int(m.group(1)), int(m.group(2))
        md.append("| Cortex-M4 core flash (`budget_core_flash`: text + data of "
                  "libdaran_ascii.a, `-Os`) | <= %s | %s | %s |" % (
                      fmt(budget), fmt(flash), verdict(flash, budget)))

    streams = rounding["streams"]
    random = rounding["random_8_17"]
    md.append("| hand-written yardstick: decimals it rounds to another float32 than correct "
              "rounding (report) | - | %.1f%% of the streams' %s numbers; %.1f%% (positional, "
              "magnitude 1e-3 to 1e4) and %.1f%% (scientific, normal range) of random "
              "8-to-17-digit decimals | the core: 0 |" % (
                  100.0 * streams[1] / streams[0], fmt(streams[0]),
                  100.0 * random[0][1] / random[0][0], 100.0 * random[1][1] / random[1][0]))
    md.append("")
    md.append("Standing budgets and reports:")
    md.append("")
    md.append("| figure | measured | budget | verdict |")
    md.append("|---|---:|---:|---|")
    m = re.search(r"sizeof\(daran_drive_t\): (\d+) bytes, budget (\d+)", budgets)
    if m:
        md.append("| RAM of one instance (`sizeof(daran_drive_t)`, `budget_drive_ram`) | %s | "
                  "%s | %s |" % (m.group(1), m.group(2), verdict(int(m.group(1)), int(m.group(2)))))
    m = re.search(r"worst-case stack \(budget (\d+) bytes\)", budgets)
    stack = [int(x) for x in re.findall(r"^\d+: daran_\w+\s+(\d+)$", budgets, re.M)]
    deepest = re.search(r"deepest: (daran_\w+)", budgets)
    if m and stack:
        md.append("| worst-case stack of any entry point (`budget_core_stack`; deepest: `%s`) | "
                  "%d | %s | %s |" % (deepest.group(1) if deepest else "?", max(stack),
                                      m.group(1), verdict(max(stack), int(m.group(1)))))
    m = re.search(r"the core's objects \(src/\) take (\d+) bytes and pull (\d+)", m4size, re.I)
    b = re.search(r"the baseline's take (\d+) and pull (\d+)", m4size)
    h = re.search(r"the hand-written yardstick's take (\d+) and pull (\d+)", m4size)
    if m and b and h:
        md.append("| Cortex-M4 minimal image, parser flash kept after `--gc-sections` (report): "
                  "core, hand-written, sscanf/printf | %s, %s, %s | - | - |" % (
                      fmt(int(m.group(1)) + int(m.group(2))), fmt(int(h.group(1)) + int(h.group(2))),
                      fmt(int(b.group(1)) + int(b.group(2)))))
    m = re.search(r"Core flash on Cortex-M0: (\d+) bytes of its own objects kept, plus (\d+) "
                  r"bytes of library code", m0md)
    md.append("| Cortex-M0, `t 1 10 0 25 *83` (QEMU `microbit`, report) | %s | - | - |" % fmt(
        m0["counts"]["t with checksum"]))
    if m:
        md.append("| Cortex-M0 flash, core objects kept + library code pulled (soft float...) "
                  "(report) | %s + %s | - | - |" % (fmt(int(m.group(1))), fmt(int(m.group(2)))))
    md.append("| host, reference.txt: sscanf/printf yardstick / core (pre-framed, byte path) "
              "(report) | %.1fx, %.1fx | - | - |" % (ref["base"] / ref["ours"],
                                                     ref["base"] / ref["poll"]))
    print("\n".join(md))


if __name__ == "__main__":
    main()
