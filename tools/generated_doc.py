"""What every docs generator of tools/ does with its text: write it, or with
--check say whether the page already holds it (exit 1 when stale)."""
import os
import sys


def write_or_check(path, text, what, generator):
    """Write @text to @path, or with --check in argv compare; the exit status."""
    if "--check" in sys.argv[1:]:
        current = open(path, encoding="utf-8").read() if os.path.exists(path) else ""
        if current != text:
            print("%s is stale: run %s" % (what, generator))
            return 1
        print("%s is current" % what)
        return 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return 0
