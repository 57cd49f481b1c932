"""One plane-strain normal solve: the line set-up and the tangential solver's line grid
give the same pressure, and it is Hertz's (Johnson 1985, sec. 4.3)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact._materials import material
from contact.setups._line import solve_cylinder
from contact.tangential import Grid, pair_constants, steady_rolling

R, LOAD = 0.02, 1e5  # 20 mm roller, 100 N/mm


def test_line_contact_is_hertz_and_one_solve():
    # quasi-identical bodies: no normal-tangential coupling, the rolling pressure is Hertz's
    c = pair_constants(material("steel"), material("steel"))
    e = c.e_star
    # Hertz line contact: half-width b = sqrt(4 P' R/(pi E*)), peak p0 = sqrt(P' E*/(pi R))
    b = math.sqrt(4 * LOAD * R / (math.pi * e))
    p0 = math.sqrt(LOAD * e / (math.pi * R))
    res = solve_cylinder(R, LOAD, e, n=256)
    x = np.asarray(res.x)
    ph = p0 * np.sqrt(np.clip(1 - (x / b) ** 2, 0, None))
    assert res.pmax == pytest.approx(p0, rel=2e-3)
    assert res.half_width == pytest.approx(b, rel=2 * res.dx / b)
    assert np.abs(res.pressure - ph).max() < 0.02 * p0  # the edge cells of the ellipse
    # exact complementarity: no gap in contact, no interpenetration outside it
    assert np.abs(res.gap[res.pressure > 0]).max() == 0.0
    # the tangential solver's plane-strain normal problem is the same exact solve (to the
    # round-off of its pitch, taken from the cell centres; an iterative solve to a 1e-10
    # relative change differs by ~1e-9 p0)
    grid = Grid(x=x, y=np.zeros(1), h=(x**2 / (2 * R))[None, :], line=True)
    roll = steady_rolling(grid, c, LOAD, 0.3, fx=0.0)
    assert np.abs(roll.p[0] - res.pressure).max() <= 1e-10 * p0
