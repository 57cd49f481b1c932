"""3D steady viscoelastic rolling: the elastic limits (Hertz sphere), the creep filter
against direct quadrature (its numpy twin), the free-boundary Love kernel, rough input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._hertz import hertz_sphere
from contact.halfspace.influence import love_coefficients as love_kernel
from contact.viscoelastic._kernels import creep_filter_rows
from contact.viscoelastic._rheology import StandardLinearSolid, pair_creep
from contact.viscoelastic._surface import rolling_sphere

R, W, NU = 0.01, 1.0, 0.5
EG, ER = 30e6, 10e6
CG, CR = (1 - NU**2) / EG, (1 - NU**2) / ER
A_R = (3 * W * R * CR / 4) ** (1 / 3)


def _filter_twin(w: np.ndarray, x: np.ndarray, ell: float, tail) -> np.ndarray:
    """numpy twin: (1/l) int_0^inf e^{-xi/l} w(x + xi) dxi by dense trapezoids on a fine
    grid, with w linear between the nodes and ``tail(xi)`` beyond the last node."""
    out = np.empty_like(w)
    for i, xi0 in enumerate(x):
        s = np.linspace(0.0, x[-1] - xi0, 4000 * (len(x) - i) + 1)
        vals = np.interp(xi0 + s, x, w) * np.exp(-s / ell) / ell
        inside = np.trapezoid(vals, s) if s.size > 1 else 0.0
        out[i] = inside + math.exp(-(x[-1] - xi0) / ell) * tail
    return out


def test_creep_filter_matches_quadrature() -> None:
    x = np.linspace(0.0, 1.0, 21)
    w = np.sin(3 * x) + x**2
    ell = 0.3
    tail = 0.7
    ref = _filter_twin(w, x, ell, tail)
    got = creep_filter_rows(w[None, :].copy(), np.array([tail]), x[1] - x[0], ell)[0]
    assert np.allclose(got, ref, rtol=1e-6, atol=1e-7)


def test_love_kernel_centre_and_far_field() -> None:
    assert love_kernel(np.zeros(1), np.zeros(1), 1.0, 1.0)[0] == pytest.approx(
        4 * math.asinh(1.0) / math.pi)  # Johnson eq. 3.25 at the centre of a unit square
    far = love_kernel(np.array([20.0]), np.array([-7.0]), 1.0, 1.0)[0]
    assert far == pytest.approx(1 / (math.pi * math.hypot(20, 7)), rel=1e-3)


@pytest.mark.parametrize("limit", ["relaxed", "glassy"])
def test_sphere_elastic_limits_are_hertz(limit: str) -> None:
    tau = 1e-5 * A_R if limit == "relaxed" else 1e5 * A_R
    creep = pair_creep(None, StandardLinearSolid(EG, ER, tau, NU))
    res = rolling_sphere(R, W, creep, 1.0, n=128)
    hz = hertz_sphere(R, W, 1.0 / (CR if limit == "relaxed" else CG))
    assert res.pmax == pytest.approx(hz.p0, rel=0.01)
    assert res.leading == pytest.approx(hz.a, rel=0.01)
    assert -res.trailing == pytest.approx(hz.a, rel=0.01)
    assert res.approach == pytest.approx(hz.delta, rel=0.01)
    assert abs(res.rolling_resistance) < 1e-3 * hz.a / R


def test_sphere_rolling_is_asymmetric_and_converges() -> None:
    creep = pair_creep(None, StandardLinearSolid(EG, ER, A_R, NU))  # V tau = a_r
    res = {n: rolling_sphere(R, W, creep, 1.0, n=n) for n in (64, 128)}
    for r in res.values():
        assert r.gap_residual < 1e-5
        assert r.leading > -r.trailing  # contact shifted towards the leading edge
        assert r.rolling_resistance > 0
        assert float(np.asarray(r.pressure).sum()) * (r.x[1] - r.x[0]) ** 2 == \
            pytest.approx(W, rel=1e-9)
    mu64, mu128 = res[64].rolling_resistance, res[128].rolling_resistance
    assert mu128 == pytest.approx(mu64, rel=0.01)


def test_rough_sphere_runs_and_bad_input() -> None:
    rng = np.random.default_rng(4)
    z = 0.02 * A_R**2 / (2 * R) * rng.standard_normal((64, 64))
    creep = pair_creep(None, StandardLinearSolid(EG, ER, A_R, NU))
    r = rolling_sphere(R, W, creep, 1.0, n=64, roughness=z)
    assert r.rolling_resistance > 0
    with pytest.raises(ContactInputError, match="speed"):
        rolling_sphere(R, W, creep, 0.0, n=64)
    with pytest.raises(ContactInputError, match="shape"):
        rolling_sphere(R, W, creep, 1.0, n=64, roughness=np.zeros((8, 8)))


def test_against_dense_reference() -> None:
    """FFT + recursive filter + tail + splitting vs a dense quadrature of the hereditary
    integral solved by a dense active set (tests/viscoelastic_dense.py). The two
    discretisations differ at O(dx^2) (the filter takes w linear between nodes), so the
    difference must shrink ~4x from 16^2 to 32^2 and be small at 32^2."""
    from viscoelastic_dense import dense_influence, dense_solve

    creep = pair_creep(None, StandardLinearSolid(EG, ER, A_R, NU))
    diffs = {}
    for n in (16, 32):
        half = 1.6 * A_R
        dx = 2 * half / n
        x = -half + dx / 2 + np.arange(n) * dx
        h = ((x[None, :] ** 2 + x[:, None] ** 2) / (2 * R)).ravel()
        A = dense_influence(n, dx, creep.glassy, creep.amplitudes, creep.times, 1.0)
        p, delta = dense_solve(A, h, W, dx * dx)
        mu = float((p.reshape(n, n).sum(axis=0) * x).sum() * dx * dx / (W * R))
        res = rolling_sphere(R, W, creep, 1.0, n=n)
        diffs[n] = (res.rolling_resistance / mu - 1, res.pmax / p.max() - 1,
                    res.approach / delta - 1)
    for k in range(3):
        assert abs(diffs[32][k]) < 3.5e-3
        assert abs(diffs[16][k]) > 2.5 * abs(diffs[32][k])


def test_coarse_start_leaves_the_solution() -> None:
    """The nested start (the 64^2 solution interpolated) changes where the outer iteration
    begins, not where it ends: both starts reach the same pressure within the tolerance."""
    creep = pair_creep(None, StandardLinearSolid(EG, ER, A_R, NU))
    cold = rolling_sphere(R, W, creep, 1.0, n=128, nested=False)
    warm = rolling_sphere(R, W, creep, 1.0, n=128)
    p_cold, p_warm = np.asarray(cold.pressure), np.asarray(warm.pressure)
    assert np.abs(p_warm - p_cold).max() < 2e-5 * p_cold.max()
    assert warm.rolling_resistance == pytest.approx(cold.rolling_resistance, rel=1e-5)
    assert warm.iterations < cold.iterations
