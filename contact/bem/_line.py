"""The plane-strain (line-contact) normal solve: the one home of it in the package.

A line contact (a cylinder, a roller, any 2D profile on a half-plane) is one-dimensional
and small (a few hundred to a few thousand unknowns), so it is solved exactly: dense
influence coefficients and an active-set iteration, each step a direct solve of the
current contact set. :func:`contact.setups._line.solve_line`, the plane-strain normal
problem of the tangential solver (:func:`contact.tangential._normal.solve_pressure`) and
the viscoelastic line contact (:mod:`contact.viscoelastic._line`) all use it.

Conventions (those of :mod:`contact.bem`, in one dimension): cell ``j`` carries a uniform
pressure; ``u`` is the combined normal displacement of both surfaces, positive into the
bodies; the deformed gap is ``g = h + u - delta``; p >= 0, g >= 0, p g = 0, and the load
per unit length is ``sum(p) dx``.

A 2D half-plane has no displacement datum: under a strip pressure the surface
displacement grows like log(distance) (Johnson 1985, *Contact Mechanics*, eq. 2.25b,
sec. 4.3). The influence coefficients take the displacement as zero one metre from a unit
line load; ``delta`` is measured against that datum, so only differences of displacement
and approach are physical.

Influence coefficient of a uniform pressure on cell j at the centre of cell i (Johnson
eq. 2.25b integrated over the cell; the strip integral of
:mod:`contact.halfspace.plane_strain`, whose :class:`~contact.halfspace.plane_strain.StripOperator`
is the operator solved here)::

    K_ij = -(2 / (pi E*)) [F(d + dx/2) - F(d - dx/2)],  F(v) = v ln|v| - v,  d = x_i - x_j
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from contact._errors import ConvergenceError
from contact._record import SolveRecord
from contact.halfspace.plane_strain import StripOperator


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


@lru_cache(maxsize=2)
def _scaled_influence(n: int, dx: float, e_star: float) -> np.ndarray:
    # a rolling solve asks for the same grid's matrix at every coupling step; read-only
    K = StripOperator(n, dx).matrix / e_star
    K.setflags(write=False)
    return K


@dataclass(frozen=True, eq=False)
class LineSolve:
    """A solved plane-strain normal contact (per unit length along the line).

    Attributes
    ----------
    pressure : ndarray
        p (Pa) on each cell.
    approach : float
        delta (m), against the datum of the module notes.
    iterations : int
        Active-set steps.
    active : ndarray
        The final contact set (bool).
    influence : ndarray
        The dense influence matrix used, with 1/E* in it (m/Pa).
    """

    pressure: np.ndarray
    approach: float
    iterations: int
    active: np.ndarray
    influence: np.ndarray


def solve_line_pressure(h: np.ndarray, dx: float, e_star: float, load: float, *,
                        start: np.ndarray | None = None, max_iter: int = 200) -> LineSolve:
    """Pressure and approach of a plane-strain contact under a load per unit length.

    Parameters
    ----------
    h : ndarray, shape (n,)
        Undeformed separation (m), finite.
    dx : float
        Cell pitch (m).
    e_star : float
        Composite modulus E* (Pa).
    load : float
        Load per unit length W' (N/m), positive.
    start : ndarray, optional
        A previous pressure: its support is the starting contact set (a warm start);
        default the lowest cell.
    max_iter : int
        Active-set step limit.

    Raises
    ------
    ConvergenceError
        The active set did not settle in ``max_iter`` steps.
    """
    n = h.size
    K = _scaled_influence(n, float(dx), float(e_star))
    active = np.zeros(n, dtype=bool)
    if start is not None and np.any(start > 0):
        active[np.asarray(start).reshape(-1) > 0] = True
    else:
        active[int(np.argmin(h))] = True
    # gaps below this are round-off of the solve, not interpenetration
    tol = 1e-12 * max(float(np.ptp(h)), 1e-12) + 1e-15
    found = solve_active_set(K, h, 1.0, load / dx, active, tol, max_iter)
    if found is None:
        raise ConvergenceError(
            f"the line-contact active set did not settle in {max_iter} iterations; refine the "
            "grid or smooth the profile", iterations=max_iter,
        )
    p, delta, it = found
    return LineSolve(pressure=p, approach=delta, iterations=it, active=active, influence=K)


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
