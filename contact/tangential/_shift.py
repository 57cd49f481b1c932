"""Quasi-static shift and compression with friction: Cattaneo-Mindlin and Spence.

A shift step moves body 1 rigidly by w relative to body 2 while the tractions change; the
slip distance of the step is s = w + u - u', u' the displacement difference at the end of
the previous step (Kalker 1990 sec. 5.2; CONTACT's "shift" problems). From an unloaded
start (u' = 0) a prescribed tangential force gives Cattaneo's (1938) and Mindlin's (1949)
problem. A normal load raised in steps between dissimilar bodies, with no rigid shift,
gives Spence's (1975) compression problem: the coupling K pulls the surfaces tangentially
and friction resists it over a central adhesion area.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from contact._errors import ConvergenceError
from contact.halfspace.constants import PairConstants
from contact.tangential._forcecontrol import slip_for_force
from contact.tangential._grid import Grid
from contact.tangential._kinematics import Creepage
from contact.tangential._normal import solve_pressure
from contact.tangential._results import TangentialResult, tangential_record
from contact.tangential._solver import TangentialState, slip_residual, solve_tangential
from contact.tangential._steady import check_friction, operator_for


def shift(
    grid: Grid,
    constants: PairConstants,
    load: float,
    mu: float,
    *,
    fx: float | None = None,
    shift_x: float = 0.0,
    tol: float = 1e-6,
) -> TangentialResult:
    """A shift from the unloaded state: rigid shift ``shift_x`` or force ``fx`` (N).

    The force must stay below mu N (one error line otherwise). The pressure is the
    uncoupled one (Cattaneo-Mindlin take quasi-identical bodies). Returns the result with
    the rigid shift (m) in ``creepage.xi``.
    """
    mu = check_friction(mu)
    op = operator_for(grid, constants)
    p, delta = solve_pressure(op, grid.h, load)
    g = mu * p
    u0 = op.tangential_from_normal(p)
    st: list[TangentialState | None] = [None]
    ones = np.ones((len(grid.y), len(grid.x)))

    def run(v: float) -> TangentialState:
        w = np.stack([v * ones, 0.0 * ones])
        st[0] = solve_tangential(op, g, w, u0, rolling=False, start=st[0], tol=tol)
        return st[0]

    if fx is not None:
        fn = float(p.sum()) * grid.area
        scale = mu * float(p.max()) * grid.dx / constants.G
        shift_x = slip_for_force(lambda v: float(run(v).q[0].sum()) * grid.area, fx,
                                 0.0, scale, mu * fn)
    s = run(shift_x)
    return TangentialResult(grid=grid, constants=constants, mu=mu, p=p, q=s.q, s=s.s,
                            state=s.state, creepage=Creepage(shift_x, 0.0, 0.0),
                            approach=delta, rolling=False, iterations=1, outer=s.outer,
                            matvecs=s.matvecs, tol=tol)


def compress_in_steps(
    grid: Grid,
    constants: PairConstants,
    loads: Sequence[float],
    mu: float,
    *,
    tol: float = 1e-6,
    max_coupling: int = 30,
) -> list[TangentialResult]:
    """Raise the normal load through ``loads`` with no rigid shift (Spence's problem).

    Each step iterates the coupled normal and tangential problems (dissimilar bodies)
    with the displacement of the previous step as the reference of the slip.
    """
    mu = check_friction(mu)
    op = operator_for(grid, constants)
    shape = (len(grid.y), len(grid.x))
    zero_w = np.zeros((2, *shape))
    u_prev = np.zeros((2, *shape))
    q = np.zeros((2, *shape))
    p = None
    st: TangentialState | None = None
    out = []
    for load in loads:
        p, delta = solve_pressure(op, grid.h, load,
                                  extra=op.normal_from_tangential(q[0], q[1]), start=None)
        for it in range(1, max_coupling + 1):  # noqa: B007 (read after the loop)
            u_p = op.tangential_from_normal(p)
            st = solve_tangential(op, mu * p, zero_w, u_p - u_prev, rolling=False,
                                  start=st, tol=tol)
            q = st.q
            p_new, delta = solve_pressure(op, grid.h, load,
                                          extra=op.normal_from_tangential(q[0], q[1]),
                                          start=p)
            change = float(np.abs(p_new - p).sum() / p.sum())
            p = p_new
            if change < tol:
                break
        else:
            raise ConvergenceError("compression step: the coupling did not settle")
        # the slip is measured from the previous step's displacement: its own record
        res = slip_residual(st.s, st.state, st.e, zero_w, u_p - u_prev, mu * p, grid.dx,
                            False)
        record = tangential_record(res, rolling=False, iterations=it, outer=st.outer, tol=tol,
                                   p=p, s=st.s)
        u_prev = op.tangential(q[0], q[1]) + op.tangential_from_normal(p)
        out.append(TangentialResult(grid=grid, constants=constants, mu=mu, p=p, q=q,
                                    s=st.s, state=st.state, creepage=Creepage(),
                                    approach=delta, rolling=False, iterations=it,
                                    outer=st.outer, matvecs=st.matvecs, tol=tol,
                                    solve=record))
    return out
