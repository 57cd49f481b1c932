"""A rough periodic surface pressed on a flat with adhesion, at prescribed nominal pressures.

A flat-contact sweep imposes the nominal (mean) pressure. Adhesive equilibria depend on
the path (a contact pressed too far and backed off keeps more area, and a big loading
step snaps in pixels that small steps would leave apart where the grid does not resolve
the cohesive zone), so the path is made quasi-static and unique. A compressive pressure
is reached under load control (:func:`load_path`): each state is one minimisation with
the mean pressure imposed (:func:`contact.adhesion.solver.solve_adhesive_at_pressure`),
the first loaded from the rigid gap touching at its highest point (where a loading from
the non-contact state first touches), every later one warm-started from the last state
taken at a lower pressure (never from one past it), and a step is halved and tried again
while the touching area changes by more than
:data:`contact.adhesion.cycle.MAX_AREA_CHANGE` of it. The intermediate states only steer
the path, so they are solved to :data:`LOAD_PATH_TOL` with float32 FFTs, and the state at
the pressure asked for to the full tolerance. Under load control a snap-in is a jump: when
a step of the finest size (1/32 of the path) still leaps in area, it is taken, and the path
goes on from the branch it landed on. For P > 0 the energy with the load's potential is
bounded below, so every compressive pressure has an equilibrium.

A tensile pressure (surfaces apart are unstable under load control: the tension falls
with the gap) is found under displacement control (:func:`secant_at_pressure`): a secant
on the approach, safeguarded by bisection once the pressure is bracketed, every try a
loading step from the furthest state short of the pressure, from the non-contact state
(every gap beyond the law's reach), split (:func:`contact.adhesion.cycle.advance`) while
the touching area changes by more than 10 %. A tensile pressure that falls inside a jump of
the load-approach curve has no equilibrium on the branch and is one
:class:`~contact._errors.ConvergenceError`.

On the tests' 64^2 surface at 0.1 pixel of cohesive zone (exponential law, w 0.2 J/m^2,
rho 5 nm, 0.1 MPa) both controls find the same contact set (area fraction 0.0168, mean gap
within 2e-6), and halving the threshold to 5 % changes nothing; unsplit displacement steps
had changed the area by 3.9 % with the starting estimate and overestimated it by 10 to
15 %. The Dugdale law of the same work and range there gives 0.0098 under both controls,
but 0.0088 under load control with the path's states solved to 1e-3 instead of 3e-3 (or
with unsplit load steps, or with the free cells' shift of
:data:`contact.adhesion.solver.FREE_SHIFT` unweighted by their share): where the zone is
unresolved the loading path, and the solver's iterates, set the area, to a few cells.
On the resolved benchmark case (benchmarks/adhesion_flat.py, 10 to 40 pixels of zone)
one direct solve, the load path and the secant agree to the
cell: 0.254822 at 512^2. There the load path takes 15 solves and 542 iterations (836
before the longer load-controlled steps of :mod:`contact.adhesion.solver`; see
benchmarks/adhesion_flat.py for the CPU times), the secant 42 solves and 6197.

Per pressure the sweep reports, with the same definitions as the non-adhesive driver
:func:`contact.setups._flat.flat_contact`: the area fraction where the surfaces touch (gap
zero), the mean gap (the mean of the deformed gap), and the attractive pressure
:func:`attractive_pressure`, the interaction law's traction averaged over the whole
nominal area, touching points included (a positive magnitude). The nominal pressure is
the repulsive mean minus the attractive one.

Resolution: as for a sphere (:mod:`contact.adhesion.ball`), the cohesive zone at each
contact edge is about l_pz = pi E* w / (4 sigma0^2) wide; below
:func:`contact._zone_resolution.min_zone_pixels` pixels the edges are pinned by the grid and
the adhesive area is not resolved, which the result warns about.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._grid import Grid
from contact._record import SolveRecord
from contact._zone_resolution import min_zone_pixels
from contact.adhesion.cycle import MAX_AREA_CHANGE, MAX_SPLITS, advance
from contact.adhesion.laws import InteractionLaw, checked_law
from contact.adhesion.solver import (
    AdhesiveProblem,
    AdhesiveState,
    adhesive_problem,
    solve_adhesive,
    solve_adhesive_at_pressure,
)

#: Secant tries allowed per tensile nominal pressure.
MAX_SOLVES = 40
#: Equilibrium tolerance of the secant's quasi-static sub-steps (tensile pressures).
PATH_TOL = 1e-6
#: Equilibrium tolerance of the load path's intermediate states (compressive pressures;
#: float32 FFTs): only their touching area steers the path.
LOAD_PATH_TOL = 3e-3
#: The state at the pressure asked for is first solved to this tolerance with float32 FFTs,
#: then to the tolerance asked for in float64 (at 512^2: 64 + 34 iterations instead of 90
#: in float64, 0.60 s instead of 0.64 s, least of six paired runs, faster in each).
FINAL_SINGLE_TOL = 3e-5
#: A load step is sized to change the touching area by this share of the threshold
#: ``max_change``, from the rate of the last step taken (a step that overshoots it is
#: halved and tried again).
STEP_AIM = 0.8
#: The solve record's method, tensile (False) and compressive (True) pressures.
METHODS = {False: "adhesive, secant on the approach to a tensile mean pressure",
           True: "adhesive, mean pressure imposed along a quasi-static load path"}


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
        Mean of the deformed gap over all cells, touching ones (gap zero) included (m):
        the mean separation of the deformed surfaces, Persson's u-bar and the mean of
        Tamaas' gap field (:func:`gap_means`).
    attractive_pressure : float
        The law's traction averaged over the nominal area, touching points included (Pa).
    approach : float
        Approach of the flat to the mean plane of the deformed surface (m).
    solves, iterations : int
        Equilibrium solves on the loading path (the secant's tries and their quasi-static
        sub-steps), and their iterations in all.
    solve : SolveRecord
        The record (:mod:`contact._record`): the iterations in all, the solves as outer
        iterations, the last equilibrium's residual.
    mean_gap_out_of_contact : float
        Mean of the deformed gap over the cells that do not touch only (m; NaN where all
        touch), the other definition in use (:func:`gap_means`).
    """

    pressure: float
    area_fraction: float
    mean_gap: float
    attractive_pressure: float
    approach: float
    solves: int
    iterations: int
    solve: SolveRecord
    mean_gap_out_of_contact: float = math.nan

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


def gap_means(gap: np.ndarray) -> tuple[float, float]:
    """The two means of a deformed gap field (m): (over all cells, over free cells only).

    The gap is measured from the flat to the deformed surface, so it is zero where they
    touch, whatever the undeformed surface's datum (its mean plane or its highest point:
    the datum only shifts the approach). The first mean counts the touching cells as
    zeros: the mean separation of the two deformed surfaces, the one that enters
    p(u-bar) and the contact stiffness, and the one Tamaas' gap field gives (its
    PolonskyKeerRey on the gap, on the same array: tests/data/tamaas_adhesive_gap.json).
    The second leaves them out (the mean opening where the surfaces are apart); it is the
    larger by a factor 1 / (1 - area fraction).
    """
    g = np.asarray(gap, dtype=float)
    free = g > 0.0
    return float(np.mean(g)), float(np.mean(g[free])) if free.any() else math.nan


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


def load_path(problem: AdhesiveProblem, pressure: float,
              start: tuple[float, AdhesiveState] | None = None, *, tol: float = 1e-8,
              max_change: float = MAX_AREA_CHANGE) -> tuple[AdhesiveState, int, int]:
    """The equilibrium of the compressive mean pressure ``pressure`` (Pa), reached under load
    control by a quasi-static path of increasing pressures.

    Every state on the path is a minimisation with the mean pressure imposed
    (:func:`contact.adhesion.solver.solve_adhesive_at_pressure`), warm-started from the
    last state taken. A step is taken when the touching area changes by at most
    ``max_change`` of it, else halved and tried again from the same state (never from the
    state past it), down to 2**-:data:`~contact.adhesion.cycle.MAX_SPLITS` of the path's
    span, which is taken as it comes: the area then leaps at that load (a snap-in, the
    load-controlled jump to another branch). The next step is sized from the area's rate
    over the last one to change it by :data:`STEP_AIM` of the threshold. The path's states
    are solved to :data:`LOAD_PATH_TOL` with float32 FFTs, the last one then to ``tol``
    (first to :data:`FINAL_SINGLE_TOL` in float32 where ``tol`` is finer).

    Parameters
    ----------
    problem : AdhesiveProblem
        Grid, stiffness and law.
    pressure : float
        Nominal pressure to reach (Pa, > 0).
    start : (float, AdhesiveState), optional
        A state at a lower pressure (with its approach, unused) to load from; default the
        rigid gap touching at its highest point under no load, where a loading from the
        non-contact state first touches.
    tol : float
        Equilibrium tolerance of the final solve.
    max_change : float
        Largest change of the touching area per step, as a share of it.

    Returns
    -------
    (state, solves, iterations in all)
    """
    area0 = problem.gap0.size * problem.cell_area
    if start is None:
        p_now, gap = 0.0, problem.gap0 - problem.gap0.min()
    else:
        p_now, gap = start[1].load / area0, start[1].gap
    if not p_now < pressure:
        raise ContactInputError(f"the load path must rise: from {p_now:.4g} Pa to "
                                f"{pressure:.4g} Pa")
    touching = int(np.count_nonzero(gap <= 0.0))
    finest = (pressure - p_now) / 2 ** MAX_SPLITS
    # from a single touching cell any step changes the area by more than a tenth
    step = finest if touching <= 1 else pressure - p_now
    solves = iterations = 0
    loose = max(tol, LOAD_PATH_TOL)
    while p_now < pressure:
        target = min(p_now + step, pressure)
        st = solve_adhesive_at_pressure(problem, target, gap, tol=loose, single=True)
        solves, iterations = solves + 1, iterations + st.iterations
        now = int(np.count_nonzero(st.gap <= 0.0))
        change = abs(now - touching)
        if change > max_change * max(now, touching) and step > finest * (1.0 + 1e-9):
            step = max(0.5 * step, finest)
            continue
        taken = target - p_now
        p_now, gap, touching = target, st.gap, now
        aim = STEP_AIM * max_change * now * taken / change if change else math.inf
        step = max(finest, min(2.0 * taken, aim))
    if FINAL_SINGLE_TOL > tol:
        st = solve_adhesive_at_pressure(problem, pressure, st.gap, tol=FINAL_SINGLE_TOL,
                                        single=True)
        solves, iterations = solves + 1, iterations + st.iterations
    if loose > tol:
        st = solve_adhesive_at_pressure(problem, pressure, st.gap, tol=tol)
        solves, iterations = solves + 1, iterations + st.iterations
    return st, solves, iterations


def solve_at_pressure(problem: AdhesiveProblem, pressure: float, approach: float,
                      slope: float, start: tuple[float, AdhesiveState] | None = None, *,
                      rtol: float = 1e-4, tol: float = 1e-8,
                      max_change: float = MAX_AREA_CHANGE,
                      ) -> tuple[AdhesiveState, float, int, int]:
    """The equilibrium of nominal pressure ``pressure`` (Pa), loading from ``start``.

    A compressive pressure is reached under load control (:func:`load_path`), which
    needs no estimate: ``approach``, ``slope`` and ``rtol`` serve tensile pressures, for
    which surfaces apart are unstable under load control. Those are found under
    displacement control by a secant on the approach (:func:`secant_at_pressure`).

    Parameters
    ----------
    problem : AdhesiveProblem
        Grid, stiffness and law.
    pressure : float
        Nominal pressure to reach (Pa, compression positive; non-zero).
    approach : float
        First rigid approach tried (m; tensile pressures).
    slope : float
        Estimate of d(pressure)/d(approach) (Pa/m; tensile pressures), for the first
        secant step: negative on an open branch pulled by the interaction, where
        approaching raises the tension.
    start : (float, AdhesiveState), optional
        A state short of the pressure, with its rigid approach, to load from; default the
        first touch (compressive, :func:`load_path`) or the non-contact state (tensile,
        :func:`non_contact`).
    rtol : float
        A tensile pressure is reached when within ``rtol |pressure|``.
    tol : float
        Equilibrium tolerance of the final solve (:func:`solve_adhesive`).
    max_change : float
        A loading step is split while the touching area changes by more than this share.

    Returns
    -------
    (state, rigid approach, solves, iterations in all); under load control the approach
    is the state's (no spring: the rigid and the surface approach agree).

    Raises
    ------
    ConvergenceError
        No equilibrium carries the tensile pressure on this branch (a jump) within
        :data:`MAX_SOLVES` tries.
    """
    if not (math.isfinite(pressure) and pressure != 0.0):
        raise ContactInputError(f"the nominal pressure must be finite and non-zero, got "
                                f"{pressure!r}")
    if pressure > 0.0:
        st, solves, iterations = load_path(problem, pressure, start, tol=tol,
                                           max_change=max_change)
        return st, st.approach, solves, iterations
    return secant_at_pressure(problem, pressure, approach, slope, start, rtol=rtol,
                               tol=tol, max_change=max_change)


def secant_at_pressure(problem: AdhesiveProblem, pressure: float, approach: float,
                        slope: float, start: tuple[float, AdhesiveState] | None, *,
                        rtol: float, tol: float, max_change: float,
                        ) -> tuple[AdhesiveState, float, int, int]:
    """:func:`solve_at_pressure` under displacement control: a secant on the approach,
    each try a quasi-static loading path from the furthest state short of the pressure
    (:func:`contact.adhesion.cycle.advance`)."""
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


def adhesive_flat(gap0: np.ndarray | Grid, dx: float | None = None,
                  e_star: float | None = None, law: InteractionLaw | None = None,
                  pressures: np.ndarray | None = None, mean_gaps: np.ndarray | None = None,
                  stiffnesses: np.ndarray | None = None, *,
                  rtol: float = 1e-4, tol: float = 1e-8, max_change: float = MAX_AREA_CHANGE,
                  progress: Callable[[int, int], None] | None = None) -> AdhesiveFlat:
    """Press the periodic gap ``gap0`` (m, square pixels ``dx``) at each nominal pressure.

    Parameters
    ----------
    gap0 : ndarray or Grid
        Initial gap to the flat (``max(z) - z`` for a surface z), or a periodic
        :class:`contact._grid.Grid` carrying it and its pitch (then ``dx`` is not given).
    dx, e_star : float
        Pixel (m) and composite modulus (Pa),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    law : InteractionLaw
        The adhesion law.
    pressures : array_like
        Nominal pressures (Pa), in increasing order (the loading branch).
    mean_gaps, stiffnesses : array_like
        Starting estimates per pressure: the non-adhesive solve's mean gap (m) and contact
        stiffness -dp/dū (Pa/m) (:func:`contact.setups._flat.flat_contact`); only the
        secant of a tensile pressure uses them (a compressive one is imposed).
    rtol, tol : float
        Pressure and equilibrium tolerances (:func:`solve_at_pressure`).
    max_change : float
        Loading steps are split while the touching area changes by more than this share
        (the quasi-static path of the module notes); with ``math.inf`` a load step is
        never split, only grown (twice the last) from 1/32 of the path from the first
        touch, and a displacement step never split (then the area depends on the
        starting estimates by a few per cent where the cohesive zone is not resolved).
    progress : callable, optional
        Called as ``progress(done, total)`` after each pressure.
    """
    from contact._material_pair import modulus

    if any(v is None for v in (e_star, law, pressures, mean_gaps, stiffnesses)):
        raise ContactInputError("give e_star, the law, the pressures and one starting mean "
                                "gap and stiffness per pressure")
    e_star = modulus(e_star)  # a resolved pair or its E*
    checked_law(law)  # an unknown law is refused, never solved as another
    problem = adhesive_problem(gap0, dx, e_star, law)
    dx = problem.dx
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
        every, free = gap_means(st.gap)
        points.append(AdhesiveFlatPoint(
            pressure=st.load / (h.size * problem.cell_area),
            area_fraction=float(np.mean(st.gap <= 0.0)), mean_gap=every,
            mean_gap_out_of_contact=free,
            attractive_pressure=attractive_pressure(law, st.gap), approach=st.approach,
            solves=n, iterations=its,
            solve=replace(st.solve, method=METHODS[pk > 0], iterations=its,
                          outer_iterations=n)))
        if progress is not None:
            progress(k + 1, p.size)
    zone = math.pi * e_star * law.work / (4.0 * law.peak ** 2)
    least = min_zone_pixels(law.smoothing > 0.0)
    warnings = () if zone >= least * dx else (
        f"grid too coarse for the interaction: the cohesive zone (pi E* w / (4 sigma0^2) = "
        f"{zone:.3g} m) spans {zone / dx:.2g} pixels, fewer than {least:g}, so the "
        "contact edges are pinned by the pixels and the adhesive area is not resolved",)
    return AdhesiveFlat(points=tuple(points), law=law, e_star=float(e_star), dx=float(dx),
                        process_zone=zone, warnings=warnings)
