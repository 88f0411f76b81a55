#!/usr/bin/env python3
"""The docs name only what exists.

Reads docs/*.md, README.md and the latest section of CHANGELOG.md (older
sections describe history) and fails, listing file:line, when a doc names

  path    a repository path in backticks or in a code block (`src/foo.c`,
          `tools/replay`, `docs/x.md`) or a relative link ([x](porting.md),
          [y](../examples/adopter/)) that is not in the tree, or a link to a
          #heading that the target page does not have;
  option  a `-DDARAN_X` / `DARAN_X=...` CMake option not defined in a
          CMakeLists.txt, a *.cmake file, CMakePresets.json or include/*.h;
  name    any other DARAN_X or daran_x name (macro, function, type, CMake
          function, environment variable) found nowhere in the sources
          (DARAN_PROP_<ID> counts for each row of DARAN_PROPERTY_LIST);
  preset  a `--preset NAME`, a "`NAME` preset" or "presets `A`, `B`" that
          CMakePresets.json does not define;
  count   a count of the property table ("165 properties", "all 165",
          "165 rows", "the 159 property paths") that is neither the rows of
          DARAN_PROPERTY_LIST in include/daran_properties.h nor, said of the
          vendor, the paths of tests/vendor/properties.csv;
  machine a machine-specific absolute path (/work/..., /root/..., /home/...).

What is not checked, to keep false alarms away: build outputs (`build/...`,
*.elf, *.a ...), install-prefix paths (`<prefix>/...`, `/opt/...`, `lib/...`,
`share/...`), paths outside the tree (`shared/recordings/`), names relative
to another folder (`sim_model.c`), scratch files under /tmp. A placeholder
(`<area>`, `*`, `{a,b}`, an upper-case word such as NAME or DIR) must still
match at least one file.

Deliberate exceptions go in tests/docs/allowed.txt, one per line:
    FILE RULE TEXT  # reason
(an entry that no longer matches anything is itself reported).

Usage: check_docs.py [--root DIR] [--allow FILE] [DOC...]
       check_docs.py --expect-fail DOC --expect TEXT [--expect TEXT ...]
                     [--expect-findings N]
         (self-test: passes only if checking DOC fails, the report names
          every TEXT and, if given, makes exactly N findings)
"""
import csv
import glob
import json
import os
import re
import sys

from docs_common import (AllowList, Finding, arguments, default_docs, expect_fail,
                         line_numbers, lines_with_code_flag, read)

BUILD_OUTPUT_EXT = (".elf", ".o", ".obj", ".a", ".so", ".bin", ".hex", ".map", ".exe",
                    ".gcda", ".gcno", ".profraw")
REAL_UPPER = {"README", "LICENSE", "CHANGELOG", "CMAKELISTS", "NOTICE", "CONTRIBUTING"}
MACHINE_RE = re.compile(r"(?<![\w.~$}-])/(?:work|root|home|Users|mnt|srv|scratch)/[^\s`)\]\"']*")
NAME_RE = re.compile(r"(?:(?<=-D)|(?<![\w]))DARAN_[A-Z0-9_]+")
SYMBOL_RE = re.compile(r"(?<![\w])daran_[a-z0-9_]+")
OPTION_USE_RE = re.compile(r"-D(DARAN_[A-Z0-9_]+)|\b(DARAN_[A-Z0-9_]+)=(?!=)")
PRESET_RE = re.compile(r"--preset[= ]+([A-Za-z0-9_.-]+)")
PRESET_WORD_RE = re.compile(r"`([A-Za-z0-9_.-]+)`\s+(?:(?:configure|build|test|workflow)\s+)?presets?\b")
PRESET_LIST_RE = re.compile(r"\bpresets?\s+((?:`[A-Za-z0-9_.-]+`(?:,\s*|\s+and\s+|\s+or\s+)?)+)")
COUNT_RES = [
    # "165 properties", "159 property paths", "165 rows", "159 paths", "165 of 165 rows"
    re.compile(r"\b(\d{3})(?:\s+of\s+\d{3})?\s+(?:[A-Za-z'-]+\s+){0,2}?(?:propert(?:y|ies)|rows|paths)\b"),
    # "all 165", "all the 165"
    re.compile(r"\ball\s+(?:the\s+)?(\d{3})\b"),
]
COUNT_CONTEXT = 160  # characters each side of a count that must mention "propert"
RULES = ("path", "option", "name", "preset", "count", "machine")


def tree_files(root):
    """Every file of the tree, build folders and .git left out."""
    for dirpath, dirnames, filenames in os.walk(root):
        rel = os.path.relpath(dirpath, root)
        if rel == ".":
            dirnames[:] = [d for d in dirnames if d != ".git" and not d.startswith("build")]
        else:
            dirnames[:] = [d for d in dirnames if d != ".git"]
        for name in filenames:
            yield os.path.join(dirpath, name)


class Tree:
    def __init__(self, root):
        self.root = root
        self.top = {n for n in os.listdir(root) if n != ".git" and not n.startswith("build")}
        # every DARAN_ name the sources use (docs and changelog are what is checked, not a source)
        self.names = set()
        # names that can be options: the build files and the public headers
        self.option_names = set()
        docs_dir = os.path.join(root, "docs")
        for path in tree_files(root):
            rel = os.path.relpath(path, root)
            base = os.path.basename(path)
            if path.startswith(docs_dir + os.sep) or rel in ("README.md", "CHANGELOG.md"):
                continue
            if rel.startswith(os.path.join("tests", "docs") + os.sep):
                continue  # the fixtures name what does not exist on purpose
            try:
                if os.path.getsize(path) > 2_000_000:
                    continue
                text = read(path)
            except OSError:
                continue
            found = set(NAME_RE.findall(text))
            self.names |= found | set(SYMBOL_RE.findall(text))
            if (base == "CMakeLists.txt" or base.endswith(".cmake") or base.endswith(".cmake.in")
                    or rel == "CMakePresets.json"
                    or (rel.startswith("include" + os.sep) and base.endswith(".h"))):
                self.option_names |= found
        props = read(os.path.join(root, "include", "daran_properties.h"))
        start = props.index("#define DARAN_PROPERTY_LIST(X)")
        body = props[start:props.index("\n\n", start)]
        self.prop_ids = re.findall(r"X\(\s*(\w+)\s*,\s*\"", body)
        self.rows = len(self.prop_ids)
        self.names |= {"DARAN_PROP_" + i for i in self.prop_ids}
        with open(os.path.join(root, "tests", "vendor", "properties.csv"), encoding="utf-8") as f:
            vendor = list(csv.reader(l for l in f if not l.startswith("#")))[1:]
        self.vendor_rows = len([r for r in vendor if r])
        presets = json.loads(read(os.path.join(root, "CMakePresets.json")))
        self.presets = {p["name"] for key, value in presets.items() if key.endswith("Presets")
                        for p in value}

    def exists_pattern(self, rel):
        """rel names a file of the tree, or (with placeholders) matches one."""
        if os.path.exists(os.path.join(self.root, rel)):
            return True
        pats = expand_braces(rel)
        for pat in pats:
            pat = re.sub(r"<[^>]*>", "*", pat)
            parts = []
            for part in pat.split("/"):
                stem = part.split(".")[0]
                if (re.fullmatch(r"[A-Z][A-Z0-9_]*", stem) and stem not in REAL_UPPER
                        and not os.path.exists(os.path.join(self.root, *parts, part))):
                    part = "*" + part[len(stem):]
                parts.append(part)
            pat = "/".join(parts)
            if os.path.exists(os.path.join(self.root, pat)) or glob.glob(os.path.join(self.root, pat)):
                return True
        return False


def expand_braces(s):
    m = re.search(r"\{([^{}]*)\}", s)
    if not m:
        return [s]
    out = []
    for alt in m.group(1).split(","):
        out += expand_braces(s[:m.start()] + alt + s[m.end():])
    return out


def slug(heading):
    """GitHub's anchor for a heading."""
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(text):
    seen, out = {}, set()
    for line, code in lines_with_code_flag(text):
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m and not code:
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            out.add(s if n == 0 else "%s-%d" % (s, n))
    return out


def changelog_latest(text):
    """The changelog up to the end of its first (latest) ## section; older lines blanked."""
    lines = text.split("\n")
    seen = 0
    for i, line in enumerate(lines):
        if line.startswith("## "):
            seen += 1
            if seen == 2:
                return "\n".join(lines[:i] + [""] * (len(lines) - i))
    return text


def path_tokens(code):
    """The tokens of a code span or code line that may be repository paths."""
    for tok in re.findall(r"(?:<[^<>\s]*>|\{[^{}\s]*\}|[^\s=,;()\"'|<>])+", code):
        tok = tok.strip().rstrip(".:;,")
        tok = re.sub(r":\d+(?::\d+)?$", "", tok)  # file:line
        if tok.startswith("./"):
            tok = tok[2:]
        if tok:
            yield tok


class Checker:
    def __init__(self, tree, allow):
        self.tree = tree
        self.allow = allow
        self.findings = []
        self.anchor_cache = {}
        self.seen = {"paths": 0, "links": 0, "names": 0, "presets": 0, "counts": 0}

    def report(self, doc, line, rule, text, why):
        if self.allow.allows(doc, rule, text):
            return
        # a line's finding once (a count: once whichever form states the number)
        if not any(f.doc == doc and f.line == line and f.rule == rule and
                   (f.text == text or rule == "count" and re.findall(r"\d{3}", f.text) == re.findall(r"\d{3}", text))
                   for f in self.findings):
            self.findings.append(Finding(doc, line, rule, text, why))

    def check_path(self, doc, n, tok):
        first = tok.split("/")[0]
        if "/" not in tok or first not in self.tree.top or first.startswith("build"):
            return
        if tok.endswith(BUILD_OUTPUT_EXT) or "..." in tok or "…" in tok:
            return
        self.seen["paths"] += 1
        if not self.tree.exists_pattern(tok.rstrip("/")):
            self.report(doc, n, "path", tok, "no such file or folder in the tree")

    def page_anchors(self, path):
        if path not in self.anchor_cache:
            self.anchor_cache[path] = anchors(read(path))
        return self.anchor_cache[path]

    def check_link(self, doc, doc_path, n, target):
        target = (target.split() or [""])[0]  # a link's "title" left out
        if not target or re.match(r"[a-z][a-z0-9+.-]*:", target, re.I):
            return  # https:, mailto:
        self.seen["links"] += 1
        path, _, anchor = target.partition("#")
        base = os.path.dirname(doc_path)
        full = os.path.normpath(os.path.join(base, path)) if path else doc_path
        if path and not os.path.exists(full):
            self.report(doc, n, "path", target, "the link's target is not in the tree")
            return
        if anchor and full.endswith(".md") and os.path.isfile(full):
            if anchor.lower() not in self.page_anchors(full):
                self.report(doc, n, "path", target, "the page has no heading with that anchor")

    def check_counts(self, doc, text, line_of):
        for rx in COUNT_RES:
            for m in rx.finditer(text):
                value = int(m.group(1))
                if value < 100:
                    continue
                lo, hi = max(0, m.start() - COUNT_CONTEXT), m.end() + COUNT_CONTEXT
                around = text[lo:hi].lower()
                if "propert" not in around:
                    continue
                self.seen["counts"] += 1
                if value == self.tree.rows:
                    continue
                if value == self.tree.vendor_rows and "vendor" in around:
                    continue
                phrase = " ".join(m.group(0).split())
                self.report(doc, line_of(m.start()), "count", phrase,
                            "the property table has %d rows (DARAN_PROPERTY_LIST), the vendor's "
                            "paths are %d" % (self.tree.rows, self.tree.vendor_rows))

    def check_doc(self, doc, doc_path, text):
        prose_lines = []
        for n, (line, code) in enumerate(lines_with_code_flag(text), 1):
            if code:
                for tok in path_tokens(line):
                    self.check_path(doc, n, tok)
                prose_lines.append("")
            else:
                spans = re.findall(r"`+([^`]+)`+", line)
                for span in spans:
                    for tok in path_tokens(span):
                        self.check_path(doc, n, tok)
                prose = re.sub(r"`+[^`]+`+", "", line)
                for m in re.finditer(r"\]\(([^)\s]*(?:\s+\"[^\"]*\")?)\)", prose):
                    self.check_link(doc, doc_path, n, m.group(1))
                m = re.match(r"\s*\[[^\]]+\]:\s+(\S+)", prose)
                if m:
                    self.check_link(doc, doc_path, n, m.group(1))
                prose_lines.append(line)
            for m in MACHINE_RE.finditer(line):
                self.report(doc, n, "machine", m.group(0),
                            "a path of one machine; say where it is relative to the project")
            options = set()
            for m in OPTION_USE_RE.finditer(line):
                name = m.group(1) or m.group(2)
                options.add(name)
                if name not in self.tree.option_names:
                    self.report(doc, n, "option", name, "no CMakeLists.txt, *.cmake, "
                                "CMakePresets.json or include/*.h defines this option")
            for name in NAME_RE.findall(line) + SYMBOL_RE.findall(line):
                self.seen["names"] += 1
                if name.endswith("_"):
                    if not any(x.startswith(name) for x in self.tree.names):
                        self.report(doc, n, "name", name + "*", "no name of the sources starts so")
                elif name not in self.tree.names and name not in options:
                    self.report(doc, n, "name", name, "no source of the tree names it")
            named = [m.group(1) for m in PRESET_RE.finditer(line)]
            named += [m.group(1) for m in PRESET_WORD_RE.finditer(line)]
            for m in PRESET_LIST_RE.finditer(line):
                named += re.findall(r"`([^`]+)`", m.group(1))
            for name in named:
                self.seen["presets"] += 1
                if name not in self.tree.presets and not name.isupper():
                    self.report(doc, n, "preset", name, "CMakePresets.json has no such preset")
        prose = "\n".join(prose_lines)
        self.check_counts(doc, prose, line_numbers(prose))


def run(root, docs, allow):
    """The findings on @p docs, then the allow-list's entries of these rules
    that excepted nothing (the other rules are check_figures.py's and
    check_snippets.py's)."""
    tree = Tree(root)
    checker = Checker(tree, allow)
    for doc_path in docs:
        text = read(doc_path)
        if os.path.basename(doc_path) == "CHANGELOG.md":
            text = changelog_latest(text)
        checker.check_doc(os.path.relpath(doc_path, root), doc_path, text)
    checker.findings.sort(key=lambda f: (f.doc, f.line))
    return tree, checker, allow.unused(RULES, docs, root)


def main():
    args = arguments(__doc__).parse_args()
    root = os.path.abspath(args.root)
    if args.expect_fail:
        _, checker, _ = run(root, [os.path.abspath(args.expect_fail)], AllowList())
        return expect_fail(args, checker.findings)

    docs = [os.path.abspath(d) for d in args.docs] or default_docs(root, changelog=True)
    tree, checker, unused = run(root, docs, AllowList(args.allow))
    if checker.findings or unused:
        print("\n".join([str(f) for f in checker.findings] + unused))
        print("docs name what is not in the tree: fix the doc (or, for a deliberate exception, "
              "add it with its reason to %s)" % os.path.relpath(args.allow, root))
        return 1
    print("ok: %d docs name only what exists: %s checked (the table: %d rows, the vendor: "
          "%d paths)" % (len(docs), ", ".join("%d %s" % (v, k) for k, v in checker.seen.items()),
                         tree.rows, tree.vendor_rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
