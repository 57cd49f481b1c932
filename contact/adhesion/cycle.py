"""Displacement-controlled approach and retraction of an adhesive contact.

The rigid approach is stepped in and back out, each solve warm-started from the last
(:func:`contact.adhesion.solver.solve_adhesive`), so the solution follows one equilibrium
branch until it ends and then jumps. From the two branches come the pull-off force (the
largest tension on the way out, refined by a golden-section search between the samples
around it), the jump-in and jump-out (where the touching area appears and vanishes) and
the energy lost in the cycle, the work  -closed integral of P d(delta)  done by the
machine (Greenwood & Johnson 1998, Phil. Mag. A 77:1491, for the loss in a cycle).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from contact._record import SolveRecord, combine
from contact.adhesion.laws import InteractionLaw
from contact.adhesion.solver import AdhesiveState

_GOLDEN = 0.5 * (math.sqrt(5.0) - 1.0)


class AdhesiveProblem(Protocol):
    """What a cycle asks of a problem: its undeformed gap, modulus and law, and one
    equilibrium at an approach from a warm-start gap (the periodic grid's
    :class:`contact.adhesion.solver.AdhesiveProblem`, the rings'
    :class:`contact.adhesion._rings.RingProblem`)."""

    @property
    def gap0(self) -> np.ndarray: ...

    @property
    def e_star(self) -> float: ...

    @property
    def law(self) -> InteractionLaw: ...

    def equilibrium(self, approach: float, initial: np.ndarray | None = None, *,
                    tol: float = 1e-7) -> AdhesiveState: ...


@dataclass(frozen=True)
class Branch:
    """One leg of the cycle, in the order it was run (SI units).

    ``approach`` is the rigid approach imposed (m), ``surface_approach`` the approach of the
    mean plane (m), ``load`` (N), ``contact_area`` (m^2), ``energy`` the elastic plus
    interaction energy (J), ``iterations`` per step; ``solve`` the records of every solve
    run for the leg combined (:func:`contact._record.combine`), a split step's discarded
    attempt included.
    """

    approach: np.ndarray
    surface_approach: np.ndarray
    load: np.ndarray
    contact_area: np.ndarray
    energy: np.ndarray
    iterations: np.ndarray
    solve: SolveRecord

    @property
    def contact_radius(self) -> np.ndarray:
        """Radius of the disc of the touching area (m)."""
        return np.sqrt(self.contact_area / math.pi)


@dataclass(frozen=True)
class Jump:
    """Where the touching area appears (jump-in) or vanishes (jump-out).

    ``approach`` is the middle of the two steps (m) between which it happens, ``step`` their
    distance (the resolution), ``load_before``/``load_after`` the loads (N) on either
    side; ``abrupt`` tells a jump of the load from a smooth transition (:func:`find_jump`);
    ``resolved`` is False where the step is wider than the interaction's range, so that a
    transition found smooth may hide a snap inside the step.
    """

    approach: float
    step: float
    load_before: float
    load_after: float
    abrupt: bool
    resolved: bool = True


@dataclass(frozen=True)
class Cycle:
    """An approach-retraction cycle (SI units).

    ``hysteresis_energy`` is the energy lost (J; :func:`hysteresis`), 0 where its closed
    integral is within ``hysteresis_resolution`` of zero: the solves' tolerance times the
    work done on the two legs, what loads converged to that tolerance can tell from no
    loss (a cycle without a jump, whose legs coincide).
    """

    approach_leg: Branch
    retraction_leg: Branch
    pull_off_force: float
    pull_off_approach: float
    jump_in: Jump | None
    jump_out: Jump | None
    hysteresis_energy: float
    pull_off_solve: SolveRecord | None = None
    hysteresis_resolution: float = 0.0

    @property
    def solve(self) -> SolveRecord:
        """The solve records of both legs and of the pull-off's golden-section refinement
        (``pull_off_solve``, None where the most tensile sample needed none) combined."""
        legs = [self.approach_leg.solve, self.retraction_leg.solve]
        if self.pull_off_solve is None:
            return combine(legs, "adhesive approach-retraction cycle, one solve per step")
        return combine([*legs, self.pull_off_solve],
                       "adhesive approach-retraction cycle, one solve per step and a "
                       "golden-section refinement of the pull-off")


#: A jump is abrupt when the load changes across its step by more than this many times
#: what a continuous branch could (:func:`find_jump`).
ABRUPT_FACTOR = 3.0
#: A step that changes the touching area by more than this share of it is split in two,
#: so that the solution follows its branch quasi-statically instead of leaping off it.
MAX_AREA_CHANGE = 0.1
#: Halvings allowed per step (the finest step is 2**-MAX_SPLITS of the one asked for).
MAX_SPLITS = 5


def advance(problem: AdhesiveProblem, previous: tuple[float, AdhesiveState] | None,
            target: float, tol: float, depth: int = 0, *,
            max_change: float = MAX_AREA_CHANGE,
            records: list[SolveRecord] | None = None) -> list[tuple[float, AdhesiveState]]:
    """Solve at ``target`` from ``previous`` (approach, state); split the step in two while
    the touching area changes by more than ``max_change`` of it (up to
    :data:`MAX_SPLITS` halvings). Returns every (approach, state) reached, in order; the
    record of every solve run, the attempts a split discards included, is appended to
    ``records`` if given."""
    st = problem.equilibrium(target, None if previous is None else previous[1].gap, tol=tol)
    if records is not None:
        records.append(st.solve)
    if previous is None or depth >= MAX_SPLITS:
        return [(target, st)]
    a0, a1 = previous[1].contact_area, st.contact_area
    if abs(a1 - a0) <= max_change * max(a0, a1):
        return [(target, st)]
    middle = advance(problem, previous, 0.5 * (previous[0] + target), tol, depth + 1,
                     max_change=max_change, records=records)
    return middle + advance(problem, middle[-1], target, tol, depth + 1,
                            max_change=max_change, records=records)


def run_branch(problem: AdhesiveProblem, approaches: np.ndarray,
               initial: tuple[float, np.ndarray] | None = None, *, tol: float = 1e-7,
               progress: Callable[[int, int], None] | None = None,
               ) -> tuple[Branch, list[np.ndarray]]:
    """Solve at each approach in turn, warm-started; the branch and every step's gap.

    ``initial`` is (approach, gap) of the state to start from. A step over which the
    touching area changes by more than :data:`MAX_AREA_CHANGE` is halved (up to
    :data:`MAX_SPLITS` times), so the branch holds the approaches asked for and the
    intermediate ones. The branch's record counts every solve run for it (the start and
    the attempts a split discards too), so it can exceed the points on the branch.
    """
    done: list[tuple[float, AdhesiveState]] = []
    run: list[SolveRecord] = []  # every solve, the start and the discarded attempts too
    previous = None
    if initial is not None:
        d0, g0 = initial
        previous = (float(d0), problem.equilibrium(float(d0), g0, tol=tol))
        run.append(previous[1].solve)
    for k, d in enumerate(approaches):
        done += advance(problem, previous, float(d), tol, records=run)
        previous = done[-1]
        if progress is not None:
            progress(k + 1, len(approaches))
    states = [st for _, st in done]
    branch = Branch(
        approach=np.array([d for d, _ in done]),
        surface_approach=np.array([s.approach for s in states]),
        load=np.array([s.load for s in states]),
        contact_area=np.array([s.contact_area for s in states]),
        energy=np.array([s.energy for s in states]),
        iterations=np.array([s.iterations for s in states]),
        solve=combine(run, "adhesive, one solve per approach step"),
    )
    return branch, [s.gap for s in states]


def refine_pull_off(problem: AdhesiveProblem, branch: Branch, gaps: list[np.ndarray],
                    *, tol: float = 1e-7, rounds: int = 10,
                    records: list[SolveRecord] | None = None) -> tuple[float, float]:
    """The largest tension of a retraction and its approach, refined between samples.

    A golden-section search on the load between the neighbours of the most tensile
    sample, every solve warm-started from the neighbour met first on the way out, so it
    stays on the retraction's branch. Returns (pull-off force >= 0, approach); the solves'
    records are appended to ``records`` if given. A retraction that never pulls (no
    tensile load at any step: roughness can hide adhesion) has a pull-off of 0, at the
    approach of its least load.
    """
    k = int(np.argmin(branch.load))
    if branch.load[k] >= 0.0:
        return 0.0, float(branch.approach[k])
    best = (-float(branch.load[k]), float(branch.approach[k]))
    if k == 0 or k == len(branch.load) - 1:
        return best
    hi, lo, start = float(branch.approach[k - 1]), float(branch.approach[k + 1]), gaps[k - 1]

    def tension(d: float) -> float:
        state = problem.equilibrium(d, start, tol=tol)
        if records is not None:
            records.append(state.solve)
        return -state.load

    a, b = lo, hi
    c, d = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
    fc, fd = tension(c), tension(d)
    for _ in range(rounds):
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - _GOLDEN * (b - a)
            fc = tension(c)
        else:
            a, c, fc = c, d, fd
            d = a + _GOLDEN * (b - a)
            fd = tension(d)
    for f, x in ((fc, c), (fd, d)):
        if f > best[0]:
            best = (f, x)
    return best


def find_jump(branch: Branch, *, entering: bool, e_star: float | None = None,
              reach: float | None = None) -> Jump | None:
    """Where the touching area appears (``entering``) or vanishes along ``branch``.

    The jump is ``abrupt`` when the load changes across the step by more than
    :data:`ABRUPT_FACTOR` times what a continuous branch could change it by. With
    ``e_star`` (Pa; areal contacts: a sphere, a rough scan) that bound is the elastic
    change the step would give at the stiffness of the touching area A on the touching
    side, 2 E* sqrt(A / pi) (the flat punch of that area, Sneddon 1965; any contact
    shape within a few per cent, Pharr, Oliver & Brotzen 1992, J. Mater. Res. 7:613),
    plus the load's change over the neighbouring step on the side without contact (the
    interaction's own pull) scaled to the step. Without it (a line contact, whose stiffness
    per length has no such local form) the bound is the larger load change one step
    either side. ``reach`` (m), the interaction's range, marks a wider step unresolved.
    """
    touching = branch.contact_area > 0.0
    flips = np.flatnonzero(touching[1:] != touching[:-1])
    change = [int(i) for i in flips if touching[i + 1] == entering]
    if not change:
        return None
    i = change[0]
    steps = np.abs(np.diff(branch.load))
    jump = float(steps[i])
    if e_star is None:
        around = [steps[j] for j in (i - 1, i + 1) if 0 <= j < steps.size]
        typical = float(max(around)) if around else 0.0
    else:
        typical = _continuous_change(branch, i, entering, e_star)
    step = abs(float(branch.approach[i + 1] - branch.approach[i]))
    return Jump(
        approach=0.5 * float(branch.approach[i] + branch.approach[i + 1]),
        step=step, load_before=float(branch.load[i]), load_after=float(branch.load[i + 1]),
        abrupt=jump > ABRUPT_FACTOR * typical, resolved=reach is None or step <= reach,
    )


def _continuous_change(branch: Branch, i: int, entering: bool, e_star: float) -> float:
    """The most a continuous branch changes the load over step i -> i + 1 (N): elastic
    at the touching area's punch stiffness, plus the interaction's pull (find_jump)."""
    d = np.asarray(branch.approach, dtype=float)
    step = abs(float(d[i + 1] - d[i]))
    area = float(branch.contact_area[i + 1] if entering else branch.contact_area[i])
    elastic = 2.0 * e_star * math.sqrt(area / math.pi) * step
    j = i - 1 if entering else i + 1  # the neighbouring step without contact
    pull = 0.0
    if 0 <= j < len(d) - 1 and d[j + 1] != d[j]:
        pull = abs(float(branch.load[j + 1] - branch.load[j])) / abs(float(d[j + 1] - d[j]))
    return elastic + pull * step


def hysteresis(approach_leg: Branch, retraction_leg: Branch) -> float:
    """Work done by the machine over the closed cycle (J), by the trapezoidal rule.

    The legs must start and end at the same approach. Under rigid displacement control a
    jump happens at a fixed approach and does no work, so the integral of P over the
    imposed approach is the energy the cycle loses.
    """
    d = np.concatenate([approach_leg.approach, retraction_leg.approach])
    p = np.concatenate([approach_leg.load, retraction_leg.load])
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(d)))


def hysteresis_resolution(approach_leg: Branch, retraction_leg: Branch, tol: float) -> float:
    """The smallest loss (J) loads solved to ``tol`` (relative to the pressure scale) tell
    from none: ``tol`` times the work done on the two legs, the trapezoidal integrals of
    |P| over the imposed approach. A loss within it is reported as 0 (:class:`Cycle`)."""
    work = 0.0
    for leg in (approach_leg, retraction_leg):
        p = np.abs(leg.load)
        work += float(np.sum(0.5 * (p[1:] + p[:-1]) * np.abs(np.diff(leg.approach))))
    return tol * work


def approach_retraction(problem: AdhesiveProblem, approaches: np.ndarray, *,
                        tol: float = 1e-7,
                        progress: Callable[[int, int], None] | None = None) -> Cycle:
    """Run ``approaches`` (increasing) in, then back out, and read the cycle."""
    steps = np.asarray(approaches, dtype=float)
    n = 2 * len(steps)

    def half(offset: int) -> Callable[[int, int], None] | None:
        return None if progress is None else (lambda k, _m: progress(offset + k, n))

    leg_in, gaps_in = run_branch(problem, steps, tol=tol, progress=half(0))
    leg_out, gaps_out = run_branch(problem, steps[::-1], (steps[-1], gaps_in[-1]), tol=tol,
                                   progress=half(len(steps)))
    areal = problem.e_star if problem.gap0.shape[0] > 1 else None  # not a line contact
    refining: list[SolveRecord] = []
    force, where = refine_pull_off(problem, leg_out, gaps_out, tol=tol, records=refining)
    lost = hysteresis(leg_in, leg_out)
    resolution = hysteresis_resolution(leg_in, leg_out, tol)
    return Cycle(
        approach_leg=leg_in, retraction_leg=leg_out, pull_off_force=force,
        pull_off_approach=where,
        jump_in=find_jump(leg_in, entering=True, e_star=areal, reach=problem.law.range),
        jump_out=find_jump(leg_out, entering=False, e_star=areal, reach=problem.law.range),
        hysteresis_energy=lost if abs(lost) > resolution else 0.0,
        pull_off_solve=combine(refining, "golden-section refinement of the pull-off")
        if refining else None,
        hysteresis_resolution=resolution,
    )
