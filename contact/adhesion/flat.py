"""A rough periodic surface pressed on a flat with adhesion, at prescribed nominal pressures.

:func:`contact.adhesion.solver.solve_adhesive` imposes the rigid approach; a flat-contact
sweep imposes the nominal (mean) pressure instead. :func:`solve_at_pressure` finds the
approach whose equilibrium carries the pressure asked for: a secant on the approach,
safeguarded by bisection once the pressure is bracketed. Adhesive equilibria depend on
the path (a contact pressed too far and backed off keeps more area, and a big loading
step snaps in pixels that small steps would leave apart where the grid does not resolve
the cohesive zone), so the path is made quasi-static and unique: the first pressure is
approached from the non-contact state (every gap beyond the law's reach), every try is a
loading step from the furthest state still short of the pressure (never from one past
it), and every step is split in two (:func:`contact.adhesion.cycle.advance`) while the
touching area changes by more than :data:`contact.adhesion.cycle.MAX_AREA_CHANGE` of it.
On the tests' 64^2 surface at 0.1 pixel of cohesive zone, starting estimates 0.3 to 3
times apart then give the same contact set (they changed the area by 3.9 % before, and
the big steps had overestimated it by 10 to 15 %); halving the threshold to 5 % changes
nothing. On its 128^2 twin (exponential law, w 0.2 J/m^2, rho 5 nm, 0.1 and 1 MPa) the
area fractions are 0.0076 and 0.0724 (threshold 10 %), 0.0072 and 0.0724 (5 %), 0.0089
and 0.0889 (30 %), 0.0169 and 0.113 unsplit, against 0.0044 and 0.0468 without
adhesion: where the zone is unresolved the loading path, not the solver, sets the area.
The price is solves: 5 to 7 times those of unsplit steps (``max_change=math.inf``).
Pressed surfaces carry more pressure the closer they come (the slope is the contact
stiffness); surfaces apart but within reach carry more tension instead. A pressure that
falls inside a jump of the load-approach curve has no equilibrium on the branch and is
one :class:`~contact.errors.ConvergenceError`.

Per pressure the sweep reports, with the same definitions as the non-adhesive driver
:func:`contact.setups.flat.flat_contact`: the area fraction where the surfaces touch (gap
zero), the mean gap (the mean of the deformed gap), and the attractive pressure
:func:`attractive_pressure`, the interaction law's traction averaged over the whole
nominal area, touching points included (a positive magnitude). The nominal pressure is
the repulsive mean minus the attractive one.

Resolution: as for a sphere (:mod:`contact.adhesion.ball`), the cohesive zone at each
contact edge is about l_pz = pi E* w / (4 sigma0^2) wide; below
:data:`contact.adhesion.ball.MIN_ZONE_PIXELS` pixels the edges are pinned by the grid and
the adhesive area is not resolved, which the result warns about.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from contact.adhesion.ball import MIN_ZONE_PIXELS
from contact.adhesion.cycle import MAX_AREA_CHANGE, advance
from contact.adhesion.laws import InteractionLaw
from contact.adhesion.solver import AdhesiveProblem, AdhesiveState, adhesive_problem, solve_adhesive
from contact.errors import ContactInputError, ConvergenceError
from contact.record import SolveRecord

#: Secant tries allowed per nominal pressure.
MAX_SOLVES = 40
#: Equilibrium tolerance of the quasi-static sub-steps that lead to each try.
PATH_TOL = 1e-6


@dataclass(frozen=True)
class AdhesiveFlatPoint:
    """The adhesive equilibrium at one nominal pressure (SI).

    Attributes
    ----------
    pressure : float
        Nominal pressure reached (Pa): the repulsive mean minus the attractive one.
    area_fraction : float
        Share of the cells where the gap is zero.
    mean_gap : float
        Mean of the deformed gap (m).
    attractive_pressure : float
        The law's traction averaged over the nominal area, touching points included (Pa).
    approach : float
        Approach of the flat to the mean plane of the deformed surface (m).
    solves, iterations : int
        Equilibrium solves on the loading path (the secant's tries and their quasi-static
        sub-steps), and their iterations in all.
    solve : SolveRecord
        The record (:mod:`contact.record`): the iterations in all, the solves as outer
        iterations, the last equilibrium's residual.
    """

    pressure: float
    area_fraction: float
    mean_gap: float
    attractive_pressure: float
    approach: float
    solves: int
    iterations: int
    solve: SolveRecord

    @property
    def repulsive_pressure(self) -> float:
        """Mean of the compressive part of the pressure (Pa)."""
        return self.pressure + self.attractive_pressure


@dataclass(frozen=True)
class AdhesiveFlat:
    """An adhesive flat-contact sweep (SI); ``process_zone`` is l_pz (m)."""

    points: tuple[AdhesiveFlatPoint, ...]
    law: InteractionLaw
    e_star: float
    dx: float
    process_zone: float
    warnings: tuple[str, ...]

    @property
    def pressure(self) -> np.ndarray:
        return np.array([pt.pressure for pt in self.points])

    @property
    def area_fraction(self) -> np.ndarray:
        return np.array([pt.area_fraction for pt in self.points])

    @property
    def mean_gap(self) -> np.ndarray:
        return np.array([pt.mean_gap for pt in self.points])

    @property
    def attractive_pressure(self) -> np.ndarray:
        return np.array([pt.attractive_pressure for pt in self.points])


def attractive_pressure(law: InteractionLaw, gap: np.ndarray) -> float:
    """The mean of the law's attractive traction t(g) over all cells (Pa, >= 0).

    Touching cells (g = 0) count with t(0), the law's peak tension: where the surfaces
    touch the interaction still pulls, and the contact pressure there balances it.
    """
    return float(np.mean(law.traction(np.asarray(gap, dtype=float))))


def non_contact(problem: AdhesiveProblem, tol: float = 1e-8) -> tuple[float, AdhesiveState]:
    """The state where every gap is beyond the law's reach: the start of a loading path.

    It only warm-starts the first step and says that nothing touches, so it is solved to
    1e-5 at most (the exponential law's faint tail can take long to balance more finely
    when the law is weak)."""
    d0 = float(problem.gap0.min()) - problem.law.reach
    return d0, solve_adhesive(problem, d0, None, tol=max(tol, 1e-5))


def solve_at_pressure(problem: AdhesiveProblem, pressure: float, approach: float,
                      slope: float, start: tuple[float, AdhesiveState] | None = None, *,
                      rtol: float = 1e-4, tol: float = 1e-8,
                      max_change: float = MAX_AREA_CHANGE,
                      ) -> tuple[AdhesiveState, float, int, int]:
    """The equilibrium of nominal pressure ``pressure`` (Pa), loading from ``start``.

    Parameters
    ----------
    problem : AdhesiveProblem
        Grid, stiffness and law.
    pressure : float
        Nominal pressure to reach (Pa, compression positive; non-zero).
    approach : float
        First rigid approach tried (m).
    slope : float
        Estimate of d(pressure)/d(approach) (Pa/m), for the first secant step: positive
        where the surfaces are pressed (the contact stiffness), negative on an open branch
        pulled by the interaction, where approaching raises the tension.
    start : (float, AdhesiveState), optional
        A state short of the pressure, with its rigid approach, to load from; default the
        non-contact state (:func:`non_contact`).
    rtol : float
        The pressure is reached when within ``rtol |pressure|``.
    tol : float
        Equilibrium tolerance of each solve (:func:`solve_adhesive`).
    max_change : float
        A loading step is split while the touching area changes by more than this share.

    Returns
    -------
    (state, rigid approach, solves, iterations in all)

    Raises
    ------
    ConvergenceError
        No equilibrium carries the pressure on this branch (a jump) within
        :data:`MAX_SOLVES` tries.
    """
    if not (math.isfinite(pressure) and pressure != 0.0):
        raise ContactInputError(f"the nominal pressure must be finite and non-zero, got "
                                f"{pressure!r}")
    if not (math.isfinite(slope) and slope != 0.0):
        slope = abs(pressure) / max(float(np.std(problem.gap0)), problem.law.range)
    area0 = problem.gap0.size * problem.cell_area
    goal = rtol * abs(pressure)
    sense = math.copysign(1.0, slope)  # f * sense < 0: short of the pressure
    # the furthest state short of the pressure (every try loads from it), the nearest
    # try past it, and the last try
    base = non_contact(problem, tol) if start is None else start
    short: tuple[float, float, tuple[float, AdhesiveState]] | None = None
    past: tuple[float, float] | None = None
    prev: tuple[float, float] | None = None
    x, iterations, solves = float(approach), 0, 0
    for _ in range(MAX_SOLVES):
        # the path's steps to PATH_TOL (near the first touch a weak law's pressures are
        # tiny, and finer balance there only costs time), the try itself to ``tol``
        path = advance(problem, base if short is None else short[2], x,
                       max(tol, PATH_TOL), max_change=max_change)
        for xi, si in path[:-1]:  # the sub-steps short of the pressure load the next try
            iterations += si.iterations
            fi = si.load / area0 - pressure
            if fi * sense < 0:
                short = (xi, fi, (xi, si))
        st = solve_adhesive(problem, x, path[-1][1].gap, tol=tol)
        solves += len(path) + 1
        iterations += path[-1][1].iterations + st.iterations
        f = st.load / area0 - pressure
        if abs(f) <= goal:
            return st, x, solves, iterations
        if f * sense < 0:
            short = (x, f, (x, st))
        else:
            past = (x, f)
        x_new = _next_try(x, f, prev, slope, short, past, problem.law.range)
        if x_new is None:
            break
        prev, x = (x, f), x_new
    raise ConvergenceError(
        f"no adhesive equilibrium carries the nominal pressure {pressure:.4g} Pa on this "
        f"branch (it lies in a jump of the load-approach curve, or {MAX_SOLVES} tries "
        "were not enough): choose other pressures or a weaker adhesion")


def _next_try(x: float, f: float, prev: tuple[float, float] | None, slope: float,
              short: tuple[float, float, object] | None, past: tuple[float, float] | None,
              scale: float) -> float | None:
    """The secant's next approach, bisected inside the bracket once there is one (None:
    the bracket has closed without reaching the pressure)."""
    x_new = x - f / slope if prev is None or f == prev[1] else \
        x - f * (x - prev[0]) / (f - prev[1])
    if short is not None and past is not None:
        lo, hi = sorted((short[0], past[0]))
        if hi - lo <= 1e-12 * max(abs(lo), scale):
            return None
        if not (lo < x_new < hi):
            x_new = 0.5 * (lo + hi)
    elif not math.isfinite(x_new) or (short is not None and x_new <= x):
        x_new = x - f / slope  # forward from the furthest solve short of it
    return float(x_new)


def adhesive_flat(gap0: np.ndarray, dx: float, e_star: float, law: InteractionLaw,
                  pressures: np.ndarray, mean_gaps: np.ndarray, stiffnesses: np.ndarray, *,
                  rtol: float = 1e-4, tol: float = 1e-8, max_change: float = MAX_AREA_CHANGE,
                  progress: Callable[[int, int], None] | None = None) -> AdhesiveFlat:
    """Press the periodic gap ``gap0`` (m, square pixels ``dx``) at each nominal pressure.

    Parameters
    ----------
    gap0 : ndarray
        Initial gap to the flat (``max(z) - z`` for a surface z).
    dx, e_star : float
        Pixel (m) and composite modulus (Pa),
        or a resolved :class:`contact.material_pair.MaterialPair` (its E*, bit for bit).
    law : InteractionLaw
        The adhesion law.
    pressures : array_like
        Nominal pressures (Pa), in increasing order (the loading branch).
    mean_gaps, stiffnesses : array_like
        Starting estimates per pressure: the non-adhesive solve's mean gap (m) and contact
        stiffness -dp/dū (Pa/m) (:func:`contact.setups.flat.flat_contact`).
    rtol, tol : float
        Pressure and equilibrium tolerances (:func:`solve_at_pressure`).
    max_change : float
        Loading steps are split while the touching area changes by more than this share
        (the quasi-static path of the module notes); ``math.inf`` never splits them (about
        six times fewer solves, but the area then depends on the starting estimates by a
        few per cent where the cohesive zone is not resolved).
    progress : callable, optional
        Called as ``progress(done, total)`` after each pressure.
    """
    from contact.material_pair import modulus

    e_star = modulus(e_star)  # a resolved pair or its E*
    problem = adhesive_problem(gap0, dx, e_star, law)
    p = np.atleast_1d(np.asarray(pressures, dtype=float))
    if p.size == 0 or not np.all(np.isfinite(p)) or np.any(np.diff(p) <= 0):
        raise ContactInputError("nominal pressures must be finite and increasing")
    if np.shape(mean_gaps) != p.shape or np.shape(stiffnesses) != p.shape:
        raise ContactInputError("give one starting mean gap and stiffness per pressure")
    h = problem.gap0
    points, warm = [], None
    for k, pk in enumerate(p):
        # mean(g) = mean(h) - delta + p / spring (solver's mean-plane spring)
        x0 = float(np.mean(h)) - float(mean_gaps[k]) + pk / problem.spring
        st, xk, n, its = solve_at_pressure(problem, float(pk), x0, float(stiffnesses[k]),
                                           warm, rtol=rtol, tol=tol,
                                           max_change=max_change)
        warm = (xk, st)
        points.append(AdhesiveFlatPoint(
            pressure=st.load / (h.size * problem.cell_area),
            area_fraction=float(np.mean(st.gap <= 0.0)), mean_gap=float(np.mean(st.gap)),
            attractive_pressure=attractive_pressure(law, st.gap), approach=st.approach,
            solves=n, iterations=its,
            solve=replace(st.solve, method="adhesive, load-controlled secant",
                          iterations=its, outer_iterations=n)))
        if progress is not None:
            progress(k + 1, p.size)
    zone = math.pi * e_star * law.work / (4.0 * law.peak ** 2)
    warnings = () if zone >= MIN_ZONE_PIXELS * dx else (
        f"grid too coarse for the interaction: the cohesive zone (pi E* w / (4 sigma0^2) = "
        f"{zone:.3g} m) spans {zone / dx:.2g} pixels, fewer than {MIN_ZONE_PIXELS:g}, so the "
        "contact edges are pinned by the pixels and the adhesive area is not resolved",)
    return AdhesiveFlat(points=tuple(points), law=law, e_star=float(e_star), dx=float(dx),
                        process_zone=zone, warnings=warnings)
