"""CLI conventions: exit codes, one-line errors, JSON on stdout, python -m surfmet."""

import json
import subprocess
import sys

import numpy as np

import surfmet
from surfmet.cli import main


def test_help_lists_examples():
    out = subprocess.run(
        [sys.executable, "-m", "surfmet", "--help"], capture_output=True, text=True
    )
    assert out.returncode == 0
    assert "examples:" in out.stdout and "info" in out.stdout


def test_info_json_units(tmp_path, capsys):
    t = surfmet.Topography(np.ones((4, 5)), 312.5e-9, 0.5e-6, {"instrument": "t"})
    p = surfmet.write(t, tmp_path / "s.npz")
    assert main(["info", str(p), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["nx"] == 5 and rec["ny"] == 4 and rec["nan_fraction"] == 0
    assert rec["dx"] == {"value": 312.5e-9, "unit": "m"}
    assert rec["dy"] == {"value": 0.5e-6, "unit": "m"}
    assert rec["kind"] == "areal" and rec["format"] == "npz"


def test_user_error_is_one_line_exit_1(tmp_path):
    bad = tmp_path / "bad.x3p"
    bad.write_bytes(b"PK\x03\x04garbage")
    out = subprocess.run([sys.executable, "-m", "surfmet", "info", str(bad)],
                         capture_output=True, text=True)
    assert out.returncode == 1
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("surfmet: error:") and "bad.x3p" in lines[0]
    assert "Traceback" not in out.stderr and out.stdout == ""


def test_usage_error_exit_1(capsys):
    assert main(["info"]) == 1
    assert main(["no-such-command"]) == 1
    assert "error" in capsys.readouterr().err
