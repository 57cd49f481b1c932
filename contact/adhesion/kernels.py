"""numba kernels of the adhesive solve (:mod:`contact.adhesion.solver`), compiled once and cached.

One iteration of the projected gradient with momentum is two FFTs and some twenty
whole-array operations; these kernels fuse the element-wise part into two passes over
memory. Their plain-numpy twins are in ``tests/test_adhesion_kernels.py``.

The law is passed as a code and two numbers: ``DUGDALE`` (tension ``peak`` below the gap
``reach``, none beyond) or ``EXPONENTIAL`` (tension ``peak`` exp(-g / ``reach``)), as in
:mod:`contact.adhesion.laws`.
"""

from __future__ import annotations

import math

import numba as nb

DUGDALE = 0
EXPONENTIAL = 1


@nb.njit(cache=True)
def gradient_step(y, g, p, kind, peak, reach, step, g_new):  # pragma: no cover - compiled
    """One projected-gradient step from ``y``, on flattened arrays.

    The gradient is grad = p + t(y) (p the elastic pressure, t the law's tension). Writes
    g_new = max(y - step grad, 0) and returns (largest violation of equilibrium, largest
    p, <grad, g_new - g>); the violation is max(-grad, 0) where y touches, |grad| elsewhere.
    """
    viol = 0.0
    pmax = -math.inf
    dot = 0.0
    for i in range(y.size):
        yi = y[i]
        if kind == DUGDALE:
            t = peak if yi < reach else 0.0
        else:
            t = peak * math.exp(-yi / reach)
        pi = p[i]
        gr = pi + t
        if pi > pmax:
            pmax = pi
        v = (-gr if gr < 0.0 else 0.0) if yi <= 0.0 else abs(gr)
        if v > viol:
            viol = v
        gn = yi - step * gr
        if gn < 0.0:
            gn = 0.0
        g_new[i] = gn
        dot += gr * (gn - g[i])
    return viol, pmax, dot


@nb.njit(cache=True)
def momentum(g_new, g, c, y):  # pragma: no cover - compiled
    """y = max(g_new + c (g_new - g), 0), then g = g_new (flattened arrays, in place)."""
    for i in range(y.size):
        gn = g_new[i]
        v = gn + c * (gn - g[i])
        y[i] = v if v > 0.0 else 0.0
        g[i] = gn
