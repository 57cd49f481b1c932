"""The shipped stand-ins for the paper's scans (surfmet/data/paper_plate.x3p and
paper_ball.x3p) against the paper's own numbers (Table 2, the scan settings, the 20 mm
ball), read with surfmet's reader and evaluated with its roughness pipeline."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import surfmet
from surfmet.roughness import roughness

LC = "0.8mm"  # ISO 4288 for Ra in 0.1-2 µm


def _data(name: str) -> Path:
    return Path(str(resources.files("surfmet").joinpath("data", name)))


@pytest.fixture(scope="module")
def paper():
    from conftest import PAPER, shared_file

    return json.loads(shared_file(PAPER / "paper_values.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def plate():
    return surfmet.read(_data("paper_plate.x3p"))


@pytest.fixture(scope="module")
def ball():
    return surfmet.read(_data("paper_ball.x3p"))


def _rows(scan, level):
    """R-parameters of every row (median over rows: a few rows carry spikes)."""
    out = {k: [] for k in ("Ra", "Rq", "Rz", "Rt")}
    for k in range(scan.ny):
        res = roughness(scan, profile=f"row:{k}", level=level, lc=LC)
        for key in out:
            out[key].append(res.value(key) * 1e6)
    return {k: np.asarray(v) for k, v in out.items()}


def test_files_are_small_x3p_at_the_paper_pitch(plate, ball, paper):
    settings = paper["scan_settings"]
    for name in ("paper_plate.x3p", "paper_ball.x3p"):
        path = _data(name)
        assert path.stat().st_size <= 3_000_000
        assert path.read_bytes()[:2] == b"PK"  # an X3P zip, written by surfmet.write/encode
    assert plate.dx == pytest.approx(settings["plate_step_mm"] * 1e-3, rel=1e-9)
    assert ball.dx == pytest.approx(settings["ball_step_mm"] * 1e-3, rel=1e-9)
    # the ball scan covers the paper's 7.327 x 7.580 mm to within one step
    (w, h) = settings["ball_area_mm"]
    assert abs(ball.nx * ball.dx * 1e3 - w) <= 0.05 and abs(ball.ny * ball.dy * 1e3 - h) <= 0.05
    assert plate.nan_fraction == 0 and ball.nan_fraction == 0


def test_plate_rows_reproduce_table2(plate, paper):
    rows = paper["table2_profile_um"]["aluminium_plate"]
    st = _rows(plate, "plane")
    for key in ("Ra", "Rq", "Rz", "Rt"):
        table = np.array([r[key] for r in rows])
        med = float(np.median(st[key]))
        # within the spread of the paper's three profiles, and close to their mean
        assert table.min() <= med <= table.max(), key
        assert med == pytest.approx(table.mean(), rel=0.05), key


def test_plate_carries_a_few_spikes(plate):
    # Table 1's Sq/Sa up to 4.3 says the real scans had spikes; so does the stand-in,
    # and the spike detection finds them as isolated points
    from surfmet._spikes import remove_spikes

    raw = roughness(plate, which=("Sa", "Sq"))
    assert raw.spike_diagnosis.suspected
    cleaned, rep = remove_spikes(plate)
    assert 20 <= rep.count <= 200 and rep.n_points == rep.count
    clean = roughness(cleaned, which=("Sa", "Sq"))
    ratio = clean.value("Sq") / clean.value("Sa")
    assert ratio == pytest.approx(np.sqrt(np.pi / 2), abs=0.03)  # Gaussian underneath


def test_ball_rows_reproduce_table2_ra_rq(ball, paper):
    rows = paper["table2_profile_um"]["steel_ball"]
    st = _rows(ball, "poly:2")
    for key in ("Ra", "Rq"):
        table = np.array([r[key] for r in rows])
        med = float(np.median(st[key]))
        assert table.min() <= med <= table.max(), key


def test_ball_radius_and_a_measurable_form_deviation(ball):
    import profiles
    from surfmet._extract import extract_profile
    from surfmet.fitting import fit_sphere

    fit = fit_sphere(ball)
    assert fit.convex
    # a 20 mm nominal ball ...
    assert fit.radius == pytest.approx(0.02, rel=0.01)
    # ... whose measured radius differs from the nominal one by far more than its
    # uncertainty (Fig. 16), with a form deviation that the row and column fits resolve
    assert abs(fit.radius - 0.02) > 20 * fit.radius_uncertainty
    iy = round(fit.center[1] / ball.dy)
    ix = round(fit.center[0] / ball.dx)
    row = extract_profile(ball, f"row:{iy}")
    col = extract_profile(ball, f"col:{ix}")
    r_row = profiles.fit_circle(row.positions, row.z).radius
    r_col = profiles.fit_circle(col.positions, col.z).radius
    assert abs(r_row - r_col) > 0.1e-3
    assert min(r_row, r_col) < fit.radius < max(r_row, r_col)
