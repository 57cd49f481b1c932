"""Compiled element loops of the tangential solver (numba, cache=True).

Their numpy reference twins live in ``tests/test_tangential_kernels.py``.

Element states: 0 exterior (no pressure), 1 adhesion (stick), 2 slip.
"""

from __future__ import annotations

import numba as nb
import numpy as np

EXTERIOR = 0
STICK = 1
SLIP = 2


@nb.njit(cache=True)
def update_states(qx, qy, sx, sy, g, state, ex, ey, dxx, dyy, slack, allow):  # pragma: no cover
    """One active-set update of Kalker's friction law on every element (in place).

    With ``dxx > 0`` each element is judged on its own, the others held (the local
    problem of Kalker's Gauss-Seidel schemes): its slip without its own contribution is
    r = s - D q, D the diagonal of the slip operator (``dxx``, ``dyy``), and the traction
    that would make it stick is q* = -r/D. An element sticks when |q*| <= g, and
    otherwise slips with q = g q*/|q*| (opposite to its slip). With ``dxx = 0`` the plain
    complementarity test is used (for operators that are far from diagonally dominant,
    such as the upwind rolling operator): adhesion elements with |q| > g slip along q,
    slip elements with s . e > 0 stick, the others take e = -s/|s|. ``allow`` is a bit
    mask of the moves permitted in this pass (1: stick to slip, 2: slip to stick, 4:
    re-aim the slip directions); the solver takes the moves into slip
    first, which stops two groups of elements from trading places for ever. Returns the
    number of state changes and the largest change of a slip direction.
    """
    ny, nx = g.shape
    changes = 0
    de_max = 0.0
    for i in range(ny):
        for j in range(nx):
            st = state[i, j]
            if st == 0:
                continue
            if dxx > 0.0:
                tx = -(sx[i, j] - dxx * qx[i, j]) / dxx
                ty = -(sy[i, j] - dyy * qy[i, j]) / dyy
                fits = np.sqrt(tx * tx + ty * ty) <= g[i, j] * (1.0 + slack)
            elif st == 1:
                tx, ty = qx[i, j], qy[i, j]
                fits = np.sqrt(tx * tx + ty * ty) <= g[i, j] * (1.0 + slack)
            else:
                tx, ty = -sx[i, j], -sy[i, j]
                fits = sx[i, j] * ex[i, j] + sy[i, j] * ey[i, j] > 0.0
            tn = np.sqrt(tx * tx + ty * ty)
            if tn == 0.0:
                continue
            if fits:
                if st == 2 and allow & 2:
                    state[i, j] = 1
                    changes += 1
                continue
            nxv = tx / tn
            nyv = ty / tn
            if st == 1:
                if not allow & 1:
                    continue
                state[i, j] = 2
                changes += 1
            elif not allow & 4:
                continue
            else:
                d = np.sqrt((nxv - ex[i, j]) ** 2 + (nyv - ey[i, j]) ** 2)
                if d > de_max:
                    de_max = d
            ex[i, j] = nxv
            ey[i, j] = nyv
    return changes, de_max
