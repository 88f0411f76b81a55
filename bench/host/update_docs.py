#!/usr/bin/env python3
"""Replace the generated blocks of docs/performance.md with fresh results.

    update_docs.py DOC NAME=FILE...

Each NAME names a block written as
    <!-- BEGIN generated: NAME (bench/host/run_all.sh) -->
    ...
    <!-- END generated: NAME -->
(the blocks m4insns and m0 name bench/target_insns.sh instead, the block
summary bench/summary.py), whose
inside becomes FILE's text. Nothing outside the markers is touched, so
other sections of the page stay as their owners wrote them."""
import sys


def main():
    doc = sys.argv[1]
    text = open(doc).read()
    for arg in sys.argv[2:]:
        name, path = arg.split("=", 1)
        script = {"m4insns": "bench/target_insns.sh", "m0": "bench/target_insns.sh",
                  "summary": "bench/summary.py"}.get(name, "bench/host/run_all.sh")
        begin = "<!-- BEGIN generated: %s (%s) -->" % (name, script)
        end = "<!-- END generated: %s -->" % name
        if begin not in text or end not in text:
            print("update_docs: no '%s' block in %s; left as is" % (name, doc))
            continue
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        body = open(path).read().strip("\n")
        text = head + begin + "\n" + body + "\n" + end + tail
        print("update_docs: %s block of %s updated from %s" % (name, doc, path))
    with open(doc, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
