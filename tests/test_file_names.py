"""File names that are not UTF-8 (issue 25 item 17): every text output stays valid UTF-8,
with the name's undecodable bytes written as ``\\xNN`` escapes (as ``ls -b`` and Python's
``repr`` show them), and a CSV of several such files is written whole."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import main

pytestmark = pytest.mark.skipif(os.name == "nt", reason="POSIX file names are bytes")


@pytest.fixture
def odd_scans(tmp_path):
    """Two small scans whose names hold the byte 0xFF (not UTF-8)."""
    rng = np.random.default_rng(3)
    paths = []
    for k in range(2):
        raw = os.path.join(os.fsencode(tmp_path), b"pl\xffte-%d.x3p" % k)
        topo = Topography(rng.normal(0, 1e-7, (48, 64)), 1e-6, 1e-6)
        surfmet.write(topo, os.fsdecode(raw))
        paths.append(os.fsdecode(raw))
    return paths


def test_info_json_is_valid_utf8(odd_scans, capsys):
    assert main(["info", "--json", odd_scans[0]]) == 0
    out = capsys.readouterr().out
    rec = json.loads(out.encode("utf-8").decode("utf-8"))  # strict: no lone surrogate
    assert rec["file"].endswith("pl\\xffte-0.x3p")


def test_roughness_csv_of_such_files_is_whole(odd_scans, tmp_path, capsys):
    out = tmp_path / "table.csv"
    assert main(["roughness", *odd_scans, "--csv", str(out), "--workers", "1"]) == 0
    lines = out.read_bytes().decode("utf-8").splitlines()  # strict UTF-8
    assert len(lines) == 3
    assert lines[1].split(",")[0].endswith("pl\\xffte-0.x3p")
    assert all(line.split(",")[1] == "ok" for line in lines[1:])


def test_report_of_such_a_file_is_valid_utf8(odd_scans, tmp_path):
    out = tmp_path / "r.html"
    assert main(["report", odd_scans[0], "-o", str(out), "--no-3d", "--quiet"]) == 0
    assert "pl\\xffte-0.x3p" in out.read_bytes().decode("utf-8")


def test_valid_text_keeps_good_text_and_escapes_bad_bytes():
    from surfmet.units import valid_text

    assert valid_text("µm plate ü.x3p") == "µm plate ü.x3p"
    assert valid_text(os.fsdecode(b"a\xff\xfeb")) == "a\\xff\\xfeb"
