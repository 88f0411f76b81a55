#!/usr/bin/env python3
"""The figures the docs quote are the build's.

Measures what this build can measure, finds every figure docs/*.md and
README.md state in a form this check reads, and fails, naming file:line,
when a stated figure differs from the measured one, or when a line states a
size it cannot read (say it in one of the forms below, or allow it).

Figures and where they come from:

  drive_ram@T  sizeof(daran_drive_t), default options, on target T
  can_ram@T    sizeof(daran_can_t), default options, on target T
               (T = cortex-m4 or x86-64): `nm -S` of tests/target/sizeof_drive.c,
               the RAM budget's own probe, compiled for T (--probe) or taken
               from the cortex-m4 build (--probe-object)
  core_flash@cortex-m4, can_flash@cortex-m4, bridge_flash@cortex-m4,
  core_flash@cortex-m4-seed
               text + data of libdaran_ascii.a (the core without can*.c, the
               CAN front end, the bridge), as tests/target/check_budgets.py
               measures them for the budget_*_flash tests (--flash-lib)
  core_stack@cortex-m4
               the worst-case stack of any entry point, check_budgets.py's
               measure for budget_core_stack (--stack-objdir)
  conformance_requirements
               the requirements of the conformance suite (the conf_req enum of
               testkit/conformance/conformance.h); always measured. The
               **C1**..**CN** and **CAN1**..**CANM** lists of docs/conformance.md
               must have as many as the enum has before and from REQ_CAN_FIRST.
  transcripts, fuzz_harnesses, broken_hals, broken_fuzz_ports
               the suites' own lists: tests/transcripts/*.txt with an .expected,
               tests/fuzz's _harnesses, tests/conformance's _breaches,
               tests/adopter-fuzz's _broken_* mistakes; always measured

Forms a doc states them in (the number may carry thousands commas):

  "N bytes on a Cortex-M4" / "N bytes on x86-64", after `daran_drive_t`,
      `daran_can_t` in the same paragraph (the nearest before it counts);
  "N bytes (`budget_core_flash`)" and the other budget tests' names within
      the same clause after the number: the figure that test measures, of
      the `cortex-m4-seed` build when the clause names that preset;
  "N requirements" near "conformance"; "N transcripts through the simulator",
      "N libFuzzer harnesses", "N broken HALs", "N broken ports".

Any other "N bytes" (N >= 100) on a line that names `daran_drive_t`,
`daran_can_t`, a budget test, the CAN front end, the core's or the bridge's
flash is reported as a figure the check cannot verify, unless it is a budget
("budget N", "against N", "N bytes (`DARAN_BUDGET_...`)").
docs/performance.md is not read: each of its figures is stamped with the
commit it was measured at.

A figure this build cannot measure (no Cortex-M4 compiler, a host build for
the flash, a build with other options) is listed as skipped, never as
passed; when nothing could be checked the exit status is 77 (CTest: skipped).

Deliberate exceptions (history quoted as such) go in tests/docs/allowed.txt
as `FILE figure TEXT  # why`, TEXT being the matched "N bytes" text.

Usage: check_figures.py [--root DIR] [--probe T=CC,NM[,FLAG...]]
                        [--probe-object T=OBJ,NM] [--build-kind K]
                        [--flash-lib LIB --size SIZE]
                        [--stack-objdir DIR --nm NM --objdump OBJDUMP]
                        [--value KEY=N ...] [DOC...]
       check_figures.py ... --expect-fail DOC --expect TEXT ... [--expect-findings N]
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

from docs_common import (ROOT, AllowList, Findings, arguments, default_docs, expect_fail,
                         line_numbers, read)

BUDGETS = os.path.join(ROOT, "tests", "target", "check_budgets.py")
UNREAD_DOCS = {"docs/performance.md"}

NUMBER = r"(\d{1,3}(?:,\d{3})+|\d+)"
COUNT = r"(?<![\w.,-])" + NUMBER  # a count on its own, not the 14 of clang-14
TYPES = {"daran_drive_t": "drive_ram", "daran_can_t": "can_ram"}
TARGET_FORM = re.compile(NUMBER + r"\s+bytes\s+on\s+(?:a\s+Cortex-M4F?|(x86-64))\b")
TEST_KEYS = {"budget_core_flash": "core_flash", "budget_can_flash": "can_flash",
             "budget_bridge_flash": "bridge_flash", "budget_core_stack": "core_stack",
             "budget_drive_ram": "drive_ram", "budget_can_ram": "can_ram"}
TEST_FORM = re.compile(NUMBER + r"\s+bytes(?P<gap>(?:[^|;\n]|\n(?!\n)){0,80}?)`(budget_(?:core|can|bridge)_flash|"
                       r"budget_(?:drive|can)_ram|budget_core_stack)`")
REQUIREMENTS_FORM = re.compile(COUNT + r"\s+requirements\b")
ANY_BYTES = re.compile(r"(?<![\w.-])" + NUMBER + r"(?:\s|&nbsp;)*bytes\b")
TRIGGER = re.compile(r"daran_drive_t|daran_can_t\b|`budget_\w+`|CAN front end|core flash|"
                     r"\bbridge\b.*\bflash\b", re.I)
BUDGET_BEFORE = re.compile(r"(?:budget|against|<=|≤|limit)\s*(?:of\s*)?$", re.I)
BUDGET_AFTER = re.compile(r"^\s*(?:\(`?DARAN_BUDGET_|budget\b)")


def number(text):
    return int(text.replace(",", ""))


def run(cmd):
    return subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True).stdout


# ---- what the build measures ----

def sizes_from_object(obj, nm):
    out = run([nm, "-S", obj])
    found = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[3].startswith("daran_target_sizeof_"):
            found[parts[3][len("daran_target_sizeof_"):] + "_ram"] = int(parts[1], 16)
    return found


def probe_sizes(root, cc, nm, flags):
    """The RAM probe compiled for a target, default options (no options header)."""
    with tempfile.TemporaryDirectory() as tmp:
        obj = os.path.join(tmp, "sizeof_drive.o")
        run([cc, "-std=c11", "-c", "-o", obj, "-I" + os.path.join(root, "include")] + flags
            + [os.path.join(root, "tests", "target", "sizeof_drive.c")])
        return sizes_from_object(obj, nm)


def flash_figures(lib, size, python):
    figures = {}
    for key, members in (("core_flash", ["--except", "^(can|hal_can)"]),
                         ("can_flash", ["--only", r"^(can(|_address|_codec|_ring)|hal_can)\.c"]),
                         ("bridge_flash", ["--only", r"^can_(bridge|encode)\.c"])):
        out = run([python, BUDGETS, "flash", lib, size, str(1 << 30)] + members)
        m = re.search(r"flash \(text \+ data\)[^:]*: (\d+) bytes", out)
        if not m:
            raise SystemExit("check_budgets.py flash printed no figure:\n" + out)
        figures[key] = int(m.group(1))
    return figures


def stack_figure(objdir, lib, nm, objdump, python):
    out = run([python, BUDGETS, "stack", objdir, lib, nm, objdump, str(1 << 30)])
    costs = [int(m.group(1)) for m in re.finditer(r"^daran_\w+\s+(\d+)\s*$", out, re.M)]
    if not costs:
        raise SystemExit("check_budgets.py stack printed no figure:\n" + out)
    return max(costs)


def count_in(root, rel, pattern, within=None):
    """How many times @p pattern occurs in a file of the tree (in the part
    @p within matches, when given)."""
    text = read(os.path.join(root, rel))
    if within:
        text = re.search(within, text, re.S).group(0)
    return len(re.findall(pattern, text, re.M))


def fuzz_harnesses(root):
    """tests/fuzz's harnesses: its _harnesses list and what is appended to it."""
    text = read(os.path.join(root, "tests", "fuzz", "CMakeLists.txt"))
    names = re.search(r"set\(_harnesses ([^)]*)\)", text).group(1).split()
    return names + re.findall(r"list\(APPEND _harnesses (\w+)\)", text)


# Counts of the test suites that the docs quote: (key, form, how it is counted).
SOURCE_COUNTS = (
    ("transcripts", re.compile(COUNT + r"\s+transcripts\s+through\s+the\s+simulator"),
     lambda root: len([t for t in glob.glob(os.path.join(root, "tests", "transcripts", "*.txt"))
                       if os.path.exists(t[:-4] + ".expected")])),
    ("fuzz_harnesses", re.compile(COUNT + r"\s+libFuzzer\s+harnesses"),
     lambda root: len(fuzz_harnesses(root))),
    ("broken_hals", re.compile(COUNT + r"\s+broken\s+HALs"),
     lambda root: count_in(root, "tests/conformance/CMakeLists.txt", r'^\s*"\d+\|',
                           r"set\(_breaches.*?\)\n")),
    ("broken_fuzz_ports", re.compile(COUNT + r"\s+broken\s+ports"),
     lambda root: count_in(root, "tests/adopter-fuzz/CMakeLists.txt", r"^set\(_broken_[\w-]+\b")),
)


def conformance_groups(root):
    """(line requirements, CAN requirements) of the conf_req enum: the CAN
    ones start at REQ_CAN_FIRST's value and are numbered CAN1.. apart."""
    text = read(os.path.join(root, "testkit", "conformance", "conformance.h"))
    body = re.search(r"typedef enum conf_req \{(.*?)REQ_COUNT", text, re.S).group(1)
    names = re.findall(r"\b(REQ_\w+)\s*,", body)
    first = re.search(r"#define REQ_CAN_FIRST (REQ_\w+)", text)
    split = names.index(first.group(1)) if first else len(names)
    return split, len(names) - split


class Measures:
    def __init__(self):
        self.values, self.why_not = {}, {}

    def missing(self, key):
        target = key.split("@")[1] if "@" in key else ""
        if target == "x86-64":
            return "no x86-64 probe in this build (--probe x86-64=...)"
        if "flash" in key or "stack" in key:
            return "measured only in the %s preset's build (its library)" % target
        return self.why_not.get(target, "no %s probe in this build" % target)


# ---- what the docs state ----

class Claim:
    def __init__(self, doc, line, key, stated, text):
        self.doc, self.line, self.key, self.stated, self.text = doc, line, key, stated, text


def paragraph_start(text, pos):
    start = text.rfind("\n\n", 0, pos)
    return 0 if start < 0 else start + 2


def clause_bounds(text, pos, end_pos):
    """The clause around a figure: up to a `;`, a table cell's `|` or a blank line."""
    start = max(text.rfind(c, 0, pos) for c in (";", "|", "\n\n"))
    ends = [i for i in (text.find(c, end_pos) for c in (";", "|", "\n\n")) if i >= 0]
    return start + 1, (min(ends) if ends else len(text))


def find_claims(doc, text):
    claims, spans, problems = [], [], []
    line_of = line_numbers(text)

    for m in TARGET_FORM.finditer(text):
        p_start = paragraph_start(text, m.start())
        before = text[max(p_start, m.start() - 300):m.start()]
        named = [(b.end(), TYPES[b.group(0)]) for b in re.finditer(r"daran_drive_t|daran_can_t\b", before)]
        spans.append((m.start(), m.end()))
        if not named:
            problems.append((line_of(m.start()), m.group(0),
                             "a size on a target with no `daran_drive_t` or `daran_can_t` before it "
                             "in its paragraph: the check cannot tell what it measures"))
            continue
        target = "x86-64" if m.group(2) else "cortex-m4"
        claims.append(Claim(doc, line_of(m.start()), "%s@%s" % (named[-1][1], target),
                            number(m.group(1)), m.group(0)))
    for m in TEST_FORM.finditer(text):
        if any(s <= m.start() < e for s, e in spans):
            continue  # "N bytes on a Cortex-M4 (`budget_drive_ram`)": read once
        c_start, c_end = clause_bounds(text, m.start(), m.end())
        target = "cortex-m4-seed" if "cortex-m4-seed" in text[c_start:c_end] else "cortex-m4"
        spans.append((m.start(), m.end()))
        claims.append(Claim(doc, line_of(m.start()), "%s@%s" % (TEST_KEYS[m.group(3)], target),
                            number(m.group(1)), m.group(1) + " bytes"))
    for key, form, _ in SOURCE_COUNTS:
        for m in form.finditer(text):
            claims.append(Claim(doc, line_of(m.start()), key, number(m.group(1)), m.group(0)))
    for m in REQUIREMENTS_FORM.finditer(text):
        if "conformance" in text[max(0, m.start() - 200):m.end() + 200].lower():
            spans.append((m.start(), m.end()))
            claims.append(Claim(doc, line_of(m.start()), "conformance_requirements",
                                number(m.group(1)), m.group(0)))
    # a size on a figure's line that none of the forms above reads
    offset = 0
    for line in text.split("\n"):
        if TRIGGER.search(line):
            for m in ANY_BYTES.finditer(line):
                pos = offset + m.start()
                if number(m.group(1)) < 100 or any(s <= pos < e for s, e in spans):
                    continue
                if BUDGET_BEFORE.search(line[:m.start()]) or BUDGET_AFTER.match(line[m.end():]):
                    continue
                problems.append((line_of(pos), m.group(0),
                                 "a size the check cannot verify: state it as \"N bytes on a "
                                 "Cortex-M4\" after the type, or \"N bytes (`budget_...`)\" "
                                 "(tests/docs/check_figures.py)"))
        offset += len(line) + 1
    return claims, problems


def conformance_list(root, doc_path):
    """The numbers of the **Cn** bullets under docs/conformance.md's "The requirements"."""
    text = read(doc_path)
    m = re.search(r"^## The requirements\n(.*?)(?=^## )", text, re.S | re.M)
    section = m.group(1) if m else ""
    return ([int(n) for n in re.findall(r"^- \*\*C(\d+)\*\*", section, re.M)],
            [int(n) for n in re.findall(r"^- \*\*CAN(\d+)\*\*", section, re.M)])


# ---- the check ----

def check(root, docs, measures, allow):
    findings, checked, skipped = Findings(allow), [], []
    for path in docs:
        doc = os.path.relpath(path, root)
        if doc in UNREAD_DOCS:
            continue
        claims, problems = find_claims(doc, read(path))
        for line, text, why in problems:
            findings.add(doc, line, "figure", text, why)
        for c in claims:
            real = measures.values.get(c.key)
            where = "%s:%d" % (c.doc, c.line)
            if real is None:
                skipped.append("%s %s (%d): %s" % (where, c.key, c.stated, measures.missing(c.key)))
            elif real != c.stated:
                findings.add(c.doc, c.line, "figure", c.text,
                             "the build measures %s = %d" % (c.key, real))
            else:
                checked.append("%s %s = %d" % (where, c.key, real))
        if doc == "docs/conformance.md":
            for prefix, listed, count in zip(("C", "CAN"), conformance_list(root, path),
                                             conformance_groups(root)):
                want = list(range(1, count + 1))
                if listed != want:
                    stated = "%s1..%s%d" % (prefix, prefix, listed[-1] if listed else 0)
                    findings.add(doc, 1, "figure", stated,
                                 "the requirements listed are %s, the suite has %s1..%s%d"
                                 % (listed and "%s%d..%s%d (%d bullets)" % (prefix, listed[0], prefix,
                                                                           listed[-1], len(listed)),
                                    prefix, prefix, count))
                else:
                    checked.append("%s the list %s1..%s%d = conformance requirements"
                                   % (doc, prefix, prefix, count))
    return findings, checked, skipped


def measure(args, root):
    m = Measures()
    m.values["conformance_requirements"] = sum(conformance_groups(root))
    for key, _, count in SOURCE_COUNTS:
        m.values[key] = count(root)
    kind = args.build_kind
    for spec in args.probe:
        target, _, rest = spec.partition("=")
        cc, nm, *flags = rest.split(",")
        try:
            sizes = probe_sizes(root, cc, nm, flags)
        except (OSError, subprocess.CalledProcessError) as e:
            m.why_not[target] = "the %s probe could not be built: %s" % (target, e)
            continue
        for name, value in sizes.items():
            m.values["%s@%s" % (name, target)] = value
    for spec in args.probe_object:
        target, _, rest = spec.partition("=")
        obj, nm = rest.split(",")
        if kind != "default":
            m.why_not[target] = "this %s build does not have the default options" % target
            continue
        for name, value in sizes_from_object(obj, nm).items():
            m.values["%s@%s" % (name, target)] = value
    if args.flash_lib:
        target = {"default": "cortex-m4", "seed": "cortex-m4-seed"}.get(kind)
        if target:
            for name, value in flash_figures(args.flash_lib, args.size, sys.executable).items():
                m.values["%s@%s" % (name, target)] = value
            if args.stack_objdir:
                m.values["core_stack@" + target] = stack_figure(
                    args.stack_objdir, args.flash_lib, args.nm, args.objdump, sys.executable)
    for spec in args.value:
        key, _, value = spec.partition("=")
        m.values[key] = int(value)
    return m


def main():
    ap = arguments(__doc__)
    ap.add_argument("--probe", action="append", default=[], metavar="T=CC,NM[,FLAG...]")
    ap.add_argument("--probe-object", action="append", default=[], metavar="T=OBJ,NM")
    ap.add_argument("--build-kind", default="default", choices=("default", "seed", "other"),
                    help="the options of the build whose library and probe object are given")
    ap.add_argument("--flash-lib")
    ap.add_argument("--size")
    ap.add_argument("--stack-objdir")
    ap.add_argument("--nm")
    ap.add_argument("--objdump")
    ap.add_argument("--value", action="append", default=[], metavar="KEY=N",
                    help="a measured figure given (the self-test)")
    args = ap.parse_args()
    root = os.path.abspath(args.root)
    measures = measure(args, root)
    if args.expect_fail:
        findings, _, _ = check(root, [os.path.abspath(args.expect_fail)], measures, AllowList())
        return expect_fail(args, findings)

    docs = [os.path.abspath(d) for d in args.docs] or default_docs(root)
    allow = AllowList(args.allow)
    findings, checked, skipped = check(root, docs, measures, allow)
    unused = allow.unused(("figure",), docs, root)
    print("measured: " + ", ".join("%s = %d" % kv for kv in sorted(measures.values.items())))
    for line in checked:
        print("checked: " + line)
    for line in skipped:
        print("SKIPPED (not verified here): " + line)
    if findings or unused:
        print("\n".join([str(f) for f in findings] + unused))
        print("the docs state figures the build does not have: fix the doc (or, for history "
              "quoted as such, add it with its reason to %s)" % os.path.relpath(args.allow, root))
        return 1
    if not checked:
        print("nothing could be checked in this build")
        return 77
    print("ok: %d figures checked, %d skipped" % (len(checked), len(skipped)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
