"""The BEM solver on the smooth sphere, against Hertz (free boundary, 256 x 256)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact import (
    DomainSpec,
    SolveOptions,
    SphereContact,
    composite_modulus,
    hertz_sphere,
    material,
    solve_sphere,
)
from contact._geometry import sphere_gap
from contact._grid import gap_grid
from contact.bem import solve_normal

E_STAR = composite_modulus(material("steel"), material("aluminium"))
R, W = 0.02, 10.0


@pytest.fixture(scope="module")
def smooth():
    hz = hertz_sphere(R, W, E_STAR)
    n = 256
    dx = 2.5 * hz.a / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx, origin=(-(n // 2) * dx, -(n // 2) * dx)),
                       e_star=E_STAR, load=W)
    return hz, res


def test_peak_pressure_and_radius_match_hertz(smooth):
    hz, res = smooth
    assert res.converged and not res.touches_edge
    assert abs(res.pmax / hz.p0 - 1) < 1e-4
    assert abs(res.contact_radius - hz.a) < res.dx
    assert res.n_clusters == 1
    # the peak sits on the apex cell, the centroid on the apex
    i, j = np.unravel_index(np.argmax(res.pressure), res.shape)
    assert (res.x[j], res.y[i]) == (0.0, 0.0)
    assert max(abs(c) for c in res.centroid) < 1e-6 * res.dx


def test_force_balance(smooth):
    _hz, res = smooth
    assert abs(res.pressure.sum() * res.dx * res.dy / W - 1) < 1e-10
    assert abs(res.load / W - 1) < 1e-10


def test_fields_match_hertz(smooth):
    hz, res = smooth
    r = res.radial_coordinates()
    # pressure: the semi-ellipsoid, up to the cells that straddle the contact edge
    err = np.abs(res.pressure - hz.pressure(r))
    assert err[r < 0.95 * hz.a].max() < 2e-3 * hz.p0
    # displacement and approach
    assert res.approach == pytest.approx(hz.delta, rel=1e-4)
    np.testing.assert_allclose(res.displacement[r < 0.9 * hz.a], hz.displacement(r[r < 0.9 * hz.a]),
                               rtol=2e-4)
    out = r > 1.1 * hz.a
    np.testing.assert_allclose(res.displacement[out], hz.displacement(r[out]), rtol=2e-3)
    # the gap is closed inside, open outside, never negative
    assert res.gap.min() >= 0
    assert np.all(res.gap[res.pressure > 0] == 0)
    assert np.all(res.gap[r > 1.05 * hz.a] > 0)
    # 95 % of a Hertz load lies within a (1 - 0.05^(2/3))^(1/2)
    assert res.radius_95 == pytest.approx(hz.a * math.sqrt(1 - 0.05 ** (2 / 3)), abs=1.5 * res.dx)


def test_approach_control_gives_the_hertz_load():
    hz = hertz_sphere(R, W, E_STAR)
    n = 128
    dx = 2.5 * hz.a / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, approach=hz.delta)
    assert res.load == pytest.approx(W, rel=1e-3)
    assert res.approach == hz.delta
    # short of contact: no load at all, and no complaint
    none = solve_normal(gap_grid(sphere_gap(n, dx, R) + 1e-6, dx), e_star=E_STAR, approach=0.5e-6)
    assert none.load == 0 and none.contact_area == 0 and none.converged


def test_mixed_and_double_precision_agree():
    hz = hertz_sphere(R, W, E_STAR)
    n = 128
    dx = 2.5 * hz.a / n
    h = sphere_gap(n, dx, R)
    a = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W,
                     options=SolveOptions(precision="mixed", tol=1e-8))
    b = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W,
                     options=SolveOptions(precision="double", tol=1e-8))
    assert np.abs(a.pressure - b.pressure).max() < 1e-6 * hz.p0
    c = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W,
                     options=SolveOptions(precondition=False, nested=False, tol=1e-8))
    assert np.abs(a.pressure - c.pressure).max() < 1e-6 * hz.p0


def test_solve_sphere_automatic_domain_and_warm_started_sweep():
    res = solve_sphere(R, W, E_STAR)
    assert res.shape == (256, 256)
    assert abs(res.pmax / res.hertz.p0 - 1) < 1e-4
    prob = SphereContact(R, E_STAR, 12.0, domain=DomainSpec(grid=128))
    cold = prob.solve(11.0)
    base = prob.solve(10.0)
    warm = prob.solve(11.0, initial=base)
    assert warm.iterations < sum(it for *_, it in cold.solve.counters["levels"])
    assert np.abs(warm.pressure - cold.pressure).max() < 1e-5 * cold.pmax
    sweep = prob.sweep([2.0, 4.0, 8.0])
    for r, w in zip(sweep, (2.0, 4.0, 8.0)):
        assert r.load == pytest.approx(w, rel=1e-12)
        assert r.pmax == pytest.approx(r.hertz.p0, rel=2e-3)
