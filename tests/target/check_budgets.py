#!/usr/bin/env python3
"""Footprint budgets of the protocol core on the Cortex-M4, run by CTest in
the cortex-m4 build. Each subcommand prints what it measured and exits 1
when the budget is exceeded.

  flash   LIB SIZE LIMIT [--except RE | --only RE]
                                  text + data of libdaran_ascii.a, or of the
                                  members whose name does not match / matches
                                  RE (the CAN front end has its own budget)
  ram     OBJ NM LIMIT [can]      sizeof(daran_drive_t) (or daran_can_t), read from the size of
                                  a symbol declared as char[sizeof(daran_drive_t)]
  stack   OBJDIR LIB NM OBJDUMP LIMIT
                                  worst-case stack of every public function:
                                  its own frame (-fstack-usage .su) plus the
                                  deepest chain of calls (-fcallgraph-info .ci)
  symbols ELF LIB NM              no heap, stdio or strtod in the firmware
                                  image; no double-precision helpers in the core
"""
import collections
import glob
import os
import re
import subprocess
import sys

# Stack allowed for a call that leaves the core into libc/libgcc (memcpy,
# memset, soft-float division): these are leaf routines with small frames.
EXTERNAL_CALL_STACK = 32


def run(cmd):
    return subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout


def check_flash(lib, size_tool, limit, members=None):
    """members: None for the whole library, else ("except"|"only", regex)."""
    out = run([size_tool, "-t", lib])
    print(out)
    if members is None:
        totals = [l for l in out.splitlines() if l.rstrip().endswith("(TOTALS)")]
        text, data, bss = (int(x) for x in totals[-1].split()[:3])
        what = "core flash (text + data)"
    else:
        mode, pattern = members
        text = data = bss = 0
        for line in out.splitlines():
            parts = line.split()
            if len(parts) < 6 or not parts[0].isdigit() or line.rstrip().endswith("(TOTALS)"):
                continue
            name = parts[5]
            if (re.search(pattern, name) is not None) == (mode == "only"):
                text, data, bss = text + int(parts[0]), data + int(parts[1]), bss + int(parts[2])
        what = "flash (text + data) of the members %s /%s/" % (
            "matching" if mode == "only" else "not matching", pattern)
        if mode == "except":
            what = "core flash (text + data), without the members matching /%s/" % pattern
    used = text + data
    print(f"{what}: {used} bytes, budget {limit}; bss {bss}")
    if used > limit:
        print(f"OVER BUDGET by {used - limit} bytes")
        return 1
    return 0


def check_ram(obj, nm, limit, what="drive"):
    out = run([nm, "-S", obj])
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[3] == "daran_target_sizeof_" + what:
            size = int(parts[1], 16)
            print(f"sizeof(daran_{what}_t): {size} bytes, budget {limit}")
            if size > limit:
                print(f"OVER BUDGET by {size - limit} bytes")
                return 1
            return 0
    if what != "drive":
        print(f"no daran_{what}_t in this build (compiled out): nothing to measure")
        return 0
    print("daran_target_sizeof_" + what, "not found in", obj)
    return 1


def read_frames(objdir):
    frames = {}
    for su in glob.glob(os.path.join(objdir, "**", "*.su"), recursive=True):
        with open(su) as f:
            for line in f:
                loc, size, kind = line.rstrip("\n").split("\t")
                name = loc.rsplit(":", 1)[-1]
                if "dynamic" in kind and "bounded" not in kind:
                    raise SystemExit(f"unbounded dynamic stack in {name} ({su})")
                frames[name] = max(frames.get(name, 0), int(size))
    return frames


def read_calls(objdir):
    calls = collections.defaultdict(set)
    edge = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    for ci in glob.glob(os.path.join(objdir, "**", "*.ci"), recursive=True):
        with open(ci) as f:
            for m in edge.finditer(f.read()):
                # static functions are titled "path/file.c:name"
                calls[m.group(1).rsplit(":", 1)[-1]].add(m.group(2).rsplit(":", 1)[-1])
    return calls


def function_tables(lib, objdump):
    """Indirect calls that stay inside the core: {dispatcher: {targets}}.

    A data section whose relocations name functions is a function table (the
    command handlers); a function whose code refers to such a table
    dispatches through it. Every other indirect call goes through a pointer
    the port gave (HAL, reply and forward callbacks) and leaves the core."""
    out = run([objdump, "-r", lib])
    dispatch = collections.defaultdict(set)
    per_object = re.split(r"^\S+\.o(?:bj)?:\s+file format.*$", out, flags=re.M)
    for chunk in per_object:
        relocs = collections.defaultdict(list)
        section = None
        for line in chunk.splitlines():
            m = re.match(r"RELOCATION RECORDS FOR \[(.*)\]:", line)
            if m:
                section = m.group(1)
                continue
            parts = line.split()
            if section and len(parts) == 3 and parts[1].startswith("R_ARM_"):
                relocs[section].append(parts[2].split("+")[0])

        def as_function(sym):
            return sym[len(".text."):] if sym.startswith(".text.") else sym

        tables = {}
        for sec, syms in relocs.items():
            if sec.startswith(".text") or sec.startswith(".ARM") or sec.startswith(".debug"):
                continue
            funcs = {as_function(x) for x in syms
                     if x.startswith(".text.") or x.startswith("daran_")}
            if funcs:
                tables[sec] = funcs
        for sec, syms in relocs.items():
            if not sec.startswith(".text."):
                continue
            for x in syms:
                if x in tables:
                    dispatch[sec[len(".text."):]] |= tables[x]
    return dispatch


def check_stack(objdir, lib, nm, objdump, limit):
    frames = read_frames(objdir)
    calls = read_calls(objdir)
    dispatch = function_tables(lib, objdump)
    public = sorted(l.split()[2] for l in run([nm, "-g", "--defined-only", lib]).splitlines()
                    if len(l.split()) == 3 and l.split()[1] == "T")
    memo = {}
    externals = set()

    def worst(fn, path):
        if fn in path:
            raise SystemExit("recursion: " + " -> ".join(path + [fn]))
        if fn in memo:
            return memo[fn]
        if fn.startswith("__indirect_call@"):
            # Through a table of the core: the deepest handler in it.
            # Through a pointer the port gave (HAL, reply and forward
            # callbacks): the port's own budget, 0 here.
            best = (0, [])
            for t in sorted(dispatch.get(fn.split("@", 1)[1], ())):
                cost, chain = worst(t, path + [fn])
                if cost > best[0]:
                    best = (cost, chain)
            memo[fn] = best
            return best
        if fn not in frames:
            externals.add(fn)
            memo[fn] = (EXTERNAL_CALL_STACK, [fn + " (outside the core)"])
            return memo[fn]
        best = (0, [])
        for callee in sorted(calls.get(fn, ())):
            if callee == "__indirect_call":
                callee = "__indirect_call@" + fn
            cost, chain = worst(callee, path + [fn])
            if cost > best[0]:
                best = (cost, chain)
        memo[fn] = (frames[fn] + best[0], [f"{fn} {frames[fn]}"] + best[1])
        return memo[fn]

    status = 0
    print(f"{'entry point':28} worst-case stack (budget {limit} bytes)")
    for fn in public:
        cost, chain = worst(fn, [])
        flag = "" if cost <= limit else "   OVER BUDGET"
        print(f"{fn:28} {cost:5}{flag}")
        if cost > limit:
            status = 1
    deepest = max(public, key=lambda f: worst(f, [])[0])
    print(f"deepest: {deepest}: " + " -> ".join(worst(deepest, [])[1]))
    for fn in sorted(dispatch):
        print(f"{fn} calls through a table: " + ", ".join(sorted(dispatch[fn])))
    print("other indirect calls go to the port (HAL, reply, forward): their stack is the port's")
    print(f"calls leaving the core (counted {EXTERNAL_CALL_STACK} bytes each):",
          ", ".join(sorted(externals)) or "none")
    return status


FORBIDDEN_IMAGE = re.compile(
    r"^(malloc|_malloc_r|calloc|realloc|free|_sbrk|_sbrk_r|sbrk|"
    r"_?v?[sfd]?n?printf|_?v?[sfd]?n?printf_r|_?v?[sf]?scanf|_?v?[sf]?scanf_r|"
    r"_?vfprintf_r|_?svfprintf_r|_?vfiprintf_r|_?svfiprintf_r|puts|fputs|"
    r"strtod|_strtod_r|strtof|_strtof_r|atof)$")
FORBIDDEN_CORE = re.compile(r"^__aeabi_d")


def check_symbols(elf, lib, nm):
    status = 0
    image = set(l.split()[-1] for l in run([nm, elf]).splitlines() if l.split())
    bad = sorted(s for s in image if FORBIDDEN_IMAGE.match(s))
    print(f"{elf}: {len(image)} symbols; heap/stdio/strtod: {', '.join(bad) or 'none'}")
    if bad:
        status = 1
    core = set(l.split()[-1] for l in run([nm, "-u", lib]).splitlines() if l.split())
    core |= set(l.split()[-1] for l in run([nm, lib]).splitlines() if len(l.split()) >= 2)
    bad_core = sorted(s for s in core if FORBIDDEN_CORE.match(s))
    print(f"{lib}: double-precision helpers: {', '.join(bad_core) or 'none'}")
    if bad_core:
        status = 1
    return status


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    cmd, args = argv[1], argv[2:]
    if cmd == "flash":
        members = None
        if len(args) >= 5 and args[3] in ("--except", "--only"):
            members = (args[3][2:], args[4])
        return check_flash(args[0], args[1], int(args[2]), members)
    if cmd == "ram":
        return check_ram(args[0], args[1], int(args[2]), args[3] if len(args) > 3 else "drive")
    if cmd == "stack":
        return check_stack(args[0], args[1], args[2], args[3], int(args[4]))
    if cmd == "symbols":
        return check_symbols(args[0], args[1], args[2])
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
