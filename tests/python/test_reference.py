"""docs/python-reference.md is tools/gen-python-reference's output (the stubs and
the module's docstrings): a stub or docstring changed without running
tools/gen-reference fails here, so the page cannot go stale."""

import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_python_reference_is_generated():
    out = subprocess.run([sys.executable, str(ROOT / "tools" / "gen-python-reference")], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    committed = (ROOT / "docs" / "python-reference.md").read_text()
    assert committed == out, "run tools/gen-reference"
