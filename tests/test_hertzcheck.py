"""The Hertz check: GJM alpha, radial averages, the effective radius, the elastic-plastic
solve, and the verdict on smooth, nearly smooth and paper-rough plates (hidden roughness
level and hidden non-measured fraction)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from contact_synth import rough_surface
from plastic_reference import fixed_point_plastic

from contact import DomainSpec, composite_modulus, hertz_sphere, material
from contact._errors import ContactError, ContactInputError
from contact._fields import effective_radius, radial_average
from contact._hertzcheck import ALPHA_LIMIT, check_sphere
from contact._roughstats import combined_rms, gjm_alpha
from contact.setups import CompositeRoughness
from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.mechanics.hertz_check import hertz_check

E_STAR = composite_modulus(material("steel"), material("aluminium"))
H_AL = material("aluminium").hardness


def test_alpha_is_the_roughness_in_units_of_the_hertz_approach():
    rng = np.random.default_rng(4)
    for _ in range(5):
        R, W, s = 10 ** rng.uniform(-3, -1.5), 10 ** rng.uniform(-1, 2), 10 ** rng.uniform(-8, -5)
        hz = hertz_sphere(R, W, E_STAR)
        assert gjm_alpha(s, R, hz.a) == pytest.approx(s / hz.delta, rel=1e-12)
    with pytest.raises(ContactInputError):
        gjm_alpha(1e-6, 0.0, 1e-4)


def test_combined_rms_uses_measured_points_only():
    rng = np.random.default_rng(2)
    a = np.where(rng.random((40, 50)) < 0.5, 3.0, -3.0) * 1e-6  # rms exactly 3 µm about mean
    a = a - a.mean()
    s_a = float(np.sqrt(np.mean(a**2)))
    b = rng.standard_normal((30, 30)) * 1e-7
    s_b = float(np.std(b))
    holed = a.copy()
    holed[rng.random(a.shape) < 0.3] = np.nan  # holes are skipped, never counted as zero
    assert combined_rms(a, b) == pytest.approx(math.hypot(s_a, s_b), rel=1e-12)
    assert combined_rms(holed, None) == pytest.approx(s_a, rel=0.03)
    with pytest.raises(ContactInputError):
        combined_rms(np.full((4, 4), np.nan))


def test_radial_average_of_r_squared_matches_the_annulus_mean():
    # mean of r^2 over the annulus [r - w/2, r + w/2) is r^2 + w^2/4 (continuum)
    n, d = 401, 1e-6
    x = (np.arange(n) - n // 2) * d
    p = x[None, :] ** 2 + x[:, None] ** 2
    w = 10 * d
    prof = radial_average(p, x, x, width=w, r_max=150e-6)
    k = prof.r >= 3 * w
    expect = prof.r[k] ** 2 + w**2 / 4
    assert np.allclose(prof.p[k], expect, rtol=3e-3)
    assert prof.count.sum() == np.count_nonzero(np.hypot(x[None, :], x[:, None]) < 155e-6)


def test_effective_radius_of_a_hertz_field_is_a():
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    n = 512
    x = (np.arange(n) - n // 2) * (3 * hz.a / n)
    p = hz.pressure(np.hypot(x[None, :], x[:, None]))
    assert effective_radius(p, x, x) == pytest.approx(hz.a, rel=2e-3)
    shifted = hz.pressure(np.hypot(x[None, :] - 0.2 * hz.a, x[:, None]))
    assert effective_radius(shifted, x, x) == pytest.approx(hz.a, rel=2e-3)  # about centroid


def test_smooth_ball_hertz_holds():
    chk = check_sphere(0.02, 10.0, E_STAR, hardness=H_AL, domain=DomainSpec(grid=128))
    c = chk.comparison
    assert c.hertz_holds
    assert c.alpha == 0.0 and c.plastic_fraction == 0.0
    assert c.profile_deviation < 0.01
    assert c.effective_radius / c.hertz.a == pytest.approx(1.0, abs=0.01)
    assert c.approach / c.hertz.delta == pytest.approx(1.0, abs=0.01)
    assert c.pmax / c.hertz.p0 == pytest.approx(1.0, abs=0.01)
    names = {k.name for k in c.criteria}
    assert names == {"alpha", "profile", "radius", "approach", "yield", "first_yield", "peak",
                     "area"}
    assert all(any(ch.isdigit() for ch in r) for r in c.reasons)


def test_soft_plate_yields_and_the_verdict_says_so():
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    # p0 beyond first yield (0.57 H) but below H: elastic everywhere, still no Hertz
    chk = check_sphere(0.02, 10.0, E_STAR, hardness=1.3 * hz.p0, domain=DomainSpec(grid=96))
    c = chk.comparison
    assert not c.hertz_holds and c.plastic_fraction == 0.0
    assert not c.criterion("first_yield").passed
    assert "first yield" in c.criterion("first_yield").reason
    # p0 beyond H: the centre yields
    chk = check_sphere(
        0.02, 10.0, E_STAR, hardness=0.8 * hz.p0, domain=DomainSpec(grid=96, size=4 * hz.a)
    )
    c = chk.comparison
    assert not c.hertz_holds and c.plastic_fraction > 0.05
    assert not c.criterion("yield").passed and "%" in c.criterion("yield").reason


def test_elastic_plastic_solution_matches_the_capped_solver_and_its_conditions():
    from contact import PressureBounds
    from contact._grid import gap_grid
    from contact.bem import solve_normal
    from contact.setups._ball_on_plate import SphereContact

    hz = hertz_sphere(0.02, 10.0, E_STAR)
    H = hz.p0 / 1.2
    prob = SphereContact(0.02, E_STAR, 10.0, domain=DomainSpec(grid=128, size=6 * hz.a))
    el = prob.solve(10.0)
    n, dx = prob.domain.n, prob.domain.dx
    ref = solve_normal(gap_grid(prob.gap0, dx, origin=(-(n // 2) * dx,) * 2), e_star=E_STAR,
                       load=10.0, initial=np.asarray(el.pressure), bounds=PressureBounds.elastic(H))
    # the plastic-displacement iteration, an algorithm independent of the capped solver
    mine = fixed_point_plastic(prob, 10.0, H, el)
    assert np.abs(np.asarray(mine.pressure) - np.asarray(ref.pressure)).max() < 2e-3 * H
    d_ref = np.asarray(ref.plastic_displacement)
    assert np.abs(np.asarray(mine.plastic_displacement) - d_ref).max() < 5e-3 * d_ref.max()

    # a rough contact: check the contact conditions of the default (capped) solution
    z = rough_surface(256, 4e-6, 1e-6, seed=5, corr=12e-6)
    prob = SphereContact(
        0.02, E_STAR, 10.0, roughness=CompositeRoughness(z, 4e-6), domain=DomainSpec(grid=128)
    )
    el = prob.solve(10.0, on_edge="warn")
    res = prob.solve(10.0, hardness=H_AL, initial=el, on_edge="warn")
    p = np.asarray(res.pressure)
    upl = np.asarray(res.plastic_displacement)
    assert res.load == pytest.approx(10.0, rel=2e-3)
    assert p.max() <= H_AL and (upl > 0).any()
    assert np.all(p[upl > 0] == H_AL)
    assert np.all(np.asarray(res.gap)[p > 0] == 0)
    assert res.plastic_area > 0


def _holes(shape, fraction, rng):
    from scipy.ndimage import gaussian_filter

    if fraction <= 0:
        return np.zeros(shape, dtype=bool)
    m = gaussian_filter(rng.standard_normal(shape), 2.5)  # blobs of dropouts
    return m > np.quantile(m, 1 - fraction)


@pytest.mark.parametrize("seed", [11, 12, 13, 14])
def test_verdict_and_alpha_follow_the_roughness_not_the_holes(seed):
    rng = np.random.default_rng(seed)
    R, W = 5e-3, 1.0
    hz = hertz_sphere(R, W, E_STAR)
    rough = bool(seed % 2)  # both kinds among the seeds; level and holes random
    alpha_true = 10 ** (rng.uniform(np.log10(0.3), np.log10(3.0)) if rough
                        else rng.uniform(np.log10(0.003), np.log10(0.02)))
    z = rough_surface(256, 2e-6, alpha_true * hz.delta, seed=seed, corr=10e-6)
    z = z + rng.uniform(-1e-3, 1e-3) * np.arange(256)[None, :] * 2e-6  # a tilt, levelled
    frac = rng.uniform(0.05, 0.3)
    holed = np.where(_holes(z.shape, frac, rng), np.nan, z)
    chk = hertz_check(Topography(holed, 2e-6, 2e-6), radius=R, load=W,
                      materials="steel,aluminium", grid=96)
    assert chk.hertz_holds is (alpha_true < ALPHA_LIMIT)
    assert chk.alpha == pytest.approx(alpha_true, rel=0.06)
    reason = chk.reasons[0] if rough else next(r for r in chk.reasons if r.startswith("α"))
    assert f"{chk.alpha:.3g}" in reason
    if rough:
        assert not chk.comparison.criterion("profile").passed


def test_paper_rough_plate_fails_with_reasons():
    # Table 2's Rq = 2.2 µm at the paper's 5 µm pitch, 20 mm ball, 10 N
    z = rough_surface(320, 5e-6, 2.2e-6, seed=21, corr=10e-6)
    chk = hertz_check(Topography(z, 5e-6, 5e-6), radius=0.02, load=10.0,
                      materials="steel,aluminium", grid=128)
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    assert not chk.hertz_holds
    assert chk.alpha == pytest.approx(2.2e-6 / hz.delta, rel=0.02)
    assert chk.reasons[0].startswith("α") and "≫" in chk.reasons[0]
    c = chk.comparison
    assert c.plastic_fraction > 0.01  # the asperities yield (Fig. 17)
    assert c.effective_radius > 1.3 * hz.a and c.approach > 1.5 * hz.delta
    failed = {k.name for k in c.criteria if k.decisive and not k.passed}
    assert {"alpha", "profile", "radius", "approach", "yield"} <= failed


def test_to_json_has_exactly_the_issue_keys():
    z = rough_surface(128, 2e-6, 20e-9, seed=3, corr=10e-6)
    from surfmet.records._hertz import hertz_check_record

    rec = hertz_check_record(hertz_check(Topography(z, 2e-6, 2e-6), radius=5e-3, load=1.0,
                                         materials="steel,aluminium", grid=64))
    # issue 5's keys, plus issue 11's model hierarchy (models, verdict, summits), plus
    # issue 16's grid, scan preparation and warnings, plus issue 26's solve record
    assert set(rec) == {"hertz_holds", "judged", "alpha", "sigma", "hertz", "bem", "reasons",
                        "radial_profile", "models", "verdict", "summits", "grid",
                        "scan_preparation", "warnings", "solve"}
    assert set(rec["hertz"]) == {"a", "delta", "p0"}
    assert set(rec["bem"]) == {"pmax", "effective_radius", "contact_radius", "approach",
                               "area_fraction", "plastic_fraction"}
    assert set(rec["radial_profile"]) == {"r", "p_bem", "p_hertz"}
    units = {("alpha",): "", ("sigma",): "m", ("hertz", "a"): "m", ("hertz", "p0"): "Pa",
             ("hertz", "delta"): "m", ("bem", "pmax"): "Pa", ("bem", "approach"): "m",
             ("bem", "contact_radius"): "m", ("bem", "effective_radius"): "m",
             ("bem", "area_fraction"): "",
             ("bem", "plastic_fraction"): "", ("radial_profile", "r"): "m",
             ("radial_profile", "p_bem"): "Pa", ("radial_profile", "p_hertz"): "Pa"}
    for path, unit in units.items():
        node = rec
        for key in path:
            node = node[key]
        assert node["unit"] == unit and "value" in node
    assert isinstance(rec["hertz_holds"], bool) and isinstance(rec["reasons"], list)
    n = len(rec["radial_profile"]["r"]["value"])
    assert n > 5 and len(rec["radial_profile"]["p_bem"]["value"]) == n


def test_bad_inputs_are_refused_clearly():
    z = rough_surface(64, 1e-6, 1e-7, seed=1)
    scan = Topography(z, 1e-6, 1e-6)
    with pytest.raises(SurfmetInputError, match="areal"):
        hertz_check(Profile(z[0], 1e-6), radius=1e-3, load=0.01)
    with pytest.raises(SurfmetInputError, match="load"):
        hertz_check(scan, radius=1e-3, load=-1.0)
    with pytest.raises(ContactInputError, match="unknown material"):
        hertz_check(scan, radius=1e-3, load=0.01, materials="steel,unobtainium")
    with pytest.raises(SurfmetInputError, match="BALL,PLATE"):
        hertz_check(scan, radius=1e-3, load=0.01, materials="steel")
    with pytest.raises(SurfmetInputError):
        hertz_check(Topography(np.full((16, 16), np.nan), 1e-6, 1e-6), radius=1e-3, load=0.01)
    # a 64 µm scan cannot hold the ~1 mm contact of a 20 mm ball at 10 N
    with pytest.raises(ContactError, match=r"larger scan|too small"):
        hertz_check(scan, radius=0.02, load=10.0)


def test_models_that_cannot_be_evaluated_are_left_out_with_their_reason():
    """Issue 25 item 11: heights of a few pm leave the Greenwood-Tripp population no summit
    that responds (its Newton matrix is singular): the check still answers, and names the
    models it left out and why, instead of a LinAlgError."""
    z = rough_surface(128, 5e-6, 3e-12, seed=7, corr=20e-6)
    chk = hertz_check(Topography(z, 5e-6, 5e-6), radius=0.02, load=10.0,
                      materials="steel,aluminium", grid=48)
    h = chk.hierarchy
    assert set(h.left_out) == {"greenwood_tripp", "greenwood_tripp_plastic"}
    assert all("no summit" in why for why in h.left_out.values())
    assert any(r.startswith("greenwood_tripp: not evaluated (") for r in h.reasons)
    assert any("greenwood_tripp left out of the models" in n for n in chk.notes)
    assert chk.hertz_holds  # a smooth plate: the answer itself is Hertz


def test_a_reference_loaded_on_one_cell_has_no_radius_error():
    """Issue 25 item 11: a 0/1 (bool) height map of 1 m pixels on a coarse grid loads a
    single cell; a* = 0 is no radius to measure a model against (NaN, not a division by
    zero), and no model is within tolerance of it."""
    z = (np.random.default_rng(3).normal(size=(64, 64)) > 0).astype(float)
    chk = hertz_check(Topography(z, 1.0, 1.0), radius=0.02, load=10.0,
                      materials="steel,aluminium", grid=32)
    assert chk.comparison.effective_radius == 0.0
    hz = chk.hierarchy.models["hertz"]
    assert math.isnan(hz.radius_error) and not hz.within_tolerance
    assert not chk.comparison.judged and not chk.hertz_holds
