"""The example scripts start: their imports resolve (examples/paper_2022/contact.py shares
its name with the contact package, which must not shadow it) and they parse arguments."""

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").rglob("*.py"))


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_imports_and_shows_help(script):
    out = subprocess.run([sys.executable, str(script), "--help"], capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.startswith("usage:")


def test_examples_are_found():
    assert {p.name for p in EXAMPLES} >= {"contact.py", "rotor.py", "make_surfaces.py"}
