"""Result of a steady viscoelastic rolling solve (2D line contact or 3D point contact)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact._grid import Grid
from contact._record import SolveRecord
from contact._validate import frozen as _frozen


def frozen(a: np.ndarray) -> np.ndarray:
    """A read-only contiguous float copy (:func:`contact._validate.frozen`)."""
    return _frozen(a, copy=True, dtype=float)


@dataclass(frozen=True, eq=False)
class RollingResult:
    """Steady rolling on a viscoelastic body (SI; a line contact is per unit length).

    The contact moves towards +x over the viscoelastic body: material enters at the
    leading edge (large x) and leaves at the trailing edge.

    Attributes
    ----------
    grid : Grid
        The cells (:class:`contact._grid.Grid`, without its gap): ``x`` the centres along
        the rolling direction (m), ``y`` across it (m; None for a line contact).
    pressure : ndarray
        p (Pa), shape (n,) or (ny, nx).
    displacement : ndarray
        Combined normal surface displacement u (m), positive into the bodies (2D: against
        the 1 m datum of :mod:`contact.line`; only differences are physical).
    gap : ndarray
        Deformed gap h + u - approach (m); 0 in contact.
    approach : float
        Rigid-body approach delta (m).
    load : float
        N (N) or W' (N/m for a line contact).
    radius : float or None
        Radius R of the ball or cylinder (m), where the geometry has one.
    speed : float
        Rolling speed V (m/s).
    leading, trailing : float
        Contact edges on the line y = 0 (m), sub-cell estimates from p^2 ~ distance.
    rolling_resistance : float
        mu_r = (moment of the pressure about the axis, x p summed) / (N R): the resisting
        force over the load for a rigid or elastic roller (nan without a radius).
    solve : SolveRecord
        The solve record (:mod:`contact._record`): active-set iterations and the largest
        gap error (2D); outer fixed-point iterations and the last relative change of the
        pressure (3D).
    gap_residual : float
        Largest gap on the contact over the range of the initial gap there.
    inner_iterations : int
        Iterations of the last elastic (BEM) solve inside the outer loop (3D; 0 in 2D).
    """

    grid: Grid
    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    approach: float
    load: float
    radius: float | None
    speed: float
    leading: float
    trailing: float
    rolling_resistance: float
    solve: SolveRecord
    gap_residual: float
    inner_iterations: int = 0

    @property
    def iterations(self) -> int:
        """Active-set (2D) or outer (3D) iterations (the solve record's)."""
        return self.solve.iterations

    @property
    def pmax(self) -> float:
        """Largest cell pressure (Pa)."""
        return float(np.max(self.pressure))

    @property
    def x(self) -> np.ndarray:
        """Cell centres along the rolling direction (m), read-only."""
        return self.grid.x

    @property
    def y(self) -> np.ndarray | None:
        """Cell centres across the rolling direction (m); None for a line contact."""
        return None if self.grid.line else self.grid.y

    @property
    def line(self) -> bool:
        """True for a plane-strain line contact."""
        return self.grid.line

    @property
    def pressure_offset(self) -> float:
        """x of the pressure's centroid (m): ahead of the axis when positive."""
        p = np.asarray(self.pressure)
        px = p if p.ndim == 1 else p.sum(axis=0)
        return float((px * self.x).sum() / px.sum())


def edges_1d(x: np.ndarray, p: np.ndarray) -> tuple[float, float]:
    """(trailing, leading) edges of the pressed band of a 1D pressure row.

    Near a smooth edge p^2 falls linearly with the distance to it, so the edge is
    extrapolated from the two outermost loaded cells (clamped to within one cell).
    """
    on = np.flatnonzero(p > 0)
    if on.size == 0:
        return float("nan"), float("nan")
    dx = float(x[1] - x[0]) if x.size > 1 else 0.0
    i0, i1 = int(on[0]), int(on[-1])

    def extrap(i_edge: int, i_in: int) -> float:
        if i_in < 0 or i_in >= p.size or p[i_in] <= p[i_edge]:
            return 0.5 * dx
        q0, q1 = p[i_edge] ** 2, p[i_in] ** 2
        return float(np.clip(q0 / (q1 - q0) * dx, 0.0, dx))

    return float(x[i0] - extrap(i0, i0 + 1)), float(x[i1] + extrap(i1, i1 - 1))
