#!/usr/bin/env python3
"""Instruction table of the port-extension mechanism, from measure_insns.py's JSON.

    report.py NONE.json BRAKE.json

NONE.json and BRAKE.json: tools/qemu-insn-count/measure_insns.py --json of
ext-none.elf (core with no port rows) and ext-brake.elf (core with
examples/port-brake/brake_options.h). Each label ends in "[N]", the reply
lines the step sent. Prints one Markdown table: instructions per step in both
images, reply lines, and per reply line for the discovery steps.
"""
import json
import re
import sys

LABEL = re.compile(r"^(.*) \[(\d+)\]$")


def steps(path):
    data = json.load(open(path))
    result = []
    for label, count in data["counts"].items():
        name, lines = LABEL.match(label).groups()
        result.append((name, data["texts"][label], count, int(lines)))
    return result


def main():
    none, brake = steps(sys.argv[1]), steps(sys.argv[2])
    assert [s[0] for s in none] == [s[0] for s in brake]
    rows = {"none": None, "brake": None}
    for image, data in (("none", none), ("brake", brake)):
        rows[image] = next(s[3] for s in data if s[0] == "discovery, every row") - 1
    print("| step | line or call | instructions, core with no port rows | replies "
          "| instructions, core with the example's header | replies |")
    print("|---|---|---:|---:|---:|---:|")
    for (name, text, n0, l0), (_, _, n1, l1) in zip(none, brake):
        cells = []
        for n, lines, image in ((n0, l0, "none"), (n1, l1, "brake")):
            note = ""
            if name.startswith("discovery") and lines > 1:
                note = " (%d a line)" % round(n / lines)
            elif name.startswith("discovery"):
                note = " (%d a row scanned)" % round(n / rows[image])
            cells.append(("{:,}".format(n) + note, lines))
        print("| %s | `%s` | %s | %d | %s | %d |" % (name, text, cells[0][0], cells[0][1],
                                                  cells[1][0], cells[1][1]))
    print()
    print("Rows in the build: %d (no port rows), %d (the example: 2 rows added, 5 omitted); "
          "discovery's replies are one line a listed row and `end`. Discovery builds every "
          "row's path to compare it with the prefix, so a prefix saves the formatting of the "
          "rows it leaves out, not the scan." % (rows["none"], rows["brake"]))


if __name__ == "__main__":
    main()
