"""Periodic solver against Westergaard's wavy surface (Johnson 1985, sec. 13.2).

Surface h(x) = Delta (1 - cos(2 pi x / lambda)) against a flat, plane strain. Full contact
needs the mean pressure p* = pi E* Delta / lambda (Delta the amplitude); below it the
contact strips have half-width a with p_mean = p* sin^2(pi a / lambda), and the pressure is
p(x) = 2 p_mean cos(pi x/lambda) sqrt(sin^2(pi a/lambda) - sin^2(pi x/lambda))
/ sin^2(pi a/lambda).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact import SolveOptions
from contact._grid import gap_grid
from contact.bem import solve_normal

E_STAR, LAM, DELTA = 80e9, 1e-3, 1e-6
NX, NY = 512, 4
DX = LAM / NX
X = np.arange(NX) * DX
PSTAR = math.pi * E_STAR * DELTA / LAM


def _solve(frac):
    h = np.tile(DELTA * (1 - np.cos(2 * np.pi * X / LAM)), (NY, 1))
    load = frac * PSTAR * LAM * NY * DX
    return solve_normal(gap_grid(h, DX, periodic=True), e_star=E_STAR, load=load,
                        options=SolveOptions(tol=1e-8))


@pytest.mark.parametrize("frac", [0.05, 0.3, 0.6, 0.9])
def test_partial_contact_area_and_pressure(frac):
    res = _solve(frac)
    p = res.pressure[0]
    a = LAM / math.pi * math.asin(math.sqrt(frac))
    width = np.count_nonzero(p > 0) * DX
    assert abs(width - 2 * a) <= 2 * DX  # each strip edge to within a cell
    s = math.sin(math.pi * a / LAM)
    xs = np.where(X > LAM / 2, X - LAM, X)
    exact = 2 * frac * PSTAR * np.cos(np.pi * xs / LAM) / s**2 * np.sqrt(
        np.clip(s**2 - np.sin(np.pi * xs / LAM) ** 2, 0, None))
    assert res.pmax == pytest.approx(2 * frac * PSTAR / s, rel=2e-4)
    inner = np.abs(xs) < 0.9 * a
    assert np.abs(p - exact)[inner].max() < 2e-3 * exact.max()
    # uniform along the cylinder axis
    assert np.ptp(res.pressure, axis=0).max() < 1e-9 * res.pmax
    assert res.n_clusters == 1


def test_full_contact_threshold_is_pi_e_delta_over_lambda():
    below = _solve(0.98)
    above = _solve(1.02)
    assert not (below.pressure > 0).all()
    assert (above.pressure > 0).all()


@pytest.mark.parametrize("frac", [1.2, 2.0])
def test_full_contact_pressure_is_mean_plus_cosine(frac):
    res = _solve(frac)
    exact = frac * PSTAR + PSTAR * np.cos(2 * np.pi * X / LAM)
    # the piecewise-constant cells see the cosine through sinc(q dx/2): ~6e-6 here
    assert np.abs(res.pressure[0] - exact).max() < 2e-5 * PSTAR
    assert res.area_fraction == 1.0


def test_periodic_clusters_wrap_around():
    # shift the surface by half a period: the single contact strip now straddles x = 0
    h = np.tile(DELTA * (1 + np.cos(2 * np.pi * X / LAM)), (NY, 1))
    res = solve_normal(gap_grid(h, DX, periodic=True), e_star=E_STAR,
                       load=0.3 * PSTAR * LAM * NY * DX)
    assert res.pressure[0, 0] == 0 and res.pressure[0, NX // 2] > 0
    h2 = np.tile(DELTA * (1 - np.cos(2 * np.pi * X / LAM)), (NY, 1))
    res2 = solve_normal(gap_grid(h2, DX, periodic=True), e_star=E_STAR,
                        load=0.3 * PSTAR * LAM * NY * DX)
    assert res2.pressure[0, 0] > 0 and res2.pressure[0, -1] > 0
    assert res2.n_clusters == 1 == res.n_clusters
