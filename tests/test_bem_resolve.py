"""The warm normal re-solve of the steady-rolling coupling (:func:`contact.bem._solver.
resolve_pressure`): the normal solver's iteration without its record, started from the
last answer of a loop and, where known, that answer's displacement.

Independent truths: the displacement it returns against the normal block of the coupled
half-space pair (:class:`contact.halfspace.pair.HalfSpacePair`, Boussinesq's influence
over E*, its own padded FFT), and its answer against :func:`contact.bem.solve_normal`
from the same warm start (the public solver with its checks and record).
"""

from __future__ import annotations

import numpy as np
import pytest

from contact import SolveOptions
from contact._errors import ConvergenceError
from contact._grid import gap_grid
from contact._hertz import hertz_sphere
from contact._materials import material
from contact.bem import solve_normal
from contact.bem._solver import WarmStart, resolve_pressure
from contact.halfspace.pair import HalfSpacePair
from contact.tangential import _coupling as coupling
from contact.tangential import pair_constants, sphere_grid

STEEL_AL = pair_constants(material("steel"), material("aluminium"))


@pytest.fixture(scope="module")
def ball():
    """The benchmark ball's gap on 64^2, a bump added (as the tractions' normal
    displacement adds one) and the pressure of the plain gap as the warm start."""
    a = hertz_sphere(0.02, 5.0, STEEL_AL.e_star).a
    grid = sphere_grid(0.02, 1.25 * a, 64)
    x, y = np.meshgrid(grid.x, grid.y)
    # a thousandth of Hertz's approach a^2/R, off centre
    bump = 1e-3 * a**2 / 0.02 * np.exp(-((x - 0.3 * a)**2 + y**2) / (0.4 * a)**2)
    p0 = solve_normal(grid, e_star=STEEL_AL.e_star, load=5.0,
                      options=SolveOptions(tol=1e-10)).pressure
    return grid, grid.h + bump, np.asarray(p0)


def test_the_displacement_is_that_of_the_pressure(ball):
    """The returned displacement is the normal displacement of the returned pressure,
    within 1e-12 of the coupled pair's own product."""
    grid, gap, p0 = ball
    r = resolve_pressure(gap, grid.dx, grid.dy, e_star=STEEL_AL.e_star, load=5.0,
                         start=WarmStart(p0), tol=1e-8)
    u = HalfSpacePair(64, 64, grid.dx, grid.dy, STEEL_AL).normal(r.pressure)
    assert r.converged
    assert np.abs(r.displacement - u).max() <= 1e-12 * np.abs(u).max()


@pytest.mark.parametrize("tol", [1e-5, 1e-8])
def test_a_given_displacement_gives_the_public_solvers_answer(ball, tol):
    """Started from a pressure and its displacement, the re-solve gives solve_normal's
    pressure (1e-8 of its largest value: the start's displacement is the pair's own FFT
    product, whose last-bit rounding the iterations carry, 2.3e-10 seen with numpy 2.4.6
    pocketfft; a different algorithm differs by the tolerance, 1e-5) and approach (1e-12)
    from the same warm start,
    in the same iterations; a wrong displacement does not (the start is read from it).
    The start carries a tenth more than the load: both rescale it, with its
    displacement."""
    grid, gap, p0 = ball
    p0 = 1.1 * p0
    ref = solve_normal(gap_grid(gap, grid.dx), e_star=STEEL_AL.e_star, load=5.0, initial=p0,
                       options=SolveOptions(tol=tol, edge="ignore"))
    u0 = HalfSpacePair(64, 64, grid.dx, grid.dy, STEEL_AL).normal(p0)
    r = resolve_pressure(gap, grid.dx, grid.dy, e_star=STEEL_AL.e_star, load=5.0,
                         start=WarmStart(p0, u0), tol=tol)
    assert r.iterations == ref.iterations
    assert np.abs(r.pressure - ref.pressure).max() <= 1e-8 * ref.pressure.max()
    assert abs(r.approach - ref.approach) <= 1e-12 * abs(ref.approach)
    wrong = resolve_pressure(gap, grid.dx, grid.dy, e_star=STEEL_AL.e_star, load=5.0,
                             start=WarmStart(p0, 0.9 * u0), tol=tol, max_iter=1)
    assert np.abs(wrong.pressure - ref.pressure).max() > 1e-6 * ref.pressure.max()


def test_a_coupling_solve_that_does_not_converge_says_so_in_one_line(ball, monkeypatch):
    """The coupling's solve raises the contact ConvergenceError (not a silent answer)
    when the normal iteration stops short."""
    import contact.bem._solver as solver

    grid, gap, p0 = ball
    op = HalfSpacePair(64, 64, grid.dx, grid.dy, STEEL_AL)
    monkeypatch.setattr(solver, "resolve_pressure",
                        lambda *a, **k: resolve_pressure(*a, **{**k, "max_iter": 0}))
    monkeypatch.setattr(coupling, "resolve_pressure", solver.resolve_pressure)
    with pytest.raises(ConvergenceError, match="coupled normal solve stopped"):
        coupling.solve_pressure_to(op, grid.h, 5.0, 1e-12, gap - grid.h, p0, None)


def test_a_start_that_carries_nothing_starts_uniform(ball):
    """An all-zero start (and any displacement with it) is no start: the re-solve begins
    from a uniform pressure, as solve_normal's warm start does, and reaches its answer
    (1e-8 of the largest pressure, both to 1e-10)."""
    grid, gap, _ = ball
    ref = solve_normal(gap_grid(gap, grid.dx), e_star=STEEL_AL.e_star, load=5.0,
                       options=SolveOptions(tol=1e-10, nested=False))
    r = resolve_pressure(gap, grid.dx, grid.dy, e_star=STEEL_AL.e_star, load=5.0,
                         start=WarmStart(np.zeros_like(gap), np.ones_like(gap)), tol=1e-10)
    assert r.converged
    assert np.abs(r.pressure - ref.pressure).max() <= 1e-8 * ref.pressure.max()
