#!/usr/bin/env python3
"""Summarise the Cortex-M4 images m4_size.sh links: flash (text + data)
and RAM (data + bss) from arm-none-eabi-size, each minus the empty image,
and the flash bytes each image takes from every input, read from its link
map (only sections the link kept: --gc-sections leaves the rest in the map's
"Discarded input sections" part, which is skipped)."""
import os
import re
import subprocess
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "build/bench/m4"


def size(elf):
    text = subprocess.run(["arm-none-eabi-size", "-A", elf], check=True,
                          stdout=subprocess.PIPE).stdout.decode()
    flash = ram = 0
    for line in text.splitlines():
        parts = line.split()
        if len(parts) < 3 or not parts[1].isdigit():
            continue
        name, n, addr = parts[0], int(parts[1]), int(parts[2])
        if name.startswith(".debug") or name in (".comment", ".ARM.attributes") or addr == 0 and name != ".text":
            continue
        if name in (".data",):
            flash += n
            ram += n
        elif name in (".bss", ".heap", ".stack", ".stack_dummy") or name.startswith(".bss"):
            ram += n
        else:
            flash += n
    return flash, ram


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from link_map import kept_sections  # noqa: E402


def by_origin(mapfile, members_by_archive=None):
    """Bytes of kept input sections per origin: the object or archive."""
    if members_by_archive is None:
        members_by_archive = {}
    totals = {}
    for section, addr, n, origin in kept_sections(mapfile):
        if n == 0 or section.startswith((".debug", ".comment", ".ARM.attributes")):
            continue
        if section.startswith((".bss", "COMMON", ".heap", ".stack", ".noinit")):
            continue  # RAM only: this table is about flash
        if addr == 0:
            continue
        name = os.path.basename(origin)
        if "(" in name:
            archive, member = name.split("(", 1)
            members = members_by_archive.setdefault(archive, {})
            member = member.rstrip(")")
            members[member] = members.get(member, 0) + n
            name = archive
        elif "/obj/" in origin:
            name = origin.split("/obj/")[1].split("/")[0]
            name = "main" if name.startswith("main-") else name
        else:
            name = "startup (" + name + ")" if name.startswith("crt") else name
        totals[name] = totals.get(name, 0) + n
    return totals


rows = {}
IMAGES = ("empty", "daran", "daran-nohelp", "baseline", "handwritten")
for image in IMAGES:
    rows[image] = size(os.path.join(out, image + ".elf"))
base_flash, base_ram = rows["empty"]
print("| image | flash (text+data) | RAM (data+bss) | flash over empty | RAM over empty |")
print("|---|---:|---:|---:|---:|")
for image in IMAGES:
    flash, ram = rows[image]
    print("| %s | %d | %d | %d | %d |" % (image, flash, ram, flash - base_flash, ram - base_ram))
print()
print("Flash bytes kept per input (core = src/, core-nohelp = src/ with DARAN_ENABLE_HELP=0, "
      "baseline = bench/baseline/baseline.c, handwritten = bench/baseline/handwritten.c, "
      "main = m4_main.c):")
print()
origins = set()
parts = {}
members = {}
for image in IMAGES:
    members[image] = {}
    parts[image] = by_origin(os.path.join(out, image + ".map"), members[image])
    origins |= set(parts[image])
images = IMAGES
print("| input | " + " | ".join(images) + " |")
print("|---|" + "---:|" * len(images))
for origin in sorted(origins):
    print("| %s | %s |" % (origin, " | ".join(str(parts[i].get(origin, 0)) for i in images)))

def own_and_pulled(image, own):
    """Flash of the parser's own objects plus what it pulls from the libraries
    (each archive's bytes beyond the empty image's)."""
    pulled = sum(n - parts["empty"].get(origin, 0) for origin, n in parts[image].items()
                 if origin.endswith(".a"))
    return parts[image].get(own, 0), pulled


# The budget CTest enforces (budget_core_flash), raised with the vendor's
# whole property table (97424e3): read from where the cortex-m4 build sets it.
budget = 0
try:
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests",
                           "target", "CMakeLists.txt")) as f:
        m = re.search(r"set\(DARAN_BUDGET_FLASH (\d+)", f.read())
        if m:
            budget = int(m.group(1))
except OSError:
    pass
core_own, core_pulled = own_and_pulled("daran", "core")
base_own, base_pulled = own_and_pulled("baseline", "baseline")
hand_own, hand_pulled = own_and_pulled("handwritten", "handwritten")
core_total = core_own + core_pulled
nohelp_own, nohelp_pulled = own_and_pulled("daran-nohelp", "core-nohelp")
print()
# budget_core_flash counts the whole library (every object, text + data); an
# image keeps less after --gc-sections (what this image does not call goes),
# so this is a report on the linked image, not the budget's verdict.
headline = ("**In this minimal image the core keeps %d bytes** (%s the %d of CTest "
            "budget_core_flash, which counts the whole library before --gc-sections: "
            "see the summary)." % (core_own + core_pulled,
                                   "within" if core_own + core_pulled <= budget else "over",
                                   budget))
print(headline + " The core's objects (src/) take %d bytes and pull "
      "%d bytes from the libraries: %d in all; the baseline's take %d and pull %d: %d in "
      "all, %.1fx the core; the hand-written yardstick's take %d and pull %d: %d in all. "
      "Without the help text (DARAN_ENABLE_HELP=0) the core is %d in all. "
      "Whole images over the empty one (trivial HAL and glue included): "
      "%d (daran), %d (daran, no help text), %d (baseline), %d (hand-written)." % (
          core_own, core_pulled, core_total,
          base_own, base_pulled, base_own + base_pulled, (base_own + base_pulled) / core_total,
          hand_own, hand_pulled, hand_own + hand_pulled,
          nohelp_own + nohelp_pulled,
          rows["daran"][0] - base_flash, rows["daran-nohelp"][0] - base_flash,
          rows["baseline"][0] - base_flash, rows["handwritten"][0] - base_flash))
for image in ("daran", "baseline", "handwritten"):
    print()
    print("Library members in the %s image beyond the empty one (flash bytes):" % image)
    print()
    extra = []
    for archive, found in members[image].items():
        for member, n in found.items():
            n -= members["empty"].get(archive, {}).get(member, 0)
            if n > 0:
                extra.append((n, archive, member))
    extra.sort(reverse=True)
    if not extra:
        print("- none")
    shown = extra[:12]
    for n, archive, member in shown:
        print("- %s(%s): %d" % (archive, member, n))
    if len(extra) > len(shown):
        print("- %d more members: %d" % (len(extra) - len(shown), sum(e[0] for e in extra[len(shown):])))
