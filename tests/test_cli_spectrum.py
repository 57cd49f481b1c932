"""``surfmet spectrum``: units in the JSON, periodic detection, plot, exit 1 on bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import main
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


def _spectrum_json(capsys, *argv):
    assert main(["spectrum", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_spectrum_prepares_the_scan_as_every_contact_command(capsys):
    """Issue 25 item 3: the quickstart's plate has 60 spikes; ``spectrum`` removed none (its
    "noise floor" was the spikes). It now goes through the shared preparation and says so:
    the same spikes as flat-contact removes, and --spikes keep keeps them."""
    from pathlib import Path

    plate = str(Path(surfmet.__file__).parent / "data" / "paper_plate.x3p")
    rec = _spectrum_json(capsys, plate)
    prep = rec["scan_preparation"]
    assert prep["spikes"] == "remove" and prep["spikes_removed"]["scan"] > 0
    assert main(["flat-contact", plate, "--e-star", "50GPa", "--pressures", "10MPa",
                 "--json", "--quiet"]) == 0
    flat = json.loads(capsys.readouterr().out)["scan_preparation"]
    assert flat["spikes_removed"] == prep["spikes_removed"]
    assert flat["levelling"] == prep["levelling"] == rec["levelling"]
    kept = _spectrum_json(capsys, plate, "--spikes", "keep")
    assert kept["scan_preparation"]["spikes_removed"]["scan"] == 0
    assert kept["h_rms"]["real_space"]["value"] > rec["h_rms"]["real_space"]["value"]


def test_doubtful_spectra_carry_caveats(realdata, capsys):
    """Issue 25 item 3: nms-1's spectral h_rms is 2.5 x its real-space one and its Hurst
    band spans half a decade; both are said. A clean synthetic self-affine scan has none."""
    rec = _spectrum_json(capsys, str(realdata("nms-1.nms")))
    h = rec["h_rms"]
    assert h["spectrum"]["value"] > 1.25 * h["real_space"]["value"]  # the premise
    assert any("h_rms from the spectrum" in c for c in rec["caveats"])
    lo, hi = (q["value"] for q in rec["hurst"]["q_range"])
    assert np.log10(hi / lo) < 1
    assert any("decades of wavevector only" in c for c in rec["caveats"])


def test_clean_self_affine_scan_has_no_spectrum_caveat(scan, capsys):
    rec = _spectrum_json(capsys, str(scan))
    assert not [c for c in rec["caveats"] if "Hurst" in c or "h_rms" in c]


def test_report_psd_is_the_spectrum_commands(tmp_path):
    """Issue 25 item 3: the report's PSD figure is fitted as ``spectrum`` fits it (on the
    quickstart's plate its own fit crossed the plateau, H = -0.479) and carries its caveat."""
    from pathlib import Path

    from surfmet._report_figures import spectrum_section

    plate = surfmet.read(Path(surfmet.__file__).parent / "data" / "paper_plate.x3p")
    _rec, (caption, png) = spectrum_section(plate, "paper_plate.x3p")
    assert png.startswith(b"\x89PNG")
    assert "as surfmet spectrum gives it" in caption and "Hurst" in caption
