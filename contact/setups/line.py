"""Line contact (plane strain): a cylinder, or any 2D profile, pressed on a half-plane.

Why a 1D solver rather than the 3D one with a periodic direction: the 3D FFT solver is
periodic in both directions or in neither, so a long cylinder would come with periodic
images along the rolling direction too, whose interaction changes the pressure by
O((a/L)^2) and the load exponent with it. The plane-strain problem is one-dimensional,
small (a few hundred unknowns) and exact: it is solved here directly, with dense influence
coefficients and an active-set iteration.

Conventions (those of :mod:`contact.bem`, in one dimension): cell ``j`` is centred at
``x[j] = x0 + j dx`` and carries a uniform pressure; ``u`` is the combined normal
displacement of both surfaces, positive into the bodies; the deformed gap is
``g = h + u - delta``.

A 2D half-plane has no displacement datum: under a strip pressure the surface
displacement grows like log(distance) (Johnson 1985, *Contact Mechanics*, eq. 2.25b,
sec. 4.3). The influence coefficients below take the displacement as zero one metre from
a unit line load; ``approach`` is measured against that datum, so only differences of
``displacement`` and ``approach`` are physical.

Influence coefficient of a uniform pressure on cell j at the centre of cell i
(Johnson eq. 2.25b integrated over the cell)::

    K_ij = -(2 / (pi E*)) [F(d + dx/2) - F(d - dx/2)],  F(v) = v ln|v| - v,  d = x_i - x_j
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._validate import frozen, positive
from contact.errors import ContactInputError, ConvergenceError
from contact.hertz import hertz_cylinder
from contact.record import SolveRecord, edge_contact, edge_warning


def _prim(v: np.ndarray) -> np.ndarray:
    """F(v) = v ln|v| - v (0 at v = 0)."""
    av = np.abs(v)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(av > 0, v * np.log(np.where(av > 0, av, 1.0)) - v, 0.0)
    return out


def line_column(d: np.ndarray, dx: float) -> np.ndarray:
    """Displacement at offsets ``d`` (m) from a uniform-pressure cell of width ``dx`` on a
    half-plane, E* = 1 (m per Pa; the datum of the module notes)."""
    return -(2.0 / math.pi) * (_prim(d + dx / 2) - _prim(d - dx / 2))


def line_influence(n: int, dx: float) -> np.ndarray:
    """Dense (n, n) influence matrix of a uniform-pressure cell on a half-plane, E* = 1.

    ``u = K @ p`` gives the combined displacement (m per Pa of pressure, times 1/E*).
    """
    if n < 1 or not (math.isfinite(dx) and dx > 0):
        raise ContactInputError("the line grid needs n >= 1 cells of positive pitch")
    col = line_column(np.arange(n) * dx, dx)
    idx = np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])
    return col[idx]


def solve_active_set(A: np.ndarray, h: np.ndarray, weight: float, target: float,
                     active: np.ndarray, tol: float,
                     max_iter: int) -> tuple[np.ndarray, float, int] | None:
    """Dense active-set solution of a line contact under a load: p >= 0, gap >= 0.

    On the contact set the pressures and the approach solve ``h + A p - delta = 0`` with
    ``weight * sum(p) = target``; cells with negative pressure leave the set, cells whose
    gap is below ``-tol`` enter it, until neither happens. ``active`` (bool, changed in
    place) is the starting set. Returns (p, delta, iterations), or None when the set has
    not settled after ``max_iter`` steps.
    """
    n = h.size
    p = np.zeros(n)
    for it in range(1, max_iter + 1):
        idx = np.flatnonzero(active)
        m = idx.size
        M = np.empty((m + 1, m + 1))
        M[:m, :m] = A[np.ix_(idx, idx)]
        M[:m, m] = -1.0
        M[m, :m] = weight
        M[m, m] = 0.0
        rhs = np.empty(m + 1)
        rhs[:m] = -h[idx]
        rhs[m] = target
        sol = np.linalg.solve(M, rhs)
        p[:] = 0.0
        p[idx] = sol[:m]
        delta = float(sol[m])
        neg = idx[sol[:m] < 0]
        if neg.size:
            active[neg] = False
            if not active.any():  # pragma: no cover - cannot happen with a positive load
                active[int(np.argmin(h))] = True
            continue
        enter = (~active) & (h + A @ p - delta < -tol)
        if not enter.any():
            return p, delta, it
        active |= enter
    return None


@dataclass(frozen=True, eq=False)
class LineContactResult:
    """Solution of a plane-strain line contact (all SI, per unit length along the line).

    Attributes
    ----------
    x : ndarray
        Cell centres (m).
    pressure : ndarray
        Contact pressure p (Pa).
    displacement : ndarray
        Combined normal displacement u (m), positive into the bodies, against the datum of
        the module notes (only differences are physical).
    gap : ndarray
        Deformed gap (m), 0 in contact.
    dx, e_star : float
        Pitch (m), composite modulus (Pa).
    load : float
        Load per unit length W' (N/m).
    approach : float
        delta in g = h + u - delta, against the same datum as ``displacement``.
    pmax : float
        Peak pressure (Pa).
    half_width : float
        Half the extent of the contact (m): (last - first contact cell + 1) dx / 2.
    centre : float
        Mid-point of the contact extent (m).
    iterations : int
        Active-set iterations.
    solve : SolveRecord
        The solve record (:mod:`contact.record`): the residual is the largest gap error
        (gap on the contact set, interpenetration off it) over the range of the gap.
    hertz : HertzCylinder or None
        The Hertz solution of the same load, when the problem is a cylinder.
    """

    x: np.ndarray
    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    dx: float
    e_star: float
    load: float
    approach: float
    pmax: float
    half_width: float
    centre: float
    iterations: int
    solve: SolveRecord
    hertz: Any = None
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def touches_edge(self) -> bool:
        """Pressure on the first or last cell (the record's ``edge_contact``): the domain
        may cut the contact short."""
        return self.solve.edge_contact


def active_set_record(method: str, gap: np.ndarray, active: np.ndarray, h: np.ndarray,
                      iterations: int, edge: bool) -> SolveRecord:
    """The record of a settled :func:`solve_active_set`: the residual is the largest gap
    error (|gap| on the set, interpenetration off it) over the range of ``h``, against the
    1e-12 the set is settled to."""
    err = np.where(active, np.abs(gap), np.maximum(-gap, 0.0))
    return SolveRecord(method=method, iterations=int(iterations),
                       residual=float(err.max()) / max(float(np.ptp(h)), 1e-300),
                       tolerance=1e-12, converged=True, edge_contact=bool(edge),
                       residual_definition="largest gap error over the range of the gap")


def solve_line(
    gap0: np.ndarray,
    dx: float,
    *,
    e_star: float,
    load: float,
    origin: float = 0.0,
    max_iter: int = 200,
) -> LineContactResult:
    """Frictionless normal contact of two plane-strain bodies with initial gap ``gap0``.

    Active-set method: on the current contact set the pressures and the approach solve
    ``h + K p - delta = 0`` with ``sum(p) dx = W'``; cells with negative pressure leave
    the set, cells that interpenetrate enter it, until neither happens. Each step is a
    dense solve of the contact set (exact, no tolerance to choose).

    Parameters
    ----------
    gap0 : ndarray, shape (n,)
        Initial gap h (m), e.g. x^2/(2R) minus a roughness profile.
    dx : float
        Cell pitch (m).
    e_star : float
        Composite modulus E* (Pa).
    load : float
        Load per unit length W' (N/m).
    origin : float
        x of the centre of cell 0 (m).
    max_iter : int
        Active-set iteration limit.

    Raises
    ------
    ContactInputError
        Bad gap, pitch, modulus or load.
    ConvergenceError
        The active set did not settle.
    """
    h = np.asarray(gap0, dtype=float)
    if h.ndim != 1 or h.size < 2 or not np.isfinite(h).all():
        raise ContactInputError("the line gap must be a finite 1D array of at least 2 cells")
    dx = positive(dx, "dx", "m")
    e_star = positive(e_star, "E*", "Pa")
    load = positive(load, "the load per length", "N/m")
    n = h.size
    K = line_influence(n, dx) / e_star
    active = np.zeros(n, dtype=bool)
    active[int(np.argmin(h))] = True
    tol = 1e-12 * max(float(np.ptp(h)), 1e-12) + 1e-15
    found = solve_active_set(K, h, 1.0, load / dx, active, tol, max_iter)
    if found is None:
        raise ConvergenceError(
            f"the line-contact active set did not settle in {max_iter} iterations; refine the "
            "grid or smooth the profile", iterations=max_iter,
        )
    p, delta, it = found
    u = K @ p
    gap = np.maximum(h + u - delta, 0.0)
    gap[active] = 0.0
    record = active_set_record("plane-strain active set", h + u - delta, active, h, it,
                               edge_contact(p))
    edge_warning(record.edge_contact)
    x = origin + np.arange(n) * dx
    on = np.flatnonzero(p > 0)
    lo, hi = (x[on[0]], x[on[-1]]) if on.size else (math.nan, math.nan)
    return LineContactResult(
        x=frozen(x), pressure=frozen(p), displacement=frozen(u), gap=frozen(gap),
        dx=float(dx), e_star=float(e_star), load=float(p.sum() * dx),
        approach=delta, pmax=float(p.max()),
        half_width=0.5 * (hi - lo + dx) if on.size else 0.0,
        centre=0.5 * (hi + lo) if on.size else math.nan, iterations=it, solve=record,
    )


def solve_cylinder(
    radius: float,
    load: float,
    e_star: float,
    *,
    n: int = 1024,
    size: float | None = None,
    roughness: np.ndarray | None = None,
    roughness_dx: float | None = None,
) -> LineContactResult:
    """A cylinder (axis along y) of radius R on a flat, load W' per unit length.

    Parameters
    ----------
    radius : float
        R (m).
    load : float
        W' (N/m).
    e_star : float
        E* (Pa).
    n : int
        Cells across the domain.
    size : float, optional
        Domain width (m); default 2.5 Hertz contact widths (5 a).
    roughness : ndarray, optional
        Composite roughness profile (m, closes the gap: h = x^2/(2R) - z), sampled at
        ``roughness_dx`` and centred on the cylinder's axis; resampled onto the grid.
    roughness_dx : float, optional
        Pitch of the roughness profile (m).
    """
    radius = positive(radius, "the cylinder's radius", "m")
    load = positive(load, "the cylinder's load", "N/m")
    e_star = positive(e_star, "the cylinder's E*", "Pa")
    if int(n) < 8:
        raise ContactInputError("the line grid needs at least 8 cells")
    hz = hertz_cylinder(radius, load, e_star)
    side = 5.0 * hz.a if size is None else positive(size, "the domain size", "m")
    n = int(n)
    dx = side / n
    x = (np.arange(n) - n // 2) * dx
    h = x**2 / (2.0 * radius)
    if roughness is not None:
        z = np.asarray(roughness, dtype=float)
        if z.ndim != 1 or not np.isfinite(z).all():
            raise ContactInputError("the roughness profile must be a finite 1D array")
        if not (roughness_dx and roughness_dx > 0):
            raise ContactInputError("give the roughness profile's pitch roughness_dx")
        xs = (np.arange(z.size) - (z.size - 1) / 2) * roughness_dx
        if x[0] < xs[0] or x[-1] > xs[-1]:
            raise ContactInputError("the roughness profile is shorter than the domain")
        h = h - np.interp(x, xs, z)
    res = solve_line(h - h.min(), dx, e_star=e_star, load=load, origin=float(x[0]))
    import dataclasses

    return dataclasses.replace(res, hertz=hz, extra={"radius": float(radius)})
