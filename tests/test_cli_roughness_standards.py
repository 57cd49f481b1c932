"""``surfmet roughness`` on profiles: --standard, --lc none, --n-sampling, --ls, and the
instrument's stated conditions, checked against a Mitutoyo SurfTest printout."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest
from mitutoyo_printout import read_printout

import surfmet
from surfmet._model import Profile
from surfmet.cli import main


def _run(capsys, *argv):
    rc = main(list(argv))
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.fixture(scope="module")
def printout():
    from conftest import REALDATA, shared_file

    return read_printout(shared_file(REALDATA / "mitutoyo_2_mock.xlsx"))


@pytest.fixture
def mitutoyo_npz(tmp_path, printout):
    # the exported R-profile with the conditions the instrument states, as a reader of the
    # export hands them over (metadata["evaluation_conditions"])
    conditions = {"standard": "iso4287", "lc": 2.5e-3, "ls": 8e-6, "n_sampling": 4,
                  "profile": "R", "rk_line": "levels", "source": "Mitutoyo SurfTest export"}
    path = tmp_path / "mitutoyo.npz"
    surfmet.write(Profile(printout.z, printout.dx,
                          metadata={"evaluation_conditions": conditions}), path)
    return path


@pytest.fixture
def sine_profile(tmp_path):
    # stepped amplitudes: ISO 4287 (mean of per-sampling-length Rq) and ISO 21920-2
    # (Rq of the whole) have different closed forms
    lam, dx, n = 0.1e-3, 0.5e-6, 1600
    x = np.arange(n) * dx
    amps = np.array([1.0, 2.0, 3.0, 4.0]) * 1e-6
    z = np.concatenate([a * np.sin(2 * np.pi * x / lam) for a in amps])
    path = tmp_path / "r_profile.npz"
    surfmet.write(Profile(z, dx), path)
    return path, amps


def test_stated_conditions_reproduce_the_printout_without_flags(capsys, mitutoyo_npz,
                                                                printout):
    rc, out, _ = _run(capsys, "roughness", str(mitutoyo_npz), "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    cond = rec["settings"]["conditions"]
    assert cond["standard"]["value"] == "iso4287" and "file" in cond["standard"]["why"]
    assert cond["lc"]["value"] == 2.5e-3 and cond["lc"]["applied"] is False
    assert cond["n_sampling"]["value"] == 4 and "file" in cond["n_sampling"]["why"]
    got = rec["parameters"]
    for sym, ours in (("Ra", "Ra"), ("Rq", "Rq"), ("Rz", "Rz"), ("Rsk", "Rsk"),
                      ("Rkµ", "Rku"), ("RDq", "Rdq"), ("Rt", "Rt"), ("Rpk", "Rpk"),
                      ("Rvk", "Rvk"), ("Mr1", "Mr1"), ("Mr2", "Mr2")):
        assert abs(got[ours]["value"] - printout.results[sym]) <= 1.01 * printout.digits[sym]
    # A1, A2: printed in µm·%, ours in m (height times the ratio as a fraction)
    for sym in ("A1", "A2"):
        assert got[sym]["unit"] == "m"
        assert abs(got[sym]["value"] * 1e8 - printout.results[sym]) <= printout.digits[sym]
    assert rec["settings"]["rk_line"]["value"] == "levels"
    assert "instrument's own Rk construction" in rec["settings"]["rk_line"]["why"]
    assert cond["rk_line"] == rec["settings"]["rk_line"]


@pytest.mark.realdata
def test_the_export_itself_gives_the_printed_rk_family(capsys, printout):
    """The Mitutoyo export read directly: its Rk construction is part of the evaluation
    it states, so the defaults reproduce the printed Rpk, Rvk, Mr1, Mr2, A1, A2 to the
    printed digits, and the output says which construction and why (main: the secant
    construction, Rpk 2.731 against the printed 2.912 µm, Mr1 6.77 against 5.822 %)."""
    from conftest import REALDATA, shared_file

    path = str(shared_file(REALDATA / "mitutoyo_2_mock.xlsx"))
    rc, out, _ = _run(capsys, "roughness", path, "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    got = rec["parameters"]
    for sym in ("Rpk", "Rvk", "Mr1", "Mr2"):
        assert abs(got[sym]["value"] - printout.results[sym]) <= 1.01 * printout.digits[sym]
    for sym in ("A1", "A2"):
        assert abs(got[sym]["value"] * 1e8 - printout.results[sym]) <= printout.digits[sym]
    rk = rec["settings"]["conditions"]["rk_line"]
    assert rk["value"] == "levels" and "Mitutoyo" in rk["why"]
    rc, text, _ = _run(capsys, "roughness", path)
    assert "Rk construction levels" in text


@pytest.mark.realdata
def test_the_export_itself_gives_the_printed_rsm_and_rc(capsys, printout):
    """The export read directly pairs its profile elements as the SurfTest does (from the
    first mean-line crossing of each sampling length), so the defaults reproduce the
    printed RSm 419.9 µm and Rc 13.306 µm to the printed digits (main: peak-first
    elements, 416.6 µm and 13.217 µm), and the output says which pairing and why."""
    from conftest import REALDATA, shared_file

    path = str(shared_file(REALDATA / "mitutoyo_2_mock.xlsx"))
    rc, out, _ = _run(capsys, "roughness", path, "--json")
    assert rc == 0
    rec = json.loads(out)[0]
    got = rec["parameters"]
    for sym, ours in (("RSm", "Rsm"), ("Rc", "Rc")):
        assert abs(got[ours]["value"] - printout.results[sym]) <= printout.digits[sym], sym
    start = rec["settings"]["conditions"]["element_start"]
    assert start["value"] == "first-crossing" and "Mitutoyo" in start["why"]
    assert rec["settings"]["element_start"] == start
    rc, text, _ = _run(capsys, "roughness", path)
    assert "profile elements paired first-crossing" in text


def test_standard_flag_and_lc_none(capsys, sine_profile):
    path, amps = sine_profile
    rq = {}
    for std in ("iso4287", "iso21920"):
        rc, out, _ = _run(capsys, "roughness", str(path), "--standard", std, "--lc", "none",
                          "--level", "none",
                          "--n-sampling", "4", "--json")
        assert rc == 0
        rec = json.loads(out)[0]
        s = rec["settings"]
        assert s["conditions"]["standard"]["value"] == std
        assert s["conditions"]["standard"]["why"] == "given by the user"
        assert s["conditions"]["lc"] == {"value": None, "unit": "m",
                                         "why": "given by the user"}
        assert s["n_sampling"] == 4
        assert s["sampling_length"] == {"value": pytest.approx(0.8e-3), "unit": "m"}
        assert s["dx"]["unit"] == "m" and s["evaluation_length"]["unit"] == "m"
        rq[std] = rec["parameters"]["Rq"]["value"]
    assert rq["iso4287"] == pytest.approx(np.mean(amps) / math.sqrt(2), rel=1e-4)
    assert rq["iso21920"] == pytest.approx(math.sqrt(np.mean(amps**2) / 2), rel=1e-4)


def test_default_is_stated_in_text_json_and_csv(capsys, sine_profile, tmp_path):
    path, _ = sine_profile
    rc, out, _ = _run(capsys, "roughness", str(path), "--lc", "0.8mm", "--n-sampling", "4")
    assert rc == 0 and "standard ISO 21920-2:2021 (default)" in out
    assert "λc 800 µm (given by the user)" in out
    table = tmp_path / "t.csv"
    rc, _, _ = _run(capsys, "roughness", str(path), str(path), "--lc", "0.8mm", "--ls",
                    "2.5um", "--n-sampling", "4", "--csv", str(table))
    rows = list(csv.DictReader(io.StringIO(table.read_text())))
    assert rc == 0 and rows[0]["standard"] == "iso21920"
    assert float(rows[0]["lc [m]"]) == pytest.approx(0.8e-3)
    assert float(rows[0]["ls [m]"]) == pytest.approx(2.5e-6)
    assert rows[0]["n_sampling"] == "4" and "lc: given by the user" in rows[0]["conditions"]


def test_help_states_the_default(capsys):
    with pytest.raises(SystemExit):
        main(["roughness", "--help"])
    out = capsys.readouterr().out
    assert "iso21920" in out and "default" in out and "--n-sampling" in out


def test_bad_standard_or_count_is_one_line(capsys, sine_profile):
    path, _ = sine_profile
    rc, out, err = _run(capsys, "roughness", str(path), "--standard", "din")
    assert rc != 0 and out == "" and "invalid choice" in err
    rc, out, err = _run(capsys, "roughness", str(path), "--n-sampling", "9", "--lc", "0.8mm")
    assert rc == 1 and out == "" and err.count("\n") == 1
