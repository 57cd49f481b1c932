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
previous pressure; in plane strain the package's line-contact solve
(:func:`contact.bem._line.solve_line_pressure`: the same strip kernel as this grid's
operator, dense, an exact active set), whose starting set is the previous pressure's
support.
"""

from __future__ import annotations

import numpy as np

from contact._errors import ContactInputError
from contact.halfspace.pair import HalfSpacePair


def solve_pressure(
    op: HalfSpacePair,
    h: np.ndarray,
    load: float,
    *,
    extra: np.ndarray | None = None,
    start: np.ndarray | None = None,
    max_iter: int = 200,
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
    max_iter : int
        Active-set step limit (plane strain).

    Raises
    ------
    ConvergenceError
        If the solve does not settle.
    """
    if not (np.isfinite(load) and load > 0):
        raise ContactInputError("normal load must be a positive number of newtons")
    if not op.line:
        return _solve_3d(op, h if extra is None else h + extra, load, start)
    from contact.bem._line import solve_line_pressure

    hh = (h if extra is None else h + extra).reshape(-1)
    sol = solve_line_pressure(hh, op.dx, op.c.e_star, load,
                              start=None if start is None else start.reshape(-1),
                              max_iter=max_iter)
    return sol.pressure.reshape(h.shape), sol.approach


def _solve_3d(op: HalfSpacePair, h: np.ndarray, load: float,
              start: np.ndarray | None) -> tuple[np.ndarray, float]:
    """The 3D pressure by the package's normal solver (:func:`contact.bem.solve_normal`,
    the same Love influence coefficients), warm-started from ``start``."""
    from contact._grid import scan_grid
    from contact.bem import solve_normal
    from contact.bem._options import SolveOptions

    r = solve_normal(scan_grid(h.shape, op.dx, op.dy, h=h), e_star=op.c.e_star, load=load,
                     options=SolveOptions(tol=1e-8, edge="ignore"), initial=start)
    return np.asarray(r.pressure, dtype=float), float(r.approach)
