"""Rolling resistance: the hysteresis work against Hertz (sphere and cylinder), the load
exponent 4/3 and 3/2, the line-contact solver against Hertz, the material derivative on a
rolling rough surface, the plastic work, and the exponent fit."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from contact_synth import rough_surface
from scipy import stats

from contact import (
    Dissipation,
    DomainSpec,
    composite_modulus,
    hertz_cylinder,
    hertz_sphere,
    material,
    solve_sphere,
)
from contact._errors import ContactInputError
from contact._exponent import fit_exponent, local_exponent
from contact._rolling import (
    cylinder_sweep,
    hysteresis_work,
    log_loads,
    plastic_work,
    sphere_sweep,
)
from contact.setups import CompositeRoughness
from contact.setups._line import solve_cylinder

E_STAR = composite_modulus(material("steel"), material("aluminium"))
R = 0.02


@pytest.fixture(scope="module")
def smooth10():
    return solve_sphere(R, 10.0, E_STAR)  # 256 cells, 2.5 Hertz radii


def test_smooth_sphere_hysteresis_is_three_sixteenths_n_a_over_r(smooth10):
    hz = hertz_sphere(R, 10.0, E_STAR)
    exact = 3.0 / 16.0 * 10.0 * hz.a / R  # Johnson eq. 9.19 with alpha_h = 1
    assert hysteresis_work(smooth10, R) == pytest.approx(exact, rel=2e-4)
    assert hysteresis_work(smooth10, R, kinematics="frozen") == pytest.approx(exact, rel=3e-4)
    # a smooth ball is symmetric: rolling the other way, or along y, costs the same
    for d in ("-x", "+y", "-y"):
        assert hysteresis_work(smooth10, R, direction=d) == pytest.approx(exact, rel=2e-4)
    # the lossy body's share scales the work linearly
    assert hysteresis_work(smooth10, R, share=0.25) == pytest.approx(0.25 * exact, rel=2e-4)
    with pytest.raises(ContactInputError):
        hysteresis_work(smooth10, None)
    with pytest.raises(ContactInputError):
        hysteresis_work(smooth10, R, share=1.5)
    with pytest.raises(ContactInputError):
        hysteresis_work(smooth10, R, kinematics="sliding")


def test_smooth_sphere_exponent_is_four_thirds():
    s = sphere_sweep(
        R,
        E_STAR,
        log_loads(1.0, 100.0, 5),
        dissipation=Dissipation(alpha_h=0.02),
        domain=DomainSpec(grid=128),
    )
    assert s.lambda_eff == pytest.approx(4.0 / 3.0, abs=0.01)
    assert np.all(np.abs(s.local_lambda - 4.0 / 3.0) < 0.01)
    # the interval is Student's t on the least-squares slope of ln M against ln N
    # (scipy's linregress as the reference), and it is tight on a smooth ball
    ref = stats.linregress(np.log(s.loads), np.log(s.moments))
    half = stats.t.ppf(0.975, s.loads.size - 2) * ref.stderr
    assert s.lambda_eff == pytest.approx(ref.slope, rel=1e-12)
    assert s.lambda_ci == pytest.approx((ref.slope - half, ref.slope + half), rel=1e-9)
    assert s.lambda_ci[1] - s.lambda_ci[0] < 0.01
    # and the moments themselves: M_r = alpha_h (3/16) N a
    a = np.array([hertz_sphere(R, w, E_STAR).a for w in s.loads])
    assert np.allclose(s.moments, 0.02 * 3.0 / 16.0 * s.loads * a, rtol=3e-3)


def test_line_contact_solver_reproduces_hertz():
    for w in (2e4, 3e5):
        res = solve_cylinder(R, w, E_STAR, n=512)
        hz = hertz_cylinder(R, w, E_STAR)
        assert res.load == pytest.approx(w, rel=1e-12)
        assert res.pmax == pytest.approx(hz.p0, rel=1e-3)
        assert res.half_width == pytest.approx(hz.a, abs=res.dx)
        i0 = int(np.argmin(np.abs(res.x)))
        drop = res.displacement[i0] - np.asarray(res.displacement)
        assert np.allclose(drop, hz.relative_displacement(res.x), atol=1e-4 * drop.max())
        assert not res.touches_edge


def test_cylinder_exponent_is_three_halves():
    s = cylinder_sweep(R, E_STAR, log_loads(1e4, 1e6, 5), n=512)
    assert s.lambda_eff == pytest.approx(1.5, abs=0.01)
    assert np.all(np.abs(s.local_lambda - 1.5) < 0.01)
    # F' = 2 W' a / (3 pi R) per unit length (Johnson 9.2)
    a = np.array([hertz_cylinder(R, w, E_STAR).a for w in s.loads])
    assert np.allclose(s.forces, 2 * s.loads * a / (3 * math.pi * R), rtol=2e-3)
    f = cylinder_sweep(
        R, E_STAR, log_loads(1e4, 1e6, 3), dissipation=Dissipation(kinematics="frozen"), n=512
    )
    assert f.lambda_eff == pytest.approx(1.5, abs=0.01)


@pytest.mark.parametrize("seed", [1, 2])
def test_asperities_travel_with_the_material_in_rolling(seed):
    # Roll a rough surface under the ball by one cell (material moves -x) and follow each
    # material point: on the cells in contact at both instants its displacement grows by
    # exactly the change of approach plus (x_j^2 - x_{j-1}^2)/2R, whatever the roughness:
    # the asperity slopes do not load the material ("rolling" kinematics). The snapshot's
    # -du/dx ("frozen") differs from it by the roughness slope.
    from contact._geometry import sphere_gap
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    rng = np.random.default_rng(seed)
    Rb, W = 5e-3, 1.0
    hz = hertz_sphere(Rb, W, E_STAR)
    n = 128
    dx = 6 * hz.a / n
    z = rough_surface(n, dx, rng.uniform(0.3, 2.0) * hz.delta, seed=seed, corr=5 * dx)
    base = sphere_gap(n, dx, Rb)
    origin = (-(n // 2) * dx,) * 2
    a = solve_normal(gap_grid(base - z, dx, origin=origin), e_star=E_STAR, load=W)
    b = solve_normal(gap_grid(base - np.roll(z, -1, axis=1), dx, origin=origin), e_star=E_STAR,
                     load=W, initial=np.asarray(a.pressure))
    x = np.asarray(a.x)[None, :]
    du = np.roll(np.asarray(b.displacement), 1, axis=1) - np.asarray(a.displacement)
    both = (np.asarray(a.pressure) > 0) & (np.roll(np.asarray(b.pressure), 1, axis=1) > 0)
    both[:, 0] = False
    geometric = (b.approach - a.approach) + dx * (2 * x - dx) / (2 * Rb)
    geometric = np.broadcast_to(geometric, du.shape)
    scale = float(np.abs(geometric[both]).max())
    assert both.sum() > 20
    assert np.abs(du - geometric)[both].max() < 1e-4 * scale
    frozen = -np.gradient(np.asarray(a.displacement), dx, axis=1) * dx
    assert np.abs(frozen - geometric)[both].max() > 0.5 * scale
    # and hysteresis_work("rolling") is the pressure-weighted geometric rate
    ref = float((np.asarray(a.pressure) * np.clip(x / Rb, 0, None)).sum() * dx * dx)
    assert hysteresis_work(a, Rb) == pytest.approx(ref, rel=1e-12)


def test_rough_contact_exponent_lies_between_one_and_hertz():
    # a rough plate spreads the load over a region set by the roughness, so M_r grows
    # nearly linearly at light load and tends to 4/3 only once the ball's shape dominates
    hz1 = hertz_sphere(5e-3, 0.2, E_STAR)
    z = rough_surface(512, 1e-6, 2 * hz1.delta, seed=8, corr=6e-6)
    loads = log_loads(0.2, 20.0, 5)
    s = sphere_sweep(
        5e-3, E_STAR, loads, roughness=CompositeRoughness(z, 1e-6), domain=DomainSpec(grid=128)
    )
    smooth = sphere_sweep(5e-3, E_STAR, loads, domain=DomainSpec(grid=96))
    assert 0.9 < s.lambda_eff < 4.0 / 3.0 - 0.05
    assert s.local_lambda[-1] > s.local_lambda[1]  # drifting back towards 4/3
    assert np.all(s.moments > smooth.moments)  # the spread load rolls harder


def _fake_plastic(d0, c, H, Rb, n=801):
    x = np.linspace(-1.5 * c, 1.5 * c, n)
    upl = np.clip(d0 * (1 - (x[None, :] ** 2 + x[:, None] ** 2) / c**2), 0, None)
    dx = float(x[1] - x[0])
    return SimpleNamespace(plastic_displacement=upl, x=x, y=x, dx=dx, dy=dx, hardness=H)


def test_plastic_work_is_hardness_times_the_track_volume():
    H, Rb, c = 1e9, 0.02, 50e-6
    d0 = c**2 / (2 * Rb)  # a truncated sphere: d = (c^2 - r^2) / 2R
    res = _fake_plastic(d0, c, H, Rb)
    band = 0.01
    b = math.sqrt(2 * Rb * band * d0)
    # exact: H * int dy of the mean over |x| <= b of (c^2 - x^2 - y^2)/2R
    exact = H * (4 / 3 * c**3 - 2 * c * b**2 / 3) / (2 * Rb)
    assert plastic_work(res, Rb, band=band) == pytest.approx(exact, rel=5e-3)
    assert plastic_work(res, Rb, band=band, direction="+y") == pytest.approx(exact, rel=5e-3)
    nothing = _fake_plastic(0.0, c, H, Rb, n=11)
    assert plastic_work(nothing, Rb) == 0.0
    with pytest.raises(ContactInputError, match="hardness"):
        plastic_work(SimpleNamespace(hardness=None), Rb)


def test_plastic_sweep_on_a_soft_plate():
    hz = hertz_sphere(R, 10.0, E_STAR)
    H = hz.p0 / 1.5  # the centre yields from about 3 N upwards
    s = sphere_sweep(
        R,
        E_STAR,
        [4.0, 7.0, 10.0, 14.0],
        dissipation=Dissipation(model="plastic", hardness=H),
        domain=DomainSpec(grid=96, size=5 * hz.a),
    )
    assert np.all(np.diff(s.moments) > 0)
    assert s.fit is not None and s.lambda_eff > 4.0 / 3.0  # plastic work grows fast
    assert all(r.plastic_area > 0 for r in s.results)
    with pytest.raises(ContactInputError, match="hardness"):
        sphere_sweep(R, E_STAR, [1.0, 2.0, 3.0], dissipation=Dissipation(model="plastic"))


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_exponent_fit_recovers_a_hidden_power_law(seed):
    rng = np.random.default_rng(seed)
    lam, s_r = rng.uniform(0.8, 1.6), 10 ** rng.uniform(-6, -3)
    n = log_loads(1.0, 100.0, int(rng.integers(5, 15)))
    exact = fit_exponent(n, s_r * n**lam)
    assert exact.exponent == pytest.approx(lam, abs=1e-12)
    assert exact.prefactor == pytest.approx(s_r, rel=1e-10)
    noise = rng.uniform(0.01, 0.05)
    m = s_r * n**lam * np.exp(noise * rng.standard_normal(n.size))
    fit = fit_exponent(n, m, confidence=0.999)
    assert fit.ci[0] < lam < fit.ci[1]
    assert fit.ci[1] - fit.ci[0] < 20 * noise


def test_local_exponent_follows_a_crossover():
    n = np.geomspace(0.1, 1000.0, 200)
    m = n + n ** (4 / 3)  # linear at light load, 4/3 at heavy load
    exact = (n + 4 / 3 * n ** (4 / 3)) / (n + n ** (4 / 3))
    assert np.allclose(local_exponent(n, m), exact, atol=1e-3)
    with pytest.raises(ContactInputError):
        fit_exponent([1.0, 2.0], [1.0, 2.0])
    with pytest.raises(ContactInputError):
        fit_exponent([1.0, 2.0, 3.0], [1.0, 0.0, 2.0])
    with pytest.raises(ContactInputError):
        log_loads(10.0, 1.0, 5)
