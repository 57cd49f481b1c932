"""``surfmet spectrum``: units in the JSON, periodic detection, plot, exit 1 on bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

import surfmet
from surfmet.cli import main
from surfmet.model import Topography
from surfmet.synth import self_affine


@pytest.fixture
def scan(tmp_path):
    topo = self_affine(128, 1e-6, hurst=0.6, h_rms=2e-7, roll_off=32e-6, seed=4)
    return str(surfmet.write(topo, tmp_path / "sa.npz"))


def test_json_units_and_values(scan, capsys):
    assert main(["spectrum", scan, "--json", "--materials", "steel,aluminium",
                 "--hardness", "1GPa"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["periodic"] is True and rec["window"] == "none" and rec["levelling"] == "mean"
    assert rec["h_rms"]["spectrum"]["unit"] == "m"
    assert rec["h_rms"]["spectrum"]["value"] == pytest.approx(2e-7, rel=1e-9)
    assert rec["summits"]["radius"]["unit"] == "m"
    assert rec["summits"]["density"]["unit"] == "1/m^2"
    assert rec["roll_off"]["wavelength"]["value"] == pytest.approx(32e-6, rel=0.15)
    assert abs(rec["hurst"]["value"] - 0.6) < 0.06
    assert rec["plasticity_index"] > 0 and rec["hardness"]["value"] == 1e9
    assert "slope_rms" in rec["resolution_dependent"] and "h_rms" not in \
        rec["resolution_dependent"]


def test_periodic_no_windows_and_plot(scan, tmp_path, capsys):
    out = tmp_path / "psd.png"
    assert main(["spectrum", scan, "--periodic", "no", "--plot", str(out), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["window"] == "hann" and rec["periodic"] is False
    assert out.stat().st_size > 1000


def test_text_output_marks_resolution_dependence(scan, capsys):
    assert main(["spectrum", scan]) == 0
    out, err = capsys.readouterr()
    assert "Hurst" in out and "h'_rms *" in out and "resolution" in err


@pytest.mark.parametrize("argv", [
    ["spectrum", "{tmp}/absent.npz"],
    ["spectrum", "{scan}", "--periodic", "maybe"],
    ["spectrum", "{scan}", "--materials", "steel,aluminium,steel"],
    ["spectrum", "{small}"],
])
def test_bad_input_exits_1(argv, scan, tmp_path, capsys):
    small = surfmet.write(Topography(np.random.default_rng(0).standard_normal((8, 8)), 1e-6,
                                     1e-6), tmp_path / "small.npz")
    argv = [a.format(tmp=tmp_path, scan=scan, small=small) for a in argv]
    assert main(argv) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Traceback" not in err[0]
