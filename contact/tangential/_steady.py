"""Steady rolling with friction: prescribed creepages or a prescribed tangential force.

The pressure comes from the normal problem on the same grid; for dissimilar bodies
(K != 0) the normal and tangential problems are coupled: the tractions' normal
displacement is added to the gap and the pressure solved again. In plane strain the two
problems are iterated in turn until the pressure settles (the Panagiotopoulos process of
CONTACT; Kalker 1990 sec. 2.3). In 3D the pressure is solved again after every Newton
step of the tangential problem instead, warm-started, so that pressure, tractions, slip
areas and (under force control) the creepage converge together in one loop rather than
the tangential problem being converged in full for each pressure (about half the FFT
products at 256^2; the answer is the same to the solvers' tolerances). Those pressures
are solved inexactly, to a residual that follows their change, and only the last ones
to the final tolerance, and after a coarse start the first Newton step keeps the start's
pressure (:mod:`contact.tangential._coupling`).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._record import LEADING_EDGE, edge_contact, raise_edge
from contact.halfspace.constants import PairConstants
from contact.halfspace.pair import HalfSpacePair
from contact.tangential._coupling import (
    LAG,
    LOOSEST,
    PRESSURE_TOL,
    Recoupling,
    solve_pressure_to,
)
from contact.tangential._forcecontrol import slip_for_force
from contact.tangential._grid import Grid
from contact.tangential._kinematics import Creepage, rigid_slip
from contact.tangential._nested import CoarseStart, coarse_grid, prolong, restate
from contact.tangential._normal import solve_pressure
from contact.tangential._results import TangentialResult
from contact.tangential._solver import TangentialState, solve_tangential

# GMRES tolerance of the last Newton steps: each step's residual is formed afresh in
# float64 and the last steps start from a residual that is already small, so 1e-2 of it
# ends with stick-zone slips below 1e-9 of the creepage (measured on the benchmark ball
# at 64^2, 128^2 and 256^2: 5e-10, 3e-12, 4e-11)
POLISH_RTOL = 1e-2
# residual of the normal solves of a coarse grid whose answer is only a start
COARSE_PRESSURE_TOL = LOOSEST


@dataclasses.dataclass(frozen=True)
class RollingOptions:
    """How a steady-rolling problem is solved (:func:`steady_rolling`).

    Attributes
    ----------
    coupled : bool
        Iterate the normal problem with the tractions (only matters when K != 0).
    tol : float
        Tolerance of the slip directions and of the pressure between couplings.
    max_coupling : int
        Limit on normal-tangential iterations.
    nested : bool
        Start from the solution of a grid of twice the pitch (:mod:`contact.tangential.
        nested`), recursively; the answer is still the fine grid's.
    polish_rtol : float
        GMRES tolerance of the last Newton steps.
    start_only : bool
        The answer is only the start of a finer solve (nested grids): the tangential
        iteration stops once the stick and slip areas stand.
    """

    coupled: bool = True
    tol: float = 1e-6
    max_coupling: int = 30
    nested: bool = True
    polish_rtol: float = POLISH_RTOL
    start_only: bool = False


def check_friction(mu: float) -> float:
    """mu as a float, or one error line when it is not a positive finite number."""
    if not (isinstance(mu, (int, float)) and math.isfinite(mu) and mu > 0):
        raise ContactInputError(f"friction coefficient mu must be positive, got {mu}")
    return float(mu)


def operator_for(grid: Grid, constants: PairConstants) -> HalfSpacePair:
    """The influence operator of a grid."""
    return HalfSpacePair(len(grid.y), len(grid.x), grid.dx, grid.dy, constants,
                         line=grid.line)


def steady_rolling(
    grid: Grid,
    constants: PairConstants,
    load: float,
    mu: float,
    creepage: Creepage | None = None,
    *,
    fx: float | None = None,
    pressure: np.ndarray | None = None,
    options: RollingOptions | None = None,
) -> TangentialResult:
    """Solve steady rolling on ``grid``.

    Parameters
    ----------
    grid : Grid
        Grid and undeformed separation (:mod:`contact.tangential._grid`).
    constants : PairConstants
        Combined constants of body 1 and body 2.
    load : float
        Normal force (N; N/m for a line contact).
    mu : float
        Coefficient of friction (> 0).
    creepage : Creepage, optional
        Prescribed creepages (xi is the starting guess when ``fx`` is given).
    fx : float, optional
        Prescribed tangential force on body 1 along x (N; N/m); 0 is free rolling.
        The creepage xi is then solved for.
    pressure : ndarray, optional
        A pressure to use instead of solving the normal problem (uncoupled only).
    options : RollingOptions, optional
        Coupling, tolerances, nesting (:class:`RollingOptions`); default all defaults.
    """
    opts = RollingOptions() if options is None else options
    coupled, tol, max_coupling = opts.coupled, opts.tol, opts.max_coupling
    mu = check_friction(mu)
    creep = creepage or Creepage()
    op = operator_for(grid, constants)
    start = _coarse_start(grid, constants, load, mu, creep, fx, opts) \
        if opts.nested and pressure is None else None
    # 3D: the pressure is solved again after every Newton step of the tangential problem
    # (one loop); plane strain keeps the outer loop around the force's root search
    fold = coupled and op.coupled and not grid.line and pressure is None
    u_p = None  # the normal displacement of p, where its solve gives it
    if pressure is not None:
        p, delta = np.asarray(pressure, float), float("nan")
        coupled = False
    elif start is not None and fold:
        # solved again, to its final tolerance, with the tractions of the Newton steps
        extra = op.normal_from_tangential(start.state.q[0], start.state.q[1])
        first = solve_pressure_to(op, grid.h, load, LOOSEST, extra, start.p, None)
        p, delta, u_p = first.pressure, first.approach, first.displacement
    elif start is not None:
        # uncoupled: the pressure of the gap alone, whatever tractions the start carries
        extra = (op.normal_from_tangential(start.state.q[0], start.state.q[1])
                 if coupled else None)
        p, delta = solve_pressure(op, grid.h, load, extra=extra, start=start.p)
    else:
        p, delta = solve_pressure(op, grid.h, load)
    if edge_contact(p, leading_only=True):
        raise_edge(LEADING_EDGE, "the grid")
    if start is not None:
        restate(start.state, mu * p)
    st: list[TangentialState | None] = [None if start is None else start.state]
    xi = creep.xi if start is None else start.xi
    iterations = 0
    pressure_now = Recoupling(op, grid.h, load, mu, p, delta, tol,
                              COARSE_PRESSURE_TOL if opts.start_only else PRESSURE_TOL,
                              0 if start is None else LAG, u_p) if fold else None
    # inexact outer iteration: while the pressure still moves by more than 1e-3, the
    # tangential problems are solved loosely (their exact answer is for a pressure that is
    # about to change); the last ones, which decide convergence, are solved tight
    loose = [coupled and op.coupled and not fold]
    for iterations in range(1, max_coupling + 1):
        u0 = op.tangential_from_normal(p)
        g = mu * p

        def run(v: float, g=g, u0=u0, force=None) -> TangentialState:
            w = rigid_slip(grid.x, grid.y, Creepage(v, creep.eta, creep.phi))
            st[0] = solve_tangential(op, g, w, u0, rolling=True, start=st[0],
                                     tol=1e-3 if loose[0] else tol, force=force, area=grid.area,
                                     polish_rtol=1e-4 if loose[0] else opts.polish_rtol,
                                     recouple=pressure_now, start_only=opts.start_only)
            return st[0]

        if fx is None:
            run(xi)
        elif not grid.line:
            # 3D: the creepage is one more unknown of the Newton steps
            fn = float(p.sum()) * grid.area
            if abs(fx) >= mu * fn:
                raise ContactInputError(
                    f"tangential force {abs(fx):.4g} N is not below the friction limit "
                    f"mu N = {mu * fn:.4g} N: the bodies slide as a whole")
            xi += run(xi, force=fx).dw
        else:
            scale = 2.0 * mu * float(p.max()) / constants.e_star
            fn = float(p.sum()) * grid.area
            xi = slip_for_force(lambda v: float(run(v).q[0].sum()) * grid.area, fx, xi,
                                scale / 8.0, mu * fn)
            run(xi)
        if fold:
            p, delta = pressure_now.p, pressure_now.delta
            iterations = pressure_now.solves
            break
        if not (coupled and op.coupled):
            break
        q = st[0].q
        p_new, delta = solve_pressure(op, grid.h, load,
                                      extra=op.normal_from_tangential(q[0], q[1]), start=p)
        change = float(np.abs(p_new - p).sum() / p.sum())
        p = p_new
        if change < tol and not loose[0]:
            break
        loose[0] = loose[0] and change > 1e-3
    else:
        raise ConvergenceError(
            f"normal-tangential coupling did not settle in {max_coupling} iterations")
    s = st[0]
    return TangentialResult(grid=grid, constants=constants, mu=mu, p=p, q=s.q, s=s.s,
                            state=s.state, creepage=Creepage(xi, creep.eta, creep.phi),
                            approach=delta, rolling=True, iterations=iterations,
                            outer=s.outer, matvecs=s.matvecs, tol=tol)


def _coarse_start(grid, constants, load, mu, creep, fx,
                  opts: RollingOptions) -> CoarseStart | None:
    """The coarse grid's answer copied to ``grid``, or None where nesting does not pay."""
    nest = coarse_grid(grid)
    if nest is None:
        return None
    coarse, levels = nest
    # only a start: its own tolerances can be loose (the fine solve converges in full)
    start_opts = RollingOptions(coupled=opts.coupled, tol=max(opts.tol, 1e-3),
                                max_coupling=opts.max_coupling, start_only=True)
    r = steady_rolling(coarse, constants, load, mu, creep, fx=fx, options=start_opts)
    return prolong(r.p, r.q, r.state, r.creepage.xi, levels)
