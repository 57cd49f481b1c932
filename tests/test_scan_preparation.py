"""Every contact built from a scan prepares it the same way (issue 16, item 1): spikes removed
by default (``--spikes keep`` keeps them), non-measured points filled, and the output says
what was done; a pressure beyond the elastic limit or an unresolved contact is a warning.

Truths: the generator of the bundled plate (``examples/paper_2022/make_surfaces.py``) put
exactly ``PLATE_SPIKES`` = 60 single-pixel spikes of 20-150 µm on a surface of rms
``PLATE_RQ`` = 2.2 µm; a linear-elastic half-space cannot carry a pressure above E*.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import json
from pathlib import Path

import numpy as np
import pytest

from contact._materials import composite_modulus, material
from surfmet.cli import main

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "surfmet" / "data"
PLATE, BALL = str(DATA / "paper_plate.x3p"), str(DATA / "paper_ball.x3p")
E_STAR = composite_modulus(material("steel"), material("aluminium"))


@pytest.fixture(scope="module")
def generator():
    path = ROOT / "examples" / "paper_2022" / "make_surfaces.py"
    spec = importlib.util.spec_from_file_location("make_surfaces_for_prep_test", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _run(argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    return rc, out.getvalue(), err.getvalue()


def _contact(*extra):
    rc, out, err = _run(["contact", "--plate", PLATE, "--ball", BALL, "--radius", "20mm",
                         "--load", "10N", "--materials", "steel,aluminium", "--json", *extra])
    assert rc == 0, err
    return json.loads(out)


def test_contact_removes_the_spikes_and_says_so(generator):
    rec = _contact()
    prep = rec["scan_preparation"]
    assert prep["spikes"] == "remove"
    assert prep["spikes_removed"]["plate"] == generator.PLATE_SPIKES
    # with the spikes gone the elastic peak stays below E* (67 GPa with them)
    assert rec["pmax"]["value"] < E_STAR
    # ... but an elastic rough contact still exceeds aluminium's hardness: said, not silent
    assert any("elastic limit" in w for w in rec["warnings"])


def test_contact_spikes_keep_is_stated_and_warned():
    rec = _contact("--spikes", "keep")
    assert rec["scan_preparation"]["spikes"] == "keep"
    assert rec["scan_preparation"]["spikes_removed"] == {"plate": 0, "ball": 0}
    assert rec["pmax"]["value"] > E_STAR  # a spike carries the load: the physics breaks
    assert any("E*" in w or "elastic limit" in w for w in rec["warnings"])


def test_contact_text_states_the_preparation():
    rc, out, _ = _run(["contact", "--plate", PLATE, "--radius", "20mm", "--load", "10N",
                       "--materials", "steel,aluminium", "--grid", "64"])
    assert rc == 0
    assert "spikes removed (plate 60)" in out


@pytest.mark.parametrize("spikes", ["remove", "keep"])
def test_flat_contact_mean_gap_is_set_by_roughness_not_spikes(generator, spikes):
    rc, out, err = _run(["flat-contact", PLATE, "--materials", "steel,aluminium",
                         "--pressures", "1MPa", "--spikes", spikes, "--json"])
    assert rc == 0, err
    rec = json.loads(out)
    gap = rec["results"][0]["bem"]["mean_gap"]["value"]
    prep = rec["scan_preparation"]
    assert prep["spikes"] == spikes
    if spikes == "remove":
        assert prep["spikes_removed"]["scan"] == generator.PLATE_SPIKES
        # a few rms heights of the generated surface (8.15 µm; 127.7 µm with the spikes)
        assert gap < 5 * generator.PLATE_RQ
    else:
        # the flat rests on the spikes, at least the smallest spike's 20 µm away
        assert gap > 20e-6


def test_sweep_contact_rows_use_the_same_preparation(tmp_path, generator):
    from surfmet.mechanics.scan_preparation import prepare_scans
    from surfmet.sweep import run_item, sweep_items

    (item,) = sweep_items(task="contact", loads=[2.0], radius=0.02, plates=[PLATE],
                          grid=64)
    row = run_item(item)
    assert row["spikes"][0] == "remove"
    # the sweep's contact sees the same roughness as the one preparation gives
    prep = prepare_scans(PLATE)
    assert prep.spikes_removed == {"plate": generator.PLATE_SPIKES}
    rc, out, err = _run(["contact", "--plate", PLATE, "--radius", "20mm", "--load", "2N",
                         "--materials", "steel,aluminium", "--grid", "64", "--json"])
    assert rc == 0, err
    assert row["max_pressure"][0] == json.loads(out)["pmax"]["value"]


def test_prepare_flat_fills_non_measured_points():
    from surfmet import Topography
    from surfmet.mechanics.scan_preparation import prepare_flat

    rng = np.random.default_rng(16)
    z = rng.normal(0, 1e-6, (64, 64))
    z[10, 10] = np.nan
    z[20:22, 30] = np.nan
    scan, rec = prepare_flat(Topography(z, 1e-6, 1e-6), spikes="keep")
    assert np.isfinite(scan.heights).all()
    assert rec.filled_fraction == pytest.approx(3 / 64**2)
    assert scan.heights[10, 10] in {z[9, 10], z[11, 10], z[10, 9], z[10, 11]}


def test_unknown_spike_choice_is_one_line():
    rc, _, err = _run(["contact", "--radius", "20mm", "--load", "1N", "--materials",
                       "steel,aluminium", "--spikes", "drop"])
    assert rc == 1
    assert "remove" in err and "keep" in err and len(err.strip().splitlines()) == 1


def test_a_profile_is_refused_in_words_a_user_reads(tmp_path):
    # the message used to read "an areal scan of the scan, got profile"
    import numpy as np
    import pytest

    from surfmet._errors import SurfmetInputError
    from surfmet._model import Profile
    from surfmet.mechanics.scan_preparation import read_areal

    prof = Profile(np.zeros(16), dx=1e-6)
    with pytest.raises(SurfmetInputError) as err:
        read_areal(prof, "scan")
    msg = str(err.value)
    assert "of the scan" not in msg
    assert msg.startswith("a contact needs an areal scan (a height map), got a ")
    with pytest.raises(SurfmetInputError, match="height map\\) of the plate, got a "):
        read_areal(prof, "plate")
