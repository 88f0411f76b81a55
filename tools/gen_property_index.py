#!/usr/bin/env python3
"""Generate the core's property index from DARAN_PROPERTY_LIST.

Run by the build (daran_ascii_add_library(), cmake/DaranAddLibrary.cmake), never committed: the list in
include/daran_properties.h is the one source of truth, and a build may leave
rows out (--omit) without editing it.

What it writes, for src/table/property_table.c (and can_index.h, the CAN address of
each row that has one, for src/can/can_address.c):
  - every word of every path once (the parts between '.' and '_':
    "output", "shaft", "pos", "setpoint"), sorted, packed 5 bits a character
    with no terminators, and where each word ends (10 bits: a low byte, and
    two high bits four words to a byte);
  - per property: its path as word numbers (one byte each), where that list
    starts (10 bits), one bit per separator ('.' or '_') and one 16-bit
    attribute word (type, access, scope, range, unit), so `r`, `w` and
    discovery read one row. Words are shared by many paths (this saved about
    600 bytes of flash against whole dot-separated segments when it came in);
  - a perfect hash of the paths (hash-and-displace): the key is the path's
    bytes and its scope, with no fixed width; one FNV-1a pass (32-bit state)
    over them picks a bucket, the bucket's displacement picks the slot, the
    slot names the only property the path can be, and one comparison of its
    words decides. O(path length), independent of the row count;
  - the order discovery lists the rows in, when it is not the id order.

With --config, the port's options header adds its DARAN_PORT_PROPERTY_LIST
rows and leaves out its DARAN_OMIT_PROPERTIES; --omit (the CMake list
DARAN_PROPERTY_OMIT) leaves out more.

Usage: gen_property_index.py --list include/daran_properties.h --out FILE
                             [--config OPTIONS_HEADER] [--omit ID,ID,...] [--stats]
"""
import argparse
import os
import re
import sys

FNV_PRIME = 16777619
MASK32 = 0xFFFFFFFF
MAX_WORDS = 7  # six separator bits and two bits of the path start share a byte
ROW_RE = re.compile(r'X\(\s*(\w+)\s*,\s*"([^"]*)"\s*,\s*(SYSTEM|AXIS)\s*,\s*(\w+)\s*,\s*(RO|RW)\s*,\s*(\w+)\s*,\s*"([^"]*)"\s*,\s*(\d+)\s*\)')
# Where a port's own rows may sit on CAN (docs/can.md, C20); 0 keeps a row off it.
PORT_CAN_FIRST, PORT_CAN_LAST = 60000, 65535


def macro_body(text, name):
    """The body of `#define name(X) ...`, its continuation lines joined; None
    when the text does not define it."""
    match = re.search(r"^[ \t]*#[ \t]*define[ \t]+" + name + r"\(X\)(.*)$", text, re.M)
    if not match:
        return None
    body = []
    rest = text[match.start(1):].split("\n")
    for line in rest:
        body.append(line.rstrip("\\ \t"))
        if not line.rstrip().endswith("\\"):
            break
    return " ".join(body)


def read_rows(path, name="DARAN_PROPERTY_LIST", required=True):
    text = open(path, encoding="ascii").read()
    body = macro_body(text, name)
    if body is None:
        if required:
            sys.exit("gen_property_index: no %s in %s" % (name, path))
        return []
    rows = ROW_RE.findall(body)
    if required and not rows:
        sys.exit("gen_property_index: no X(...) rows in %s of %s" % (name, path))
    return rows


def read_omitted(path):
    body = macro_body(open(path, encoding="ascii").read(), "DARAN_OMIT_PROPERTIES")
    return set(re.findall(r"X\(\s*(\w+)\s*\)", body)) if body else set()


# Where each row ("row ID") and range ("range NAME") came from, so a refusal
# names the adopter's header and row rather than the library's list.
ORIGIN = {}


def refuse(key, why):
    """Stop with a message naming the file and the row or range (key) at fault."""
    where = ORIGIN.get(key)
    if where:
        sys.exit("gen_property_index: %s: %s: %s" % (where, key, why))
    sys.exit("gen_property_index: %s: %s" % (key, why))


RANGE_RE = re.compile(r'X\(\s*(\w+)\s*,\s*((?:"[^"]*"|\s|DARAN_RANGE_STR\(\s*\w+\s*\))+)\)')
NUMBER_RE = re.compile(r"^-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")
INTEGER_RE = re.compile(r"^-?\d+$")
OPTION_RE = re.compile(r"^\$\w+$")  # an option's value, e.g. $DARAN_MOTOR_ID_MAX


def read_ranges(path, name):
    """[(NAME, text)] of `#define name(X)` in path; a DARAN_RANGE_STR(MACRO)
    piece is kept as $MACRO: an integer option whose value is the core's
    business."""
    body = macro_body(open(path, encoding="ascii").read(), name)
    if body is None:
        return []
    ranges = []
    for ident, rest in RANGE_RE.findall(body):
        pieces = re.findall(r'"([^"]*)"|DARAN_RANGE_STR\(\s*(\w+)\s*\)', rest)
        ranges.append((ident, "".join(text if text or not macro else "$" + macro
                                      for text, macro in pieces)))
    return ranges


def check_range(ident, text, typ):
    """Refuse a range the core cannot check for row ident of type typ."""
    row = "row " + ident
    if text in ("", ">=0", ">0", "<=0"):
        return
    if ".." in text:
        low, _, high = text.partition("..")
        ends = (low, high)
        if not all(NUMBER_RE.match(e) or OPTION_RE.match(e) for e in ends):
            refuse(row, "range %r: both ends of lo..hi must be numbers" % text)
        if typ == "F32" and any(OPTION_RE.match(e) for e in ends):
            refuse(row, "range %r: an f32 row takes decimal ends" % text)
        if typ != "F32" and not all(INTEGER_RE.match(e) or OPTION_RE.match(e) for e in ends):
            refuse(row, "range %r: an integer row takes integer ends" % text)
        if all(NUMBER_RE.match(e) for e in ends) and float(low) > float(high):
            refuse(row, "range %r: lo is above hi" % text)
        return
    if typ == "F32":
        refuse(row, "an f32 row takes a sign condition or an interval lo..hi, not %r" % text)
    items = text.strip("{}").replace("|", ",").split(",")
    if not all(INTEGER_RE.match(v) for v in items):
        refuse(row, "range %r: a set lists integers" % text)


def fnv(seed, scope, data):
    """FNV-1a over the path four bytes a step (each four as a little-endian
    word, whatever the target's byte order), then the bytes left one at a
    time: daran_find_property() in C takes the same steps."""
    h = (seed + scope) & MASK32
    whole = len(data) - len(data) % 4
    for k in range(0, whole, 4):
        h = ((h ^ int.from_bytes(data[k:k + 4], "little")) * FNV_PRIME) & MASK32
    for byte in data[whole:]:
        h = ((h ^ byte) * FNV_PRIME) & MASK32
    return h


def slot_of(h, displacement, slots):
    # Mirrors property_table.c: the low half of the hash is where the key
    # starts, the high half (odd) its stride, so each displacement moves the
    # keys of one bucket by different amounts.
    x = (h + displacement * ((h >> 16) | 1)) & 0xFFFF
    return (x * slots) >> 16


def build_hash(keys):
    """keys: list of (scope, bytes). Returns seed, bucket bits, displacements,
    slot table, slot count: a minimal perfect hash (as many slots as keys)
    when one is found, else a little room is added."""
    n = len(keys)
    bucket_bits = max(1, (max(1, n // 3)).bit_length())
    buckets = 1 << bucket_bits
    for slots in (max(1, n), n + n // 8, n + n // 4):
        for seed in range(1, 1024):
            hashes = [fnv(seed, scope, data) for scope, data in keys]
            groups = [[] for _ in range(buckets)]
            for index, h in enumerate(hashes):
                groups[h >> (32 - bucket_bits)].append(index)
            order = sorted(range(buckets), key=lambda b: -len(groups[b]))
            taken = [None] * slots
            displacement = [0] * buckets
            ok = True
            for b in order:
                members = groups[b]
                if not members:
                    continue
                for d in range(256):
                    wanted = [slot_of(hashes[i], d, slots) for i in members]
                    if len(set(wanted)) == len(wanted) and all(taken[s] is None for s in wanted):
                        for i, s in zip(members, wanted):
                            taken[s] = i
                        displacement[b] = d
                        break
                else:
                    ok = False
                    break
            if ok:
                return seed, bucket_bits, displacement, taken, slots
    sys.exit("gen_property_index: no perfect hash found")


def c_string(data):
    return '"' + data.replace("\\", "\\\\").replace('"', '\\"') + '"'


def shared_segments(paths):
    """Each path as segments and the separators between them. A segment is a
    word, or a run of words that many paths share ("controller.config"),
    stored once with its own separators: a path then names it with one byte
    instead of one a word. Runs are merged greedily, the pair of neighbours
    that saves the most bytes first, while a merge still saves any."""
    split = {}
    for path in paths:
        words = re.split(r"([._])", path)
        split[path] = [words[0::2], words[1::2]]

    def text_bytes(word):  # a byte a character and 10 bits of end position
        return (8 * len(word) + 10) / 8.0

    while True:
        pairs = {}
        for words, seps in split.values():
            k = 0
            while k + 1 < len(words):
                key = (words[k], seps[k], words[k + 1])
                pairs[key] = pairs.get(key, 0) + 1
                k += 1
        uses = {}
        for words, _ in split.values():
            for w in words:
                uses[w] = uses.get(w, 0) + 1
        best = None
        for (a, sep, b), count in sorted(pairs.items()):
            merged = a + sep + b
            gain = count - (0 if merged in uses else text_bytes(merged))
            # a word whose every use becomes the merged one is stored no more
            gain += text_bytes(a) if uses[a] == count else 0
            gain += text_bytes(b) if uses[b] == count and b != a else 0
            if gain > 0 and (best is None or gain > best[0]):
                best = (gain, a, sep, b)
        if best is None:
            return {path: (words, seps) for path, (words, seps) in split.items()}
        _, a, sep, b = best
        for words, seps in split.values():
            k = 0
            while k + 1 < len(words):
                if words[k] == a and seps[k] == sep and words[k + 1] == b:
                    words[k:k + 2] = [a + sep + b]
                    del seps[k]
                k += 1


def generate(rows, omit, ranges):
    ids = [r[0] for r in rows]
    unknown = sorted(set(omit) - set(ids))
    if unknown:
        sys.exit("gen_property_index: DARAN_PROPERTY_OMIT (--omit) names unknown properties: " +
                 " ".join(unknown))
    if len(set(ids)) != len(ids):
        twice = sorted({i for i in ids if ids.count(i) > 1})
        refuse("row " + twice[0], "the property id appears twice")
    range_text = dict(ranges)
    if len(ranges) > 32:
        refuse("range " + ranges[32][0], "at most 32 ranges in all (5 bits of the attribute word)")
    for ident, path, scope, typ, access, rng, unit, can in rows:
        # what src/ascii/commands_property.c can check for each type
        if rng not in range_text:
            refuse("row " + ident, "range %s is neither in DARAN_RANGE_LIST nor in DARAN_PORT_RANGE_LIST" % rng)
        if typ == "BOOL" and rng != "BOOL":
            refuse("row " + ident, "a bool row takes the range BOOL, not %s" % rng)
        if typ == "U64" and access == "RW" and rng != "NONE":
            refuse("row " + ident, "a writable u64 row takes no range (NONE), not %s" % rng)
        if typ != "BOOL":
            check_range(ident, range_text[rng], typ)
        if len(path) > 64:
            refuse("row " + ident, "path %s: paths are 64 characters at most (DARAN_PATH_MAX)" % path)
        address = int(can)
        if address > 0xFFFF:
            refuse("row " + ident, "CAN address %d: addresses are 16 bits" % address)
        if address and typ == "U64":
            refuse("row " + ident, "a u64 row has no CAN type code: its CAN address must be 0")
        port_row = "DARAN_PORT_PROPERTY_LIST" in ORIGIN.get("row " + ident, "")
        if port_row and address and not PORT_CAN_FIRST <= address <= PORT_CAN_LAST:
            refuse("row " + ident, "CAN address %d: a port's rows take 0 (none) or %d..%d"
                   % (address, PORT_CAN_FIRST, PORT_CAN_LAST))
    kept = [i for i, r in enumerate(rows) if r[0] not in omit]
    seen = {}
    for i in kept:
        key = (rows[i][2], rows[i][1])
        if key in seen:
            refuse("row " + rows[i][0], "path %s appears twice (also row %s): a port row must not reuse a "
                               "vendor path; omit the vendor row first" % (rows[i][1], seen[key]))
        seen[key] = rows[i][0]

    segments = shared_segments([rows[i][1] for i in kept])

    def words_of(path):
        return segments[path][0]

    def separators_of(path):
        return segments[path][1]

    words = sorted({w for i in kept for w in words_of(rows[i][1])}, key=lambda w: w.encode())
    if len(words) > 255:
        sys.exit("gen_property_index: more than 255 distinct words")
    number = {w: k + 1 for k, w in enumerate(words)}
    units = sorted({r[6] for r in rows} - {""})
    if len(units) > 63:
        sys.exit("gen_property_index: more than 63 distinct units")
    unit_number = {u: k + 1 for k, u in enumerate(units)}
    unit_number[""] = 0

    keys = []
    for i in kept:
        parts = re.split(r"[._]", rows[i][1])
        if len(parts) > MAX_WORDS or "" in parts:
            refuse("row " + rows[i][0], "path %s: 1..%d non-empty words" % (rows[i][1], MAX_WORDS))
        keys.append((1 if rows[i][2] == "AXIS" else 0, rows[i][1].encode()))
    seed, bucket_bits, displacement, taken, slots = build_hash(keys)
    if len(rows) >= 0xFFFF:
        sys.exit("gen_property_index: too many properties")
    slot_type = "uint8_t" if len(rows) < 0xFF else "uint16_t"
    empty = 0xFF if slot_type == "uint8_t" else 0xFFFF

    out = []
    out.append("/* Generated by tools/gen_property_index.py from DARAN_PROPERTY_LIST at build time. */")
    out.append("#ifndef DARAN_PROPERTY_INDEX_H")
    out.append("#define DARAN_PROPERTY_INDEX_H")
    out.append("")
    out.append("#define DARAN_INDEX_PROPERTIES %du /* rows with a path in this build */" % len(kept))
    out.append("#define DARAN_WORD_COUNT %du" % len(words))
    out.append("#define DARAN_HASH_SEED 0x%08xu" % seed)
    out.append("#define DARAN_HASH_PRIME %du /* the one FNV-1a prime: fnv() here, daran_find_property() in C */" % FNV_PRIME)
    out.append("#define DARAN_HASH_BUCKET_BITS %du" % bucket_bits)
    out.append("#define DARAN_HASH_SLOTS %du" % slots)
    out.append("#define DARAN_HASH_EMPTY 0x%xu" % empty)
    out.append("typedef %s daran_hash_slot_t;" % slot_type)
    out.append("")
    text = "".join(words)
    if len(text) > 1023:
        sys.exit("gen_property_index: %d characters of words; 10 bits hold 1023" % len(text))
    out.append("/* Every word once, sorted, without terminators, a byte a character: a")
    out.append(" * path is compared and copied straight from here. */")
    for k in range(0, len(words), 12):
        out.append("/*   " + " ".join(words[k:k + 12]) + " */")
    out.append("static const char word_text[%d] =" % len(text))
    for k in range(0, len(text), 72):
        out.append("    " + c_string(text[k:k + 72]))
    out[-1] += ";"
    out.append("")
    ends = []
    pos = 0
    for w in words:
        pos += len(w)
        ends.append(pos)
    out.append("/* Where word n (1-based) ends in word_text (it starts where n-1 ends):")
    out.append(" * the low 8 bits, and the high 2 of four words a byte. */")
    out.append("static const uint8_t word_end_low[DARAN_WORD_COUNT] = {")
    for k in range(0, len(ends), 16):
        out.append("    " + ", ".join(str(e & 0xFF) for e in ends[k:k + 16]) + ",")
    out.append("};")
    highs = [0] * ((len(ends) + 3) // 4)
    for k, e in enumerate(ends):
        highs[k // 4] |= (e >> 8) << (2 * (k % 4))
    out.append("static const uint8_t word_end_high[%d] = {" % len(highs))
    for k in range(0, len(highs), 16):
        out.append("    " + ", ".join(str(b) for b in highs[k:k + 16]) + ",")
    out.append("};")
    out.append("")
    refs = []
    starts = []
    dots = []
    for i, r in enumerate(rows):
        starts.append(len(refs))
        if i in kept:
            refs.extend(number[w] for w in words_of(r[1]))
            dots.append(sum(1 << k for k, c in enumerate(separators_of(r[1])) if c == "."))
        else:
            dots.append(0)
    starts.append(len(refs))
    dots.append(0)
    if len(refs) > 1023:
        sys.exit("gen_property_index: %d word references; 10 bits hold 1023" % len(refs))
    out.append("/* Each property's path as word numbers: property p's are from")
    out.append(" * path_start(p) up to path_start(p + 1) (none: left out of this build). */")
    out.append("static const uint8_t path_words[%d] = {" % max(1, len(refs)))
    for k in range(0, len(refs), 20):
        out.append("    " + ", ".join(str(x) for x in refs[k:k + 20]) + ",")
    out.append("};")
    out.append("/* path_start(p): the low 8 bits here, the high 2 in path_info's top bits. */")
    out.append("static const uint8_t path_start_low[DARAN_PROP_COUNT + 1u] = {")
    for k in range(0, len(starts), 16):
        out.append("    " + ", ".join(str(x & 0xFF) for x in starts[k:k + 16]) + ",")
    out.append("};")
    out.append("/* Bit k (k < 6) set: the separator after word k is '.', else '_'. */")
    out.append("static const uint8_t path_info[DARAN_PROP_COUNT + 1u] = {")
    info = [d | (st >> 8) << 6 for d, st in zip(dots, starts)]
    for k in range(0, len(info), 16):
        out.append("    " + ", ".join(str(x) for x in info[k:k + 16]) + ",")
    out.append("};")
    out.append("")
    out.append("/* type, access, scope, range, unit of each property. */")
    out.append("static const uint16_t property_attr[DARAN_PROP_COUNT] = {")
    for r in rows:
        out.append("    DARAN_ATTR(DARAN_TYPE_%s, DARAN_ACCESS_%s, DARAN_SCOPE_%s, DARAN_RANGE_%s, %du)," % (
            r[3], r[4], r[2], r[5], unit_number[r[6]]))
    out.append("};")
    out.append("")
    out.append("/* Units named by the attribute's unit number (1-based), NUL-separated. */")
    out.append("#define DARAN_UNIT_TEXT \\")
    out.append("    " + " ".join(c_string(u)[:-1] + '\\0"' for u in units))
    out.append("")
    out.append("static const uint8_t hash_displacement[1u << DARAN_HASH_BUCKET_BITS] = {")
    for k in range(0, len(displacement), 16):
        out.append("    " + ", ".join(str(d) for d in displacement[k:k + 16]) + ",")
    out.append("};")
    out.append("")
    out.append("/* The property each slot holds, DARAN_HASH_EMPTY for none. */")
    out.append("static const daran_hash_slot_t hash_slot[DARAN_HASH_SLOTS] = {")
    cells = [str(kept[t]) if t is not None else "DARAN_HASH_EMPTY" for t in taken]
    for k in range(0, len(cells), 12):
        out.append("    " + ", ".join(cells[k:k + 12]) + ",")
    out.append("};")
    out.append("")
    full = lambda i: (("axis0." if rows[i][2] == "AXIS" else "") + rows[i][1]).encode()
    order = sorted(kept, key=full)
    if order == kept:
        out.append("/* Discovery lists the rows in id order: that is path order. */")
        out.append("#define DARAN_DISCOVERY_IN_ID_ORDER 1")
    else:
        out.append("/* Discovery's order (by path as a host writes it): a port's rows are not at the end. */")
        out.append("#define DARAN_DISCOVERY_IN_ID_ORDER 0")
        out.append("static const %s discovery_order[%d] = {" % (slot_type, len(order)))
        for k in range(0, len(order), 16):
            out.append("    " + ", ".join(str(x) for x in order[k:k + 16]) + ",")
        out.append("};")
    out.append("#define DARAN_DISCOVERY_COUNT %du" % len(order))

    # The CAN address of each kept row that has one, sorted: a binary search
    # finds the property of a read or write frame.
    on_can = sorted((int(rows[i][7]), i) for i in kept if int(rows[i][7]))
    seen_address = {}
    for address, i in on_can:
        if address in seen_address:
            refuse("row " + rows[i][0], "CAN address %d is also row %s's" % (address, seen_address[address]))
        seen_address[address] = rows[i][0]
    # Rows next to each other in the list (paths sorted) mostly sit next to
    # each other on CAN too (the vendor numbers a family in a block): a run
    # is consecutive ids whose addresses share the high byte, and a row
    # keeps only its address's low byte, at its id.
    runs = []
    for i in kept:
        address = int(rows[i][7])
        if not address:
            continue
        if runs and runs[-1][0] == address >> 8 and runs[-1][1] + runs[-1][2] == i:
            runs[-1][2] += 1
        else:
            runs.append([address >> 8, i, 1])
    runs.sort()  # by high byte: a lookup stops at the first run past its own
    low = [int(r[7]) & 0xFF for r in rows]
    can = ["/* Generated by tools/gen_property_index.py from the last column of the property",
           " * list, for src/can/can_address.c: run r (in the order of their high bytes) holds",
           " * the properties can_run_first[r] ..",
           " * can_run_first[r] + can_run_count[r] - 1, whose CAN addresses all have the high",
           " * byte can_run_high[r]; can_low[p] is the low byte of property p's address. A",
           " * property in no run has none. */",
           "#ifndef DARAN_CAN_INDEX_H", "#define DARAN_CAN_INDEX_H", "",
           "#include <stdint.h>", "",
           "#define DARAN_CAN_ROWS %du" % len(on_can),
           "#define DARAN_CAN_RUNS %du" % len(runs)]
    def table(ctype, name, size, values, per_line=16):
        can.append("static const %s %s[%s] = {" % (ctype, name, size))
        for k in range(0, len(values), per_line):
            can.append("    " + ", ".join(str(v) for v in values[k:k + per_line]) + ",")
        can.append("};")
    if runs:
        table("uint8_t", "can_run_high", "DARAN_CAN_RUNS", [r[0] for r in runs])
        table(slot_type, "can_run_first", "DARAN_CAN_RUNS", [r[1] for r in runs])
        table("uint8_t", "can_run_count", "DARAN_CAN_RUNS", [r[2] for r in runs])
        table("uint8_t", "can_low", "DARAN_PROP_COUNT", low)
    can += ["", "#endif /* DARAN_CAN_INDEX_H */", ""]

    out.append("")
    out.append("#endif /* DARAN_PROPERTY_INDEX_H */")
    stats = {"rows": len(rows), "kept": len(kept), "words": len(words), "text": len(text), "refs": len(refs),
             "slots": slots, "buckets": 1 << bucket_bits, "seed": seed, "can": len(on_can)}
    intervals = any(rows[i][3] == "F32" and ".." in range_text[rows[i][5]] for i in kept)
    features = "\n".join([
        "/* Generated by tools/gen_property_index.py: what this build's table needs",
        " * compiled in, for the files that must not include the tables. */",
        "#ifndef DARAN_PROPERTY_FEATURES_H",
        "#define DARAN_PROPERTY_FEATURES_H",
        "/* 1: an f32 row has an interval range lo..hi (else f32 ranges are sign conditions). */",
        "#define DARAN_F32_INTERVALS %d" % (1 if intervals else 0),
        "#endif /* DARAN_PROPERTY_FEATURES_H */", ""])
    return "\n".join(out) + "\n", features, "\n".join(can), stats


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", required=True, help="header with DARAN_PROPERTY_LIST")
    parser.add_argument("--out", required=True, help="header to write")
    parser.add_argument("--omit", default="", help="property ids to leave out, comma or semicolon separated")
    parser.add_argument("--config", default="", help="the port's options header: DARAN_PORT_PROPERTY_LIST, DARAN_OMIT_PROPERTIES")
    parser.add_argument("--stats", action="store_true", help="print table sizes")
    args = parser.parse_args()
    omit = {x for x in re.split(r"[,;\s]+", args.omit) if x}
    rows = read_rows(args.list)
    ranges = read_ranges(args.list, "DARAN_RANGE_LIST")
    vendor = {r[0] for r in rows}
    vendor_ranges = {r[0] for r in ranges}
    for r in rows:
        ORIGIN["row " + r[0]] = "%s (DARAN_PROPERTY_LIST)" % args.list
    for r in ranges:
        ORIGIN["range " + r[0]] = "%s (DARAN_RANGE_LIST)" % args.list
    if args.config:
        port_ranges = read_ranges(args.config, "DARAN_PORT_RANGE_LIST")
        for r in port_ranges:
            if r[0] in vendor_ranges:
                sys.exit("gen_property_index: %s (DARAN_PORT_RANGE_LIST): range %s reuses a vendor "
                         "range name" % (args.config, r[0]))
            ORIGIN["range " + r[0]] = "%s (DARAN_PORT_RANGE_LIST)" % args.config
        ranges += port_ranges
        port_rows = read_rows(args.config, "DARAN_PORT_PROPERTY_LIST", required=False)
        for r in port_rows:
            if r[0] in vendor:
                sys.exit("gen_property_index: %s (DARAN_PORT_PROPERTY_LIST): row %s reuses a vendor id"
                         % (args.config, r[0]))
            ORIGIN["row " + r[0]] = "%s (DARAN_PORT_PROPERTY_LIST)" % args.config
        rows += port_rows
        port_omit = read_omitted(args.config)
        unknown = sorted(port_omit - vendor)
        if unknown:
            sys.exit("gen_property_index: %s (DARAN_OMIT_PROPERTIES): names no vendor property: %s"
                     % (args.config, " ".join(unknown)))
        omit |= port_omit
    # `e` names each error register by its path: they cannot be left out
    needed = {"AXIS_ERROR", "MOTOR_ERROR", "ENCODER_ERROR", "CONTROLLER_ERROR",
              "FET_THERMISTOR_ERROR", "MOTOR_THERMISTOR_ERROR", "CAN_ERROR"}
    if omit & needed:
        where = args.config + " (DARAN_OMIT_PROPERTIES) or DARAN_PROPERTY_OMIT" if args.config \
            else "DARAN_PROPERTY_OMIT (--omit)"
        sys.exit("gen_property_index: %s: the error registers cannot be left out (`e` names them): %s"
                 % (where, " ".join(sorted(omit & needed))))
    text, features, can, stats = generate(rows, omit, ranges)
    # property_features.h and can_index.h go beside the index; each is
    # rewritten only when it changes, so the build does not recompile for
    # nothing.
    here = os.path.dirname(os.path.abspath(args.out))
    features_out = os.path.join(here, "property_features.h")
    can_out = os.path.join(here, "can_index.h")
    for path, content in ((args.out, text), (features_out, features), (can_out, can)):
        try:
            old = open(path, encoding="ascii").read()
        except OSError:
            old = None
        if old != content:
            with open(path, "w", encoding="ascii") as f:
                f.write(content)
    if args.stats:
        print(" ".join("%s=%s" % kv for kv in stats.items()))


if __name__ == "__main__":
    main()
