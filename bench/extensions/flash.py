#!/usr/bin/env python3
"""Flash tables of the port-extension mechanism, from bench/extensions/build.sh's trees.

    flash.py OUT_DIR

Prints Markdown: the mechanism's own objects and what its hooks add to
others; the core library with no port rows, with the example's options
header, with its rows only and with its omissions only; the port's object;
and the generated property tables symbol by symbol (what a row costs, what
an omission saves). Bytes are text + data (`arm-none-eabi-size`), as CTest
budget_core_flash counts the library.
"""
import os
import subprocess
import sys

CONFIGS = [("none", "no options header (default)"),
           ("brake", "`examples/port-brake/brake_options.h`"),
           ("rows", "its 2 rows only (`bench/extensions/rows_only.h`)"),
           ("omit", "its 5 omissions only (`bench/extensions/omit_only.h`)")]
MECHANISM = ["port_commands", "discovery", "telemetry"]
# property_table.c's part that only discovery uses
DISCOVERY_FUNCTIONS = ["daran_discovery_next", "daran_unit_text", "unit_text"]


def size(path):
    """{member: text + data} of an archive or object."""
    rows = subprocess.run(["arm-none-eabi-size", path], check=True, stdout=subprocess.PIPE,
                          text=True).stdout.splitlines()[1:]
    result = {}
    for row in rows:
        parts = row.split()
        name = parts[5].split(" ")[0]
        result[os.path.basename(name).replace(".c.obj", "").replace(".o", "")] = \
            int(parts[0]) + int(parts[1])
    return result


def library(out, config):
    return os.path.join(out, "core-" + config, "src", "libdaran_ascii.a")


def member_symbols(out, config, member):
    """{symbol: size} of one object of the library."""
    data = subprocess.run(["arm-none-eabi-ar", "p", library(out, config), member + ".c.obj"],
                          check=True, stdout=subprocess.PIPE).stdout
    path = os.path.join(out, "core-%s-%s.o" % (config, member))
    with open(path, "wb") as f:
        f.write(data)
    symbols = {}
    for line in subprocess.run(["arm-none-eabi-nm", "-S", "--size-sort", path], check=True,
                               stdout=subprocess.PIPE, text=True).stdout.splitlines():
        parts = line.split()
        if len(parts) == 4:
            symbols[parts[3]] = symbols.get(parts[3], 0) + int(parts[1], 16)
    return symbols


def main():
    out = sys.argv[1]
    libs = {c: size(library(out, c)) for c, _ in CONFIGS}
    none = libs["none"]
    hooks_drive = none["drive"] - size(os.path.join(out, "core-none", "no-port-drive.o"))["no-port-drive"]
    hooks_table = none["command_table"] - \
        size(os.path.join(out, "core-none", "no-port-command_table.o"))["no-port-command_table"]
    table_symbols = member_symbols(out, "none", "property_table")
    discovery_part = sum(table_symbols.get(s, 0) for s in DISCOVERY_FUNCTIONS)

    print("**The mechanism's code** (core with no port rows; `arm-none-eabi-size` of the")
    print("library's objects, text + data):")
    print()
    print("| part | bytes | how measured |")
    print("|---|---:|---|")
    for member in MECHANISM:
        symbols = member_symbols(out, "none", member)
        names = ", ".join("`%s` %d" % (s, n) for s, n in
                          sorted(symbols.items(), key=lambda kv: -kv[1]) if n > 0)
        print("| `%s.o` | %d | exact; %s |" % (member, none[member], names))
    print("| dispatch hook in `drive.o` (port lookup, handler call) | %d | exact: `drive.c` "
          "recompiled with the lookup returning NULL (`no_port_drive.c`) |" % hooks_drive)
    print("| `h` hooks in `command_table.o` (port lines, discovery call) | %d | exact: "
          "`command_table.c` recompiled without them (`no_port_command_table.c`) |" % hooks_table)
    print("| discovery's part of `property_table.o` | %d | estimate: `arm-none-eabi-nm -S` of %s |"
          % (discovery_part, ", ".join("`%s` %d" % (s, table_symbols.get(s, 0))
                                       for s in DISCOVERY_FUNCTIONS)))
    total = sum(none[m] for m in MECHANISM) + hooks_drive + hooks_table + discovery_part
    print("| **total** | **%d** | of %d bytes of library (%.1f %%) |"
          % (total, sum(none.values()), 100.0 * total / sum(none.values())))
    print()

    port_object = size(os.path.join(out, "obj-brake", "brake_port.o"))["brake_port"]
    print("**The core with the example's options header** (`arm-none-eabi-size -t` of")
    print("`libdaran_ascii.a`, text + data; `property_table.o` holds the generated tables):")
    print()
    print("| core built with | library | vs none | `property_table.o` | vs none |")
    print("|---|---:|---:|---:|---:|")
    for config, what in CONFIGS:
        lib = sum(libs[config].values())
        table = libs[config]["property_table"]
        print("| %s | %d | %+d | %d | %+d |" % (what, lib, lib - sum(none.values()), table,
                                               table - none["property_table"]))
    print()
    print("The port's own object, `examples/port-brake/brake_port.o` (the `sb` table, its")
    print("handler and `brake_port_attach`): %d bytes. Other objects than `property_table.o`"
          % port_object)
    changed = sorted({m for c, _ in CONFIGS for m in libs[c] if libs[c][m] != none.get(m)})
    print("that change with the options header: %s." %
          (", ".join("`%s.o` (%s)" % (m, ", ".join("%s %+d" % (c, libs[c][m] - none[m])
                                                    for c, _ in CONFIGS[1:]))
                     for m in changed if m != "property_table") or "none"))
    print()

    print("**The generated tables, symbol by symbol** (`arm-none-eabi-nm -S` of")
    print("`property_table.o`, bytes):")
    print()
    symbols = {c: member_symbols(out, c, "property_table") for c, _ in CONFIGS}
    names = sorted(set().union(*[s.keys() for s in symbols.values()]),
                   key=lambda s: (-symbols["none"].get(s, 0), s))
    print("| symbol | none | brake | rows only | omissions only |")
    print("|---|---:|---:|---:|---:|")
    for name in names:
        values = [symbols[c].get(name, 0) for c, _ in CONFIGS]
        if len(set(values)) > 1:
            print("| `%s` | %s |" % (name, " | ".join(str(v) for v in values)))
    print("| (every other symbol) | unchanged | | | |")


if __name__ == "__main__":
    main()
