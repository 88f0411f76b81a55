"""The input sections a GNU ld link map says the link kept, for the scripts
that count flash by origin (bench/host/m4_map_summary.py,
bench/m0/map_summary.py)."""
import re

SECTION = re.compile(r"^ (\.\S+)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+)$")


def kept_sections(mapfile):
    """Yield (section, address, size, origin) of every kept input section:
    the "Linker script and memory map" part only (the "Discarded input
    sections" before it are what --gc-sections left out), with the entries
    whose long section name ld wrapped onto a line of its own joined."""
    started = False
    pending = None
    with open(mapfile) as f:
        for raw in f:
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
            if m:
                yield m.group(1) or "", int(m.group(2), 16), int(m.group(3), 16), m.group(4)
