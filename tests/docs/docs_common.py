"""What the three docs checks (check_docs.py, check_figures.py,
check_snippets.py) share: the docs they read, a finding and its form
`DOC:LINE: RULE `TEXT`: WHY`, the allow-list tests/docs/allowed.txt, the
command line and its self-test (--expect-fail).
"""
import argparse
import bisect
import glob
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def default_docs(root, changelog=False):
    """docs/*.md and README.md (and CHANGELOG.md), the docs a check reads
    when it is given none."""
    docs = sorted(glob.glob(os.path.join(root, "docs", "*.md"))) + [os.path.join(root, "README.md")]
    return docs + [os.path.join(root, "CHANGELOG.md")] if changelog else docs


def line_numbers(text):
    """A function from an offset in @p text to its 1-based line number."""
    starts = [0] + [m.end() for m in re.finditer("\n", text)]
    return lambda offset: bisect.bisect_right(starts, offset)


def lines_with_code_flag(text):
    """(line, inside a fenced code block?) of each line; a fence line counts as code."""
    fence = None
    for line in text.split("\n"):
        m = re.match(r"\s*(```+|~~~+)", line)
        if m:
            if fence is None:
                fence = m.group(1)[:3]
                yield line, True
                continue
            if m.group(1).startswith(fence):
                fence = None
                yield line, True
                continue
        yield line, fence is not None


class Finding:
    def __init__(self, doc, line, rule, text, why):
        self.doc, self.line, self.rule, self.text, self.why = doc, line, rule, text, why

    def __str__(self):
        return "%s:%d: %s `%s`: %s" % (self.doc, self.line, self.rule, self.text, self.why)


class AllowList:
    """tests/docs/allowed.txt: the deliberate exceptions of all three checks,
    `FILE RULE TEXT  # reason` a line; each check owns its RULEs."""

    def __init__(self, path=None):
        self.path = path
        self.entries = []  # [doc, rule, text, reason, used]
        if not path or not os.path.exists(path):
            return
        for n, line in enumerate(read(path).splitlines(), 1):
            if line.lstrip().startswith("#"):
                continue
            parts = re.split(r"\s#\s", line + " ", maxsplit=1)
            body, reason = parts[0].strip(), (parts[1] if len(parts) > 1 else "")
            if not body:
                continue
            parts = body.split(None, 2)
            if len(parts) != 3 or not reason.strip():
                sys.exit("%s:%d: want `FILE RULE TEXT  # reason`" % (path, n))
            self.entries.append([parts[0], parts[1], parts[2], reason.strip(), False])

    def allows(self, doc, rule, text):
        """Whether an entry excepts this finding (the entry is then in use)."""
        for entry in self.entries:
            if entry[:3] == [doc, rule, text]:
                entry[4] = True
                return True
        return False

    def unused(self, rules, docs, root):
        """An entry of @p rules for a doc among @p docs that excepted nothing:
        it is reported, so that it is removed."""
        checked = {os.path.relpath(d, root) for d in docs}
        return ["%s: allow-list entry `%s %s %s` matches nothing any more; remove it"
                % (self.path, e[0], e[1], e[2])
                for e in self.entries if not e[4] and e[1] in rules and e[0] in checked]


class Findings(list):
    """The findings of a check, less those the allow-list excepts."""

    def __init__(self, allow):
        super().__init__()
        self.allow = allow

    def add(self, doc, line, rule, text, why):
        if not self.allow.allows(doc, rule, text):
            self.append(Finding(doc, line, rule, text, why))


def arguments(doc):
    """The command line all three checks have; a check adds its own options."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--allow", default=os.path.join(HERE, "allowed.txt"))
    ap.add_argument("--expect-fail", metavar="DOC")
    ap.add_argument("--expect", action="append", default=[], metavar="TEXT")
    ap.add_argument("--expect-findings", type=int, metavar="N")
    ap.add_argument("docs", nargs="*")
    return ap


def expect_fail(args, findings):
    """The self-test: passes only if the check found something on the
    --expect-fail doc, its report names every --expect TEXT and, when
    --expect-findings N is given, it made exactly N findings."""
    report = "\n".join(str(f) for f in findings)
    print(report)
    if args.expect_findings is not None and len(findings) != args.expect_findings:
        print("FAIL: %d findings, want %d (a line that has not drifted was reported?)"
              % (len(findings), args.expect_findings))
        return 1
    if not findings:
        print("FAIL: the check passed on %s, which has drifted" % args.expect_fail)
        return 1
    missing = [t for t in args.expect if t not in report]
    if missing:
        print("FAIL: the report does not name: %s" % ", ".join(missing))
        return 1
    print("ok: the check fails on %s and its report names all %d expected texts"
          % (args.expect_fail, len(args.expect)))
    return 0

