#!/usr/bin/env python3
"""The docs' C snippets keep the results the headers say must be kept, and
their complete examples compile.

Every ```c block of docs/*.md and README.md:

  result   a call, as a statement of its own, of a function the headers mark
           DARAN_NODISCARD (warn_unused_result) or of a macro that expands to
           one (daran_init): a program written from the snippet fails to build
           under -Werror. A `(void)` cast does not help: gcc still warns.

A block whose fence is preceded by the line

    <!-- compiled: a complete example (tests/docs/check_snippets.py) -->

is a complete example: it is compiled on its own as a C11 translation unit
with the project's public headers and the default options, `-Wall -Werror`
(warn_unused_result included), after tests/docs/snippet_prelude.h, which
declares the adopter's own functions the examples call (my_hal, my_millis...).

Deliberate exceptions go in tests/docs/allowed.txt (`FILE result NAME  # why`).

Usage: check_snippets.py [--root DIR] [--cc CC] [DOC...]
       check_snippets.py --expect-fail DOC --expect TEXT ... [--expect-findings N]
Without --cc the complete examples are reported as not compiled (the lint
still runs); with it, a compiler that cannot run at all is an error.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

from docs_common import (HERE, AllowList, Findings, arguments, default_docs, expect_fail,
                         lines_with_code_flag, read)

MARKER = "<!-- compiled: a complete example (tests/docs/check_snippets.py) -->"
# The public headers an example may include: the core, the test kit, the
# simulated drive, the minimal port (the client is in include/).
HEADER_DIRS = ("include", "testkit/include", "port/sim/lib", "port/minimal")
NODISCARD_RE = re.compile(r"DARAN_NODISCARD\s+[\w\s\*]*?\b(daran_\w+)\s*\(")
MACRO_RE = re.compile(r"#define\s+(daran_\w+)\s*\([^)]*\)\s*(?:\\\s*)*\(?\s*(daran_\w+)\s*\(")
# a call that begins a statement: after ; { } or at the block's start (one after
# an if or loop head is left to the compile of the complete examples)
STATEMENT_CALL_RE = re.compile(r"(?:\A|(?<=[;{}]))\s*(\(void\)\s*)?(daran_\w+)\s*\(")


def nodiscard_names(root):
    names, macros = set(), {}
    for d in HEADER_DIRS:
        for path in glob.glob(os.path.join(root, d, "*.h")):
            text = read(path)
            names |= set(NODISCARD_RE.findall(text))
            for macro, target in MACRO_RE.findall(text):
                macros[macro] = target
    names |= {m for m, t in macros.items() if t in names}
    return names


def strip_comments(code):
    code = re.sub(r"/\*.*?\*/", lambda m: " " * len(m.group(0)), code, flags=re.S)
    code = re.sub(r"//[^\n]*", "", code)
    return re.sub(r'"(?:[^"\\\n]|\\.)*"', '""', code)


def c_blocks(text):
    """(first line number, code, compiled?) of each ```c block."""
    out, block, start, previous, compiled = [], None, 0, "", False
    for n, (line, code) in enumerate(lines_with_code_flag(text), 1):
        if block is None:
            if code and re.match(r"\s*```+\s*c\s*$", line):
                block, start, compiled = [], n + 1, previous.strip() == MARKER
            previous = line
        elif code and re.match(r"\s*```", line):
            out.append((start, "\n".join(block), compiled))
            block = None
        else:
            block.append(line)
    return out


class Snippets:
    def __init__(self, root, allow, cc):
        self.root, self.cc = root, cc
        self.nodiscard = nodiscard_names(root)
        self.findings, self.compiled, self.not_compiled = Findings(allow), 0, []

    def lint(self, doc, start, code):
        bare = strip_comments(code)
        for m in STATEMENT_CALL_RE.finditer(bare):
            if m.group(2) in self.nodiscard:
                line = start + bare.count("\n", 0, m.start(2))
                why = ("its result is marked warn_unused_result: test it (a `(void)` cast does not "
                       "silence gcc)" if m.group(1) else
                       "its result is marked warn_unused_result: test it, or the example fails "
                       "to build under -Werror")
                self.findings.add(doc, line, "result", m.group(2), why)

    def compile(self, doc, start, code):
        if not self.cc:
            self.not_compiled.append("%s:%d" % (doc, start))
            return
        with tempfile.TemporaryDirectory() as tmp:
            src = os.path.join(tmp, "snippet.c")
            with open(src, "w", encoding="utf-8") as f:
                f.write('#line %d "%s"\n%s\n' % (start, doc, code))
            cmd = [self.cc, "-std=c11", "-Wall", "-Werror", "-c", "-o", os.path.join(tmp, "s.o"),
                   "-include", os.path.join(HERE, "snippet_prelude.h")]
            cmd += ["-I" + os.path.join(self.root, d) for d in HEADER_DIRS]
            result = subprocess.run(cmd + [src], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                    text=True)
        self.compiled += 1
        if result.returncode != 0:
            first = next((l for l in result.stdout.splitlines() if "error" in l), "")
            self.findings.add(doc, start, "compile", first.split(": error: ")[-1] or "fails",
                              "the complete example does not compile with %s -Wall -Werror:\n%s"
                              % (os.path.basename(self.cc), result.stdout.rstrip()))

    def check(self, doc, text):
        for start, code, compiled in c_blocks(text):
            self.lint(doc, start, code)
            if compiled:
                self.compile(doc, start, code)


def run(root, docs, allow, cc):
    checker = Snippets(root, allow, cc)
    for path in docs:
        checker.check(os.path.relpath(path, root), read(path))
    return checker


def main():
    ap = arguments(__doc__)
    ap.add_argument("--cc", help="the C compiler for the complete examples")
    args = ap.parse_args()
    root = os.path.abspath(args.root)
    if args.expect_fail:
        checker = run(root, [os.path.abspath(args.expect_fail)], AllowList(), args.cc)
        return expect_fail(args, checker.findings)

    docs = [os.path.abspath(d) for d in args.docs] or default_docs(root)
    allow = AllowList(args.allow)
    checker = run(root, docs, allow, args.cc)
    unused = allow.unused(("result", "compile"), docs, root)
    if checker.findings or unused:
        print("\n".join([str(f) for f in checker.findings] + unused))
        print("the docs' C snippets would not build under -Werror: fix the snippet (or, for a "
              "deliberate exception, add it with its reason to %s)" % os.path.relpath(args.allow, root))
        return 1
    if checker.not_compiled:
        print("not compiled (no --cc): " + ", ".join(checker.not_compiled))
    if checker.compiled == 0:
        print("no complete example compiled: the lint passed, the compile was skipped")
        return 77
    print("ok: the docs' C snippets keep every result marked warn_unused_result (%d names), and "
          "%d complete examples compile with %s -Wall -Werror"
          % (len(checker.nodiscard), checker.compiled, os.path.basename(args.cc)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
