"""Elastic-perfectly-plastic contact: the pressure cap, load balance, the regime report.

Truths used here, none of them the solver checking itself:

- a brute-force solve: on a small grid the discrete problem (dense Love influence matrix,
  0 <= p <= H) at the solver's approach is a bound-constrained least-squares problem,
  solved exactly by the active-set BVLS of scipy (Stark & Parker 1995); its pressure and
  its load must be the solver's;
- the contact conditions, with the displacement recomputed by a plain linear convolution
  of the pressure with the Love kernel (scipy.signal, not the solver's DC-FFT);
- the plastic-displacement fixed point of ``tests/plastic_reference.py``, an independent
  algorithm built on elastic solves only;
- the fully plastic limit: as p0/H grows the whole contact carries H, so its radius tends
  to sqrt(W / (pi H)).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from contact_synth import rough_surface
from plastic_reference import fixed_point_plastic
from scipy.linalg import cholesky, solve_triangular
from scipy.optimize import lsq_linear
from scipy.signal import fftconvolve

from contact import (
    ConvergenceError,
    DomainSpec,
    PressureBounds,
    SolveOptions,
    composite_modulus,
    hertz_sphere,
    material,
    solve_sphere,
)
from contact._geometry import sphere_gap
from contact._grid import gap_grid
from contact.bem import solve_normal
from contact.halfspace.influence import love_coefficients, self_influence
from contact.setups import CompositeRoughness
from contact.setups._ball_on_plate import SphereContact

E_STAR = composite_modulus(material("steel"), material("aluminium"))
H_AL = material("aluminium").hardness
R, W = 0.02, 10.0
HZ = hertz_sphere(R, W, E_STAR)


def _plastic_radius(H):
    return math.sqrt(W / (math.pi * H))


def _smooth_problem(ratio, n, side=2.6):
    """Smooth ball with Hertz p0 = ratio * H on an n x n grid around the contact."""
    H = HZ.p0 / ratio
    dx = side * max(_plastic_radius(H), HZ.a) / n
    return sphere_gap(n, dx, R), dx, H


def _displacement(p, dx, dy, e_star):
    """u = K * p / E* by direct linear convolution with Love's kernel (no DC-FFT)."""
    ny, nx = p.shape
    oy = np.arange(-(ny - 1), ny)[:, None] * dy
    ox = np.arange(-(nx - 1), nx)[None, :] * dx
    full = fftconvolve(p, love_coefficients(ox, oy, dx, dy), mode="full")
    return full[ny - 1:2 * ny - 1, nx - 1:2 * nx - 1] / e_star


def _check_contact_conditions(res, h, H, load, rel=1e-6):
    """p in [0, H], load balance, gap/pressure complementarity, plastic closure."""
    p = np.asarray(res.pressure)
    assert p.min() >= 0 and p.max() <= H
    assert p.sum() * res.dx * res.dy == pytest.approx(load, rel=1e-10)
    u = _displacement(p, res.dx, res.dy, res.e_star)
    # one cell's displacement under the hardness: the natural scale of the gap errors
    scale = self_influence(res.dx, res.dy) * H / res.e_star
    assert np.abs(u - res.displacement).max() < rel * scale
    g = h + u - res.approach
    free = (p > 0) & (p < H)
    capped = p >= H
    out = p == 0
    assert free.any() and capped.any()
    assert np.abs(g[free]).max() < rel * scale  # elastic contact: closed gap
    assert g[out].min() > -rel * scale  # no overlap out of contact
    # capped cells interpenetrate elastically by exactly the plastic displacement
    upl = np.asarray(res.plastic_displacement)
    assert np.abs((g + upl)[capped]).max() < rel * scale
    assert upl.min() >= 0 and np.all(upl[~capped] == 0)
    assert np.all(np.asarray(res.gap)[p > 0] == 0)
    return g


def _bvls_pressure(h, dx, e_star, approach, H):
    """Exact solution of min p.K p/2 + (h - delta).p over 0 <= p <= H, dense K."""
    ny, nx = h.shape
    iy, ix = np.divmod(np.arange(ny * nx), nx)
    K = love_coefficients((ix[:, None] - ix[None, :]) * dx, (iy[:, None] - iy[None, :]) * dx,
                          dx, dx) / e_star
    L = cholesky(K, lower=True)  # p.K p/2 + c.p = |L^T p + L^-1 c|^2 / 2 + const
    b = -solve_triangular(L, (h - approach).ravel(), lower=True)
    sol = lsq_linear(L.T, b, bounds=(0.0, H), method="bvls", tol=1e-14)
    assert sol.status > 0
    return sol.x.reshape(h.shape)


@pytest.mark.parametrize("ratio", [1.5, 4.0, 10.0])
def test_smooth_plastic_ball_matches_a_brute_force_solve(ratio):
    h, dx, H = _smooth_problem(ratio, 24)
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W, bounds=PressureBounds.elastic(H),
                       options=SolveOptions(tol=1e-10, precision="double"))
    assert res.converged and not res.touches_edge
    ref = _bvls_pressure(h, dx, E_STAR, res.approach, H)
    # the same pressure field, and the brute force at the solver's approach carries W
    assert np.abs(ref - res.pressure).max() < 1e-8 * H
    assert ref.sum() * dx * dx == pytest.approx(W, rel=1e-9)
    assert res.plastic_area > 0


def test_approach_control_matches_a_brute_force_solve():
    h, dx, H = _smooth_problem(4.0, 24)
    delta = 1.5 * HZ.delta
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, approach=delta,
                       bounds=PressureBounds.elastic(H),
                       options=SolveOptions(tol=1e-10, precision="double"))
    assert res.converged and res.approach == delta
    ref = _bvls_pressure(h, dx, E_STAR, delta, H)
    assert np.abs(ref - res.pressure).max() < 1e-8 * H
    assert res.load == pytest.approx(ref.sum() * dx * dx, rel=1e-9)


@pytest.mark.parametrize("ratio", [1.5, 4.0, 10.0])
def test_smooth_plastic_ball_converges_and_meets_the_contact_conditions(ratio):
    h, dx, H = _smooth_problem(ratio, 128)
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W, bounds=PressureBounds.elastic(H),
                       options=SolveOptions(tol=1e-8))
    assert res.converged and not res.touches_edge
    assert res.iterations < 100
    _check_contact_conditions(res, h, H, W)
    assert res.regime == "plastic at the Hertz scale"


@pytest.mark.parametrize("ratio", [1.5, 4.0])
def test_capped_solver_agrees_with_the_plastic_displacement_fixed_point(ratio):
    H = HZ.p0 / ratio
    prob = SphereContact(
        R, E_STAR, W, domain=DomainSpec(grid=64, size=2.6 * max(_plastic_radius(H), HZ.a))
    )
    el = prob.solve(W)
    capped = prob.solve(W, hardness=H, initial=el, on_edge="warn", options=SolveOptions(tol=1e-10))
    fixed = fixed_point_plastic(prob, W, H, el, tol=1e-10, yield_tol=1e-6)
    # stated tolerance: the fixed point stops at p <= H (1 + 1e-6) on the yielded cells
    assert np.abs(np.asarray(fixed.pressure) - capped.pressure).max() < 1e-5 * H
    upl = np.asarray(capped.plastic_displacement)
    assert np.abs(np.asarray(fixed.plastic_displacement) - upl).max() < 1e-5 * upl.max()
    assert fixed.approach == pytest.approx(capped.approach, rel=1e-6)


def test_contact_radius_tends_to_the_fully_plastic_limit():
    # W = H * plastic area + elastic fringe; as p0/H grows the fringe narrows and the
    # radius tends to sqrt(W / (pi H)) from above (the grid is scaled with that radius,
    # 66 cells per radius, so the fringe is resolved down to about one cell)
    dev = []
    fringe = []
    for ratio in (1.5, 2.5, 4.0, 10.0):
        h, dx, H = _smooth_problem(ratio, 160, side=2.4)
        res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W, bounds=PressureBounds.elastic(H))
        assert res.converged and res.pmax <= H
        assert res.load == pytest.approx(W, rel=1e-10)
        dev.append(res.contact_radius / _plastic_radius(H) - 1)
        fringe.append(1 - res.plastic_area / res.contact_area)
    assert all(b < a for a, b in itertools.pairwise(dev))
    assert all(b < a for a, b in itertools.pairwise(fringe))
    assert dev[0] > 0.03  # the elastic fringe is wide at p0 = 1.5 H
    assert 0 <= dev[-1] < 1e-3
    assert fringe[-1] < 2e-3


def test_plastic_displacement_closes_the_gap():
    # on capped cells the surfaces interpenetrate elastically by exactly the plastic
    # displacement: h + u - delta + u_plastic = 0
    n = 96
    dx = 4 * HZ.a / n
    h = sphere_gap(n, dx, R)
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W,
                       bounds=PressureBounds.elastic(0.7 * HZ.p0), options=SolveOptions(tol=1e-8))
    capped = res.pressure >= res.hardness
    closure = h + res.displacement - res.approach + res.plastic_displacement
    assert np.abs(closure[capped]).max() < 1e-6 * HZ.delta


@pytest.mark.parametrize("ratio", [0.9, 0.6])
def test_pressure_is_capped_and_load_balanced(ratio):
    H = ratio * HZ.p0
    n = 128
    dx = 4 * HZ.a / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, load=W,
                       bounds=PressureBounds.elastic(H))
    assert res.converged
    assert res.pmax <= H
    assert res.pressure.sum() * dx * dx == pytest.approx(W, rel=1e-10)
    assert res.plastic_area > 0
    # the capped cells carry H: W lies between H * plastic area and H * contact area
    assert H * res.plastic_area <= W <= H * res.contact_area
    # the plastic displacement lives exactly on the capped cells and is an indentation
    capped = res.pressure >= H
    assert np.all(res.plastic_displacement[~capped] == 0)
    assert res.plastic_displacement[capped].max() > 0
    assert res.plastic_displacement.min() >= 0
    # the cap flattens the peak and spreads the contact beyond the Hertz radius
    assert res.contact_radius > HZ.a
    assert res.regime == "plastic at the Hertz scale"


def test_paper_pair_converges_plastic_at_the_asperity_scale():
    # the paper's plate and ball (stand-in scans): the capped solver used to stop after a
    # few iterations with every loaded cell at the cap
    from importlib import resources

    from surfmet.mechanics.scan_preparation import prepare_scans

    data = resources.files("surfmet").joinpath("data")
    prep = prepare_scans(str(data / "paper_plate.x3p"), str(data / "paper_ball.x3p"))
    rough = CompositeRoughness(prep.pair.roughness, prep.pair.dx)
    prob = SphereContact(R, E_STAR, W, roughness=rough, hardness=H_AL)
    res = prob.solve(W, options=SolveOptions(tol=1e-8))
    assert res.converged and not res.touches_edge
    _check_contact_conditions(res, prob.gap0, H_AL, W)
    # p0 < H: elastic at the Hertz scale, yet most of the real contact yields
    assert HZ.p0 < H_AL
    assert res.regime == "plastic at the asperity scale"
    assert res.plastic_area / res.contact_area > 0.5
    assert any("asperity scale" in note for note in res.notes)


@pytest.mark.parametrize("seed", [3, 11])
def test_rough_ball_on_cold_and_warm_starts(seed):
    # most loaded cells of the clipped elastic warm start sit at the cap (few free cells
    # left to step on); from no start the nested coarse grids lead the way
    zdx = 4e-6
    z = rough_surface(256, zdx, 1.5e-6, seed=seed, corr=12e-6)
    prob = SphereContact(
        R, E_STAR, 1.0, roughness=CompositeRoughness(z, zdx), domain=DomainSpec(grid=160)
    )
    el = prob.solve(1.0)
    dx = prob.domain.dx
    start = np.minimum(el.pressure, H_AL)
    assert (start == H_AL).sum() > 0.5 * (start > 0).sum()
    warm = solve_normal(gap_grid(prob.gap0, dx), e_star=E_STAR, load=1.0, initial=start,
                        bounds=PressureBounds.elastic(H_AL), options=SolveOptions(tol=1e-8))
    cold = solve_normal(gap_grid(prob.gap0, dx), e_star=E_STAR, load=1.0,
                        bounds=PressureBounds.elastic(H_AL), options=SolveOptions(tol=1e-8))
    for res in (warm, cold):
        assert res.converged
        _check_contact_conditions(res, prob.gap0, H_AL, 1.0)
    assert np.abs(warm.pressure - cold.pressure).max() < 1e-5 * H_AL


def test_plastic_at_asperity_scale_but_elastic_at_hertz_scale():
    assert HZ.p0 < H_AL  # the smooth ball would stay elastic
    zdx = 5e-6
    z = rough_surface(256, zdx, 0.5e-6, seed=3)
    res = solve_sphere(
        R,
        W,
        E_STAR,
        roughness=CompositeRoughness(z, zdx),
        hardness=H_AL,
        domain=DomainSpec(grid=128),
    )
    assert res.converged and not res.touches_edge
    assert res.pmax <= H_AL
    assert res.load == pytest.approx(W, rel=1e-10)
    assert res.plastic_area > 0
    assert res.regime == "plastic at the asperity scale"
    assert any("asperity scale" in note and "elastic at the Hertz scale" in note
               for note in res.notes)
    # the clean (smooth) ball with the same hardness: elastic, nothing reported
    smooth = solve_sphere(R, W, E_STAR, hardness=H_AL, domain=DomainSpec(grid=128))
    assert smooth.plastic_area == 0
    assert smooth.regime == "elastic"
    assert not any("plastic" in note for note in smooth.notes)
    assert smooth.pmax == pytest.approx(HZ.p0, rel=2e-3)


def test_plastic_non_convergence_raises_with_the_residual():
    h, dx, H = _smooth_problem(4.0, 128)
    with pytest.raises(ConvergenceError) as err:
        solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W, bounds=PressureBounds.elastic(H),
                     options=SolveOptions(max_iter=2, tol=1e-12, nested=False))
    assert err.value.iterations == 2
    assert err.value.residual > 1e-12
    assert "residual" in str(err.value)
    # not strict: flagged, and still a feasible, load-balanced pressure field
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=W, bounds=PressureBounds.elastic(H),
                       options=SolveOptions(max_iter=2, tol=1e-12, nested=False, strict=False))
    assert not res.converged and res.iterations == 2
    assert res.pmax <= H
    assert res.load == pytest.approx(W, rel=1e-10)


@pytest.mark.parametrize("ratio", [4.0, 10.0])
def test_solve_sphere_sizes_the_domain_for_a_plastic_contact(ratio):
    """With a hardness the automatic domain must hold the fully plastic contact, whose
    radius sqrt(W / (pi H)) exceeds the Hertz radius once p0 > 1.5 H."""
    from contact import hertz_sphere, solve_sphere

    hz = hertz_sphere(0.02, 10.0, E_STAR)
    hardness = hz.p0 / ratio
    res = solve_sphere(0.02, 10.0, E_STAR, hardness=hardness, on_edge="raise")
    a_pl = math.sqrt(10.0 / (math.pi * hardness))
    assert res.converged and not res.touches_edge
    assert np.asarray(res.pressure).max() <= hardness * (1 + 1e-12)
    assert res.contact_radius == pytest.approx(a_pl, rel=0.01)
    assert res.contact_radius > 1.5 * hz.a
