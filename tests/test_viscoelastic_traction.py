"""Steady rolling tractions on viscoelastic bodies (plane strain) against Carter's closed
form and CONTACT's visc_cylindr reference output (creepage, adhesion and slip elements)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._hertz import hertz_cylinder
from contact.viscoelastic._line import influence_matrix, line_grid, rolling_cylinder, solve_line
from contact.viscoelastic._rheology import CreepSeries, StandardLinearSolid, pair_creep
from contact.viscoelastic._traction import steady_traction


def test_carter_creepage_and_stick_zone() -> None:
    # Carter (1926); Johnson (1985) eq. 8.9: xi = (mu a/R)(1 - sqrt(1 - F/(mu N))),
    # stick zone at the leading edge of width 2a sqrt(1 - F/(mu N)).
    R, W, mu, ratio = 0.05, 6.0e5, 0.3, 0.6
    creep = CreepSeries(1e-9)
    res = rolling_cylinder(R, W, creep, 1.0, n=512)
    dx = float(res.x[1] - res.x[0])
    t = steady_traction(influence_matrix(512, dx, creep, 1.0), np.asarray(res.pressure), dx,
                        mu, -ratio * mu * W)
    a = hertz_cylinder(R, W, 1e9).a
    assert t.creepage == pytest.approx(mu * a / R * (1 - math.sqrt(1 - ratio)), rel=0.01)
    assert t.stick.sum() * dx == pytest.approx(2 * a * math.sqrt(1 - ratio), rel=0.01)
    xs = np.asarray(res.x)
    on = np.flatnonzero(np.asarray(res.pressure) > 0)
    assert t.stick[on[-1]] and not t.stick[on[0]]  # adhesion at the leading edge
    assert xs[t.stick].min() == pytest.approx(a * (1 - 2 * math.sqrt(1 - ratio)), abs=2 * dx)
    assert t.force == pytest.approx(-ratio * mu * W, rel=1e-9)


# CONTACT examples/visc_cylindr.ref_out: (TC, CREEP X, adhesion, slip elements);
# FX / (mu FN) = -0.6, mu = 0.3, the rest as in tests/test_viscoelastic_line.py.
REF = [(0.0, 1.378e-2, 51, 29), (0.009, 1.365e-2, 37, 25), (0.045, 1.152e-2, 36, 21),
       (2.0, 9.932e-3, 35, 21)]


@pytest.mark.parametrize("tc, creep_x, n_adh, n_slip", REF)
def test_contact_visc_cylindr_tangential(tc, creep_x, n_adh, n_slip) -> None:
    G, nu = 1143e6, 0.4
    eg = 2 * G * (1 + nu)
    body = StandardLinearSolid(eg, eg / 2, tc if tc > 0 else 1e-12, nu)
    creep = pair_creep(body, body)
    x = (-7.92 + 0.16 * np.arange(99)) * 1e-3
    dx = 0.16e-3
    res = solve_line(line_grid(x, dx, x**2 / (2 * 0.05)), 6.0e5, creep, 1.0)
    t = steady_traction(influence_matrix(99, dx, creep, 1.0), np.asarray(res.pressure), dx,
                        0.3, -0.6 * 0.3 * 6.0e5)
    # tc = 2 s: CONTACT's 1 m strip is not plane strain at V tau = 2 m (0.2 % there)
    assert t.creepage == pytest.approx(creep_x, rel=3e-3 if tc == 2.0 else 5e-4)
    assert (int(t.stick.sum()), int(t.slip.sum())) == (n_adh, n_slip)


def test_bad_friction_input() -> None:
    creep = CreepSeries(1e-9)
    res = rolling_cylinder(0.05, 6e5, creep, 1.0, n=64)
    dx = float(res.x[1] - res.x[0])
    A = influence_matrix(64, dx, creep, 1.0)
    with pytest.raises(ContactInputError, match="friction"):
        steady_traction(A, np.asarray(res.pressure), dx, 0.0, 0.0)
    with pytest.raises(ContactInputError, match="slides"):
        steady_traction(A, np.asarray(res.pressure), dx, 0.3, -0.3 * 6e5)


def test_prescribed_creepage_gives_the_force_back() -> None:
    G, nu = 1143e6, 0.4
    body = StandardLinearSolid(2 * G * (1 + nu), G * (1 + nu), 0.009, nu)
    creep = pair_creep(body, body)
    x = (-7.92 + 0.16 * np.arange(99)) * 1e-3
    dx = 0.16e-3
    res = solve_line(line_grid(x, dx, x**2 / (2 * 0.05)), 6.0e5, creep, 1.0)
    A, p = influence_matrix(99, dx, creep, 1.0), np.asarray(res.pressure)
    by_force = steady_traction(A, p, dx, 0.3, -0.6 * 0.3 * 6.0e5)
    by_creep = steady_traction(A, p, dx, 0.3, creepage=by_force.creepage)
    assert by_creep.force == pytest.approx(by_force.force, rel=1e-9)
    full = steady_traction(A, p, dx, 0.3, creepage=0.1)  # far beyond saturation: sliding
    assert full.force == pytest.approx(-0.3 * 6.0e5, rel=1e-9) and not full.stick.any()
