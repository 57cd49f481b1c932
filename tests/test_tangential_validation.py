"""The tangential solver against closed forms, Kalker's tables and CONTACT's outputs.

Independent truths:

- Carter (1926): 2D rolling traction, F = -mu N (1 - c^2/a^2) with the adhesion zone of
  half-width c = a - |xi| R / mu at the leading edge.
- Cattaneo (1938) / Mindlin (1949): adhesion radius c = a (1 - F/mu N)^(1/3) and shift
  delta = 3 mu N (2 - nu)/(8 G a) [1 - (1 - F/mu N)^(2/3)] (Johnson 1985, eq. 7.42).
- Kalker's creep coefficients C11, C22, C23 of a circular contact (Kalker 1990, Table
  E.3, as tabulated in CONTACT's m_hertz.f90: nu = 0.25 gives 4.12, 3.67, 1.47).
- CONTACT (Vollebregt & Kalker, eve70a/CONTACT, examples/bentall.ref_out and
  spence35.ref_out): creepages, peak pressures, approach, adhesion and slip elements.
  bentall.inp rolls in -x (CHI = 180 deg); our rolling is in +x, so the mirror image has
  xi and F_x of opposite sign.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._errors import ContactInputError, ConvergenceError
from contact.tangential import (
    Creepage,
    Grid,
    RollingOptions,
    compress_in_steps,
    pair_constants_from,
    shift,
    sphere_grid,
    steady_rolling,
)


def _carter(nx):
    c = pair_constants_from(82000.0, 0.28, 82000.0, 0.28)  # CONTACT's carter2d.inp units
    a, radius, mu = 1.0, 500.0, 0.3
    load = math.pi * a**2 * c.e_star / (4 * radius)  # N' giving half-width a
    x = -1.05 * a + (np.arange(nx) + 0.5) * 2.1 * a / nx
    grid = Grid(x=x, y=np.zeros(1), h=(x**2 / (2 * radius))[None, :], line=True)
    return grid, c, load, a, radius, mu


def test_carter_rolling_traction():
    """220 elements over 2.1a: F/(mu N) to 0.5 %, traction to 3 % of mu p0, adhesion
    zone to two elements, at the leading edge."""
    grid, c, load, a, radius, mu = _carter(220)
    xi = -0.00024
    r = steady_rolling(grid, c, load, mu, Creepage(xi=xi))
    cc = a - abs(xi) * radius / mu
    assert r.fx / (mu * r.fn) == pytest.approx(1 - cc**2 / a**2, rel=5e-3)
    p0 = 2 * load / (math.pi * a)
    x = grid.x
    d = a - cc
    q = mu * p0 * (np.sqrt(np.clip(1 - x**2 / a**2, 0, None))
                   - cc / a * np.sqrt(np.clip(1 - (x - d) ** 2 / cc**2, 0, None)))
    assert np.abs(r.q[0, 0] - q).max() < 0.03 * mu * p0
    assert abs(r.stick_area - 2 * cc) <= 2 * grid.dx
    stick_x = grid.x[r.state[0] == 1]
    assert stick_x.max() > a - 2 * grid.dx  # adhesion reaches the leading edge


CONTACT_BENTALL = [
    # mu, F_x / (mu N) in CONTACT's frame, coupled, CREEP X, PMAX, NADH, NSLIP, FRIC.POWER
    (1e-4, 0.0, False, 5.260e-4, 103.1, 1, 199, 1.156e-4),
    (10.0, 0.0, True, 3.591e-4, 103.8, 200, 0, 0.0),
    (0.05, 0.0, True, 4.294e-4, 103.6, 125, 75, 9.475e-3),
    (0.05, 0.75, True, 2.108e-4, 103.2, 36, 164, 0.1955),
    (0.05, -0.75, True, 5.392e-4, 103.3, 106, 95, 4.418e-2),
]


@pytest.mark.parametrize("case", CONTACT_BENTALL)
def test_bentall_johnson_against_contact(case):
    """Aluminium on steel rollers (bentall.inp, 216 elements of 1 um): creepage to 0.2 %,
    peak pressure to 0.1 %, adhesion/slip element counts to one element, frictional
    power to 0.2 % (CONTACT prints watts over DY = 1000 mm at VELOC = 1000 mm/s)."""
    mu, fx_rel, coupled, creep, pmax, nadh, nslip, power = case
    c = pair_constants_from(23000.0, 0.31, 82000.0, 0.28)  # N, mm
    x = -0.108 + (np.arange(216) + 0.5) * 0.001
    grid = Grid(x=x, y=np.zeros(1), h=(x**2 / (2 * 25.0))[None, :], line=True)
    load = 16201.9 / 1000.0  # FN over DY = 1000 mm
    r = steady_rolling(grid, c, load, mu, fx=-fx_rel * mu * load,
                       options=RollingOptions(coupled=coupled))
    assert -r.creepage.xi == pytest.approx(creep, rel=2e-3)
    assert r.pmax == pytest.approx(pmax, rel=1e-3)
    assert abs(r.n_stick - nadh) <= 1
    assert abs(r.n_slip - nslip) <= 1
    # N per mm of width per unit speed -> W over 1000 mm at 1 m/s
    assert r.frictional_power * 1000.0 == pytest.approx(power, rel=2e-3, abs=1e-12)


def test_bentall_full_slip_dissipation_closed_form():
    """mu -> 0, free rolling, uncoupled (Bentall & Johnson 1967): all slips, with slip
    s = (2K/G)(p - p*), p* the pressure splitting the load in halves (theta* + sin
    theta* cos theta* = pi/4 on the ellipse); dissipation mu iint p |s| to 0.2 %."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    c = pair_constants_from(23000.0, 0.31, 82000.0, 0.28)
    x = -0.108 + (np.arange(216) + 0.5) * 0.001
    grid = Grid(x=x, y=np.zeros(1), h=(x**2 / (2 * 25.0))[None, :], line=True)
    load, mu = 16.2019, 1e-4
    r = steady_rolling(grid, c, load, mu, fx=0.0, options=RollingOptions(coupled=False))
    th = brentq(lambda t: t + math.sin(t) * math.cos(t) - math.pi / 4, 0.0, 1.5)
    a = math.sqrt(4 * load * 25.0 / (math.pi * c.e_star))
    p0 = 2 * load / (math.pi * a)
    pstar = p0 * math.cos(th)

    def p(s):
        return p0 * math.sqrt(max(1 - (s / a) ** 2, 0.0))

    ends = [-a * math.sin(th), a * math.sin(th)]
    dissipation = mu * 2 * abs(c.K) / c.G * quad(lambda s: p(s) * abs(p(s) - pstar), -a, a,
                                                  points=ends)[0]
    assert r.frictional_power == pytest.approx(dissipation, rel=2e-3)
    assert abs(r.creepage.xi) == pytest.approx(2 * abs(c.K) * pstar / c.G, rel=3e-3)


def test_spence_compression_against_contact():
    """spence35.inp (45 x 45 elements, G1 = 0.5, nu = 0, rigid body 2, mu = 0.2986): at
    stages 6 and 18 of the load steps FN = (k/45)^3, approach and peak pressure to
    0.3 %, contact and adhesion elements to 2 % (element counts at the rim)."""
    c = pair_constants_from(0.5, 0.0, 1e5, 0.0)
    x = -4.4 + 0.2 * np.arange(45)
    grid = Grid(x=x, y=x.copy(), h=0.004116 * (x[None, :] ** 2 + x[:, None] ** 2))
    out = compress_in_steps(grid, c, [(k / 45) ** 3 for k in range(1, 19)], 0.2986)
    for stage, approach, pmax, ncon, nadh in ((6, 2.901e-3, 3.941e-3, 29, 5),
                                               (18, 2.610e-2, 1.220e-2, 241, 61)):
        r = out[stage - 1]
        assert r.approach == pytest.approx(approach, rel=3e-3)
        assert r.pmax == pytest.approx(pmax, rel=3e-3)
        assert abs(int((r.p > 0).sum()) - ncon) <= max(1, 0.02 * ncon)
        assert abs(r.n_stick - nadh) <= max(1, 0.02 * nadh)


@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_cattaneo_mindlin_shift(nu):
    """32 x 32 over 2.1a, F = 7/8 mu N: adhesion radius to 2 %, shift to 1 % of Mindlin."""
    G = 80e9
    c = pair_constants_from(G, nu, G, nu)
    radius, load, mu = 0.01, 10.0, 0.3
    a = (3 * load * radius / (4 * c.e_star)) ** (1 / 3)
    r = shift(sphere_grid(radius, 1.05 * a, 32), c, load, mu, fx=-0.875 * mu * load)
    assert r.fx == pytest.approx(-0.875 * mu * load, rel=1e-6)
    assert math.sqrt(r.stick_area / math.pi) / a == pytest.approx(0.5, rel=0.02)
    delta = 3 * mu * load * (2 - nu) / (8 * G * a) * (1 - 0.125 ** (2 / 3))
    assert r.creepage.xi == pytest.approx(delta, rel=0.01)


def test_kalker_linear_creep_coefficients():
    """Full adhesion (mu = 1e4) at creepage 1e-5, 40 x 40 over 2.2a, nu = 0.25: C11,
    C22, C23 within 2 % of Kalker's 4.12, 3.67, 1.47."""
    G, nu, radius, load = 80e9, 0.25, 0.01, 10.0
    c = pair_constants_from(G, nu, G, nu)
    a = (3 * load * radius / (4 * c.e_star)) ** (1 / 3)
    grid = sphere_grid(radius, 1.1 * a, 40)
    small = 1e-5
    fx = steady_rolling(grid, c, load, 1e4, Creepage(xi=small)).fx
    fy = steady_rolling(grid, c, load, 1e4, Creepage(eta=small)).fy
    fs = steady_rolling(grid, c, load, 1e4, Creepage(phi=small / a)).fy
    assert -fx / (G * a * a * small) == pytest.approx(4.12, rel=0.02)
    assert -fy / (G * a * a * small) == pytest.approx(3.67, rel=0.02)
    assert -fs / (G * a**3 * small / a) == pytest.approx(1.47, rel=0.02)


def test_bad_input_one_error_line_each():
    c = pair_constants_from(80e9, 0.3, 80e9, 0.3)
    grid = sphere_grid(0.01, 2e-4, 16)
    with pytest.raises(ContactInputError, match="mu must be positive"):
        steady_rolling(grid, c, 10.0, 0.0)
    with pytest.raises(ContactInputError, match="finite"):
        Creepage(xi=float("nan"))
    with pytest.raises(ContactInputError, match="friction limit"):
        shift(grid, c, 10.0, 0.3, fx=3.5)
    from contact.tangential import _solver as solver

    with pytest.raises(ConvergenceError, match="did not settle"):
        solver.solve_tangential(
            *_one_problem(), rolling=True, max_outer=1)


def _one_problem():
    c = pair_constants_from(80e9, 0.3, 80e9, 0.3)
    from contact.halfspace.pair import HalfSpacePair

    op = HalfSpacePair(16, 16, 1e-5, 1e-5, c)
    x = (np.arange(16) - 7.5) * 1e-5
    p = 1e9 * np.sqrt(np.clip(1 - (x[None, :] ** 2 + x[:, None] ** 2) / 7e-5**2, 0, None))
    w = np.zeros((2, 16, 16))
    w[0] = 1e-3
    return op, 0.3 * p, w, np.zeros((2, 16, 16))
