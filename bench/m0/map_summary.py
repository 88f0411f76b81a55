#!/usr/bin/env python3
"""Flash the Cortex-M0 image keeps, by origin: the core's objects (obj/core),
the measuring program (obj/main), and each library member (libgcc's soft
float, libm, libc), from the link map's kept input sections."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from link_map import kept_sections  # noqa: E402


def kept(mapfile):
    totals = {}
    for section, addr, n, origin in kept_sections(mapfile):
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
