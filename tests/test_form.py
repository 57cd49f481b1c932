"""F-operators: least-squares forms recovered from synthetic scans with hidden form."""

from __future__ import annotations

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._form import parse_method, remove_form


def _xy(ny, nx, dx, dy):
    j, i = np.mgrid[:ny, :nx]
    return i * dx, j * dy


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_plane_and_quadric_coefficients_are_recovered(seed):
    rng = np.random.default_rng(seed)
    ny, nx = rng.integers(40, 200, 2)
    dx, dy = rng.uniform(0.2e-6, 5e-6, 2)
    X, Y = _xy(ny, nx, dx, dy)
    c = {"1": rng.normal(0, 1e-5), "x": rng.normal(0, 0.05), "y": rng.normal(0, 0.05),
         "x^2": rng.normal(0, 50), "x*y": rng.normal(0, 50), "y^2": rng.normal(0, 50)}
    z = (c["1"] + c["x"] * X + c["y"] * Y + c["x^2"] * X**2 + c["x*y"] * X * Y
         + c["y^2"] * Y**2)
    noise = 1e-9 * rng.standard_normal(z.shape)
    z = z + noise
    z[rng.random(z.shape) < rng.uniform(0, 0.5)] = np.nan  # NaN-aware
    res, fit = remove_form(Topography(z, dx, dy), "poly:2")
    got = dict(zip(fit.terms, fit.coefficients))
    scale = {"1": 1.0, "x": nx * dx, "y": ny * dy, "x^2": (nx * dx) ** 2,
             "x*y": nx * dx * ny * dy, "y^2": (ny * dy) ** 2}
    for term, true in c.items():
        # coefficient error measured in height over the scan: below 10 noise σ
        assert abs(got[term] - true) * scale[term] < 1e-8, term
    assert fit.residual_rms == pytest.approx(1e-9, rel=0.2)
    assert np.array_equal(np.isnan(res.heights), np.isnan(z))


def test_plane_equals_numpy_lstsq_on_valid_points():
    rng = np.random.default_rng(5)
    z = rng.normal(0, 1e-6, (120, 90)) + 1e-3 * _xy(120, 90, 1e-6, 1e-6)[0]
    z[rng.random(z.shape) < 0.2] = np.nan
    res, fit = remove_form(Topography(z, 1e-6, 1e-6), "plane")
    jj, ii = np.nonzero(np.isfinite(z))
    a = np.column_stack([np.ones(ii.size), ii * 1e-6, jj * 1e-6])
    coef, *_ = np.linalg.lstsq(a, z[jj, ii], rcond=None)
    assert np.allclose(fit.coefficients, coef, rtol=1e-9, atol=1e-18)
    assert np.allclose(res.heights[jj, ii], z[jj, ii] - a @ coef, atol=1e-18)


def test_high_degree_polynomial_is_well_conditioned():
    X, Y = _xy(300, 300, 1e-6, 1e-6)
    u = X / X.max()
    z = 1e-6 * (u**7 - 0.5 * u**3) * np.cos(Y / Y.max())
    _, fit = remove_form(Topography(z, 1e-6, 1e-6), "poly:10")
    assert fit.residual_rms < 1e-6 * 1e-6  # cos is a polynomial to 1e-7 at degree 10
    assert fit.method == "poly:10" and len(fit.terms) == 66


def test_mean_and_none():
    z = np.arange(12.0).reshape(3, 4) * 1e-6
    z[0, 0] = np.nan
    r, f = remove_form(Topography(z, 1e-6, 1e-6), "mean")
    assert np.nanmean(r.heights) == pytest.approx(0, abs=1e-18)
    assert f.coefficients[0] == pytest.approx(np.nanmean(z))
    r, f = remove_form(Topography(z, 1e-6, 1e-6), "none")
    assert np.array_equal(r.heights, z, equal_nan=True) and f.method == "none"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_sphere_form_is_removed(seed):
    rng = np.random.default_rng(seed)
    R = rng.uniform(2e-3, 20e-3)
    n, dx = 150, 2e-6
    X, Y = _xy(n, n, dx, dx)
    xc, yc = rng.uniform(0.3, 0.7, 2) * n * dx
    sign = rng.choice([-1, 1])
    z = sign * np.sqrt(R**2 - (X - xc) ** 2 - (Y - yc) ** 2) + 1e-9 * rng.standard_normal(X.shape)
    res, fit = remove_form(Topography(z, dx, dx), "sphere")
    assert fit.shape["radius"] == pytest.approx(R, rel=1e-3)
    assert fit.shape["convex"] == (sign > 0)
    assert np.nanstd(res.heights) == pytest.approx(1e-9, rel=0.2)


@pytest.mark.parametrize("axis, angle", [("cylinder:x", 0.0), ("cylinder:y", 90.0),
                                         ("cylinder", 37.0)])
def test_cylinder_form_is_removed(axis, angle):
    rng = np.random.default_rng(4)
    R, n, dx = 4e-3, 160, 2e-6
    X, Y = _xy(n, n, dx, dx)
    th = np.radians(angle)
    u = -(X - 1.5e-4) * np.sin(th) + (Y - 1.7e-4) * np.cos(th)
    z = np.sqrt(R**2 - u**2) + 2e-4 * (X * np.cos(th) + Y * np.sin(th))  # axis tilt
    z += 1e-9 * rng.standard_normal(z.shape)
    res, fit = remove_form(Topography(z, dx, dx), axis)
    assert fit.shape["radius"] == pytest.approx(R, rel=2e-3)
    assert fit.shape["azimuth"] == pytest.approx(angle, abs=0.2)
    assert np.nanstd(res.heights) < 2e-9


def test_bad_methods_and_data():
    t = Topography(np.zeros((5, 5)), 1e-6, 1e-6)
    for bad in ("parabola", "poly:x", "poly:99", "cylinder:z"):
        with pytest.raises(SurfmetInputError):
            remove_form(t, bad)
    with pytest.raises(SurfmetInputError):
        remove_form(Topography(np.full((3, 3), np.nan), 1e-6, 1e-6), "plane")
    with pytest.raises(SurfmetInputError):
        remove_form(Topography(np.array([[1.0, np.nan], [np.nan, np.nan]]), 1e-6, 1e-6),
                    "poly:2")
    assert parse_method("PLANE") == ("plane", 1)
