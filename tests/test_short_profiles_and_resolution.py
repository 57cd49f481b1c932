"""Short profiles, containers and the one sampling rule (issue 34, items 4 and 6).

A profile shorter than the Gaussian kernel crashed the filter (numpy's ``"same"``
convolution returns the kernel's length); the automatic ISO 4288 cut-off then crashed on
any profile under ~0.13 mm. A container's measurements are each evaluated, as ``scales``
reads them. A nesting index or sampling length under three sampling distances
(:mod:`profiles._resolution`, ISO 25178-3 Table 1) is refused in one line instead of
giving Sa = Sq = Sz = 0 or Rz = 0 beside Rt > 0.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import surfmet
from profiles import ProfileError
from profiles._filters import gaussian_mean_line
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.cli import main
from surfmet.roughness import roughness


def test_a_kernel_longer_than_the_profile_filters_it():
    # 100 points at 1 µm under an 80 µm cut-off (kernel of 161 taps): the moment criterion
    # reproduces a straight line exactly (ISO 16610-28, first order), end to end
    x = np.arange(100) * 1e-6
    line = 3e-7 + 2e-3 * x
    out = gaussian_mean_line(line, 1e-6, 80e-6)
    assert out.shape == (100,)
    assert np.allclose(out, line, rtol=0, atol=1e-18)


def test_the_automatic_cutoff_of_a_profile_shorter_than_any_iso4288_cutoff():
    # 60 µm of a 20 µm sine: shorter than ISO 4288's shortest λc (80 µm, evaluation length
    # 0.4 mm). No λc: the primary profile, named P (ISO 21920-2), over whole periods, so
    # Pq = A/√2 and Pa = mean |sin| exactly for the sampled sine (20 points per period)
    amp, n = 1e-7, 60
    z = amp * np.sin(2 * np.pi * np.arange(n) / 20)
    res = roughness(Profile(z, 1e-6), level="none")
    assert "Ra" not in res.parameters
    assert res.value("Pq") == pytest.approx(amp / math.sqrt(2), rel=1e-12)
    assert res.value("Pa") == pytest.approx(
        amp * np.mean(np.abs(np.sin(2 * np.pi * np.arange(20) / 20))), rel=1e-12)
    note = res.settings["lc_note"]
    assert "60 µm long" in note and "λc = 80 µm" in note and "P-parameters" in note
    assert res.settings["profile_kind"].startswith("primary profile")


def test_a_container_gives_one_record_per_measurement(realdata, capsys):
    # container-2.zip holds a 230 nm profile, a 100 nm map and a 0.3 mm profile, which
    # `scales` reads all of; roughness evaluates each (it crashed with IndexError)
    path = realdata("container-2.zip")
    from surfmet.io import read_container

    members = [m.metadata["member"] for m in read_container(path)]
    assert main(["roughness", str(path), "--json"]) == 0
    recs = json.loads(capsys.readouterr().out)
    assert [r["file"] for r in recs] == [f"{path}:{m}" for m in members]
    assert [r["status"] for r in recs] == ["ok"] * 3
    assert "Sa" in recs[1]["parameters"] and "Pa" in recs[0]["parameters"]
    # each measurement is levelled as its container states (detrend_mode), as scales does
    assert [r["settings"]["level"] for r in recs] == ["line", "plane", "poly:2"]


def test_a_filter_under_three_pixels_is_refused(capsys):
    # a 1 µm L-filter on a 5 µm pixel passed the scan as its own mean surface: S-L = 0
    rng = np.random.default_rng(4)
    topo = Topography(1e-7 * rng.standard_normal((40, 40)), 5e-6, 5e-6)
    with pytest.raises(SurfmetInputError, match=r"spans 0\.2 sampling distances"):
        roughness(topo, lc="1um")
    with pytest.raises(SurfmetInputError, match="ISO 25178-3"):
        roughness(topo, ls="10um")
    assert roughness(topo, lc="15um", edge="moment").value("Sq") > 0  # 3 pixels: carried


def test_the_bundled_plate_with_lc_1um_is_one_line(capsys):
    plate = surfmet.__path__[0] + "/data/paper_plate.x3p"
    assert main(["roughness", plate, "--lc", "1um"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "at least 15 µm" in err[0]


@pytest.mark.parametrize("argv", [
    ["--n-sampling", "1000000"],
    ["--standard", "iso4287", "--n-sampling", "100000"],
])
def test_sampling_lengths_with_too_few_points_are_refused(realdata, capsys, argv):
    # dektak-1.csv: 9600 points at 156 nm; 10⁶ parts gave Rz 0 beside Rt 456 nm, and 10⁵
    # parts under ISO 4287 gave Rq = Ra (one point per part)
    assert main(["roughness", str(realdata("dektak-1.csv")), *argv]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "use at most 3200" in err[0]


def test_the_sampling_rule_holds_at_its_bound():
    # 30 points divided into 10 parts of exactly 3 points: carried; 11 parts: refused
    from profiles import profile_parameters

    z = np.sin(np.arange(30.0))
    assert math.isfinite(profile_parameters(z, 1e-6, n_sampling=10).Rz)
    with pytest.raises(ProfileError, match="use at most 10"):
        profile_parameters(z, 1e-6, n_sampling=11)


def test_the_api_on_a_container_says_which_measurement(realdata):
    # roughness(path) reads one scan, the container's first (as surfmet.read does): said
    res = roughness(realdata("container-2.zip"))
    assert res.settings["notes"][0].startswith("measurement 0 (80_Scale10.472")
    assert "every measurement" in res.settings["notes"][0]
