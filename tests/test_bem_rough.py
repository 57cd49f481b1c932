"""Rough ball on a plate: hidden tilt and offset, domain edges, enlargement."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from contact_synth import rough_surface

from contact import (
    DomainSpec,
    EdgeContactError,
    EdgeContactWarning,
    SolveOptions,
    composite_modulus,
    hertz_sphere,
    material,
    solve_sphere,
)
from contact.setups import CompositeRoughness

E_STAR = composite_modulus(material("steel"), material("aluminium"))
R, W = 0.02, 10.0
ZDX = 5e-6


@pytest.fixture(scope="module")
def base():
    z = rough_surface(256, ZDX, 0.5e-6, seed=11)
    return z, solve_sphere(
        R, W, E_STAR, roughness=CompositeRoughness(z, ZDX), domain=DomainSpec(grid=128)
    )


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_hidden_tilt_and_offset_do_not_change_the_result(base, seed):
    z, clean = base
    rng = np.random.default_rng(seed)
    sx, sy = rng.uniform(-2e-3, 2e-3, 2)
    offset = rng.uniform(-50e-6, 50e-6)
    yy, xx = np.indices(z.shape)
    tilted = z + offset + sx * xx * ZDX + sy * yy * ZDX
    res = solve_sphere(
        R, W, E_STAR, roughness=CompositeRoughness(tilted, ZDX), domain=DomainSpec(grid=128)
    )
    for name in ("pmax", "contact_area", "load", "approach", "radius_95"):
        assert getattr(res, name) == pytest.approx(getattr(clean, name), rel=1e-8), name
    assert res.n_clusters == clean.n_clusters
    np.testing.assert_allclose(res.pressure, clean.pressure, atol=1e-8 * clean.pmax)
    plane = res.extra["removed_plane"]
    assert plane["slope_x"] == pytest.approx(sx, abs=1e-4)
    assert plane["slope_y"] == pytest.approx(sy, abs=1e-4)


def test_clean_rough_result_is_sensible(base):
    _z, res = base
    hz = hertz_sphere(R, W, E_STAR)
    assert res.converged and not res.touches_edge
    assert res.load == pytest.approx(W, rel=1e-10)
    assert res.n_clusters > 5  # asperity spots, not one Hertz disc
    assert res.contact_area < np.pi * hz.a**2  # real area below the Hertz area
    assert res.pmax > hz.p0  # asperity peaks above the smooth peak
    assert res.radius_95 > 0.5 * hz.a
    assert "removed_plane" in res.extra


def test_tilt_without_levelling_moves_the_contact_by_r_times_slope():
    # a smooth but tilted plate: the ball rolls to where the plane is tangent to it
    hz = hertz_sphere(R, W, E_STAR)
    n, zdx = 200, 4e-6
    slope = 4e-3  # apex shifts by R * slope = 80 um
    _yy, xx = np.indices((n, n))
    plane = -slope * xx * zdx  # plate falls away towards +x: contact moves to +x
    res = solve_sphere(
        R,
        W,
        E_STAR,
        roughness=CompositeRoughness(plane, zdx, level=False),
        domain=DomainSpec(size=5 * hz.a, grid=128),
    )
    assert res.centroid[0] == pytest.approx(-R * slope, abs=res.dx)
    assert abs(res.centroid[1]) < res.dx
    assert res.pmax == pytest.approx(hz.p0, rel=2e-3)
    lev = solve_sphere(
        R,
        W,
        E_STAR,
        roughness=CompositeRoughness(plane, zdx, level=True),
        domain=DomainSpec(size=5 * hz.a, grid=128),
    )
    assert abs(lev.centroid[0]) < 1e-3 * res.dx


def test_scan_too_small_raises_or_warns_never_silently_truncates():
    hz = hertz_sphere(R, W, E_STAR)
    zdx = 2e-6
    n = int(1.4 * hz.a / zdx)  # the scan is narrower than the contact diameter
    z = rough_surface(n, zdx, 0.05e-6, seed=5)
    with pytest.raises(EdgeContactError, match="roughness data end"):
        solve_sphere(R, W, E_STAR, roughness=CompositeRoughness(z, zdx))
    with pytest.warns(EdgeContactWarning, match="truncated"):
        res = solve_sphere(R, W, E_STAR, roughness=CompositeRoughness(z, zdx), on_edge="warn")
    assert res.touches_edge
    assert any("truncated" in note for note in res.notes)
    with pytest.raises(EdgeContactError):
        solve_sphere(R, W, E_STAR, roughness=CompositeRoughness(z, zdx), on_edge="raise")


def test_too_small_domain_is_enlarged_and_says_so():
    hz = hertz_sphere(R, W, E_STAR)
    with pytest.warns(EdgeContactWarning, match="enlarged"):
        res = solve_sphere(R, W, E_STAR, domain=DomainSpec(size=1.2 * hz.a, grid=64))
    assert not res.touches_edge
    assert res.shape[0] > 64
    assert any("enlarged" in note for note in res.notes)
    assert res.pmax == pytest.approx(hz.p0, rel=2e-3)


def test_enlarged_rough_domain_matches_a_large_one():
    z = rough_surface(400, ZDX, 0.3e-6, seed=21)
    with pytest.warns(EdgeContactWarning):
        small = solve_sphere(
            R,
            W,
            E_STAR,
            roughness=CompositeRoughness(z, ZDX),
            domain=DomainSpec(size=40 * ZDX),
            options=SolveOptions(tol=1e-8),
        )
    with warnings.catch_warnings():
        warnings.simplefilter("error", EdgeContactWarning)
        m = small.shape[0] + 40
        big = solve_sphere(
            R,
            W,
            E_STAR,
            roughness=CompositeRoughness(z, ZDX),
            domain=DomainSpec(size=m * small.dx, grid=m),
            options=SolveOptions(tol=1e-8),
        )
    assert small.dx == big.dx
    assert small.pmax == pytest.approx(big.pmax, rel=1e-5)
    assert small.contact_area == pytest.approx(big.contact_area, rel=1e-9)
    assert small.approach == pytest.approx(big.approach, rel=1e-6)


def test_raw_solver_warns_when_the_contact_is_cut_by_the_domain():
    from contact import SolveOptions
    from contact._geometry import sphere_gap
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    hz = hertz_sphere(R, W, E_STAR)
    n = 64
    dx = 1.6 * hz.a / n  # the Hertz disc does not fit
    with pytest.warns(EdgeContactWarning, match="truncated"):
        res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, load=W)
    assert res.touches_edge and any("truncated" in note for note in res.notes)
    with warnings.catch_warnings():
        warnings.simplefilter("error", EdgeContactWarning)
        quiet = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, load=W,
                             options=SolveOptions(edge="ignore"))
        fits = solve_normal(gap_grid(sphere_gap(n, 3 * hz.a / n, R), 3 * hz.a / n), e_star=E_STAR,
                            load=W)
    assert quiet.touches_edge and not fits.touches_edge


def test_unresolved_answers_carry_a_note():
    # issue 16 items 1 and 4: a grid coarser than the contact, or a spike that carries the
    # load on a handful of cells at a pressure above E*, is said in the result's notes
    hz = hertz_sphere(R, W, E_STAR)
    coarse = solve_sphere(
        R, W, E_STAR, domain=DomainSpec(grid=8, size=8 * 0.5 * hz.a)
    )  # 2 cells per a0
    assert any("too coarse" in n and "2 cells per Hertz radius" in n for n in coarse.notes)
    fine = solve_sphere(R, W, E_STAR)
    assert fine.notes == ()
    zdx = 5e-6
    z = np.zeros((160, 160))
    z[79:81, 79:81] = 50 * hz.delta  # one 10 µm wide spike, 50 Hertz approaches tall
    spiky = solve_sphere(R, W, E_STAR, roughness=CompositeRoughness(z, zdx, level=False))
    assert np.count_nonzero(spiky.contact) < 20 and spiky.pmax > E_STAR
    assert any("covers only" in n for n in spiky.notes)
    assert any("exceeds E*" in n for n in spiky.notes)
