"""``--element-start`` / ``element_start=``: the user's choice of the profile-element
pairing (RSm, Rc) beats the file's stated one, as ``--rk-line`` does; the file's is kept
only while its standard is in force (docs/parameters.md). Checked on half-sine runs of
chosen widths (RSm by construction) and on the Mitutoyo export (peak first: the separate
implementation of ``benchmarks/mitutoyo_rsm_rules.py`` gives RSm 416.58 µm, Rc 13.217)."""

from __future__ import annotations

import json

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile
from surfmet.cli import main
from surfmet.roughness import roughness

A, DX = 1e-6, 0.25e-6
# run widths (µm): a peak cut by the profile's start, then valley, peak, valley, peak and
# a valley cut by its end. Peak first (elements between up-crossings): one complete element
# 100 + 100; from the first crossing (a down-crossing here: valley first, between
# down-crossings): (300 + 100) and (100 + 100), mean 300 µm
RUNS = (100, 300, 100, 100, 100, 100)
RSM_PEAK, RSM_FIRST = 200e-6, 300e-6


def _runs_profile() -> Profile:
    edges = np.cumsum((0, *RUNS)) * 1e-6
    x = (np.arange(round(edges[-1] / DX)) + 0.5) * DX  # no point on a crossing
    k = np.searchsorted(edges, x, side="right") - 1
    w = np.diff(edges)[k]
    z = A * (-1.0) ** k * np.sin(np.pi * (x - edges[k]) / w)
    stated = {"standard": "iso4287", "lc": float(edges[-1]), "n_sampling": 1,
              "profile": "R", "element_start": "first-crossing", "source": "test instrument"}
    return Profile(z, DX, metadata={"evaluation_conditions": stated})


@pytest.fixture(scope="module")
def runs_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("runs") / "runs.npz"
    surfmet.write(_runs_profile(), path)
    return str(path)


def _record(capsys, *argv) -> dict:
    assert main(["roughness", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)[0]


@pytest.mark.parametrize(("options", "rsm", "why"), [
    ((), RSM_FIRST, "instrument's own profile-element pairing (test instrument)"),
    (("--standard", "iso4287"), RSM_FIRST, "instrument's own"),
    (("--element-start", "peak"), RSM_PEAK, "given by the user"),
    (("--standard", "iso21920"), RSM_PEAK, "not carried over to ISO 21920-2"),
    (("--standard", "iso21920", "--element-start", "first-crossing"), RSM_FIRST,
     "given by the user; iso21920 has one stretch"),
])
def test_the_option_beats_the_file_and_the_file_holds_under_its_standard(
        capsys, runs_file, options, rsm, why):
    # fails before: no --element-start (usage error), and under --standard iso21920 the
    # file's first-crossing pairing was carried over (300 µm instead of 200)
    rec = _record(capsys, runs_file, *options)
    # the crossings are interpolated linearly between points on half-sines of unequal
    # slopes: each is placed within a step, the mean width within half of one
    assert rec["parameters"]["Rsm"]["value"] == pytest.approx(rsm, abs=DX / 2)
    assert rec["parameters"]["Rc"]["value"] == pytest.approx(2 * A, rel=1e-3)
    start = rec["settings"]["conditions"]["element_start"]
    assert why in start["why"] and rec["settings"]["element_start"] == start
    api = roughness(runs_file, **{o.lstrip("-").replace("-", "_"): v
                              for o, v in zip(options[::2], options[1::2])})
    assert api.parameters["Rsm"][0] == rec["parameters"]["Rsm"]["value"]


@pytest.mark.realdata
def test_the_option_restores_peak_first_elements_on_the_mitutoyo_export(capsys):
    from conftest import REALDATA, shared_file

    path = str(shared_file(REALDATA / "mitutoyo_2_mock.xlsx"))
    rec = _record(capsys, path, "--element-start", "peak")
    assert abs(rec["parameters"]["Rsm"]["value"] - 416.585e-6) < 0.005e-6
    assert abs(rec["parameters"]["Rc"]["value"] - 13.2173e-6) < 0.0005e-6
    start = rec["settings"]["conditions"]["element_start"]
    assert start == {"value": "peak", "why": "given by the user"}
    # every other stated condition stays the file's
    assert "file" in rec["settings"]["conditions"]["standard"]["why"]
    assert "Mitutoyo" in rec["settings"]["conditions"]["rk_line"]["why"]
    assert main(["roughness", path, "--element-start", "peak"]) == 0
    assert "profile elements paired peak (given by the user)" in capsys.readouterr().out


@pytest.mark.parametrize("command", ["roughness", "report", "show"])
def test_a_bad_value_is_refused_in_one_line(capsys, runs_file, tmp_path, command):
    out = ["-o", str(tmp_path / ("x.html" if command == "report" else "x.png"))]
    rc = main([command, runs_file, *(out if command != "roughness" else []),
               "--element-start", "valley"])
    out, err = capsys.readouterr()
    assert rc != 0 and out == "" and err.count("\n") == 1 and err.startswith("surfmet: error")
    assert "invalid choice: 'valley' (choose from 'peak', 'first-crossing')" in err
    with pytest.raises(SurfmetInputError, match="first-crossing, got 'valley'"):
        roughness(runs_file, element_start="valley")


def test_the_choices_are_the_engines():
    from profiles._elements import ELEMENT_STARTS as ENGINE
    from surfmet.cli._roughness_options import ELEMENT_STARTS

    assert ELEMENT_STARTS == ENGINE
