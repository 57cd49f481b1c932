"""numba kernels of the adhesive solve (:mod:`contact.adhesion.solver`), compiled once and cached.

One iteration of the projected gradient with momentum is two FFTs and some twenty
whole-array operations; these kernels fuse the element-wise part into two passes over
memory. Their plain-numpy twins are in ``tests/test_adhesion_kernels.py``.

The law is passed as a code and two numbers: ``DUGDALE`` (tension ``peak`` below the gap
``reach``, none beyond) or ``EXPONENTIAL`` (tension ``peak`` exp(-g / ``reach``)), as in
:mod:`contact.adhesion.laws`; ``EXPONENTIAL_SINGLE`` is the exponential law with its
exponential taken in float32 (relative error about 1e-7), for the loose solves whose FFTs
are float32 too. The exponential is most of a kernel's time, so touching cells (g = 0)
take t = ``peak`` without it.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

DUGDALE = 0
EXPONENTIAL = 1
EXPONENTIAL_SINGLE = 2


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
        elif yi <= 0.0:  # exp(0) = 1, exactly
            t = peak
        elif kind == EXPONENTIAL:
            t = peak * math.exp(-yi / reach)
        else:  # float32 exp: about half the time of the float64 one
            t = peak * math.exp(np.float32(-yi / reach))
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


@nb.njit(cache=True)
def momentum_single(g_new, g, c, y, y32):  # pragma: no cover - compiled
    """:func:`momentum`, also writing y in float32 to ``y32`` (the next float32 FFT's input)."""
    for i in range(y.size):
        gn = g_new[i]
        v = gn + c * (gn - g[i])
        v = v if v > 0.0 else 0.0
        y[i] = v
        y32[i] = v
        g[i] = gn
