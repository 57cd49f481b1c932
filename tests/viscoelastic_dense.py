"""Dense reference for the 3D viscoelastic rolling solver (test helper, numpy only).

The steady-state influence of every cell is integrated along the rolling direction by
quadrature of Love's kernel (no recursive filter, no FFT, no tail model), and the
linear complementarity problem is solved by a dense active set with the load as a
constraint (no elastic splitting).
"""

from __future__ import annotations

import numpy as np

from contact.halfspace.influence import love_coefficients as love_kernel


def dense_influence(n: int, dx: float, glassy: float, amplitudes, times, speed: float):
    """(n*n, n*n) matrix: u = A p on an n x n grid of pitch dx (m/Pa)."""
    k = np.arange(-(n - 1), n) * dx
    ox, oy = np.meshgrid(k, k, indexing="xy")
    col = glassy * love_kernel(ox, oy, dx, dx)
    for dc, th in zip(amplitudes, times):
        ell = speed * th
        # (1/l) int_0^inf e^{-xi/l} K(x + xi, y) dxi: fine trapezoids over 40 l (the
        # kernel is continuous, its slope log-singular at the cell edges), e^-40 beyond
        xi = np.linspace(0.0, 40.0 * ell, 8001)
        wts = np.exp(-xi / ell) / ell
        wts[[0, -1]] *= 0.5
        acc = np.zeros_like(ox)
        for s, wt in zip(xi, wts * (xi[1] - xi[0])):
            acc += wt * love_kernel(ox + s, oy, dx, dx)
        col = col + dc * acc
    idx = np.arange(n)
    iy, ix = np.meshgrid(idx, idx, indexing="ij")
    iy, ix = iy.ravel(), ix.ravel()
    rows = (iy[:, None] - iy[None, :]) + (n - 1)
    cols = (ix[:, None] - ix[None, :]) + (n - 1)
    return col[rows, cols]


def dense_solve(A: np.ndarray, h: np.ndarray, load: float, area: float):
    """(p, delta) of g = h + A p - delta >= 0, p >= 0, p g = 0, area sum p = load."""
    on = h <= np.quantile(h, 0.1)
    for _ in range(200):
        idx = np.flatnonzero(on)
        m = idx.size
        M = np.zeros((m + 1, m + 1))
        M[:m, :m] = A[np.ix_(idx, idx)]
        M[:m, m] = -1.0
        M[m, :m] = area
        sol = np.linalg.solve(M, np.concatenate((-h[idx], [load])))
        p = np.zeros(h.size)
        p[idx] = sol[:m]
        if (sol[:m] < 0).any():
            on[idx[sol[:m] < 0]] = False
            continue
        gap = h + A @ p - sol[m]
        pen = (~on) & (gap < -1e-12 * np.ptp(h))
        if not pen.any():
            return p, float(sol[m])
        on |= pen
    raise RuntimeError("dense active set did not settle")
