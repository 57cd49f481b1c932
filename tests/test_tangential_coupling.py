"""The cheaper 3D free-rolling path: contact-box products and the inexact coupling.

Independent truths: the box products against a direct sum over the Cerruti influence
coefficients (no FFT); the inexact coupling against the same solve with every pressure
solved to the final tolerance from the first Newton step (the fixed point must not move).
The solver's agreement with CONTACT, Carter and Kalker stays in
``tests/test_tangential_validation.py`` and ``tests/test_contact_oracle_rolling.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from contact._hertz import hertz_sphere
from contact._materials import material
from contact.halfspace.cerruti import influence_blocks
from contact.halfspace.pair import HalfSpacePair
from contact.tangential import RollingOptions, pair_constants, sphere_grid, steady_rolling
from contact.tangential import _coupling as coupling
from contact.tangential._cropped import BoxProducts

STEEL_AL = pair_constants(material("steel"), material("aluminium"))


def _direct(q, dx, dy, active):
    """u = sum over the active elements of the influence blocks (no FFT)."""
    ny, nx = active.shape
    u = np.zeros((2, ny, nx))
    yy, xx = np.mgrid[0:ny, 0:nx]
    for i, j in zip(*np.nonzero(active)):
        b = influence_blocks((xx - j) * dx, (yy - i) * dy, dx, dy, STEEL_AL)
        u[0] += b["xx"] * q[0, i, j] + b["xy"] * q[1, i, j]
        u[1] += b["xy"] * q[0, i, j] + b["yy"] * q[1, i, j]
    return u


def test_box_products_equal_the_direct_sum_on_the_contact():
    """On a disc of loaded elements in a larger grid the box products equal the direct
    sum to 1e-12 on the disc and on the next element along x (the rolling slip reads
    it), while the box is smaller than the grid."""
    n, dx = 32, 1e-5
    yy, xx = np.mgrid[0:n, 0:n]
    active = (xx - 13.3) ** 2 + (yy - 15.1) ** 2 < 9.0**2
    op = HalfSpacePair(n, n, dx, dx, STEEL_AL)
    box = BoxProducts(op, active)
    assert box.box is not None
    rows, cols = box.box
    assert (rows.stop - rows.start) * (cols.stop - cols.start) < n * n
    rng = np.random.default_rng(3)
    q = rng.standard_normal((2, n, n)) * active
    got = box.tangential(q[0], q[1])
    want = _direct(q, dx, dx, active)
    read = active | np.roll(active, 1, axis=1)
    scale = np.abs(want).max()
    assert np.abs(got - want)[:, read].max() <= 1e-12 * scale


def test_box_products_leave_other_operators_alone():
    """An operator that is not the elastic pair (a subclass standing in for the
    viscoelastic ones) keeps its own products: no box is cut."""

    class Other(HalfSpacePair):
        pass

    op = Other(32, 32, 1e-5, 1e-5, STEEL_AL)
    active = np.zeros((32, 32), bool)
    active[10:20, 10:20] = True
    assert BoxProducts(op, active).box is None


@pytest.mark.parametrize("fx", [0.0, 0.3])
def test_inexact_coupling_keeps_the_answer(monkeypatch, fx):
    """Free rolling and a driven ball (fx = 0.3 N, a fifth of mu N) on 64^2 (nested
    from 32^2): the inexact coupling gives the stick/slip states of the solve with every
    pressure solved tight from the first step, tractions within 1e-6 of max|q| and the
    creepage within 1e-6."""
    a = hertz_sphere(0.02, 5.0, STEEL_AL.e_star).a
    grid = sphere_grid(0.02, 1.25 * a, 64)
    fast = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=fx)
    monkeypatch.setattr(coupling, "LOOSEST", coupling.PRESSURE_TOL)
    monkeypatch.setattr("contact.tangential._steady.LOOSEST", coupling.PRESSURE_TOL)
    monkeypatch.setattr("contact.tangential._steady.LAG", 0)
    monkeypatch.setattr("contact.tangential._steady.COARSE_PRESSURE_TOL",
                        coupling.PRESSURE_TOL)
    tight = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=fx)
    assert np.array_equal(fast.state, tight.state)
    assert np.abs(fast.q - tight.q).max() <= 1e-6 * np.abs(tight.q).max()
    assert abs(fast.creepage.xi - tight.creepage.xi) <= 1e-6 * abs(tight.creepage.xi)
    assert np.abs(fast.p - tight.p).max() <= 1e-7 * tight.p.max()


def test_uncoupled_nested_solve_keeps_the_gaps_pressure():
    """coupled=False on 64^2 nested from 32^2 gives the answer of the same solve from
    cold (the pressure of the gap alone, not one pushed by the coarse start's tractions):
    pressure within 1e-7 of its largest value, tractions within 1e-6 of max|q|, the same
    stick/slip states."""
    a = hertz_sphere(0.02, 5.0, STEEL_AL.e_star).a
    grid = sphere_grid(0.02, 1.25 * a, 64)
    nested = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=0.0,
                            options=RollingOptions(coupled=False))
    cold = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=0.0,
                          options=RollingOptions(coupled=False, nested=False))
    assert np.abs(nested.p - cold.p).max() <= 1e-7 * cold.p.max()
    assert np.array_equal(nested.state, cold.state)
    assert np.abs(nested.q - cold.q).max() <= 1e-6 * np.abs(cold.q).max()


def test_start_from_the_coarsest_grid_keeps_the_answer(monkeypatch):
    """128^2 free rolling started from 32^2 directly (prolonged twice) against the same
    solve started through 64^2: the same stick/slip states, tractions within 1e-6 of
    max|q|, the creepage within 1e-6."""
    from contact import _nesting as nesting
    from contact.tangential import _nested as nested

    a = hertz_sphere(0.02, 5.0, STEEL_AL.e_star).a
    grid = sphere_grid(0.02, 1.25 * a, 128)
    assert nested.coarse_grid(grid)[1] == 2
    direct = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=0.0)
    monkeypatch.setattr("contact.tangential._steady.coarse_grid",
                        lambda g: (lambda c: None if c is None else (c, 1))(
                            nesting.coarse_grid(g, nested.SMALLEST)))
    chained = steady_rolling(grid, STEEL_AL, 5.0, 0.3, fx=0.0)
    assert np.array_equal(direct.state, chained.state)
    assert np.abs(direct.q - chained.q).max() <= 1e-6 * np.abs(chained.q).max()
    assert abs(direct.creepage.xi - chained.creepage.xi) <= 1e-6 * abs(chained.creepage.xi)
