"""Profile extraction from areal scans (rows, columns, bilinear lines)."""

from __future__ import annotations

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._extract import extract_profile
from surfmet._model import Topography
from surfmet.roughness import roughness


def _plane(ny=40, nx=60, dx=1e-6, dy=2e-6):
    j, i = np.mgrid[:ny, :nx]
    return Topography(3e-3 * i * dx - 2e-3 * j * dy + 1e-7, dx, dy)


def test_rows_and_columns():
    t = _plane()
    r = extract_profile(t, "row:5")
    assert r.dx == t.dx and np.array_equal(r.z, t.heights[5])
    c = extract_profile(t, "col:-1")
    assert c.dx == t.dy and np.array_equal(c.z, t.heights[:, -1])
    assert c.metadata["profile"] == "col:59"


def test_a_line_on_a_plane_is_exact_and_uses_the_finer_step():
    t = _plane()
    x0, y0, x1, y1 = 3e-6, 5e-6, 50e-6, 70e-6
    p = extract_profile(t, (x0, y0, x1, y1))
    assert p.dx == 1e-6
    s = np.arange(p.n) * p.dx / np.hypot(x1 - x0, y1 - y0)
    x, y = x0 + s * (x1 - x0), y0 + s * (y1 - y0)
    assert np.allclose(p.z, 3e-3 * x - 2e-3 * y + 1e-7, atol=1e-18)
    q = extract_profile(t, "0,0,50um,0")
    assert np.allclose(q.z, t.heights[0, :51], atol=1e-18)


def test_holes_are_not_bridged():
    z = _plane().heights.copy()
    z[10, 20] = np.nan
    t = Topography(z, 1e-6, 2e-6)
    p = extract_profile(t, (0, 20e-6, 59e-6, 20e-6))
    assert np.isnan(p.z[19:22]).sum() >= 1
    assert np.isfinite(p.z[:18]).all()


@pytest.mark.parametrize("spec", ["row:40", "col:x", "diag:3", (0, 0, 1.0, 0), (1, 2, 3)])
def test_bad_specs(spec):
    with pytest.raises(SurfmetInputError):
        extract_profile(_plane(), spec)


def test_roughness_of_an_extracted_row_gives_r_parameters():
    # A sine row of amplitude A: Ra = 2A/π through the profile engine ("plane" = line).
    dx, lam, amp = 0.5e-6, 50e-6, 0.2e-6
    x = np.arange(8000) * dx
    z = np.tile(amp * np.sin(2 * np.pi * x / lam) + 1e-3 * x, (5, 1))
    res = roughness(Topography(z, dx, dx), profile="row:2", lc=0.8e-3)
    assert res.kind == "profile"
    assert res.value("Ra") == pytest.approx(2 * amp / np.pi, rel=0.01)
    assert res.parameters["Ra"][1] == "m"
    assert res.settings["profile"] == "row:2"
