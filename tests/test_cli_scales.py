"""``surfmet scales``: the JSON shape the issue states, containers and plain files together,
the plot, and one line with exit 1 for each kind of bad input."""

from __future__ import annotations

import io
import json
import zipfile

import numpy as np
import pytest

import surfmet
from surfmet._model import Profile
from surfmet.cli import main


def _profile(tmp_path, name: str, n: int, dx: float, seed: int) -> str:
    rng = np.random.default_rng(seed)
    p = Profile(np.cumsum(rng.normal(size=n)) * dx * 0.1, dx)
    return str(surfmet.write(p, tmp_path / name))


@pytest.mark.realdata
def test_container_json_shape_units_and_contributions(realdata, capsys):
    assert main(["scales", str(realdata("container-2.zip")), "--per-decade", "1", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    sd = rec["scale_dependent"]
    assert sd["distance"]["unit"] == "m" and sd["rms_slope"]["unit"] == ""
    assert sd["rms_curvature"]["unit"] == "1/m"
    d = np.array([np.nan if v is None else v for v in sd["distance"]["value"]])
    slope = np.array([np.nan if v is None else v for v in sd["rms_slope"]["value"]])
    j = int(np.argmin(abs(d - 1e-6)))
    assert slope[j] ** 2 == pytest.approx(2.058876e-04, rel=1e-6)  # ST's container value
    assert rec["psd"]["q"]["unit"] == "rad/m" and rec["psd"]["C"]["unit"] == "m^3"
    assert "hann" in rec["psd"]["window"]
    assert rec["variable_bandwidth"]["rms_height"]["unit"] == "m"
    ms = rec["measurements"]
    assert len(ms) == 3 and {"file", "kind", "reliability_cutoff"} <= set(ms[0])
    assert ms[1]["kind"] == "map" and ms[1]["reliability_cutoff"] == {"value": None, "unit": "m"}
    assert ms[2]["contributes_slope"][j] and not ms[0]["contributes_slope"][j]
    assert ms[0]["reliable_from"]["value"] == pytest.approx(228.9070382e-9 / 75, rel=1e-9)
    assert len(ms[1]["contributes_psd"]) == len(rec["psd"]["q"]["value"])


@pytest.mark.realdata
def test_tip_radius_option_plot_and_text(realdata, tmp_path, capsys):
    out = tmp_path / "scales.png"
    assert main(["scales", str(realdata("di-1.di")), "--tip-radius", "40nm", "--plot",
                 str(out)]) == 0
    text = capsys.readouterr().out
    assert "cut-off 90.7 nm (tip radius from --tip-radius)" in text
    assert out.stat().st_size > 10_000


def test_bad_inputs_are_one_line_exit_1(tmp_path, capsys):
    near = _profile(tmp_path, "near.npz", 400, 1e-8, 1)
    far = _profile(tmp_path, "far.npz", 400, 1e-3, 2)
    cases = [
        (["scales", near, far], "no overlapping bandwidth"),
        (["scales", near, "--tip-radius", "1m"], "no reliable scale"),
        (["scales", near, "--per-decade", "0"], "at least 1"),
        (["scales", near, "--plot", str(tmp_path / "nodir" / "x.png")], "does not exist"),
    ]
    broken = io.BytesIO()
    with zipfile.ZipFile(broken, "w") as zf:
        zf.writestr("meta.yml", "surfaces:\n- topographies:\n  - datafile: {original: gone.txt}\n"
                                "    unit: um\n")
    bad = tmp_path / "broken.zip"
    bad.write_bytes(broken.getvalue())
    cases.append((["scales", str(bad)], "names 'gone.txt', which the archive does not hold"))
    for argv, msg in cases:
        assert main(argv) == 1, argv
        err = [line for line in capsys.readouterr().err.splitlines()
               if line.startswith("surfmet: error")]
        assert len(err) == 1 and msg in err[0], (argv, err)
