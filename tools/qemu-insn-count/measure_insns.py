#!/usr/bin/env python3
"""Instructions per protocol line on the Cortex-M4, counted under QEMU.

Builds the counting plugin (insn_count.c, host C compiler) if needed, runs
daran-perf.elf (tests/target/perf_main.c) with it and prints a Markdown table
of instructions per line, the marker's own cost subtracted.

  measure_insns.py --elf build/cortex-m4/tests/target/daran-perf.elf
                   [--nm arm-none-eabi-nm] [--profile LABEL] [--max-t-checksum N]
                   [--machine mps2-an386]

--json FILE       also write the counts (and the profile) as JSON
--machine M       the QEMU machine (default mps2-an386, Cortex-M4F; microbit
                  is a Cortex-M0: bench/m0/measure.sh); the labels may come on
                  the UART (-serial stdio) or through semihosting, both stdout

--profile LABEL   also break that line's count down per function
--max-t-checksum  exit 1 when "t with checksum" takes more than N instructions
--budget SPEC     exit 1 when the figure is over it; SPEC is "LABEL<=N" for the
                  instructions of a line, or "bytes:LABEL<=N" for framing and the
                  ring per byte of that line (the functions in RING_AND_FRAMING,
                  divided by the line's bytes, its line end included)
--report SPEC     the same figure and verdict, printed, never failing: a budget
                  the code does not meet yet (docs/performance.md says by how much)
"""
import argparse
import bisect
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
QEMU_ARGS = ["-nographic", "-monitor", "none", "-serial", "stdio",
             "-semihosting-config", "enable=on,target=native"]
MACHINE = "mps2-an386"

# What "framing and the ring" counts: the producer's copy into the ring, the
# poll loop, the framer and its reset for the next line.
RING_AND_FRAMING = ("daran_rx_write", "write_bytes", "store_run", "daran_poll",
                    "daran_framer_feed", "daran_framer_reset")


def build_plugin(out_dir):
    src = os.path.join(HERE, "insn_count.c")
    lib = os.path.join(out_dir, "libinsn_count.so")
    if not os.path.exists(lib) or os.path.getmtime(lib) < os.path.getmtime(src):
        cc = os.environ.get("CC", "cc")
        # built beside and renamed over: two measurements started at once
        # (CTest runs tests in parallel) never load a half-written plugin
        fd, tmp = tempfile.mkstemp(prefix=".libinsn_count.", suffix=".so", dir=out_dir)
        os.close(fd)
        try:
            subprocess.run([cc, "-shared", "-fPIC", "-O2", "-fvisibility=hidden", "-o", tmp, src],
                           check=True)
            os.replace(tmp, lib)
        finally:
            if os.path.exists(tmp):
                os.remove(tmp)
    return lib


def symbols(nm, elf):
    funcs = []
    for line in subprocess.run([nm, "-S", "--defined-only", elf], check=True,
                               stdout=subprocess.PIPE, text=True).stdout.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2] in "tTwW":
            funcs.append((int(parts[0], 16) & ~1, int(parts[1], 16), parts[3]))
    funcs.sort()
    return funcs


def run(elf, plugin, mark, profile=None):
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "plugin.log")
        arg = f"{plugin},mark=0x{mark:x}" + (f",profile={profile}" if profile is not None else "")
        proc = subprocess.run(["qemu-system-arm", "-M", MACHINE] + QEMU_ARGS +
                              ["-kernel", elf, "-plugin", arg, "-d", "plugin", "-D", log],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60,
                              check=True)
        with open(log) as f:
            out = f.read().splitlines()
    # the labels: on the UART (stdout), or through semihosting (QEMU writes
    # that console to stderr)
    said = proc.stdout.decode().splitlines() or proc.stderr.decode().splitlines()
    labels = [l.split("\t")[0] for l in said if "\t" in l]
    texts = [l.split("\t")[1] for l in said if "\t" in l]
    marks = [int(l.split()[2]) for l in out if l.startswith("mark ")]
    blocks = [(int(l.split()[1], 16), int(l.split()[2])) for l in out if l.startswith("block ")]
    return labels, texts, marks, blocks


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--elf", required=True)
    ap.add_argument("--nm", default="arm-none-eabi-nm")
    ap.add_argument("--plugin-dir", default=None)
    ap.add_argument("--profile", default=None)
    ap.add_argument("--max-t-checksum", type=int, default=None)
    ap.add_argument("--machine", default="mps2-an386")
    ap.add_argument("--json", default=None)
    ap.add_argument("--budget", action="append", default=[])
    ap.add_argument("--report", action="append", default=[])
    opt = ap.parse_args()
    global MACHINE
    MACHINE = opt.machine

    plugin = build_plugin(opt.plugin_dir or os.path.dirname(os.path.abspath(opt.elf)))
    funcs = symbols(opt.nm, opt.elf)
    mark = next(a for a, _, n in funcs if n == "daran_perf_mark")
    labels, texts, marks, _ = run(opt.elf, plugin, mark)
    # marks[0]: start-up; marks[1]: empty interval (marker cost); then one per line
    base = marks[1]
    counts = [m - base for m in marks[2:2 + len(labels)]]
    print("| line | example | instructions |")
    print("|---|---|---:|")
    for label, text, n in zip(labels, texts, counts):
        print(f"| {label} | `{text.rstrip()}` | {n} |")
    status = 0
    result = {"machine": MACHINE, "counts": dict(zip(labels, counts)),
              "texts": dict(zip(labels, [t.rstrip() for t in texts]))}
    if opt.max_t_checksum is not None:
        n = counts[labels.index("t with checksum")]
        verdict = "within" if n <= opt.max_t_checksum else "OVER"
        print(f"\n`t` with checksum: {n} instructions ({verdict} the {opt.max_t_checksum} target)")
        status = 0 if n <= opt.max_t_checksum else 1
    def per_function(label):
        k = labels.index(label) + 2
        _, _, _, blocks = run(opt.elf, plugin, mark, profile=k)
        starts = [a for a, _, _ in funcs]
        per_fn = {}
        for addr, n in blocks:
            i = bisect.bisect_right(starts, addr) - 1
            name = funcs[i][2] if i >= 0 and addr < funcs[i][0] + max(funcs[i][1], 1) else hex(addr)
            per_fn[name] = per_fn.get(name, 0) + n
        return per_fn

    checks = [(spec, True) for spec in opt.budget] + [(spec, False) for spec in opt.report]
    if checks:
        print("\nBudgets:\n")
        print("| figure | measured | budget | verdict |")
        print("|---|---:|---:|---|")
        result["budgets"] = []
    for spec, enforced in checks:
        what, limit = spec.rsplit("<=", 1)
        limit = float(limit)
        if (what[len("bytes:"):] if what.startswith("bytes:") else what) not in labels:
            print(f"| {what} | - | {limit:g} | not in this image (compiled out) |")
            continue
        if what.startswith("bytes:"):
            label = what[len("bytes:"):]
            per_fn = per_function(label)
            ring = sum(per_fn.get(name, 0) for name in RING_AND_FRAMING)
            size = len(texts[labels.index(label)].rstrip("\r\n")) + 1  # its line end
            figure = ring / size
            name = f"framing and the ring per byte, `{texts[labels.index(label)].rstrip()}` ({ring} for {size} bytes)"
            shown = f"{figure:.1f}"
        else:
            figure = counts[labels.index(what)]
            name = f"`{texts[labels.index(what)].rstrip()}` ({what})"
            shown = str(figure)
        met = figure <= limit
        verdict = "met" if met else ("**OVER**" if enforced else "missed (reported)")
        print(f"| {name} | {shown} | {limit:g} | {verdict} |")
        result["budgets"].append({"figure": what, "measured": figure, "budget": limit,
                                  "enforced": enforced, "met": met})
        if enforced and not met:
            status = 1
    if opt.profile:
        per_fn = per_function(opt.profile)
        print(f"\nPer function, line `{opt.profile}`:\n")
        print("| function | instructions |")
        print("|---|---:|")
        for name, n in sorted(per_fn.items(), key=lambda kv: -kv[1]):
            print(f"| {name} | {n} |")
        result["profile_line"] = opt.profile
        result["profile"] = dict(sorted(per_fn.items(), key=lambda kv: -kv[1]))
    if opt.json:
        with open(opt.json, "w") as f:
            json.dump(result, f, indent=1)
    return status


if __name__ == "__main__":
    sys.exit(main())
