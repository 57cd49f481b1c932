"""numba kernels of the elastic-perfectly-plastic safeguards of :mod:`contact.bem`.

A projected-gradient step and an exact line search along a step, for the contacts whose
pressure is capped (hardness ``hmax``); the sets F, Z, Y are those of
:mod:`contact.bem._kernels`, which re-exports these kernels. Their numpy twins are in
``tests/kernel_twins.py``.
"""

from __future__ import annotations

import numba as nb
import numpy as np


@nb.njit(cache=True)
def _capped_sum(x, candidates, m, mu, hmax):  # pragma: no cover - compiled
    """sum over the candidates of clip(x - mu, 0, hmax) and the count strictly inside."""
    f = 0.0
    cnt = 0
    for k in range(m):
        v = x[candidates[k]] - mu
        if v >= hmax:
            f += hmax
        elif v > 0.0:
            f += v
            cnt += 1
    return f, cnt


@nb.njit(cache=True)
def _load_shift(x, candidates, xmin, xmin_c, xmax, target, hmax):  # pragma: no cover
    """The shift mu with sum clip(x - mu, 0, hmax) = target (the set-up of the projection).

    ``xmin``, ``xmax`` bound x; ``xmin_c`` is the least x over the loaded points (inf if
    none). ``candidates`` receives the indices of the points that can carry pressure.
    """
    n = x.size
    # At mu = min over the loaded points of x minus hmax every loaded point would sit
    # at the cap, which carries at least the current total when that is feasible
    # (sum p = target, p <= hmax): a lower bound of mu. Otherwise (a start that
    # overloads its points) the bound comes from all points.
    a = (xmin_c if xmin_c < np.inf else xmin) - hmax
    b = xmax
    m = 0
    for i in range(n):
        if x[i] > a:
            candidates[m] = i
            m += 1
    f, _ = _capped_sum(x, candidates, m, a, hmax)
    if f < target:
        a = xmin - hmax
        for i in range(n):
            candidates[i] = i
        m = n
    mu = min(max(0.0, a), b)
    for _ in range(200):
        f, cnt = _capped_sum(x, candidates, m, mu, hmax)
        f -= target
        if f > 0.0:
            a = mu
        else:
            b = mu
        if abs(f) <= 1e-15 * target or b - a <= 1e-15 * max(abs(a), abs(b)):
            break
        new = mu + f / cnt if cnt > 0 else 0.5 * (a + b)
        if not (a < new < b):
            new = 0.5 * (a + b)
        if new == mu:
            break
        mu = new
    return mu


@nb.njit(cache=True)
def projected_gradient(p, d, alpha, target, hmax, load_control, s, candidates,
                       nx):  # pragma: no cover - compiled
    """s = P(p - alpha d) - p, the step to the projection of a gradient step.

    P is the Euclidean projection onto the feasible pressures: the box 0 <= p <= hmax
    and, in load control, the hyperplane sum(p) = target. That projection is
    clip(x - mu, 0, hmax) with the one shift mu that restores the total (the Lagrange
    multiplier of the load; it plays the role of the approach), found by safeguarded
    Newton on the piecewise-linear, non-increasing total. Only points with x above a
    lower bound of mu can carry pressure; they are gathered in ``candidates`` first, so that
    the far, open part of the grid is passed over once.

    Returns (sum d s, sum s^2, mu, lo, hi) with [lo, hi) the rows where s != 0.
    """
    n = p.size
    xmin_c = np.inf
    xmin = np.inf
    xmax = -np.inf
    for i in range(n):
        x = p[i] - alpha * d[i]
        s[i] = x
        if x < xmin:
            xmin = x
        if x > xmax:
            xmax = x
        if p[i] > 0.0 and x < xmin_c:
            xmin_c = x
    mu = 0.0
    if load_control:
        mu = _load_shift(s, candidates, xmin, xmin_c, xmax, target, hmax)
    gs = 0.0
    ss = 0.0
    lo = n // nx
    hi = 0
    for i in range(n):
        v = s[i] - mu
        if v >= hmax:
            v = hmax
        elif v < 0.0:
            v = 0.0
        si = v - p[i]
        s[i] = si
        if si != 0.0:
            gs += d[i] * si
            ss += si * si
            r = i // nx
            if r < lo:
                lo = r
            hi = r + 1
    if hi == 0:
        lo = 0
    return gs, ss, mu, lo, hi


@nb.njit(cache=True)
def add_step(p, s, u, w, theta, hmax):  # pragma: no cover - compiled
    """p += theta s (kept in [0, hmax], a point meant to reach the cap put on it exactly),
    u += theta w (w may be float32)."""
    snap = hmax * (1.0 - 1e-14)
    for i in range(p.size):
        si = s[i]
        if si != 0.0:
            v = p[i] + theta * si
            if v >= snap:
                v = hmax
            elif v < 0.0:
                v = 0.0
            p[i] = v
        u[i] += theta * w[i]


@nb.njit(cache=True)
def step_terms(p, p_old, u, u_old, d):  # pragma: no cover - compiled
    """For the step s = p - p_old with K s = u - u_old: (sum d s, sum s K s, sum p).

    Along p_old + theta s the objective changes by theta sum(d s) + theta^2/2 sum(s K s):
    its exact minimiser is theta = -sum(d s) / sum(s K s), and the full step raises the
    objective when that is below 1/2.
    """
    gs = 0.0
    sks = 0.0
    tot = 0.0
    for i in range(p.size):
        pi = p[i]
        si = pi - p_old[i]
        if si != 0.0:
            gs += d[i] * si
            sks += si * (u[i] - u_old[i])
        tot += pi
    return gs, sks, tot


@nb.njit(cache=True)
def blend(p, p_old, u, u_old, theta):  # pragma: no cover - compiled
    """p = p_old + theta (p - p_old), u likewise, in place (a damped step)."""
    for i in range(p.size):
        po = p_old[i]
        if p[i] != po:
            p[i] = po + theta * (p[i] - po)
        uo = u_old[i]
        u[i] = uo + theta * (u[i] - uo)

