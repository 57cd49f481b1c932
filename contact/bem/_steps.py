"""The steps of the normal solver, each a function of the iteration state.

- :func:`measure_residual`: the approach (load control), the gap error and the residual;
- :func:`conjugate_gradient_step`: the constrained conjugate gradient of Polonsky & Keer
  (1999, Wear 231:206), preconditioned, with the displacement updated by superposition;
  in an elastic-plastic solve it is checked against the elastic energy and undone or cut
  (More & Toraldo 1991, SIAM J. Optim. 1:93; Vollebregt 2014, J. Optim. Theory Appl.
  162:931);
- :func:`projected_gradient_step`: the projected gradient step of an elastic-plastic
  solve, with its exact line search and a Barzilai-Borwein step length (1988, IMA J.
  Numer. Anal. 8:141);
- :func:`resync`: the mixed-precision re-sync, u recomputed exactly in float64.

A step returns an :class:`Outcome`; the one driver (:mod:`contact.bem._loop`) decides from
it whether to report the iteration, try again or stop. The reasons behind each step are
in the notes of :mod:`contact.bem`.
"""

from __future__ import annotations

import enum
import math

import numpy as np

from contact.bem import _kernels as kernels
from contact.bem._state import IterationState, Problem, SolverStats, Workspace

#: An elastic conjugate-gradient step restarts from steepest descent when more than this
#: fraction of the free points entered the contact in the step before (tuned on periodic
#: self-affine surfaces, 256^2-1024^2: 0.003, 0.01 and 0.03 within a few steps of each
#: other, 0.1 and 0 -- the rule of Polonsky & Keer -- 1.5 times as many at 1024^2).
RESTART_FRACTION = 0.01


class Outcome(enum.Enum):
    """What a step did: moved the iterate, must be tried again, or cannot go on."""

    STEPPED = "stepped"
    RETRY = "retry"
    STOP = "stop"


def exact_displacement(problem: Problem, stats: SolverStats, pressure: np.ndarray,
                       out: np.ndarray | None = None) -> np.ndarray:
    """u = K * p in float64 (flattened), transforming only the rows that carry pressure.

    ``out`` (flattened, float64, C-contiguous) receives u instead of a new array.
    """
    stats.fft_double += 1
    grid = pressure.reshape(problem.ny, problem.nx)
    rows = np.nonzero(grid.any(axis=1))[0]
    if rows.size == 0:
        if out is None:
            return np.zeros(problem.size)
        out.fill(0.0)
        return out
    u = problem.operator(grid, (int(rows[0]), int(rows[-1]) + 1), single=False,
                         workers=problem.workers,
                         out=None if out is None else out.reshape(problem.ny, problem.nx))
    return u.ravel()


def resync(problem: Problem, state: IterationState, stats: SolverStats) -> None:
    """Recompute u exactly: the mixed-precision superposition updates drift in float32.

    Written over the drifted u (only p enters the convolution): a second displacement of
    the grid's size at the re-sync was the solve's peak (8 bytes a cell).
    """
    u = state.displacement
    own = u.dtype == np.float64 and u.flags.c_contiguous and u.flags.writeable
    state.displacement = exact_displacement(problem, stats, state.pressure,
                                            out=u if own else None)
    state.synced = True


def _convolve(problem: Problem, stats: SolverStats, x: np.ndarray,
              rows: tuple[int, int]) -> np.ndarray:
    """K * x in the step precision (float32 when mixed), x zero outside ``rows``."""
    stats.fft_single += int(problem.single)
    stats.fft_double += int(not problem.single)
    return problem.operator(x.reshape(problem.ny, problem.nx), rows, single=problem.single,
                            workers=problem.workers).ravel()


def measure_residual(problem: Problem, state: IterationState, work: Workspace) -> None:
    """Set the approach (load control), the gap error d and the residual of the iterate.

    In load control the approach is the mean gap over the free points (the Lagrange
    multiplier of the load); when every loaded point is capped the rigid body sits at the
    highest overlap. The residual is the rms gap error on the contact (plus the
    violations off it) over the displacement a cell at the mean contact pressure makes on
    itself.
    """
    p, u, gap, cap = state.pressure, state.displacement, problem.gap, problem.cap
    sum_gap, n_free, sum_p, n_contact = kernels.pk_gap_mean(p, u, gap, cap)
    if problem.load_control:
        if n_free > 0:
            state.approach = sum_gap / n_free
        elif n_contact > 0:  # everything yielded: the rigid body sits at the highest overlap
            state.approach = float(np.max((u + gap)[p > 0]))
    free_gap_norm, violation, n_violations = kernels.pk_residual(
        p, u, gap, state.approach, cap, work.gap_error)
    mean_pressure = sum_p / n_contact if n_contact > 0 else state.mean_pressure
    state.mean_pressure = mean_pressure
    if n_contact == 0 and n_violations == 0:
        residual = 0.0  # approach control short of first contact: nothing touches
    elif mean_pressure > 0:
        residual = (math.sqrt((free_gap_norm + violation) / max(n_contact, 1))
                    / (problem.operator.self_influence * mean_pressure))
    else:
        residual = math.inf
    state.residual = residual
    state.free_gap_norm = free_gap_norm
    state.n_free = n_free


def projected_gradient_step(problem: Problem, state: IterationState, work: Workspace,
                            stats: SolverStats) -> Outcome:
    """p <- p + theta (P(p - alpha d) - p), theta the exact minimiser of the energy.

    It moves points on and off the cap and into contact all at once, and with the exact
    line search it always lowers the elastic energy unless p is already optimal.
    """
    state.projected_next = False
    step = work.projected_step
    gs, ss, _shift, lo, hi = kernels.projected_gradient(
        state.pressure, work.gap_error, state.alpha, problem.target, problem.cap,
        problem.load_control, step, work.candidates, problem.nx)
    if not gs < 0.0:
        # no descent direction: optimal up to the noise of an inexact u
        state.stalls += 1
        if state.synced or state.stalls > 3:
            return Outcome.STOP
        resync(problem, state, stats)
        return Outcome.RETRY
    stats.projected_steps += 1
    k_step = _convolve(problem, stats, step, (lo, hi))
    nx = problem.nx
    sks = float(np.dot(step[lo * nx:hi * nx], k_step[lo * nx:hi * nx]))
    theta = min(1.0, -gs / sks) if sks > 0 else 1.0
    kernels.add_step(state.pressure, step, state.displacement, k_step, theta, problem.cap)
    if sks > 0:
        # Barzilai-Borwein: the inverse Rayleigh quotient of K along the last step
        state.alpha = ss / sks
    state.synced = False
    state.restart = True
    state.stalls = 0
    return Outcome.STEPPED


def _search_direction(problem: Problem, state: IterationState,
                      work: Workspace) -> tuple[int, int]:
    """Update the conjugate direction t (and its FFT copy); return the rows it spans."""
    p, cap, d = state.pressure, problem.cap, work.gap_error
    if problem.precondition:
        lo, hi = kernels.masked_copy(d, p, cap, work.direction_fft, problem.nx)
        filtered = problem.operator.precondition(
            work.direction_fft.reshape(problem.ny, problem.nx), (lo, hi),
            single=problem.single, workers=problem.workers).ravel()
        # centred in place: the preconditioner's output is a fresh array, so no work
        # array of the grid's size is kept for it
        rho = kernels.center_on_free(filtered, filtered, d, p, cap, problem.load_control)
        beta = 0.0 if state.restart else rho / state.cg_norm_old
        state.cg_norm_old = rho if rho > 0 else 1.0
        residual = filtered
    else:
        norm = state.free_gap_norm
        beta = 0.0 if state.restart else norm / state.cg_norm_old
        state.cg_norm_old = norm if norm > 0 else 1.0
        residual = d
    return kernels.pk_direction(residual, p, work.direction, beta, cap, work.direction_fft,
                                problem.nx)


def _no_descent(problem: Problem, state: IterationState, stats: SolverStats) -> Outcome:
    """The conjugate-gradient step length is not positive: decide what comes next."""
    if problem.plastic:
        state.projected_next = True
        state.restart = True
        return Outcome.RETRY
    # Not a descent direction: the conjugacy was lost (a changed contact or plastic set,
    # or float32 noise in the last digits). Restart from steepest descent on an exact
    # displacement; give up if even that cannot make progress.
    if state.restart:  # steepest descent already failed
        state.stalls += 1
        if state.stalls > 3:
            return Outcome.STOP
    if not state.synced:
        resync(problem, state, stats)
    state.restart = True
    return Outcome.RETRY


def _add_corrections(problem: Problem, state: IterationState, work: Workspace,
                     stats: SolverStats, n_corrections: int) -> None:
    """u += K * c for the cells the projection and the rescaling changed (c sparse)."""
    if not n_corrections:
        return
    index, value = work.correction_index, work.correction_value
    if n_corrections <= work.sparse_limit:
        stats.sparse_corrections += n_corrections
        kernels.sparse_convolve_add(state.displacement, index, value, n_corrections,
                                    work.kernel_real, problem.nx, problem.operator.periodic)
        return
    # scattered into the search direction's FFT copy (in the precision of the step's
    # convolution, which the corrections are convolved in; the next step overwrites it
    # whole), so no separate dense work array is kept
    dense = work.direction_fft.reshape(problem.ny, problem.nx)
    dense.fill(0.0)
    lo, hi = kernels.scatter(dense, index, value, n_corrections, True)
    state.displacement += _convolve(problem, stats, dense, (lo, hi))


def _energy_safeguard(problem: Problem, state: IterationState, work: Workspace,
                      stats: SolverStats, scale: float) -> None:
    """Undo or cut an elastic-plastic CG step that does not lower the elastic energy.

    The CG step, its projection, the entering and released points and the load rescaling
    together make the step p - p_old; K of it is u - u_old, so the energy along it is
    known exactly without another convolution.
    """
    p_old, u_old = work.previous_pressure, work.previous_displacement
    gs, sks, total = kernels.step_terms(state.pressure, p_old, state.displacement, u_old,
                                        work.gap_error)
    target = problem.target
    if (not gs < 0.0 or (problem.load_control and abs(total - target) > 1e-10 * target)
            or not 0.5 <= scale <= 2.0):
        # uphill, a total the rescaling cannot restore (points must enter or leave the
        # cap), or a rescaling that blows up the few free points: undo it and take a
        # projected gradient step instead
        state.pressure, work.previous_pressure = p_old, state.pressure
        state.displacement, work.previous_displacement = u_old, state.displacement
        state.projected_next = True
        state.restart = True
        return
    state.stalls = 0
    if sks > 0.0 and -gs < 0.5 * sks:
        # the full step would raise the energy: stop at its minimiser
        kernels.blend(state.pressure, p_old, state.displacement, u_old, -gs / sks)
        stats.damped_steps += 1
        state.restart = True
        state.projected_next = True


def conjugate_gradient_step(problem: Problem, state: IterationState, work: Workspace,
                            stats: SolverStats) -> Outcome:
    """One Polonsky-Keer step: direction, step length, projection, load rescaling.

    The displacement follows by superposition, u <- s (u - tau K t) + K c, with c the few
    cells the projection onto the constraints (or the entry of new contact points)
    changed, so that one convolution per step suffices.
    """
    lo, hi = _search_direction(problem, state, work)
    k_direction = _convolve(problem, stats, work.direction_fft, (lo, hi))
    tau, _ = kernels.pk_step_length(k_direction, work.direction, work.gap_error,
                                    state.pressure, problem.cap, problem.load_control)
    if not (tau > 0 and math.isfinite(tau)):
        return _no_descent(problem, state, stats)
    if not problem.plastic:
        state.stalls = 0
    else:
        np.copyto(work.previous_pressure, state.pressure)
        np.copyto(work.previous_displacement, state.displacement)
    n_corrections, _total, entered = kernels.pk_update_pressure(
        state.pressure, work.direction, work.gap_error, tau, problem.cap,
        work.correction_index, work.correction_value)
    # Polonsky & Keer restart from steepest descent whenever a point enters the contact.
    # On a rough surface at a fine grid a few points enter at almost every step, and the
    # restarts left the iteration at the steepest-descent rate until the contact set was
    # final (56 restarts in 68 steps on a periodic self-affine 512^2). The conjugacy is
    # kept while the points entering are a small part of the free set (elastic solves;
    # an elastic-plastic step keeps the strict rule its energy safeguard assumes).
    state.restart = (entered > RESTART_FRACTION * state.n_free if not problem.plastic
                     else entered > 0)
    scale = 1.0
    if problem.load_control:
        scale, n_corrections = kernels.capped_scale(
            state.pressure, problem.target, problem.cap, work.correction_index,
            work.correction_value, n_corrections)
    kernels.axpy_scale(state.displacement, k_direction, tau, scale)
    del k_direction  # before the corrections' convolution: one transient of the grid less
    _add_corrections(problem, state, work, stats, n_corrections)
    state.synced = False
    if problem.plastic:
        _energy_safeguard(problem, state, work, stats, scale)
    return Outcome.STEPPED
