"""The iteration of the normal solver: a feasible start, then steps until converged.

:func:`start` builds the first iterate; :class:`PolonskyKeer` is the pressure solve as the
one driver of the normal solves (:func:`contact.bem._loop.drive`) runs it: it measures the
residual, re-syncs the mixed-precision displacement where due, and takes a
conjugate-gradient or projected gradient step (:mod:`contact.bem._steps`);
:func:`iterate` drives it until the tolerance, ``max_iter`` or a stall.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from contact.bem import _kernels as kernels
from contact.bem import _loop as loop
from contact.bem._loop import Check
from contact.bem._state import IterationState, Problem, SolverStats, Workspace
from contact.bem._steps import (
    Outcome,
    conjugate_gradient_step,
    exact_displacement,
    measure_residual,
    projected_gradient_step,
    resync,
)


def _first_pressure(problem: Problem, initial: np.ndarray | None,
                    approach: float) -> np.ndarray:
    """The first pressure before the constraints are imposed (flattened).

    A given ``initial`` is taken over, not copied, where it is already a C-contiguous
    float64 array (the solver's callers hand over a fresh one, clipped; a copy would keep
    a second pressure of the grid's size alive through the whole solve).
    """
    n = problem.size
    if initial is not None:
        return np.ascontiguousarray(initial, dtype=float).ravel()
    if problem.load_control:
        return np.full(n, problem.target / n)
    penetration = np.maximum(approach - problem.gap, 0.0)
    if not penetration.any():
        return np.zeros(n)
    return penetration / (problem.operator.self_influence * math.sqrt(n))


def _feasible(problem: Problem, pressure: np.ndarray, work: Workspace) -> None:
    """Scale ``pressure`` to the load and (elastic-plastic) project it under the cap."""
    if problem.load_control:
        total = pressure.sum()
        pressure *= problem.target / total
        if problem.plastic:
            # A feasible start (0 <= p <= H, sum p = target): the projection of p, where
            # the points out of contact are ranked by their gap; if the loaded points
            # cannot carry the load at the cap, the pressure goes first to the points
            # that are closest to touching.
            gap = problem.gap
            rank = np.where(pressure > 0, 0.0, gap - gap.min())
            kernels.projected_gradient(
                pressure, rank, 1.0 / problem.operator.self_influence, problem.target,
                problem.cap, True, work.projected_step, work.candidates, problem.nx)
            pressure += work.projected_step
            np.clip(pressure, 0.0, problem.cap, out=pressure)
    elif problem.plastic:
        np.minimum(pressure, problem.cap, out=pressure)


def start(problem: Problem, work: Workspace, stats: SolverStats,
          initial: np.ndarray | None, approach: float,
          displacement: np.ndarray | None = None) -> IterationState:
    """The first iterate: the warm start, a uniform pressure (load control) or the
    penetration spread over the grid (approach control), made feasible.

    ``approach`` is delta (m) in approach control (ignored in load control).
    ``displacement`` is K * ``initial`` where the caller has it exactly (a warm start
    from the last answer of a loop: one float64 convolution saved); used in elastic load
    control only, where making the start feasible only rescales it.
    """
    pressure = _first_pressure(problem, initial, approach)
    known = (displacement is not None and initial is not None and problem.load_control
             and not problem.plastic)
    given = float(pressure.sum()) if known else 1.0
    _feasible(problem, pressure, work)
    return IterationState(
        pressure=pressure,
        displacement=(np.ravel(displacement) * (problem.target / given) if known
                      else exact_displacement(problem, stats, pressure)),
        approach=0.0 if problem.load_control else approach,
        mean_pressure=problem.target / problem.size if problem.load_control else 0.0,
        # projected-gradient step: a cell's pressure closes its own gap
        alpha=1.0 / problem.operator.self_influence,
    )


class PolonskyKeer:
    """The pressure solve as :func:`contact.bem._loop.drive` runs it: the residual test
    (with the mixed-precision re-sync) and the step the bounds call for.

    Convergence is declared only on an exactly computed (float64) displacement; in mixed
    precision u is also recomputed whenever the residual has dropped 100-fold since the
    last exact evaluation. With a finite cap the projected gradient step is taken where
    the conjugate gradient cannot move (no free point) or asked for it.
    """

    def __init__(self, problem: Problem, state: IterationState, work: Workspace,
                 stats: SolverStats):
        self.problem, self.state, self.work, self.stats = problem, state, work, stats

    @property
    def iteration(self) -> int:
        """Steps taken (the state's count)."""
        return self.state.iteration

    @iteration.setter
    def iteration(self, value: int) -> None:
        self.state.iteration = value

    @property
    def residual(self) -> float:
        """The residual last measured."""
        return self.state.residual

    def _resync(self) -> Check:
        resync(self.problem, self.state, self.stats)
        self.state.residual_at_sync = self.state.residual
        return Check.AGAIN

    def check(self) -> Check:
        """Measure the residual; re-sync u where due (then test again)."""
        problem, state = self.problem, self.state
        measure_residual(problem, state, self.work)
        if state.residual <= problem.tol:
            return Check.CONVERGED if state.synced else self._resync()
        if (problem.single and not state.synced
                and state.residual < 1e-2 * state.residual_at_sync):
            return self._resync()
        return Check.STEP

    def step(self) -> Outcome:
        """A conjugate-gradient step, or (capped) a projected-gradient one where due."""
        problem, state = self.problem, self.state
        if problem.plastic and (state.projected_next or state.n_free == 0):
            return projected_gradient_step(problem, state, self.work, self.stats)
        return conjugate_gradient_step(problem, state, self.work, self.stats)


def iterate(problem: Problem, state: IterationState, work: Workspace, stats: SolverStats,
            callback: Callable[[int, float], Any] | None = None) -> bool:
    """Step ``state`` until converged (True) or stopped (False: ``max_iter`` or a stall),
    through the one driver (:func:`contact.bem._loop.drive`)."""
    method = PolonskyKeer(problem, state, work, stats)
    return loop.drive(method, problem.max_iter, callback).converged
