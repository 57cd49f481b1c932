"""numba kernels of the adhesive solve (:mod:`contact.adhesion.solver`), compiled once and cached.

One iteration of the projected gradient with momentum is two FFTs and some twenty
whole-array operations; these kernels fuse the element-wise part into two passes over
memory. Their plain-numpy twins are in ``tests/test_adhesion_kernels.py``.

The law is passed as a code and three numbers: ``DUGDALE`` (tension ``peak`` below the gap
``reach``, none beyond), ``DUGDALE_RAMP`` (the same step smoothed: ``peak`` falling
linearly to none over the gap ``width`` that ends at ``reach``) or ``EXPONENTIAL``
(tension ``peak`` exp(-g / ``reach``)), as in :mod:`contact.adhesion.laws`;
``EXPONENTIAL_SINGLE`` is the exponential law with its exponential to float32 accuracy
(a table and a polynomial, relative error below 1e-8), for the loose solves whose FFTs
are float32 too. The exponential is most of a kernel's time,
so touching cells (g = 0) take t = ``peak`` without it.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

DUGDALE = 0
EXPONENTIAL = 1
EXPONENTIAL_SINGLE = 2
DUGDALE_RAMP = 3
#: exp(-j / 16), j = 0 ... _EXP_CELLS: the single-precision exponential is a table entry
#: times exp(-f), f < 1/16, by its Taylor quartic (relative error below 1e-8)
_EXP_CELLS = 1408
_EXP_TABLE = np.exp(-np.arange(_EXP_CELLS + 1) / 16.0)


@nb.njit(cache=True)
def gradient_step(y, g, p, kind, peak, reach, width, step, g_new):  # pragma: no cover
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
        elif kind == DUGDALE_RAMP:
            r = (reach - yi) / width
            t = peak if r >= 1.0 else (peak * r if r > 0.0 else 0.0)
        elif yi <= 0.0:  # exp(0) = 1, exactly
            t = peak
        elif kind == EXPONENTIAL:
            t = peak * math.exp(-yi / reach)
        else:  # a table and a quartic: a third of the time of a float32 exp
            s = yi * (16.0 / reach)
            if s >= _EXP_CELLS:
                t = 0.0  # below 1e-38 peak
            else:
                j = int(s)
                f = (j - s) * 0.0625
                t = peak * _EXP_TABLE[j] * (1.0 + f * (1.0 + f * (
                    0.5 + f * (1.0 / 6.0 + f * (1.0 / 24.0)))))
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
def momentum_into(g_new, g, c, y, y_fft):  # pragma: no cover - compiled
    """y = max(g_new + c (g_new - g), 0), also written to ``y_fft`` (the next FFT's input:
    y's float32 copy, or y itself), on flattened arrays; g is left as it is, for the caller
    to swap g and g_new instead of copying one into the other (a pass over memory less)."""
    for i in range(y.size):
        gn = g_new[i]
        v = gn + c * (gn - g[i])
        v = v if v > 0.0 else 0.0
        y[i] = v
        y_fft[i] = v


@nb.njit(cache=True)
def free_mean_step(y, g_new):  # pragma: no cover - compiled
    """The sum of g_new - y over the cells apart after the step (g_new > 0) over the
    number of all cells, on flattened arrays: the step's mean over the free cells times
    their share of the cells."""
    total = 0.0
    count = 0
    for i in range(y.size):
        gn = g_new[i]
        if gn > 0.0:
            total += gn - y[i]
            count += 1
    return total / y.size if count else 0.0


@nb.njit(cache=True)
def momentum_shift_into(g_new, g, c, shift, y, y_fft):  # pragma: no cover - compiled
    """:func:`momentum_into` after moving the cells apart by ``shift``: g_new =
    max(g_new + shift, 0) where g_new > 0 (in place), then y = y_fft = max(g_new +
    c (g_new - g), 0)."""
    for i in range(y.size):
        gn = g_new[i]
        if gn > 0.0:
            gn = gn + shift
            gn = gn if gn > 0.0 else 0.0
            g_new[i] = gn
        v = gn + c * (gn - g[i])
        v = v if v > 0.0 else 0.0
        y[i] = v
        y_fft[i] = v
