"""The normal-contact solver's entry point: check the input, nest, iterate, assemble.

:func:`solve_normal` is the one normal solver of the package, elastic or (with a
hardness) elastic-perfectly-plastic; the algorithm and its conventions are described in
:mod:`contact.bem`.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Callable
from typing import Any

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._grid import Grid, scan_grid
from contact._nesting import coarse_grid, prolong
from contact._record import edge_warning
from contact._validate import positive
from contact.bem._bounds import PressureBounds
from contact.bem._chunks import kernel_threads
from contact.bem._iteration import iterate, start
from contact.bem._options import SolveOptions, options_of
from contact.bem._result import ContactResult, build_result
from contact.bem._state import IterationState, Problem, SolverStats, workspace
from contact.halfspace.convolution import convolution, drop_cached

#: A nested solve of at least this many cells drops the cached coarse kernels before its
#: own solve (:func:`contact.halfspace.convolution.drop_cached`): 6 bytes a cell of the
#: peak, for a rebuild of about 2 % of a cold solve's time; smaller grids keep them.
DROP_COARSE_CELLS = 2048 * 2048


def solve_normal(
    grid: Grid,
    *,
    e_star: float,
    load: float | None = None,
    approach: float | None = None,
    bounds: PressureBounds | None = None,
    options: SolveOptions | None = None,
    initial: np.ndarray | None = None,
) -> ContactResult:
    """Solve the normal contact of two rough elastic half-spaces on a regular grid.

    Parameters
    ----------
    grid : Grid
        The cells and the initial gap h (m) between the undeformed surfaces (``grid.h``,
        see the module conventions), with their pitch, origin and boundary (periodic, or
        free: no pressure outside the grid). Loose arrays become one with
        :func:`contact._grid.gap_grid`: ``gap_grid(h, dx, dy, periodic=...)``.
    e_star : float
        Composite modulus E* (Pa).
    load, approach : float
        Exactly one: the total normal load W (N) or the rigid-body approach delta (m).
    bounds : PressureBounds, optional
        The pressure bounds; default ``PressureBounds.elastic()`` (p >= 0, no cap).
        ``PressureBounds.elastic(H)`` caps the pressure at a hardness H (Pa): the
        elastic-perfectly-plastic contact. Adhesive bounds (a tension or an interaction
        law) are refused here with a pointer to :func:`contact.adhesion.solve_adhesive`:
        this iteration keeps p >= 0.
    options : SolveOptions, optional
        How to solve (tolerance, iteration budget, precision, threads, callback,
        strictness, nesting, preconditioning, edge report, kernel, live counters);
        default ``SolveOptions()``.
    initial : ndarray, optional
        Warm start: a pressure field on the same grid (e.g. the solution at a nearby load);
        it is rescaled to the load.

    Returns
    -------
    ContactResult
        Its ``solve`` record's ``iterations`` counts the finest grid; ``extra["levels"]``
        lists (ny, nx, iterations) of every grid solved, coarsest first.

    Raises
    ------
    ContactInputError
        A gap that is not finite, a non-positive modulus, load or pitch, both or neither of
        ``load`` and ``approach``.
    ConvergenceError
        The iteration stopped before ``options.tol`` (with ``options.strict``).
    ContactMemoryError
        A grid that would not fit in memory.

    See Also
    --------
    contact.solve_sphere : the ball-on-plate set-up around it.
    contact.flat_contact : a rough surface on a flat.

    References
    ----------
    .. [1] I. A. Polonsky, L. M. Keer, "A numerical method for solving rough contact
       problems based on the multi-level multi-summation and conjugate gradient
       techniques", Wear 231 (1999) 206-219.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 3.

    Examples
    --------
    A paraboloid gap of R = 20 mm at 10 N gives the Hertz peak pressure,
    ``p0 = (6 W E*² / (π³ R²))^(1/3)`` = 255 MPa:

    >>> from contact import solve_normal, sphere_gap
    >>> from contact._grid import gap_grid
    >>> grid = gap_grid(sphere_gap(64, 8e-6, 0.02), 8e-6)
    >>> res = solve_normal(grid, e_star=58.6e9, load=10.0)
    >>> print(f"pmax = {res.pmax / 1e6:.0f} MPa, W = {res.load:.2f} N")
    pmax = 255 MPa, W = 10.00 N
    """
    h, grid = _gap_of(grid)
    dx, dy = grid.dx, grid.dy
    opts = options_of(options)
    bounds = _resolve_bounds(bounds)
    hardness = bounds.hardness if bounds.plastic else None
    h = _check_inputs(h, dx, dy, e_star, load, approach, hardness)
    workers = (os.cpu_count() or 1) if opts.workers is None else int(opts.workers)
    stats = opts.stats if opts.stats is not None else SolverStats()
    ny, nx = h.shape
    cap = bounds.hardness
    tol = opts.tol

    first: ContactResult | None = None  # the coarse grid's answer, where nested
    coarse = None if initial is not None or not opts.nested else coarse_grid(grid)
    if initial is not None:
        p_init = _warm_start(initial, h.shape, cap)
    elif coarse is not None:
        # the coarse solve is only a start: looser, never raising, its edge not reported
        start_opts = opts.but(tol=max(tol, 1e-4), workers=workers, callback=None,
                              strict=False, edge="ignore", stats=stats)
        first = solve_normal(coarse, e_star=e_star, load=load, approach=approach,
                             bounds=bounds, options=start_opts)
        # C-ordered, so that the iteration takes it over without a copy
        # (wrapped round a periodic grid); no name holds the unclipped copy, which would
        # stay alive through the whole fine solve (8 bytes a cell)
        p_init = (np.clip(np.ascontiguousarray(prolong(np.asarray(first.pressure),
                                                       grid.periodic)), 0.0, cap)
                  if first.load > 0 else None)
    else:
        p_init = None
    # the coarse answer (four fields of a quarter of the cells) is not kept through the
    # fine solve: 8 bytes a cell of its peak
    first = None
    if coarse is not None and ny * nx >= DROP_COARSE_CELLS:
        drop_cached()  # the coarse levels' kernels: before the fine one is built
    if p_init is not None:
        p_init /= e_star  # a fresh array (clipped): the iteration's unit, p / E*

    problem = Problem(
        # units where the pressure is p / E* (E* = 1): the gap is h itself, a view and
        # not a copy of the grid's size (E* h was one), the displacement K * p / E* and
        # the approach delta in metres
        gap=h.ravel(), grid=grid,
        operator=convolution(ny, nx, float(dx), float(dy), grid.periodic,
                             kernel=opts.kernel),
        load_control=load is not None,
        target=load / (dx * dy * e_star) if load is not None else 0.0,
        bounds=_per_modulus(bounds, e_star), single=opts.precision == "mixed",
        precondition=opts.precondition, workers=workers, tol=tol, max_iter=opts.max_iter,
    )
    state, ok = _run(problem, stats, p_init, float(approach or 0.0),
                     None, opts.callback)
    it, res = state.iteration, state.residual
    stats.levels.append((ny, nx, it))
    stats.iterations = it

    result = _assemble(h, state, e_star, hardness, grid, ok, tol,
                       {"levels": list(stats.levels), "tol": tol, "precision": opts.precision,
                        "kernel": opts.kernel})
    result = dataclasses.replace(
        result, solve=dataclasses.replace(result.solve, counters=stats.snapshot()))
    msg = edge_warning(opts.edge == "warn" and result.touches_edge)
    if msg is not None:
        result = dataclasses.replace(result, notes=(*result.notes, msg))
    if not ok and opts.strict:
        raise ConvergenceError(
            f"the contact solver stopped after {it} iterations at residual {res:.3g} "
            f"(tolerance {tol:.3g}); raise max_iter, loosen tol, or refine the grid",
            residual=res, iterations=it,
        )
    return result


def _per_modulus(bounds: PressureBounds, e_star: float) -> PressureBounds:
    """The bounds in the iteration's pressure unit, E* (the cap H / E*)."""
    return PressureBounds.elastic(bounds.hardness / e_star) if bounds.plastic else bounds


def _run(problem: Problem, stats: SolverStats, p_init: np.ndarray | None, approach: float,
         displacement: np.ndarray | None,
         callback: Callable[[int, float], Any] | None) -> tuple[IterationState, bool]:
    """Start and iterate ``problem`` (units where E* = 1: pressures p / E*, lengths in
    metres); the final state and whether it converged."""
    try:
        # the grid passes on as many threads as the FFT (their chunks, hence the answer,
        # do not depend on it)
        with kernel_threads(problem.workers):
            work = workspace(problem)
            state = start(problem, work, stats, p_init, approach, displacement)
            ok = iterate(problem, state, work, stats, callback)
    finally:
        problem.operator.release()
    return state, ok


@dataclasses.dataclass(frozen=True, eq=False)
class PressureField:
    """A warm-started elastic pressure (:func:`resolve_pressure`), SI units.

    ``displacement`` is the normal displacement of ``pressure`` (m), exact in float64:
    handed back with the pressure as the next warm start, it spares that solve one
    convolution.
    """

    pressure: np.ndarray
    displacement: np.ndarray
    approach: float
    iterations: int
    residual: float
    converged: bool


@dataclasses.dataclass(frozen=True, eq=False)
class WarmStart:
    """Where a re-solve starts (:func:`resolve_pressure`): a pressure (Pa) and, where an
    earlier solve gave it, its normal displacement (m), which spares the re-solve the
    convolution of its start. A pressure that carries nothing is no start: the solve then
    begins from a uniform pressure, whatever the displacement."""

    pressure: np.ndarray
    displacement: np.ndarray | None = None


def resolve_pressure(gap0: np.ndarray, dx: float, dy: float, *, e_star: float, load: float,
                     start: WarmStart, tol: float = 1e-6, max_iter: int = 2000
                     ) -> PressureField:
    """The elastic pressure under ``load`` on a free grid, started from a nearby answer:
    :func:`solve_normal`'s iteration without its record, for a loop that solves the
    normal problem again after every small change of the gap (the normal-tangential
    coupling of steady rolling, :mod:`contact.tangential._coupling`).

    The same iteration and convergence test as :func:`solve_normal` with the same warm
    start (the answers agree to rounding); what is left out is the result record (its
    contact radius, clusters and fields: about a sixth of a warm solve at 256^2) and,
    when the start's displacement is given (:class:`WarmStart`), the convolution of the
    start. Inputs are trusted (an internal path: no checks).
    """
    ny, nx = gap0.shape
    problem = Problem(  # the units of solve_normal's iteration: p / E*, metres
        gap=np.ascontiguousarray(gap0, dtype=float).ravel(),
        grid=scan_grid((ny, nx), dx, dy), operator=convolution(ny, nx, float(dx), float(dy),
                                                               False),
        load_control=True, target=load / (dx * dy * e_star),
        bounds=PressureBounds.elastic(None), single=True, precondition=True,
        workers=os.cpu_count() or 1, tol=tol, max_iter=max_iter)
    p_init = np.clip(start.pressure, 0.0, None) / e_star
    displacement = start.displacement
    if not p_init.any():
        # nothing to start from (solve_normal's warm start does the same): a uniform start
        p_init, displacement = None, None
    u_init = None if displacement is None else np.asarray(displacement, dtype=float)
    state, ok = _run(problem, SolverStats(), p_init, 0.0, u_init, None)
    pressure = state.pressure
    pressure *= e_star
    return PressureField(
        pressure=pressure.reshape(ny, nx),
        displacement=state.displacement.reshape(ny, nx),
        approach=state.approach, iterations=state.iteration,
        residual=state.residual, converged=ok)


def _gap_of(grid: Grid) -> tuple[np.ndarray, Grid]:
    """The gap of a 3D grid, and the grid carrying it as floats; anything else is refused
    in one line."""
    if not isinstance(grid, Grid):
        raise ContactInputError(
            "solve_normal takes a contact._grid.Grid carrying the gap; for a bare array h of "
            "pitch dx give contact._grid.gap_grid(h, dx)")
    if grid.h is None or grid.line:
        raise ContactInputError("the grid must carry a gap (Grid.h) and be 3D, not a line")
    h = np.asarray(grid.h, dtype=float)
    return h, (grid if h is grid.h else grid.with_gap(h))


def _resolve_bounds(bounds: PressureBounds | None) -> PressureBounds:
    """The bounds of a non-adhesive solve (default: p >= 0, no cap)."""
    if bounds is None:
        return PressureBounds.elastic()
    if not isinstance(bounds, PressureBounds):
        raise ContactInputError(
            f"bounds must be a contact.PressureBounds, got {type(bounds).__name__}")
    if bounds.is_adhesive:
        raise ContactInputError(
            "adhesive pressure bounds (a tension or an interaction law) are solved by "
            "contact.adhesion.solve_adhesive, not by the non-adhesive solve_normal")
    return bounds


def _check_inputs(gap0: np.ndarray, dx: float, dy: float, e_star: float,
                  load: float | None, approach: float | None,
                  hardness: float | None) -> np.ndarray:
    """The gap as a C-contiguous float array, after checking every argument."""
    h = np.asarray(gap0, dtype=float)
    if h.ndim != 2 or min(h.shape) < 2:
        raise ContactInputError(f"the gap must be a 2D array of at least 2x2, got shape {h.shape}")
    if not np.isfinite(h).any():
        raise ContactInputError("the gap is NaN everywhere: no measured point to put in contact")
    if not np.isfinite(h).all():
        raise ContactInputError(
            "the gap has NaN or infinite points; fill the non-measured points of the scans "
            "first (surfmet.pairing does)"
        )
    for name, value in (("dx", dx), ("dy", dy), ("E*", e_star)):
        positive(value, name)
    if (load is None) == (approach is None):
        raise ContactInputError("give exactly one of load= (load control) or approach=")
    if load is not None:
        positive(load, "the load", "N")
    if approach is not None and not math.isfinite(approach):
        raise ContactInputError(f"the approach must be finite, got {approach!r}")
    if hardness is not None:
        positive(hardness, "the hardness", "Pa")
        if load is not None and load >= hardness * h.size * dx * dy:
            raise ContactInputError(
                f"a load of {load:g} N cannot be carried below the hardness {hardness:g} Pa on "
                f"this domain ({h.size * dx * dy:.3g} m^2): enlarge the domain"
            )
    return np.ascontiguousarray(h)


def _warm_start(initial: np.ndarray, shape: tuple[int, ...], cap: float) -> np.ndarray | None:
    """The warm-start pressure clipped to [0, cap]; None if it carries nothing."""
    p_init = np.array(initial, dtype=float)
    if p_init.shape != shape:
        raise ContactInputError(
            f"the warm-start pressure has shape {p_init.shape}, the grid {shape}"
        )
    p_init = np.clip(np.nan_to_num(p_init), 0.0, cap)
    return p_init if p_init.any() else None


def _assemble(h: np.ndarray, state: IterationState, e_star: float, hardness: float | None,
              grid: Grid, ok: bool, tol: float, extra: dict[str, Any]) -> ContactResult:
    """The result of a finished iteration, back in SI units."""
    ny, nx = h.shape
    p = state.pressure.reshape(ny, nx)
    # the cells at the cap H / E* of the iteration (before the unit goes back: (H / E*) E*
    # need not round to H)
    capped = None if hardness is None else p >= hardness / e_star
    p *= e_star  # in place: the iterate is not used again
    u_m = state.displacement.reshape(ny, nx)
    delta = state.approach
    g = h + u_m - delta
    if capped is not None:
        p[capped] = hardness
        plastic = np.where(capped, np.maximum(-g, 0.0), 0.0)
    else:
        plastic = np.zeros_like(p)
    gap = np.maximum(g, 0.0)
    gap[p > 0] = 0.0
    return build_result(
        pressure=p, gap=gap, displacement=u_m, plastic_displacement=plastic, grid=grid,
        e_star=e_star, hardness=hardness, approach=delta,
        iterations=state.iteration, residual=state.residual, converged=ok, tolerance=tol,
        method="normal BEM" + (", elastic-plastic" if hardness is not None else "")
        + (f", {extra['kernel']} kernel" if extra["kernel"] != "love" else ""),
        extra=extra,
    )
