"""docs/python.md's budgets (bench/figures.py), marked slow: left out of CI,
whose machine is shared (run with `pytest -m slow`)."""
import pathlib
import re
import subprocess
import sys

import pytest

FIGURES = pathlib.Path(__file__).resolve().parents[1] / "bench/figures.py"


@pytest.mark.slow
def test_the_budgets_hold():
    out = subprocess.run([sys.executable, "-P", str(FIGURES)], check=True, capture_output=True,
                         text=True, timeout=600).stdout
    ratio = float(re.search(r"ratio ([\d.]+)", out).group(1))
    state = float(re.search(r"state\(\): ([\d,]+) calls/s", out).group(1).replace(",", ""))
    import_ms = float(re.search(r"import daran: ([\d.]+) ms", out).group(1))
    assert ratio <= 1.5 and state >= 2000 and import_ms <= 100, out
