#!/usr/bin/env python3
"""Every path of the vendor's property table, as the vendor's tools use it,
on a three-drive daran-sim: each reads back one value of the type the
vendor's library decodes (`r axis1.<path>` / `r <path> 1`, plain and
checksummed), and each path the core lists as read-only refuses `w` with
`read only property` and leaves the value as it was.

usage: vendor_paths.py DARAN_SIM PROPERTIES_CSV PROPERTY_LIST_HEADER
"""
import csv
import re
import subprocess
import sys

FLOAT = re.compile(r"^(-?(0|[1-9][0-9]*)(\.[0-9]+)?|-?[0-9]\.[0-9]+e[+-][0-9]{2,}|nan|-?inf)$")
PATTERNS = {"f": FLOAT, "u32": re.compile(r"^(0|[1-9][0-9]*)$"), "s32": re.compile(r"^(0|-?[1-9][0-9]*)$")}


def request_for(path, drive=1):
    if path.startswith("axis0."):
        return "r axis%d.%s" % (drive, path[len("axis0."):])
    return "r %s %d" % (path, drive)


def write_for(path, value, drive=1):
    if path.startswith("axis0."):
        return "w axis%d.%s %s" % (drive, path[len("axis0."):], value)
    return "w %s %s %d" % (path, value, drive)


def with_checksum(line):
    payload = line + " "
    x = 0
    for c in payload.encode():
        x ^= c
    return "%s*%d" % (payload, x)


def read_only_paths(header):
    text = open(header, encoding="ascii").read()
    rows = re.findall(r'X\(\s*\w+\s*,\s*"([^"]+)"\s*,\s*(SYSTEM|AXIS)\s*,\s*\w+\s*,\s*(RO|RW)', text)
    return {("axis0." + p if scope == "AXIS" else p) for p, scope, access in rows if access == "RO"}


def main():
    sim, table, header = sys.argv[1:4]
    rows = [r for r in csv.reader(l for l in open(table) if not l.startswith("#"))][1:]
    paths = [(r[0], r[1]) for r in rows]
    read_only = read_only_paths(header)
    lines = []
    checks = []
    for path, kind in paths:
        lines.append(request_for(path))
        checks.append(("read", path, kind, False))
        lines.append(with_checksum(request_for(path)))
        checks.append(("read", path, kind, True))
    for path, kind in paths:
        if path in read_only:
            lines.append(write_for(path, "0" if kind != "f" else "1.5"))
            checks.append(("ro", path, kind, False))
            lines.append(request_for(path))
            checks.append(("reread", path, kind, False))
    out = subprocess.run([sim, "--drives", "3"], input=("\n".join(lines) + "\n").encode("ascii"),
                         capture_output=True, check=True).stdout.decode("ascii")
    replies = out.split("\n")
    if replies and replies[-1] == "":
        replies.pop()
    failures = []
    if len(replies) != len(checks):
        failures.append("%d replies to %d requests" % (len(replies), len(checks)))
    first_read = {}
    for (what, path, kind, checksummed), reply in zip(checks, replies):
        if not reply.endswith("\r"):
            failures.append("%s: reply %r does not end in \\r\\n" % (path, reply))
        reply = reply.rstrip("\r")
        if checksummed:
            body = reply.rpartition(" *")[0]
            if with_checksum(body) != body + " *" + reply.rpartition(" *")[2]:
                failures.append("%s: bad reply checksum %r" % (path, reply))
            reply = body
        if what in ("read", "reread"):
            if not PATTERNS[kind].match(reply):
                failures.append("%s: %r is not a %s" % (path, reply, kind))
            if what == "read" and not checksummed:
                first_read[path] = reply
            if what == "reread" and first_read.get(path) is not None and kind != "f" and reply != first_read[path]:
                failures.append("%s: changed from %r to %r after a refused write" % (path, first_read[path], reply))
        elif what == "ro" and reply != "error: read only property":
            failures.append("%s: w answered %r, not read only property" % (path, reply))
    n_ro = sum(1 for c in checks if c[0] == "ro")
    print("vendor_paths: %d paths read (plain and checksummed), %d read-only paths refuse w" % (len(paths), n_ro))
    for f in failures:
        print("FAIL:", f)
    print("%d passed, %d failed" % (len(checks) - len(failures), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
