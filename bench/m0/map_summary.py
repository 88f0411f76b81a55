#!/usr/bin/env python3
"""Flash the Cortex-M0 image keeps, by origin: the core's objects (obj/core),
the measuring program (obj/main), and each library member (libgcc's soft
float, libm, libc), from the link map's kept input sections."""
import os
import re
import sys

SECTION = re.compile(r"^ (\.\S+)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+)$")


def kept(mapfile):
    totals = {}
    started = False
    pending = None
    for raw in open(mapfile):
        line = raw.rstrip("\n")
        if line.startswith("Linker script and memory map"):
            started = True
            continue
        if not started:
            continue
        if pending is not None and re.match(r"^\s+0x[0-9a-f]+\s+0x[0-9a-f]+\s+\S+$", line):
            line = " " + pending + line
            pending = None
        elif re.match(r"^ \.\S+$", line):
            pending = line.strip()
            continue
        else:
            pending = None
        m = SECTION.match(line)
        if not m:
            continue
        section, addr, n, origin = m.group(1) or "", int(m.group(2), 16), int(m.group(3), 16), m.group(4)
        if n == 0 or addr >= 0x20000000 and not section.startswith(".data"):
            continue
        if section.startswith((".debug", ".comment", ".ARM.attributes", ".bss")):
            continue
        if "/obj/core/" in origin:
            key = "core (src/)"
        elif "/obj/main/" in origin:
            key = "m0_main.c (HAL stub, lines, startup)"
        else:
            key = os.path.basename(origin)
        totals[key] = totals.get(key, 0) + n
    return totals


def main():
    totals = kept(sys.argv[1])
    print("| flash kept in daran-m0.elf, by origin | bytes |")
    print("|---|---:|")
    libs = {k: v for k, v in totals.items() if ".a(" in k}
    for key in ("core (src/)", "m0_main.c (HAL stub, lines, startup)"):
        print("| %s | %d |" % (key, totals.get(key, 0)))
    for key, n in sorted(libs.items(), key=lambda kv: -kv[1]):
        print("| %s | %d |" % (key, n))
    core = totals.get("core (src/)", 0)
    pulled = sum(libs.values())
    print()
    print("Core flash on Cortex-M0: %d bytes of its own objects kept, plus %d bytes of library "
          "code the core and the stub pull in (soft float, sqrtf, memcpy...): %d." % (
              core, pulled, core + pulled))


if __name__ == "__main__":
    main()
