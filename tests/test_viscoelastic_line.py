"""Steady viscoelastic rolling of a cylinder (plane strain) against independent answers.

- Hunter (1961): contact edges, pressure offset, peak pressure and rolling-resistance
  coefficient against V tau / a, from the Chebyshev-Bessel form of Hunter's solution
  (contact.viscoelastic._hunter: a different reduction of the problem, no shared code).
- Elastic limits: tau -> 0 and tau -> inf give the Hertz line contacts of the relaxed and
  the glassy modulus (Johnson 1985, sec. 4.3).
- CONTACT's published reference output examples/visc_cylindr.ref_out (eve70a/CONTACT,
  Wang & Knothe 1993 case): numbers of contact elements, their positions, pmax, approach.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._hertz import hertz_cylinder
from contact.viscoelastic._hunter import hunter_cylinder
from contact.viscoelastic._line import exp_e1, line_grid, rolling_cylinder, solve_line
from contact.viscoelastic._rheology import CreepSeries, StandardLinearSolid, pair_creep

R, W, NU = 0.05, 6.0e5, 0.4
EG, ER = 3.2e9, 1.6e9
CG, CR = (1 - NU**2) / EG, (1 - NU**2) / ER
A_R = math.sqrt(4 * W * R * CR / math.pi)


@pytest.mark.parametrize("vt_over_a", [0.3, 1.0, 3.0])
def test_hunter_cylinder(vt_over_a: float) -> None:
    tau = vt_over_a * A_R  # V = 1 m/s
    ref = hunter_cylinder(R, W, CG, CR, tau, 1.0)
    creep = pair_creep(None, StandardLinearSolid(EG, ER, tau, NU))
    res = rolling_cylinder(R, W, creep, 1.0, n=512)
    width = ref.leading - ref.trailing
    assert res.leading - res.trailing == pytest.approx(width, rel=0.01)
    assert abs(res.leading - ref.leading) < 0.01 * width
    assert abs(res.trailing - ref.trailing) < 0.01 * width
    assert res.rolling_resistance == pytest.approx(ref.rolling_resistance, rel=0.01)
    # the pressure's centroid lies ahead of the axis by mu_r R (rigid cylinder)
    assert res.pressure_offset == pytest.approx(ref.rolling_resistance * R, rel=0.01)
    assert res.pmax == pytest.approx(ref.pmax(), rel=0.01)
    xs = np.asarray(res.x)
    assert np.allclose(res.pressure, ref.pressure(xs), atol=0.02 * ref.pmax())


def test_hunter_rolling_resistance_peaks_near_vt_equal_a() -> None:
    # Johnson (1985) fig. 8.15: mu_r vanishes at both ends and peaks at V tau ~ a.
    mus = [hunter_cylinder(R, W, CG, CR, f * A_R, 1.0).rolling_resistance
           for f in (0.03, 1.0, 30.0)]
    assert mus[1] > 3 * mus[0] and mus[1] > 3 * mus[2]


@pytest.mark.parametrize("limit", ["relaxed", "glassy"])
def test_elastic_limits_are_hertz(limit: str) -> None:
    tau = 1e-5 * A_R if limit == "relaxed" else 1e5 * A_R
    creep = pair_creep(None, StandardLinearSolid(EG, ER, tau, NU))
    res = rolling_cylinder(R, W, creep, 1.0, n=512)
    hz = hertz_cylinder(R, W, 1.0 / (CR if limit == "relaxed" else CG))
    assert res.leading == pytest.approx(hz.a, rel=0.01)
    assert -res.trailing == pytest.approx(hz.a, rel=0.01)
    assert res.pmax == pytest.approx(hz.p0, rel=0.01)
    assert abs(res.rolling_resistance) < 1e-3 * hz.a / R


# CONTACT examples/visc_cylindr.ref_out: (TC, contact elements, first, last, PMAX, APPROACH)
# for two PA6 cylinders (GG = 1143 N/mm^2, nu = 0.4, FG = 1, V = 1000 mm/s, R = 50 mm,
# FN = 600 N/mm, 99 elements of 0.16 mm centred at -7.92 ... 7.92 mm).
VISC_CYLINDR = [
    (0.0, 80, 11, 90, 60.32, 2.50845),
    (0.009, 62, 26, 87, 78.74, 2.36736),
    (0.045, 57, 26, 82, 84.72, 2.06321),
    (2.0, 56, 23, 78, 85.31, None),  # approach: CONTACT's 1 m long strip is not 2D at 2 m
]


@pytest.mark.parametrize("tc, ncon, first, last, pmax, approach", VISC_CYLINDR)
def test_contact_visc_cylindr(tc, ncon, first, last, pmax, approach) -> None:
    G = 1143e6
    eg = 2 * G * (1 + NU)
    body = StandardLinearSolid(eg, eg / 2, tc if tc > 0 else 1e-12, NU)
    x = (-7.92 + 0.16 * np.arange(99)) * 1e-3
    res = solve_line(line_grid(x, 0.16e-3, x**2 / (2 * 0.05)), 6.0e5, pair_creep(body, body),
                     1.0, radius=0.05)
    on = np.flatnonzero(np.asarray(res.pressure) > 0)
    assert (on.size, on[0] + 1, on[-1] + 1) == (ncon, first, last)
    assert res.pmax / 1e6 == pytest.approx(pmax, rel=2e-3)
    if approach is not None:
        assert res.approach * 1e3 == pytest.approx(approach, rel=1e-3)


def test_exp_e1_against_quadrature() -> None:
    from scipy.integrate import quad

    for s in (0.3, 2.0, 45.0):
        val, _ = quad(lambda t, s=s: math.exp(-t) / (s + t), 0, math.inf)
        assert exp_e1(np.array([s]))[0] == pytest.approx(val, rel=1e-6)


def test_bad_input() -> None:
    with pytest.raises(ContactInputError, match="relaxed modulus"):
        StandardLinearSolid(1e9, 2e9, 1.0)
    with pytest.raises(ContactInputError, match="creep time"):
        StandardLinearSolid(2e9, 1e9, 0.0)
    with pytest.raises(ContactInputError, match="creep time"):
        StandardLinearSolid(2e9, 1e9, -1.0)
    creep = CreepSeries(CG, (CR - CG,), (1.0,))
    for v in (0.0, -1.0, float("nan")):
        with pytest.raises(ContactInputError, match="speed"):
            rolling_cylinder(R, W, creep, v, n=64)


@pytest.mark.parametrize("scale, modulus", [(1e-6, "relaxed"), (1e6, "glassy")])
def test_prony_series_limits(scale: float, modulus: str) -> None:
    # two relaxation times, both far below (or above) the passage time a/V
    from contact.viscoelastic import PronySeries

    pr = PronySeries(1.0e9, (1.5e9, 0.5e9), (0.2 * scale, 3.0 * scale), nu=NU)
    E = pr.E_inf if modulus == "relaxed" else pr.E_g
    res = rolling_cylinder(R, W, pair_creep(None, pr), 1.0, n=512)
    hz = hertz_cylinder(R, W, E / (1 - NU**2))
    assert res.pmax == pytest.approx(hz.p0, rel=0.01)
    assert res.leading - res.trailing == pytest.approx(2 * hz.a, rel=0.01)


def test_rough_cylinder_contact_conditions() -> None:
    rng = np.random.default_rng(7)
    n = 512
    z = 0.03 * A_R**2 / (2 * R) * np.convolve(rng.standard_normal(n), np.ones(8) / 8, "same")
    creep = pair_creep(None, StandardLinearSolid(EG, ER, A_R, NU))
    res = rolling_cylinder(R, W, creep, 1.0, n=n, roughness=z)
    p = np.asarray(res.pressure)
    dx = float(res.x[1] - res.x[0])
    assert p.min() >= 0 and p.sum() * dx == pytest.approx(W, rel=1e-9)
    h = np.asarray(res.x) ** 2 / (2 * R) - z
    gap = h + np.asarray(res.displacement) - res.approach
    scale = float(np.ptp(h[p > 0]))
    assert np.abs(gap[p > 0]).max() < 1e-9 * scale  # closed where loaded
    assert gap[p == 0].min() > -1e-9 * scale  # no overlap elsewhere
    assert res.rolling_resistance > 0
