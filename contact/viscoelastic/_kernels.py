"""numba kernels of the viscoelastic rolling solver (their numpy twins live in tests/).

The steady-state hereditary integral along the rolling direction,

    F(x) = (1/l) int_0^inf exp(-xi / l) w(x + xi) dxi,

is evaluated on a row of nodes x_i = x_0 + i dx by the exact recursion for w linear
between nodes (a first-order recursive filter run from the leading end backwards):

    F_i = alpha F_{i+1} + (1 - alpha - g) w_i + g w_{i+1},
    alpha = exp(-dx/l),  g = (l/dx)(1 - alpha) - alpha,

started from a given value F_last at the last node (the tail ahead of the grid).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np


@nb.njit(cache=True)
def creep_filter_rows(w: np.ndarray, tail: np.ndarray, dx: float, ell: float) -> np.ndarray:
    """F for every row of ``w`` (ny, nx) with F[:, -1] = ``tail``; returns (ny, nx)."""
    ny, nx = w.shape
    out = np.empty((ny, nx))
    r = dx / ell
    alpha = math.exp(-r)
    if r > 1e-4:
        g = (1.0 - alpha) / r - alpha
    else:  # series of (1 - e^-r)/r - e^-r = r/2 - r^2/3 + r^3/8
        g = r / 2.0 - r * r / 3.0 + r * r * r / 8.0
    c0 = 1.0 - alpha - g
    for j in range(ny):
        f = tail[j]
        out[j, nx - 1] = f
        for i in range(nx - 2, -1, -1):
            f = alpha * f + c0 * w[j, i] + g * w[j, i + 1]
            out[j, i] = f
    return out
