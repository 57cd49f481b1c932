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
def update_states(qx, qy, sx, sy, g, state, ex, ey, dxx, dyy, slack):  # pragma: no cover
    """One active-set update of Kalker's friction law on every element (in place).

    Each element is judged on its own, the others held (the local problem of Kalker's
    Gauss-Seidel schemes): its slip without its own contribution is r = s - D q, D the
    diagonal of the slip operator (``dxx``, ``dyy``), and the traction that would make
    it stick is q* = -r/D. An element sticks when |q*| <= g, and otherwise slips with
    q = g q*/|q*| (opposite to its slip). Returns the number of state changes and the
    largest change of a slip direction.
    """
    ny, nx = g.shape
    changes = 0
    de_max = 0.0
    for i in range(ny):
        for j in range(nx):
            st = state[i, j]
            if st == 0:
                continue
            tx = -(sx[i, j] - dxx * qx[i, j]) / dxx
            ty = -(sy[i, j] - dyy * qy[i, j]) / dyy
            tn = np.sqrt(tx * tx + ty * ty)
            if tn <= g[i, j] * (1.0 + slack):
                if st == 2:
                    state[i, j] = 1
                    changes += 1
                continue
            nxv = tx / tn
            nyv = ty / tn
            if st == 1:
                state[i, j] = 2
                changes += 1
            else:
                d = np.sqrt((nxv - ex[i, j]) ** 2 + (nyv - ey[i, j]) ** 2)
                if d > de_max:
                    de_max = d
            ex[i, j] = nxv
            ey[i, j] = nyv
    return changes, de_max
