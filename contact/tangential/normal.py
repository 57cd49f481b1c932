"""The normal contact problem on the tangential solver's grid, with an extra gap.

For dissimilar bodies the tangential tractions displace the surfaces normally
(u_n = A_nt q, :mod:`contact.halfspace.pair`), so the pressure has to be solved
again with that displacement added to the gap; this module does it with the same
influence operator as the tangential problem, so that the two stay consistent.

Conventions as :mod:`contact.bem`: h is the separation of the undeformed surfaces
(positive apart), u the combined normal displacement (positive into the bodies), the
deformed gap h + u - delta >= 0, p >= 0, p (h + u - delta) = 0, and the load sum(p) dA.

Algorithm: in 3D the package's normal solver (:func:`contact.bem.solve_normal`: the same
Love influence coefficients, preconditioned conjugate gradients), warm-started from the
previous pressure; in plane strain, whose kernel it does not hold, Polonsky & Keer
(1999, Wear 231:206) constrained conjugate gradients, load controlled, with the FFT
products of this grid's operator.
"""

from __future__ import annotations

import numpy as np

from contact.errors import ContactInputError, ConvergenceError
from contact.halfspace.pair import HalfSpacePair


def _initial(h: np.ndarray, load: float, area: float) -> np.ndarray:
    # a paraboloid guess: pressure where h is within its lowest quarter, scaled
    hmin, hmax = float(h.min()), float(np.percentile(h, 50))
    p = np.clip(hmin + 0.5 * (hmax - hmin) - h, 0.0, None)
    if not np.any(p > 0):
        p = np.ones_like(h)
    return p * load / (p.sum() * area)


def solve_pressure(
    op: HalfSpacePair,
    h: np.ndarray,
    load: float,
    *,
    extra: np.ndarray | None = None,
    start: np.ndarray | None = None,
    tol: float = 1e-10,
    max_iter: int = 5000,
) -> tuple[np.ndarray, float]:
    """Pressure p and approach delta for the load ``load`` (N, or N/m in plane strain).

    Parameters
    ----------
    op : HalfSpacePair
        The grid's influence operator.
    h : ndarray, shape (ny, nx)
        Undeformed separation (m).
    load : float
        Total normal force (N; N/m for a line contact).
    extra : ndarray, optional
        A further normal displacement (m) added to the gap (the tangential tractions').
    start : ndarray, optional
        Warm start pressure.
    tol : float
        Relative change of the pressure at which to stop.
    max_iter : int
        Iteration limit.

    Raises
    ------
    ConvergenceError
        If the tolerance is not reached in ``max_iter`` iterations.
    """
    if not (np.isfinite(load) and load > 0):
        raise ContactInputError("normal load must be a positive number of newtons")
    if not op.line:
        return _solve_3d(op, h if extra is None else h + extra, load, start)
    area = op.dx * (1.0 if op.line else op.dy)
    hh = h if extra is None else h + extra
    p = _initial(hh, load, area) if start is None else start * load / (start.sum() * area)
    t = np.zeros_like(p)
    g_old, delta_flag = 1.0, 0.0
    for _ in range(max_iter):
        gap = hh + op.normal(p)
        con = p > 0
        gbar = gap[con].mean()
        gap = gap - gbar
        gsum = float(np.sum(gap[con] ** 2))
        t = np.where(con, gap + delta_flag * (gsum / g_old) * t, 0.0)
        g_old = gsum
        r = op.normal(t)
        r = r - r[con].mean()
        den = float(np.sum(r[con] * t[con]))
        tau = float(np.sum(gap[con] * t[con])) / den if den != 0.0 else 0.0
        p_old = p
        p = np.clip(p - tau * t, 0.0, None)
        enter = (~con) & (gap < 0)
        p[enter] -= tau * gap[enter]
        delta_flag = 0.0 if np.any(enter) else 1.0
        p *= load / (p.sum() * area)
        err = np.abs(p - p_old).sum() / p.sum()
        if err < tol:
            gap = hh + op.normal(p)
            return p, float(gap[p > 0].mean())
    raise ConvergenceError(f"normal solve: residual {err:.1e} after {max_iter} iterations",
                           err, max_iter)


def _solve_3d(op: HalfSpacePair, h: np.ndarray, load: float,
              start: np.ndarray | None) -> tuple[np.ndarray, float]:
    """The 3D pressure by the package's normal solver (:func:`contact.bem.solve_normal`,
    the same Love influence coefficients), warm-started from ``start``."""
    from contact.bem import solve_normal

    r = solve_normal(h, op.dx, op.dy, e_star=op.c.e_star, load=load, initial=start,
                     tol=1e-8, edge="ignore")
    return np.asarray(r.pressure, dtype=float), float(r.approach)
