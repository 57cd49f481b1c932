"""The adhesive solves take the core's one grid (contact._grid.Grid), as the normal BEM does.

Truths used: the same solve given the gap as a loose array and its pitch, which is the
entry point the adhesion validation (Maugis, JKR, DMT, Johnson's wavy surface) was run
through; the Grid form must give the same numbers bit for bit, and refuse, in one line
each, the grids the periodic square-pixel solver cannot take.
"""

from __future__ import annotations

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._grid import centred_grid, scan_grid
from contact.adhesion.flat import adhesive_flat
from contact.adhesion.laws import DugdaleLaw, ExponentialLaw
from contact.adhesion.line import periodic_line_grid
from contact.adhesion.solver import adhesive_problem, solve_adhesive

E_STAR = 1e9
DX = 0.25e-6


def _sphere_gap(n: int = 24, radius: float = 20e-6) -> np.ndarray:
    x = (np.arange(n) - n / 2) * DX
    return (x[:, None] ** 2 + x[None, :] ** 2) / (2.0 * radius)


def test_grid_and_array_give_the_same_adhesive_solve():
    h = _sphere_gap()
    law = DugdaleLaw.from_range(0.05, 2e-9).on_grid(DX, E_STAR)
    grid = centred_grid(h.shape[1], DX, periodic=True, h=h)
    by_array = solve_adhesive(adhesive_problem(h, DX, E_STAR, law), 5e-9, tol=1e-8)
    problem = adhesive_problem(grid, e_star=E_STAR, law=law)
    by_grid = solve_adhesive(problem, 5e-9, tol=1e-8)
    assert problem.grid is grid
    assert np.array_equal(by_grid.gap, by_array.gap)
    assert by_grid.load == by_array.load and by_grid.contact_area == by_array.contact_area
    assert by_grid.load < 0.0 < by_grid.contact_area  # adhesive: it pulls while touching


def test_array_problem_records_a_periodic_grid_of_its_pixels():
    h = _sphere_gap(16)
    grid = adhesive_problem(h, DX, E_STAR, ExponentialLaw(0.05, 2e-9)).grid
    assert grid.periodic and not grid.line
    assert grid.shape == h.shape and (grid.dx, grid.dy) == (DX, DX)
    assert np.array_equal(grid.h, h)


def test_adhesive_flat_takes_a_grid():
    rng = np.random.default_rng(4)
    z = 20e-9 * rng.standard_normal((16, 16))
    law = ExponentialLaw(0.02, 2e-9)
    args = dict(pressures=[1e6], mean_gaps=[10e-9], stiffnesses=[1e14])
    a = adhesive_flat(z.max() - z, DX, E_STAR, law, **args)
    b = adhesive_flat(scan_grid(z.shape, DX, periodic=True, h=z.max() - z), e_star=E_STAR,
                      law=law, **args)
    assert a.dx == b.dx == DX
    pa, pb = a.points[0], b.points[0]
    assert (pa.pressure, pa.area_fraction, pa.mean_gap, pa.attractive_pressure) == (
        pb.pressure, pb.area_fraction, pb.mean_gap, pb.attractive_pressure)
    assert pa.pressure == pytest.approx(1e6, rel=1e-3)


@pytest.mark.parametrize("grid, dx, match", [
    (centred_grid(16, DX, h=_sphere_gap(16)), None, "periodic"),
    (centred_grid(16, DX, dy=2 * DX, periodic=True, h=_sphere_gap(16)), None, "square"),
    (centred_grid(16, DX, periodic=True), None, "gap h"),
    (periodic_line_grid(16, DX, np.zeros(16)), None, "line_problem"),
    (centred_grid(16, DX, periodic=True, h=_sphere_gap(16)), DX, "do not give dx"),
    (_sphere_gap(16), None, "give the pixel dx"),
    (_sphere_gap(16), "a", "pixel dx must be a number in m"),
    (_sphere_gap(16), -DX, "pixel dx must be positive"),
])
def test_grids_the_solver_cannot_take_get_one_line(grid, dx, match):
    with pytest.raises(ContactInputError, match=match):
        adhesive_problem(grid, dx, E_STAR, ExponentialLaw(0.05, 2e-9))


def test_missing_modulus_or_law_gets_one_line():
    grid = centred_grid(16, DX, periodic=True, h=_sphere_gap(16))
    with pytest.raises(ContactInputError, match="e_star"):
        adhesive_problem(grid, law=ExponentialLaw(0.05, 2e-9))
    with pytest.raises(ContactInputError, match="one starting mean gap"):
        adhesive_flat(grid, e_star=E_STAR, law=ExponentialLaw(0.05, 2e-9), pressures=[1e6])
