"""Areal Gaussian filter (ISO 16610-61): transmission, edges, holes, errors."""

from __future__ import annotations

import math

import numpy as np
import pytest

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._filters import (
    ALPHA,
    _correlate_axis,
    gaussian_weights,
    l_filter,
    mean_surface,
    s_filter,
    transmission,
)


def _amplitude(x, z, lam):
    a = np.column_stack([np.sin(2 * np.pi * x / lam), np.cos(2 * np.pi * x / lam),
                         np.ones_like(x)])
    c, *_ = np.linalg.lstsq(a, z, rcond=None)
    return math.hypot(c[0], c[1])


@pytest.mark.parametrize("axis", [0, 1])
@pytest.mark.parametrize("ratio", [0.5, 1.0, 2.0])
def test_transmission_matches_iso_16610_61(axis, ratio):
    # Mean surface transmits exp(-π (α λc/λ)²): 50 % at λ = λc; roughness the rest.
    dx, lc = 1e-6, 80e-6
    lam = ratio * lc
    n = 1200
    x = np.arange(n) * dx
    z = np.tile(np.sin(2 * np.pi * x / lam + 0.3), (160, 1))
    if axis == 0:
        z = z.T
    topo = Topography(z, dx, dx)
    m = mean_surface(topo, lc)
    r, _ = l_filter(topo, lc)
    line_m = m[80, :] if axis == 1 else m[:, 80]
    line_r = r.heights[80, :] if axis == 1 else r.heights[:, 80]
    core = slice(200, 1000)
    assert _amplitude(x[core], line_m[core], lam) == pytest.approx(
        transmission(lam, lc), abs=2e-4)
    assert _amplitude(x[core], line_r[core], lam) == pytest.approx(
        1 - transmission(lam, lc), abs=2e-4)
    if ratio == 1.0:
        assert transmission(lam, lc) == pytest.approx(0.5, abs=1e-12)


def test_alpha_constant():
    assert ALPHA == pytest.approx(math.sqrt(math.log(2) / math.pi))
    assert ALPHA == pytest.approx(0.4697, abs=1e-4)


def test_fft_and_direct_correlation_agree_with_numpy():
    rng = np.random.default_rng(0)
    a = rng.standard_normal((7, 400))
    w = rng.standard_normal(151)  # odd kernel, long enough for the FFT path
    ref = np.array([np.correlate(np.pad(row, 75), w, mode="valid") for row in a])
    assert np.allclose(_correlate_axis(a, w, 1), ref, atol=1e-12)
    w_short = rng.standard_normal(9)
    ref = np.array([np.correlate(np.pad(row, 4), w_short, mode="valid") for row in a])
    assert np.allclose(_correlate_axis(a, w_short, 1), ref, atol=1e-12)


@pytest.mark.parametrize("holes", [False, True])
def test_moment_edge_treatment_keeps_a_plane_exactly(holes):
    rng = np.random.default_rng(1)
    j, i = np.mgrid[:150, :220]
    z = 1e-6 * (0.2 + 0.03 * i - 0.02 * j)
    if holes:
        z[rng.random(z.shape) < 0.2] = np.nan
        z[40:70, 90:130] = np.nan
    topo = Topography(z, 1e-6, 1e-6)
    r, info = l_filter(topo, 60e-6, edge="moment")
    assert info.edge == "moment"
    assert np.nanmax(np.abs(r.heights)) < 1e-18
    assert np.array_equal(np.isnan(r.heights), np.isnan(z))
    # The zeroth-order renormalisation bends a tilt near the edges (honest difference).
    r0, _ = l_filter(topo, 60e-6, edge="renormalise")
    assert np.nanmax(np.abs(r0.heights)) > 1e-8


def test_discard_band_and_interior_equality():
    rng = np.random.default_rng(2)
    z = rng.standard_normal((200, 260)) * 1e-6
    topo = Topography(z, 1e-6, 1e-6)
    rd, info = l_filter(topo, 50e-6, edge="discard")
    rm, _ = l_filter(topo, 50e-6, edge="moment")
    assert info.discarded == (25, 25)
    assert np.isnan(rd.heights[:25]).all() and np.isnan(rd.heights[:, -25:]).all()
    # More than λc from every edge all treatments are the plain ISO filter.
    core = (slice(50, 150), slice(50, 210))
    assert np.allclose(rd.heights[core], rm.heights[core], atol=1e-20)


def test_holes_do_not_spread_and_do_not_bias():
    rng = np.random.default_rng(3)
    _, i = np.mgrid[:200, :200]
    lam, dx = 20e-6, 0.8e-6  # ISO 25178-3 Table 1: λs 2.5 µm, sampling distance 0.8 µm
    z = np.sin(2 * np.pi * i * dx / lam) * 1e-6
    zh = z.copy()
    zh[rng.random(z.shape) < 0.3] = np.nan
    m, _ = s_filter(Topography(zh, dx, dx), 2.5e-6, edge="moment")
    ok = np.isfinite(zh)
    assert np.array_equal(np.isfinite(m.heights), ok)
    # λ = 8 λs: the S-filter passes 99.1 %; a zero-filled filter would lose 30 %.
    ratio = np.sum(m.heights[ok] * z[ok]) / np.sum(z[ok] ** 2)
    assert ratio == pytest.approx(transmission(lam, 2.5e-6), abs=0.01)


def test_weights_are_the_sampled_gaussian():
    w, k = gaussian_weights(100e-6, 1e-6)
    assert w.size == 201 and k[0] == -100
    assert w[100] == 1.0
    assert w[0] == pytest.approx(math.exp(-math.pi / ALPHA**2), rel=1e-12)


def test_too_small_scan_and_bad_cutoffs_raise():
    topo = Topography(np.zeros((50, 400)), 1e-6, 1e-6)
    with pytest.raises(SurfmetInputError, match="too small"):
        l_filter(topo, 80e-6)  # 50 µm tall scan, 80 µm cut-off
    with pytest.raises(SurfmetInputError):
        l_filter(topo, -1e-6)
    with pytest.raises(SurfmetInputError):
        l_filter(topo, 10e-6, edge="mirror")
    with pytest.raises(SurfmetInputError):
        l_filter(Topography(np.zeros((50, 50)), 1e-6, 1e-6), 49e-6, edge="discard")


def test_separable_moment_path_equals_the_general_3x3_solution():
    # Complete grids use separable weight moments; scans with holes solve the local 3 x 3
    # normal equations. On a complete grid both must give the same filter.
    from surfmet.areal._filters import _moment_full, _moment_masked

    rng = np.random.default_rng(4)
    z = rng.standard_normal((150, 260))
    gx, kx = gaussian_weights(50e-6, 1e-6)
    gy, ky = gaussian_weights(50e-6, 1.3e-6)
    full = _moment_full(z, gx, kx, gy, ky)
    general = _moment_masked(z, np.ones(z.shape, dtype=bool), gx, kx, gy, ky)
    assert np.allclose(full, general, atol=1e-12)
