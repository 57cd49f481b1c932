"""Steady rolling on a viscoelastic half-space in 3D, on a regular grid (FFT boundary elements).

Operator. Cell (i, j) carries a uniform pressure; on a half-space of unit compliance it
makes the surface displacement K(x, y) of Love's rectangle (Johnson 1985, *Contact
Mechanics*, eq. 3.25; :func:`contact.halfspace.influence.love_coefficients`),
and w = K * p is the free-boundary FFT convolution of :mod:`contact.halfspace.convolution`
on the grid extended ahead. The contact moves at V
towards +x; with the pair's creep series (:mod:`contact.viscoelastic._rheology`) the
displacement is the steady-state hereditary integral along x (Carbone & Putignano 2013,
J. Mech. Phys. Solids 61:1822, eq. 10; Persson 2010, Eur. Phys. J. E 33:327):

    u = C_g w + sum_m dC_m F_m,   F_m(x, y) = (1/l_m) int_0^inf e^{-xi/l_m} w(x + xi, y) dxi,

l_m = V theta_m. F_m is the exact recursive filter of :mod:`contact.viscoelastic._kernels`
for w linear between nodes. It needs w ahead of the grid: w is evaluated on the grid
extended ahead by ``ahead`` times its length, and beyond that by the monopole decay
w ~ 1/r from the pressure centroid (Gauss-Laguerre quadrature of the tail).

Solution. The operator is not symmetric, so the elastic energy minimisation behind the
normal solver does not apply. With C_e = (C_g + C_r)/2 the problem is split as

    h + (u(p) - C_e w(p)) + C_e w(p) - delta >= 0, ...

and iterated: each step is one elastic, load-controlled normal solve
(:func:`contact.bem.solve_normal`, E* = 1/C_e, warm-started) on the gap h corrected by the
lagged non-elastic part. Along x, u - C_e w has the symbol L(k) - C_e with
L(k) = C_g + sum dC_m/(1 + i k l_m) on a disc about C_e, so for one relaxation
the linear iteration contracts by (C_r - C_g)/(C_r + C_g) per step; Anderson mixing
(Walker & Ni 2011, SIAM J. Numer. Anal. 49:1715) of the last few pressures cuts the number
of steps to a handful. The fixed point satisfies the viscoelastic contact conditions
exactly (the residual is reported).

Cost. Three things keep a strongly relaxing solid (E_g/E_r = 3) near five normal solves:
the outer iteration starts from the rolling solution of the twice coarser grid, solved
recursively to 1e-2 and interpolated (as the normal solver nests its own start); the
splitting is inexact, each elastic solve tightened only to a hundredth of the last outer
change (a loose inner solve where the outer iterate is still far off, tol at the end); and
the x-transforms of w = K * p run only over the rows that carry pressure.
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np

from contact._errors import ContactInputError, ConvergenceError, EdgeContactWarning
from contact._grid import Grid, scan_grid
from contact._record import SolveRecord, edge_contact, edge_warning
from contact._validate import positive
from contact.halfspace.convolution import Convolution
from contact.viscoelastic._kernels import creep_filter_rows
from contact.viscoelastic._result import RollingResult, edges_1d, frozen
from contact.viscoelastic._rheology import CreepSeries
from contact.viscoelastic._window import sphere_window

_LAGUERRE = np.polynomial.laguerre.laggauss(32)


def monopole_tail(x_end: float, x_centre: float, dy: np.ndarray, ell: float) -> np.ndarray:
    """The creep filter's tail beyond the last column, per unit displacement there.

    Beyond the grid extended ahead, a displacement decays as the monopole 1/r from the
    load centre, so for each row (offset ``dy`` from the centre along y)
    (1/l) int_0^inf e^{-xi/l} w(x_e + xi) dxi = w(x_e) * (1/l) int e^{-xi/l} r_e/r(xi) dxi,
    computed by 32-point Gauss-Laguerre quadrature (``x_end``, ``x_centre``: x of the last
    column and of the centre, m; ``ell`` = V theta, m).
    """
    lag_x, lag_w = _LAGUERRE
    re = np.hypot(x_end - x_centre, dy)
    r = np.hypot(x_end + ell * lag_x[None, :] - x_centre, dy[:, None])
    return (re[:, None] / r) @ lag_w


class RollingOperator:
    """u(p) of a pressure grid (ny, nx) rolling towards +x (see the module notes).

    Parameters
    ----------
    ny, nx : int
        Grid shape.
    dx, dy : float
        Cell pitch (m).
    creep : CreepSeries
        The pair's creep series.
    speed : float
        V (m/s).
    ahead : float
        Extension of the evaluation grid ahead, in grid lengths.
    """

    def __init__(self, ny: int, nx: int, dx: float, dy: float, creep: CreepSeries,
                 speed: float, ahead: float = 0.5):
        self.ny, self.nx, self.dx, self.dy = ny, nx, dx, dy
        self.creep, self.speed = creep, speed
        self.m = math.ceil(ahead * nx) if creep.amplitudes else 0
        self._conv = Convolution(ny, nx, dx, dy, periodic=False, ahead=self.m)

    def elastic(self, p: np.ndarray) -> np.ndarray:
        """w = K * p on the grid extended ahead, shape (ny, nx + m) (unit compliance)."""
        # the transforms along x run only over the rows that carry pressure (forward) and
        # the rows kept (inverse): the zero padding in y would double their cost
        rows = np.nonzero(p.any(axis=1))[0]
        if rows.size == 0:
            return np.zeros((self.ny, self.nx + self.m))
        return self._conv(p, rows=(int(rows[0]), int(rows[-1]) + 1), workers=1)

    def _tail(self, w: np.ndarray, p: np.ndarray, ell: float) -> np.ndarray:
        """F at the last extended column from the monopole decay of w beyond it."""
        tot = p.sum()
        xs = np.arange(self.nx) * self.dx
        ys = np.arange(self.ny) * self.dy
        xc = float((p.sum(axis=0) * xs).sum() / tot) if tot > 0 else 0.0
        yc = float((p.sum(axis=1) * ys).sum() / tot) if tot > 0 else 0.0
        return w[:, -1] * monopole_tail((self.nx + self.m - 1) * self.dx, xc, ys - yc, ell)

    def apply(self, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(u, w) on the (ny, nx) grid: viscoelastic and unit-compliance displacement (m, m Pa)."""
        w = self.elastic(p)
        u = self.creep.glassy * w
        for dc, th in zip(self.creep.amplitudes, self.creep.times):
            ell = self.speed * th
            f = creep_filter_rows(np.ascontiguousarray(w), self._tail(w, p, ell), self.dx, ell)
            u = u + dc * f
        return u[:, : self.nx], w[:, : self.nx]


def _anderson(xs: list[np.ndarray], gs: list[np.ndarray]) -> np.ndarray:
    """Anderson-mixed next iterate from the history of inputs x_k and outputs G(x_k)."""
    f = [g - x for x, g in zip(xs, gs)]
    if len(f) < 2:
        return gs[-1]
    df = np.stack([(f[k + 1] - f[k]).ravel() for k in range(len(f) - 1)], axis=1)
    dg = np.stack([(gs[k + 1] - gs[k]).ravel() for k in range(len(f) - 1)], axis=1)
    gamma, *_ = np.linalg.lstsq(df, f[-1].ravel(), rcond=None)
    return gs[-1] - (dg @ gamma).reshape(gs[-1].shape)


def solve_surface(grid: Grid, load: float, creep: CreepSeries, speed: float, *,
                  radius: float | None = None, tol: float = 1e-6, max_outer: int = 60,
                  memory: int = 5, ahead: float = 0.5, nested: bool = True) -> RollingResult:
    """Steady rolling point contact on a viscoelastic half-space.

    Parameters
    ----------
    grid : Grid
        A free (not periodic, not line) :class:`contact._grid.Grid` of at least 8 x 8 cells
        with the undeformed gap ``h`` (m): for a ball, (x^2 + y^2)/(2R) minus the
        composite roughness. Its pitch and the centre of cell (0, 0) place the grid.
    load : float
        N (N).
    creep : CreepSeries
        The pair's creep series.
    speed : float
        V (m/s), the contact moving towards +x.
    radius : float, optional
        Ball radius (m), for the rolling-resistance coefficient (moment about x = 0).
    tol : float
        Stop when the pressure changes by less than tol * pmax in a step.
    max_outer, memory : int
        Step limit and Anderson history length.
    ahead : float
        Extension of the operator's evaluation grid ahead, in grid lengths.
    nested : bool
        Start from the rolling solution of a twice coarser grid (recursively), which
        saves about a third of the outer steps of a strongly relaxing solid.
    """
    from contact.bem import solve_normal
    from contact.bem._options import SolveOptions

    h = _gap_of(grid)
    v = positive(speed, "the rolling speed", "m/s")
    W = positive(load, "the load", "N")
    dx = positive(grid.dx, "the cell pitch", "m")
    dy = positive(grid.dy, "the cell pitch dy", "m")
    ny, nx = h.shape
    op = RollingOperator(ny, nx, dx, dy, creep, v, ahead)
    ce = 0.5 * (creep.glassy + creep.relaxed)

    def step(p_in: np.ndarray, warm: np.ndarray | None, inner: float) -> tuple[np.ndarray, Any]:
        u, w = op.apply(p_in)
        opts = SolveOptions(tol=inner, nested=warm is None, edge="ignore", strict=False)
        res = solve_normal(grid.with_gap(h + (u - ce * w)), e_star=1.0 / ce, load=W,
                           options=opts, initial=warm)
        return np.asarray(res.pressure, dtype=float), res

    p0 = _coarse_start(grid, W, creep, v, tol, ahead) if nested else None
    p, res = step(np.zeros_like(h) if p0 is None else p0, p0, tol)
    xs, gs = [], []
    x_in, change = p, 1.0
    it, inner, done = 0, tol, False
    while it < max_outer:
        it += 1
        # the mixed iterate predicts the next pressure better than the last one does
        g, res = step(x_in, np.clip(x_in, 0.0, None), inner)
        change = float(np.abs(g - p).max()) / max(float(g.max()), 1e-300)
        xs.append(x_in)
        gs.append(g)
        del xs[:-memory], gs[:-memory]
        p = g
        done = (change < tol and inner <= tol) or not creep.amplitudes
        if done:
            break
        # inexact splitting: the next elastic solve only as tight as this change asks
        # for (a hundredth of it), down to tol for the last steps
        inner = max(tol, min(1e-3, 0.01 * change))
        x_in = _anderson(xs, gs)
    if not done:
        raise ConvergenceError(f"viscoelastic rolling: pressure still changing by {change:.2g} "
                               f"of pmax after {max_outer} steps", residual=change,
                               iterations=max_outer)
    return _result(op, grid, p, res, W, radius, v, it, change, tol)


def _gap_of(grid: Grid) -> np.ndarray:
    """The grid's gap, checked: a finite (ny, nx) array of at least 8 x 8 on a free grid."""
    if not isinstance(grid, Grid) or grid.h is None:
        raise ContactInputError("viscoelastic rolling needs a contact._grid.Grid with its gap h")
    if grid.line or grid.periodic:
        raise ContactInputError("viscoelastic rolling in 3D needs a free grid (neither a line "
                                "contact nor periodic)")
    h = np.asarray(grid.h, dtype=float)
    if min(h.shape) < 8 or not np.all(np.isfinite(h)):
        raise ContactInputError("the heights must be a finite 2D array of at least 8 x 8")
    return h


def _coarse_start(grid: Grid, W: float, creep: CreepSeries, v: float, tol: float,
                  ahead: float) -> np.ndarray | None:
    """The rolling pressure of the twice coarser grid, interpolated; None where none helps.

    The discretisation difference between the grids (a few per cent of pmax at the
    contact edges) dominates the start's error, so a loose coarse tolerance suffices.
    """
    from contact._nesting import coarse_grid, prolong

    half = coarse_grid(grid) if creep.amplitudes else None
    if half is None:
        return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", EdgeContactWarning)
            coarse = solve_surface(half, W, creep, v, tol=max(tol, 1e-2), ahead=ahead)
    except (ContactInputError, ConvergenceError):
        return None  # the fine solve starts from scratch and reports its own trouble
    if coarse.solve.edge_contact:
        return None  # a truncated start: the fine solve reports the edge itself
    return np.clip(prolong(np.asarray(coarse.pressure)), 0.0, None)


def _result(op: RollingOperator, grid: Grid, p: np.ndarray, res: Any, W: float,
            radius: float | None, v: float, it: int, change: float,
            tol: float) -> RollingResult:
    h = np.asarray(grid.h, dtype=float)
    u, _ = op.apply(p)
    delta = float(res.approach)
    gap = h + u - delta
    on = p > 0
    scale = max(float(np.ptp(h[on])) if on.any() else 0.0, 1e-300)
    resid = float(np.abs(gap[on]).max()) / scale if on.any() else 0.0
    x, y = np.asarray(grid.x, dtype=float), np.asarray(grid.y, dtype=float)
    record = SolveRecord(method="viscoelastic rolling (fixed point on the normal BEM)",
                         iterations=it, residual=change, tolerance=tol, converged=True,
                         edge_contact=edge_contact(p),
                         residual_definition="last relative change of the pressure")
    edge_warning(record.edge_contact, stacklevel=4)
    row = int(np.argmin(np.abs(y)))
    trailing, leading = edges_1d(x, p[row])
    mu = float((p.sum(axis=0) * x).sum() * op.dx * op.dy / (W * radius)) if radius else \
        float("nan")
    cells = Grid(x=frozen(x), y=frozen(y), pitch=(op.dx, op.dy))
    return RollingResult(grid=cells, pressure=frozen(p), displacement=frozen(u),
                         gap=frozen(np.where(on, 0.0, np.maximum(gap, 0.0))), approach=delta,
                         load=W, radius=radius, speed=v, leading=leading, trailing=trailing,
                         rolling_resistance=mu, solve=record, gap_residual=resid,
                         inner_iterations=int(res.iterations))


def rolling_sphere(radius: float, load: float, creep: CreepSeries, speed: float, *,
                   n: int = 128, half_width: float | None = None,
                   roughness: np.ndarray | None = None, **kw: Any) -> RollingResult:
    """A ball of radius R rolling at V under N (smooth, or with a roughness map (n, n), m).

    The square grid spans +-``half_width`` (default 1.6 relaxed Hertz radii).
    """
    R = positive(radius, "the radius", "m")
    W = positive(load, "the load", "N")
    L = half_width if half_width is not None else sphere_window(W, R, creep.relaxed)
    dx = 2.0 * L / n
    # cell centres as origin + j dx (not contact._grid.centres' -L + (j + 1/2) dx, which
    # differs in the last bit and moved answers by 1e-11)
    x0 = -L + dx / 2
    grid = scan_grid((n, n), dx, dx, origin=(x0, x0))
    x = grid.x
    h = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * R)
    if roughness is not None:
        z = np.asarray(roughness, dtype=float)
        if z.shape != h.shape:
            raise ContactInputError(f"the roughness map must have shape {h.shape}")
        h = h - z
    return solve_surface(grid.with_gap(h), W, creep, speed, radius=R, **kw)
