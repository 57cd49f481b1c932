"""FFT boundary-element solver for frictionless normal contact on a regular grid.

Conventions
-----------
- Grid: row ``i`` at ``y = y0 + i dy``, column ``j`` at ``x = x0 + j dx`` (cell centres).
  Each cell carries a uniform pressure (Love's influence coefficients,
  :mod:`contact.influence`).
- ``gap0`` (h) is the initial separation of the two undeformed surfaces, in metres,
  positive where they are apart (for a ball on a plate: x^2/2R minus the composite
  roughness). Only differences of h matter to a load-controlled solve.
- ``u`` is the combined normal elastic displacement of the two surfaces, positive *into*
  the bodies (it opens the gap), u = K * p / E*.
- ``approach`` (delta) is the rigid-body approach of the two bodies. The deformed gap is
  ``g = h + u - delta`` and the contact conditions are g >= 0, p >= 0, p g = 0 (and, with a
  hardness H, p <= H, where g < 0 is the plastic displacement).
- Load control prescribes sum(p) dx dy = W and returns delta; approach control prescribes
  delta and returns W.

Algorithm
---------
Polonsky & Keer (1999), Wear 231:206: constrained conjugate gradient on the contact set,
with the mean gap removed (the Lagrange multiplier of the load constraint) and points
re-entering the contact restarting the conjugacy. Free boundaries use DC-FFT (Liu, Wang &
Liu 2000, Wear 243:101); periodic ones the periodised Love kernel.

Elastic-perfectly-plastic contact
---------------------------------
The pressure is capped at the hardness H as in Almqvist, Sahlin, Larsson & Glavatskih
(2007), Wear 262:1321: the capped points are a second active set, with their own
complementarity (0 <= p <= H; g = 0 where 0 < p < H; g >= 0 where p = 0; g <= 0 where
p = H, -g being the plastic displacement). The solution minimises the elastic energy
q(p) = p.K p / 2 + (h - delta).p over the box 0 <= p <= H (and, in load control, the
hyperplane sum p = W / (dx dy)), a convex bound-constrained quadratic programme. The
plain Polonsky-Keer step alone is not enough there: when every loaded point is capped no
free point is left to step on, the load rescaling of a handful of free points amplifies
them wildly, and a step that moves many points on and off the cap can raise q and cycle.
Following the gradient-projection / conjugate-gradient scheme of More & Toraldo (1991,
SIAM J. Optim. 1:93) and the bound-constrained CG of Vollebregt ("The bound-constrained
conjugate gradient method for non-negative matrices", 2014, J. Optim. Theory Appl.
162:931), the iteration is made monotone in q:

- each Polonsky-Keer step (CG on the free points, projection onto [0, H], points entering
  the contact or leaving the cap, load rescaling) is checked against q. The step s and
  K s (= the change of u, known by superposition) give q along s exactly, for the cost of
  a dot product: a step that raises q is cut to its minimiser;
- when that step cannot be taken (no free point, no descent, a load the rescaling cannot
  restore, or a rescaling by more than a factor 2), or after a cut one, a projected
  gradient step is taken instead: p + theta (P(p - alpha g) - p), where P is the exact
  projection onto the feasible set (clip(x - mu, 0, H) with the shift mu that restores the
  load) and theta the exact minimiser of q on that segment (one convolution). It moves
  points into contact and on and off the cap all at once and lowers q unless p is
  optimal; alpha follows Barzilai & Borwein (1988, IMA J. Numer. Anal. 8:141).

q thus decreases at every step, which rules out the cycling; the iteration stops at the
tolerance, at ``max_iter``, or (not converged) when even an exact displacement leaves no
descent direction. The elastic path (no hardness) is untouched.

What makes it fast
------------------
- Preconditioning: the search direction is built from the gap residual filtered by the
  periodic stiffness |q|/2, the approximate inverse of the influence operator (in the
  spirit of Vollebregt 2014, J. Comput. Phys. 257:333). This costs one unpadded FFT pair
  per iteration and cuts the iterations several-fold (117 -> 25 for Hertz at 1024^2).
- One padded FFT convolution per iteration instead of two: the displacement is updated by
  superposition, u <- s (u - tau K*t) + K*c, where c holds the few cells that the
  projection onto p >= 0 (or the entry of new contact points) changed. A handful of such
  cells are added by direct summation, more by one extra FFT.
- Mixed precision: the search-direction convolution K*t runs in float32 (half the memory
  traffic), while u, p and every reduction stay in float64. The float32 error of each
  update scales with the update, which shrinks as the solver converges; u is recomputed
  exactly in float64 whenever the residual has dropped 100-fold since the last exact
  evaluation and before convergence is declared, so the final answer carries float64
  accuracy.
- Pruned transforms: only the rows that carry pressure are transformed forward, the padded
  half of the result is never transformed back.
- Nested grids: without a warm start, the problem is first solved on a grid twice as
  coarse (recursively), and its pressure, interpolated, starts the fine solve.
- Kernel spectra and convolution plans are cached by (grid, pitch, periodicity).
"""

from __future__ import annotations

import dataclasses
import math
import os
import threading
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import scipy.fft as sfft

from contact import kernels as kn
from contact.errors import ContactInputError, ConvergenceError, EdgeContactWarning
from contact.influence import (
    free_kernel_quadrant,
    free_kernel_spectrum,
    periodic_kernel_real,
    periodic_kernel_spectrum,
)
from contact.result import ContactResult, build_result

#: Direct summation of a corrected cell costs about 1/SPARSE_FACTOR / log2(4 n) of one
#: padded FFT convolution of n cells; fewer corrections than the break-even are summed.
SPARSE_FACTOR = 1.8

#: Grids smaller than this (in either direction) are solved directly, not nested.
MIN_COARSE = 64


class Convolution:
    """u = K * p for one grid (E* = 1), with cached spectra in float64 and float32.

    Parameters
    ----------
    ny, nx : int
        Grid shape.
    dx, dy : float
        Cell pitch (m).
    periodic : bool
        Periodic domain instead of a free (zero-padded) boundary.
    """

    def __init__(self, ny: int, nx: int, dx: float, dy: float, periodic: bool):
        self.ny, self.nx = int(ny), int(nx)
        self.dx, self.dy = float(dx), float(dy)
        self.periodic = bool(periodic)
        if periodic:
            self.spec64 = periodic_kernel_spectrum(self.ny, self.nx, self.dx, self.dy)
            self.real = periodic_kernel_real(self.ny, self.nx, self.dx, self.dy)
        else:
            self.spec64 = free_kernel_spectrum(self.ny, self.nx, self.dx, self.dy)
            self.real = free_kernel_quadrant(self.ny, self.nx, self.dx, self.dy)
        self.spec32 = self.spec64.astype(np.float32)
        self.k00 = float(self.real[0, 0])
        self._stiff: dict[bool, np.ndarray] = {}
        # one spectral work buffer per thread, kept during a solve (see _buffer)
        self._work = threading.local()

    def _buffer(self, rows: int, cols: int, cdt: type, lo: int, hi: int) -> np.ndarray:
        """A (rows, cols) complex work array, zero outside rows [lo, hi).

        Fresh arrays of this size come from the kernel as untouched pages: every
        convolution would page-fault its buffer in again (a third of the wall time of a
        4096^2 solve went to the system). One buffer, sized for the complex128 padded
        grid and viewed as complex64 for the float32 transforms, is kept per thread while
        a solve runs (:meth:`release` drops it): no more memory than one transient.
        """
        nbytes = (2 * self.ny if not self.periodic else self.ny) * (self.nx + 1) * 16
        raw = getattr(self._work, "raw", None)
        if raw is None or raw.size < nbytes:
            raw = self._work.raw = np.empty(nbytes, dtype=np.uint8)
        buf = np.ndarray((rows, cols), dtype=cdt, buffer=raw)
        buf[:lo] = 0
        buf[hi:] = 0
        return buf

    def release(self) -> None:
        """Drop this thread's work buffer (the end of a solve)."""
        self._work.raw = None

    def stiffness(self, single: bool) -> np.ndarray:
        """1 / K^ of the periodic kernel on this (unpadded) grid, 0 at q = 0."""
        if single not in self._stiff:
            spec = periodic_kernel_spectrum(self.ny, self.nx, self.dx, self.dy, 2)
            with np.errstate(divide="ignore"):
                stiff = np.where(spec > 0, 1.0 / spec, 0.0)
            self._stiff[single] = stiff.astype(np.float32 if single else np.float64)
        return self._stiff[single]

    def precondition(self, x: np.ndarray, rows: tuple[int, int], single: bool = False,
                     workers: int = -1) -> np.ndarray:
        """Approximate inverse of K: the periodic stiffness |q|/2 applied by FFT."""
        ny, nx = self.ny, self.nx
        lo, hi = int(rows[0]), int(rows[1])
        rdt, cdt = (np.float32, np.complex64) if single else (np.float64, np.complex128)
        if hi <= lo:
            return np.zeros((ny, nx), dtype=rdt)
        buf = self._buffer(ny, nx // 2 + 1, cdt, lo, hi)
        buf[lo:hi] = sfft.rfft(np.asarray(x[lo:hi], dtype=rdt), axis=1, workers=workers)
        buf = sfft.fft(buf, axis=0, overwrite_x=True, workers=workers)
        buf *= self.stiffness(single)
        buf = sfft.ifft(buf, axis=0, overwrite_x=True, workers=workers)
        return sfft.irfft(buf, n=nx, axis=1, overwrite_x=True, workers=workers)

    def __call__(
        self,
        x: np.ndarray,
        rows: tuple[int, int] | None = None,
        single: bool = False,
        workers: int = -1,
    ) -> np.ndarray:
        """K * x on the grid, shape (ny, nx), C-contiguous.

        ``rows=(lo, hi)`` says that x is zero outside rows [lo, hi) (only those rows are
        transformed). ``single`` computes in float32 and returns float32.
        """
        ny, nx = self.ny, self.nx
        lo, hi = (0, ny) if rows is None else (int(rows[0]), int(rows[1]))
        rdt, cdt = (np.float32, np.complex64) if single else (np.float64, np.complex128)
        if hi <= lo:
            return np.zeros((ny, nx), dtype=rdt)
        block = np.asarray(x[lo:hi], dtype=rdt)
        if self.periodic:
            spec = self.spec32 if single else self.spec64
            buf = self._buffer(ny, nx // 2 + 1, cdt, lo, hi)
            buf[lo:hi] = sfft.rfft(block, axis=1, workers=workers)
            buf = sfft.fft(buf, axis=0, overwrite_x=True, workers=workers)
            buf *= spec
            buf = sfft.ifft(buf, axis=0, overwrite_x=True, workers=workers)
            return sfft.irfft(buf, n=nx, axis=1, overwrite_x=True, workers=workers)
        spec = self.spec32 if single else self.spec64
        buf = self._buffer(2 * ny, nx + 1, cdt, lo, hi)
        buf[lo:hi] = sfft.rfft(block, n=2 * nx, axis=1, workers=workers)
        buf = sfft.fft(buf, axis=0, overwrite_x=True, workers=workers)
        buf *= spec
        buf = sfft.ifft(buf, axis=0, overwrite_x=True, workers=workers)
        out = sfft.irfft(buf[:ny], n=2 * nx, axis=1, overwrite_x=True, workers=workers)
        return np.ascontiguousarray(out[:, :nx])


@lru_cache(maxsize=6)
def convolution(ny: int, nx: int, dx: float, dy: float, periodic: bool) -> Convolution:
    """The cached :class:`Convolution` of a grid (kept between calls)."""
    return Convolution(ny, nx, dx, dy, periodic)


@dataclass
class SolverStats:
    """Counters of one solve, for benchmarks and diagnostics.

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


def _check_inputs(gap0: np.ndarray, dx: float, dy: float, e_star: float,
                  load: float | None, approach: float | None,
                  hardness: float | None) -> np.ndarray:
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
    for name, v in (("dx", dx), ("dy", dy), ("E*", e_star)):
        if not (math.isfinite(v) and v > 0):
            raise ContactInputError(f"{name} must be positive and finite, got {v!r}")
    if (load is None) == (approach is None):
        raise ContactInputError("give exactly one of load= (load control) or approach=")
    if load is not None and not (math.isfinite(load) and load > 0):
        raise ContactInputError(f"the load must be a positive force in N, got {load!r}")
    if approach is not None and not math.isfinite(approach):
        raise ContactInputError(f"the approach must be finite, got {approach!r}")
    if hardness is not None:
        if not (math.isfinite(hardness) and hardness > 0):
            raise ContactInputError(f"the hardness must be a positive pressure, got {hardness!r}")
        if load is not None and load >= hardness * h.size * dx * dy:
            raise ContactInputError(
                f"a load of {load:g} N cannot be carried below the hardness {hardness:g} Pa on "
                f"this domain ({h.size * dx * dy:.3g} m^2): enlarge the domain"
            )
    return np.ascontiguousarray(h)


def _coarsen(h: np.ndarray) -> np.ndarray:
    ny, nx = h.shape
    return h.reshape(ny // 2, 2, nx // 2, 2).mean(axis=(1, 3))


def _prolong_axis(a: np.ndarray, axis: int) -> np.ndarray:
    # Bilinear interpolation from coarse cell centres to the two fine centres of each cell:
    # fine 2I sits a quarter cell before coarse I, fine 2I+1 a quarter cell after it.
    a = np.moveaxis(a, axis, 0)
    prev = np.concatenate((a[:1], a[:-1]))
    nxt = np.concatenate((a[1:], a[-1:]))
    out = np.empty((2 * a.shape[0], *a.shape[1:]), dtype=a.dtype)
    out[0::2] = 0.75 * a + 0.25 * prev
    out[1::2] = 0.75 * a + 0.25 * nxt
    return np.moveaxis(out, 0, axis)


def prolong(p: np.ndarray) -> np.ndarray:
    """Bilinear interpolation of a cell field onto the grid twice as fine."""
    return _prolong_axis(_prolong_axis(p, 0), 1)


def solve_normal(
    gap0: np.ndarray,
    dx: float,
    dy: float | None = None,
    *,
    e_star: float,
    load: float | None = None,
    approach: float | None = None,
    periodic: bool = False,
    hardness: float | None = None,
    initial: np.ndarray | None = None,
    tol: float = 1e-6,
    max_iter: int = 2000,
    precision: str = "mixed",
    nested: bool = True,
    precondition: bool = True,
    workers: int | None = None,
    origin: tuple[float, float] = (0.0, 0.0),
    callback: Callable[[int, float], Any] | None = None,
    strict: bool = True,
    edge: str = "warn",
    stats: SolverStats | None = None,
) -> ContactResult:
    """Solve the normal contact of two rough elastic half-spaces on a regular grid.

    Parameters
    ----------
    gap0 : ndarray, shape (ny, nx)
        Initial gap h (m) between the undeformed surfaces (see the module conventions).
    dx, dy : float
        Cell pitch (m); ``dy`` defaults to ``dx``.
    e_star : float
        Composite modulus E* (Pa).
    load, approach : float
        Exactly one: the total normal load W (N) or the rigid-body approach delta (m).
    periodic : bool
        Periodic domain (else a free boundary: no pressure outside the grid).
    hardness : float, optional
        Pressure cap (Pa) for an elastic-perfectly-plastic contact.
    initial : ndarray, optional
        Warm start: a pressure field on the same grid (e.g. the solution at a nearby load);
        it is rescaled to the load.
    tol : float
        Target residual (see :class:`~contact.result.ContactResult`); 1e-6 gives the
        Hertz maximum pressure to about 1e-6 of discretisation-free accuracy.
    max_iter : int
        Iteration limit of the finest grid.
    precision : {"mixed", "double"}
        "mixed" runs the search-direction FFT in float32 (see the module notes).
    nested : bool
        Start from the solution of a twice coarser grid when no warm start is given.
    precondition : bool
        Precondition the conjugate gradient with the periodic stiffness |q|/2 (the
        approximate inverse of the influence operator; Vollebregt 2014, J. Comput. Phys.
        257:333). Cuts the iterations several-fold for one unpadded FFT pair each.
    workers : int, optional
        Threads for scipy.fft (default: all cores).
    origin : (float, float)
        Coordinates (x, y) of the centre of cell (0, 0), for the result's coordinates.
    callback : callable, optional
        Called as ``callback(iteration, residual)`` after each iteration.
    strict : bool
        Raise :class:`~contact.errors.ConvergenceError` if the tolerance is not reached;
        with ``strict=False`` the result is returned with ``converged=False``.
    edge : {"warn", "ignore"}
        A free-boundary solution with pressure on the outermost cells may be cut short by
        the domain: "warn" issues an :class:`~contact.errors.EdgeContactWarning` and adds a
        note (the result's ``touches_edge`` is set either way). Higher-level callers that
        enlarge the domain themselves pass "ignore".
    stats : SolverStats, optional
        Filled with counters (iterations, FFTs) for diagnostics.

    Returns
    -------
    ContactResult
        ``iterations`` counts the finest grid; ``extra["levels"]`` lists (ny, nx,
        iterations) of every grid solved, coarsest first.
    """
    dy = dx if dy is None else dy
    h = _check_inputs(gap0, dx, dy, e_star, load, approach, hardness)
    if precision not in ("mixed", "double"):
        raise ContactInputError("precision must be 'mixed' or 'double'")
    if edge not in ("warn", "ignore"):
        raise ContactInputError("edge must be 'warn' or 'ignore'")
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    stats = stats if stats is not None else SolverStats()
    ny, nx = h.shape
    hmax = math.inf if hardness is None else float(hardness)

    p_init = None
    if initial is not None:
        p_init = np.array(initial, dtype=float)
        if p_init.shape != h.shape:
            raise ContactInputError(
                f"the warm-start pressure has shape {p_init.shape}, the grid {h.shape}"
            )
        p_init = np.clip(np.nan_to_num(p_init), 0.0, hmax)
        if not p_init.any():
            p_init = None
    elif nested and ny % 2 == 0 and nx % 2 == 0 and min(ny, nx) >= 2 * MIN_COARSE:
        coarse = solve_normal(
            _coarsen(h), 2 * dx, 2 * dy, e_star=e_star, load=load, approach=approach,
            periodic=periodic, hardness=hardness, tol=max(tol, 1e-4), max_iter=max_iter,
            precision=precision, nested=True, precondition=precondition, workers=workers,
            strict=False, edge="ignore", stats=stats,
        )
        if coarse.load > 0:
            p_init = np.clip(prolong(np.asarray(coarse.pressure)), 0.0, hmax)

    try:
        p, u, delta, it, res, ok = _pk_loop(
            h, dx, dy, e_star, load, approach, periodic, hmax, p_init, tol, max_iter,
            precision == "mixed", precondition, workers, callback, stats,
        )
    finally:
        convolution(ny, nx, float(dx), float(dy), bool(periodic)).release()
    stats.levels.append((ny, nx, it))
    stats.iterations = it

    u_m = u / e_star
    g = h + u_m - delta
    if math.isfinite(hmax):
        plastic = np.where(p >= hmax, np.maximum(-g, 0.0), 0.0)
    else:
        plastic = np.zeros_like(p)
    gap = np.maximum(g, 0.0)
    gap[p > 0] = 0.0
    x = origin[0] + np.arange(nx) * dx
    y = origin[1] + np.arange(ny) * dy
    result = build_result(
        pressure=p, gap=gap, displacement=u_m, plastic_displacement=plastic, x=x, y=y,
        dx=dx, dy=dy, e_star=e_star, hardness=hardness, periodic=periodic, approach=delta,
        iterations=it, residual=res, converged=ok,
        extra={"levels": list(stats.levels), "tol": tol, "precision": precision},
    )
    if edge == "warn" and result.touches_edge and not periodic:
        msg = ("contact pressure reaches the edge of the domain: the free-boundary solution "
               "is truncated there; enlarge the domain")
        warnings.warn(msg, EdgeContactWarning, stacklevel=2)
        result = dataclasses.replace(result, notes=(*result.notes, msg))
    if not ok and strict:
        raise ConvergenceError(
            f"the contact solver stopped after {it} iterations at residual {res:.3g} "
            f"(tolerance {tol:.3g}); raise max_iter, loosen tol, or refine the grid",
            residual=res, iterations=it,
        )
    return result


def _pk_loop(h, dx, dy, e_star, load, approach, periodic, hmax, p_init, tol, max_iter,
             single, precondition, workers, callback, stats):
    """The Polonsky-Keer iteration. Returns (p, u*E*, delta, iterations, residual, ok).

    With a finite ``hmax`` (elastic-perfectly-plastic) the steps are made monotone in the
    elastic energy and projected gradient steps are taken where the CG step cannot move
    (see "Elastic-perfectly-plastic contact" in the module notes).
    """
    ny, nx = h.shape
    n = ny * nx
    conv = convolution(ny, nx, float(dx), float(dy), bool(periodic))
    k00 = conv.k00
    da = dx * dy
    load_control = load is not None
    plastic = math.isfinite(hmax)
    # Work in units where E* = 1: hE = E* h, uE = K * p, so that gE = hE + uE - E* delta.
    hE = (h * e_star).ravel()
    target = load / da if load_control else 0.0

    if p_init is not None:
        p = np.ascontiguousarray(p_init, dtype=float).ravel().copy()
    elif load_control:
        p = np.full(n, target / n)
    else:
        pen = np.maximum(e_star * approach - hE, 0.0)
        p = pen / (k00 * math.sqrt(n)) if pen.any() else np.zeros(n)
    s_dir = np.empty(n) if plastic else None
    cand = np.empty(n, dtype=np.int64) if plastic else None
    if load_control:
        total = p.sum()
        p *= target / total
        if plastic:
            # A feasible start (0 <= p <= H, sum p = target): the projection of p, where
            # the points out of contact are ranked by their gap; if the loaded points
            # cannot carry the load at the cap, the pressure goes first to the points
            # that are closest to touching.
            rank = np.where(p > 0, 0.0, hE - hE.min())
            kn.projected_gradient(p, rank, 1.0 / k00, target, hmax, True, s_dir, cand, nx)
            p += s_dir
            np.clip(p, 0.0, hmax, out=p)
    elif plastic:
        np.minimum(p, hmax, out=p)

    def exact(pp: np.ndarray) -> np.ndarray:
        stats.fft_double += 1
        rows = np.nonzero(pp.reshape(ny, nx).any(axis=1))[0]
        if rows.size == 0:
            return np.zeros(n)
        return conv(pp.reshape(ny, nx), (int(rows[0]), int(rows[-1]) + 1),
                    single=False, workers=workers).ravel()

    u = exact(p)
    d = np.empty(n)
    z = np.zeros(n)
    t = np.zeros(n)
    t32 = np.zeros(n, dtype=np.float32 if single else np.float64)
    # a capped point may carry two corrections: one from the step, one from the rescaling
    cidx = np.empty(2 * n if plastic else n, dtype=np.int64)
    cval = np.empty(2 * n if plastic else n)
    dense = np.zeros((ny, nx))
    kernel_real = np.ascontiguousarray(conv.real)
    sparse_limit = max(4, int(SPARSE_FACTOR * math.log2(4 * n)))
    if plastic:
        p_old = np.empty(n)
        u_old = np.empty(n)
        alpha = 1.0 / k00  # projected-gradient step: a cell's pressure closes its own gap
        projected_next = False

    G_old = 1.0
    restart = True
    synced = True
    res_sync = math.inf
    res = math.inf
    it = 0
    stalls = 0
    pbar_prev = target / n if load_control else 0.0
    delta_e = e_star * approach if not load_control else 0.0
    while True:
        s_g, n_free, s_p, n_c = kn.pk_gap_mean(p, u, hE, hmax)
        if load_control:
            if n_free > 0:
                delta_e = s_g / n_free
            elif n_c > 0:  # everything yielded: the rigid body sits at the highest overlap
                delta_e = float(np.max((u + hE)[p > 0]))
        G, viol, nviol = kn.pk_residual(p, u, hE, delta_e, hmax, d)
        pbar = s_p / n_c if n_c > 0 else pbar_prev
        pbar_prev = pbar
        if n_c == 0 and nviol == 0:
            res = 0.0  # approach control short of first contact: nothing touches
        elif pbar > 0:
            res = math.sqrt((G + viol) / max(n_c, 1)) / (k00 * pbar)
        else:
            res = math.inf
        if res <= tol:
            if synced:
                return p.reshape(ny, nx), u.reshape(ny, nx), delta_e / e_star, it, res, True
            u = exact(p)
            synced = True
            res_sync = res
            continue
        if single and not synced and (res < 1e-2 * res_sync):
            u = exact(p)
            synced = True
            res_sync = res
            continue
        if it >= max_iter:
            return p.reshape(ny, nx), u.reshape(ny, nx), delta_e / e_star, it, res, False
        it += 1
        if plastic and (projected_next or n_free == 0):
            # Projected gradient step p <- p + theta (P(p - alpha d) - p): it moves points
            # on and off the cap and into contact all at once, and with the exact line
            # search theta it always lowers the objective unless p is already optimal.
            projected_next = False
            gs, ss, _mu, lo, hi = kn.projected_gradient(p, d, alpha, target, hmax,
                                                       load_control, s_dir, cand, nx)
            if not gs < 0.0:
                # no descent direction: optimal up to the noise of an inexact u
                stalls += 1
                if synced or stalls > 3:
                    return (p.reshape(ny, nx), u.reshape(ny, nx), delta_e / e_star, it,
                            res, False)
                u = exact(p)
                synced = True
                continue
            stats.projected_steps += 1
            stats.fft_single += int(single)
            stats.fft_double += int(not single)
            w = conv(s_dir.reshape(ny, nx), (lo, hi), single=single, workers=workers).ravel()
            sks = float(np.dot(s_dir[lo * nx:hi * nx], w[lo * nx:hi * nx]))
            theta = min(1.0, -gs / sks) if sks > 0 else 1.0
            kn.add_step(p, s_dir, u, w, theta, hmax)
            if sks > 0:
                # Barzilai-Borwein: the inverse Rayleigh quotient of K along the last step
                alpha = ss / sks
            synced = False
            restart = True
            stalls = 0
            if callback is not None:
                callback(it, res)
            continue
        if precondition:
            lo, hi = kn.masked_copy(d, p, hmax, t32, nx)
            zin = conv.precondition(t32.reshape(ny, nx), (lo, hi), single=single,
                                    workers=workers).ravel()
            rho = kn.center_on_free(zin, z, d, p, hmax, load_control)
            beta = 0.0 if restart else rho / G_old
            G_old = rho if rho > 0 else 1.0
            lo, hi = kn.pk_direction(z, p, t, beta, hmax, t32, nx)
        else:
            beta = 0.0 if restart else G / G_old
            G_old = G if G > 0 else 1.0
            lo, hi = kn.pk_direction(d, p, t, beta, hmax, t32, nx)
        stats.fft_single += int(single)
        stats.fft_double += int(not single)
        r = conv(t32.reshape(ny, nx), (lo, hi), single=single, workers=workers).ravel()
        tau, _ = kn.pk_step_length(r, t, d, p, hmax, load_control)
        if not (tau > 0 and math.isfinite(tau)):
            if plastic:
                projected_next = True
                restart = True
                continue
            # Not a descent direction: the conjugacy was lost (a changed contact or plastic
            # set, or float32 noise in the last digits). Restart from steepest descent on
            # an exact displacement; give up if even that cannot make progress.
            if restart:
                stalls += 1
                if stalls > 3:
                    return (p.reshape(ny, nx), u.reshape(ny, nx), delta_e / e_star, it, res,
                            False)
            if not synced:
                u = exact(p)
                synced = True
            restart = True
            continue
        if not plastic:
            stalls = 0
        else:
            np.copyto(p_old, p)
            np.copyto(u_old, u)
        nc, total, entered = kn.pk_update_pressure(p, t, d, tau, hmax, cidx, cval)
        restart = entered > 0
        s = 1.0
        if load_control:
            s, nc = kn.capped_scale(p, target, hmax, cidx, cval, nc)
        kn.axpy_scale(u, r, tau, s)
        if nc:
            if nc <= sparse_limit:
                stats.sparse_corrections += nc
                kn.sparse_convolve_add(u, cidx, cval, nc, kernel_real, nx, periodic)
            else:
                lo_c, hi_c = kn.scatter(dense, cidx, cval, nc, True)
                stats.fft_single += int(single)
                stats.fft_double += int(not single)
                u += conv(dense, (lo_c, hi_c), single=single, workers=workers).ravel()
                kn.scatter(dense, cidx, cval, nc, False)
        synced = False
        if plastic:
            # The CG step, its projection, the entering and released points and the load
            # rescaling together make the step p - p_old; K of it is u - u_old, so the
            # objective along it is known exactly without another convolution.
            gs, sks, total = kn.step_terms(p, p_old, u, u_old, d)
            if (not gs < 0.0 or (load_control and abs(total - target) > 1e-10 * target)
                    or not 0.5 <= s <= 2.0):
                # uphill, a total the rescaling cannot restore (points must enter or leave
                # the cap), or a rescaling that blows up the few free points: undo it and
                # take a projected gradient step instead
                p, p_old = p_old, p
                u, u_old = u_old, u
                projected_next = True
                restart = True
            else:
                stalls = 0
                if sks > 0.0 and -gs < 0.5 * sks:
                    # the full step would raise the objective: stop at its minimiser
                    kn.blend(p, p_old, u, u_old, -gs / sks)
                    stats.damped_steps += 1
                    restart = True
                    projected_next = True
        if callback is not None:
            callback(it, res)
