"""What the normal solver carries from one iteration to the next.

Three small objects, all in units where E* = 1 (the pressure divided by E*; gap,
approach and displacement u = K * p in metres), on flattened C-contiguous arrays:

- :class:`Problem`: what the solve is asked, fixed during the iteration;
- :class:`Workspace`: the preallocated work arrays, so that an iteration allocates nothing
  of the grid's size beyond the FFT's own output;
- :class:`IterationState`: the iterate (pressure, displacement, approach) and the flags
  that tell the step functions of :mod:`contact.bem._steps` what to do next.

:class:`SolverStats` counts what a solve does (FFTs, corrections, grid levels) while it
runs; the solve copies the counts into the one record every solver returns,
:class:`contact._record.SolveRecord` (``ContactResult.solve.counters``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from contact._grid import Grid
from contact.bem._bounds import PressureBounds
from contact.halfspace.convolution import Convolution

#: Direct summation of a corrected cell costs about 1/SPARSE_FACTOR / log2(4 n) of one
#: padded FFT convolution of n cells; fewer corrections than the break-even are summed.
SPARSE_FACTOR = 1.8


@dataclass
class SolverStats:
    """The live counters of a solve, for benchmarks and diagnostics.

    Not a result: the step functions count into it as they run, and the solve copies it
    into its one record, :attr:`contact._record.SolveRecord.counters` (see
    :meth:`snapshot`). A benchmark that reads the counts during the solve (from a
    callback) passes its own to :func:`contact.bem.solve_normal` as ``SolveOptions.stats``.

    ``projected_steps`` and ``damped_steps`` count the projected gradient steps and the
    Polonsky-Keer steps cut to the minimiser of the energy (elastic-plastic solves only).
    """

    iterations: int = 0
    fft_single: int = 0
    fft_double: int = 0
    sparse_corrections: int = 0
    projected_steps: int = 0
    damped_steps: int = 0
    levels: list[tuple[int, int, int]] = field(default_factory=list)

    def snapshot(self) -> dict:
        """A copy of the counters now, as :attr:`contact._record.SolveRecord.counters` (a
        plain dict, so that results pickle)."""
        return {
            "iterations": self.iterations, "fft_single": self.fft_single,
            "fft_double": self.fft_double, "sparse_corrections": self.sparse_corrections,
            "projected_steps": self.projected_steps, "damped_steps": self.damped_steps,
            "levels": tuple(self.levels)}


@dataclass(frozen=True, eq=False)
class Problem:
    """One solve's fixed data, in units where E* = 1.

    ``gap`` is h (m), flattened (a view of the caller's gap, not a copy); ``grid`` the
    cells (:class:`contact._grid.Grid`: shape, pitch, origin, periodic or free boundary);
    ``target`` the prescribed sum of the cell pressures (the load over the cell area and
    E*) in load control, 0 in approach control; ``bounds`` the pressure bounds
    (non-adhesive here: 0 <= p <= hardness / E*); ``single`` runs the search-direction
    convolutions in float32.
    """

    gap: np.ndarray
    grid: Grid
    operator: Convolution
    load_control: bool
    target: float
    bounds: PressureBounds
    single: bool
    precondition: bool
    workers: int
    tol: float
    max_iter: int

    @property
    def ny(self) -> int:
        """Cells along y."""
        return self.grid.ny

    @property
    def nx(self) -> int:
        """Cells along x."""
        return self.grid.nx

    @property
    def size(self) -> int:
        """Number of cells."""
        return self.ny * self.nx

    @property
    def cap(self) -> float:
        """The upper pressure bound (Pa) handed to the kernels: the hardness, or inf."""
        return self.bounds.hardness

    @property
    def plastic(self) -> bool:
        """A finite pressure cap: the elastic-perfectly-plastic path."""
        return self.bounds.plastic


@dataclass(eq=False)
class Workspace:
    """The work arrays of one solve (see :func:`workspace`)."""

    gap_error: np.ndarray  # d = u + h - delta, the gap residual
    direction: np.ndarray  # t, the conjugate search direction
    direction_fft: np.ndarray  # t in the precision of the FFT (float32 when mixed); also
    # where many corrections are scattered for one FFT (it is rewritten whole every step)
    correction_index: np.ndarray  # cells the projection changed after a linear step ...
    correction_value: np.ndarray  # ... and by how much
    kernel_real: np.ndarray  # the real-space kernel, for direct summation
    sparse_limit: int  # up to this many corrections are summed directly
    projected_step: np.ndarray | None  # elastic-plastic only: P(p - alpha d) - p
    candidates: np.ndarray | None  # elastic-plastic only: cells that may carry pressure
    previous_pressure: np.ndarray | None  # elastic-plastic only: p before the CG step
    previous_displacement: np.ndarray | None  # elastic-plastic only: u before it


def workspace(problem: Problem) -> Workspace:
    """Allocate the work arrays of ``problem``."""
    n = problem.size
    plastic = problem.plastic
    # a capped point may carry two corrections: one from the step, one from the rescaling
    n_corrections = 2 * n if plastic else n
    return Workspace(
        gap_error=np.empty(n),
        direction=np.zeros(n),
        direction_fft=np.zeros(n, dtype=np.float32 if problem.single else np.float64),
        # int32 cell numbers where they fit (4 bytes a cell less)
        correction_index=np.empty(n_corrections, dtype=np.int32 if n < 2**31 else np.int64),
        correction_value=np.empty(n_corrections),
        kernel_real=np.ascontiguousarray(problem.operator.real),
        sparse_limit=max(4, int(SPARSE_FACTOR * math.log2(4 * n))),
        projected_step=np.empty(n) if plastic else None,
        candidates=np.empty(n, dtype=np.int64) if plastic else None,
        previous_pressure=np.empty(n) if plastic else None,
        previous_displacement=np.empty(n) if plastic else None,
    )


@dataclass(eq=False)
class IterationState:
    """The iterate and the flags that steer the next step.

    ``pressure`` p and ``displacement`` u = K * p (flattened), ``approach`` delta (m).
    ``synced``: u was last computed exactly in float64 (not updated by superposition);
    ``restart``: the next conjugate-gradient step restarts from steepest descent;
    ``projected_next``: the next elastic-plastic step is a projected gradient step;
    ``stalls``: consecutive steps that found no descent; ``alpha``: the projected
    gradient's step (Barzilai-Borwein); ``cg_norm_old``: the previous (preconditioned)
    residual norm of the conjugate gradient; ``free_gap_norm``, ``n_free``: the squared
    gap error summed over the free points and their number, from the last residual.
    """

    pressure: np.ndarray
    displacement: np.ndarray
    approach: float
    mean_pressure: float
    alpha: float
    iteration: int = 0
    residual: float = math.inf
    residual_at_sync: float = math.inf
    synced: bool = True
    restart: bool = True
    projected_next: bool = False
    stalls: int = 0
    cg_norm_old: float = 1.0
    free_gap_norm: float = 0.0
    n_free: int = 0
