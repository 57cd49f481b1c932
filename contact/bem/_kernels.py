"""numba kernels of the boundary-element solver (:mod:`contact.bem`), compiled once and cached.

Each kernel fuses several whole-array numpy operations into one pass over memory, which is
what keeps the element-wise work of a conjugate-gradient iteration small next to its FFT.
Every kernel has a plain-numpy twin stating what it computes in a few lines; the twins
live in the tests (``tests/kernel_twins.py``), which run both on small inputs.

Arrays are C-contiguous and flattened (``ravel``) unless a kernel needs rows. ``hmax`` is
the pressure cap (hardness), ``inf`` for a purely elastic contact. Sets used below:

- free points ``F``: 0 < p < hmax (in contact, pressure not capped);
- zero points ``Z``: p = 0 (out of contact);
- yielded points ``Y``: p = hmax (plastic).

The conjugate-gradient passes run on numba's threads by chunks of cells
(:mod:`contact.bem._chunks`): the same answer whatever the number of threads.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from contact.bem._chunks import apply_scale, bounds, compact, n_chunks, scaled_total, uncapped_total
from contact.bem._plastic_kernels import (  # noqa: F401 - one module of kernels for the callers
    add_step,
    blend,
    projected_gradient,
    step_terms,
)

# --------------------------------------------------------------------------------------
# Polonsky-Keer conjugate gradient passes
# --------------------------------------------------------------------------------------


@nb.njit(cache=True, parallel=True)
def pk_gap_mean(p, u, h, hmax):  # pragma: no cover - compiled
    """Sum of the gap u + h over F, |F|, sum of p over the contact F+Y, |F+Y|."""
    nch = n_chunks(p.size)
    sums = np.zeros((nch, 2))
    counts = np.zeros((nch, 2), dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        s = 0.0
        n = 0
        sp = 0.0
        nc = 0
        for i in range(lo, hi):
            pi = p[i]
            if pi > 0.0:
                nc += 1
                sp += pi
                if pi < hmax:
                    s += u[i] + h[i]
                    n += 1
        sums[c, 0] = s
        sums[c, 1] = sp
        counts[c, 0] = n
        counts[c, 1] = nc
    s = 0.0
    sp = 0.0
    n = 0
    nc = 0
    for c in range(nch):
        s += sums[c, 0]
        sp += sums[c, 1]
        n += counts[c, 0]
        nc += counts[c, 1]
    return s, n, sp, nc


@nb.njit(cache=True, parallel=True)
def pk_residual(p, u, h, gbar, hmax, d):  # pragma: no cover - compiled
    """Write d = u + h - gbar; return (sum_F d^2, sum of squared violations, #violations).

    A violation is an overlap out of contact (p = 0, d < 0) or a yielded point that
    separates (p = hmax, d > 0).
    """
    nch = n_chunks(p.size)
    sums = np.zeros((nch, 2))
    counts = np.zeros(nch, dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        G = 0.0
        viol = 0.0
        nviol = 0
        for i in range(lo, hi):
            di = u[i] + h[i] - gbar
            d[i] = di
            pi = p[i]
            if pi <= 0.0:
                if di < 0.0:
                    viol += di * di
                    nviol += 1
            elif pi >= hmax:
                if di > 0.0:
                    viol += di * di
                    nviol += 1
            else:
                G += di * di
        sums[c, 0] = G
        sums[c, 1] = viol
        counts[c] = nviol
    G = 0.0
    viol = 0.0
    nviol = 0
    for c in range(nch):
        G += sums[c, 0]
        viol += sums[c, 1]
        nviol += counts[c]
    return G, viol, nviol


@nb.njit(cache=True, parallel=True)
def _free_rows(src, t, beta, p, hmax, out, nx):  # pragma: no cover - compiled
    """out = src + beta t on F, 0 elsewhere (with ``t`` None: out = src on F), and t = out
    when given; return the rows [lo, hi) of F. ``out`` may be float32."""
    ny = p.size // nx
    has = np.zeros(ny, dtype=np.bool_)
    for r in nb.prange(ny):
        row_has = False
        base = r * nx
        for c in range(nx):
            i = base + c
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                if t is None:
                    vi = src[i]
                else:
                    vi = src[i] + beta * t[i]
                    t[i] = vi
                out[i] = vi
                row_has = True
            else:
                if t is not None:
                    t[i] = 0.0
                out[i] = 0.0
        has[r] = row_has
    lo = ny
    hi = 0
    for r in range(ny):
        if has[r]:
            if r < lo:
                lo = r
            hi = r + 1
    if hi == 0:
        lo = 0
    return lo, hi


@nb.njit(cache=True, parallel=True)
def _free_mean(x, p, hmax):  # pragma: no cover - compiled
    """The mean of x over F (0 when F is empty)."""
    nch = n_chunks(p.size)
    sums = np.zeros(nch)
    counts = np.zeros(nch, dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        s = 0.0
        n = 0
        for i in range(lo, hi):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                s += x[i]
                n += 1
        sums[c] = s
        counts[c] = n
    s = 0.0
    n = 0
    for c in range(nch):
        s += sums[c]
        n += counts[c]
    return s / n if n > 0 else 0.0


@nb.njit(cache=True)
def pk_direction(d, p, t, beta, hmax, direction_fft, nx):  # pragma: no cover - compiled
    """t = d + beta t on F, 0 elsewhere; copy t to ``direction_fft`` (the precision of the FFT,
    float32 or float64); return the rows [lo, hi) of F."""
    return _free_rows(d, t, beta, p, hmax, direction_fft, nx)


@nb.njit(cache=True, parallel=True)
def pk_step_length(r, t, d, p, hmax, subtract_mean):  # pragma: no cover - compiled
    """The CG step tau = sum_F d t / sum_F (r - rbar) t, with rbar the mean of r on F.

    Returns (tau, rbar). In approach control the mean is not subtracted (rbar = 0).
    """
    rbar = _free_mean(r, p, hmax) if subtract_mean else 0.0
    nch = n_chunks(p.size)
    sums = np.zeros((nch, 2))
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        num = 0.0
        den = 0.0
        for i in range(lo, hi):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                ti = t[i]
                num += d[i] * ti
                den += (r[i] - rbar) * ti
        sums[c, 0] = num
        sums[c, 1] = den
    num = 0.0
    den = 0.0
    for c in range(nch):
        num += sums[c, 0]
        den += sums[c, 1]
    tau = num / den if den != 0.0 else 0.0
    return tau, rbar


@nb.njit(cache=True, parallel=True)
def pk_update_pressure(p, t, d, tau, hmax, index, value):  # pragma: no cover - compiled
    """Step p -= tau t on F, project onto [0, hmax], let violating points enter.

    The linear trial step is p - tau t; everything the projection changes relative to it
    is recorded as a correction (cell in ``index``, amount in ``value``, in cell order) so
    that the caller can update the displacement by superposition; ``index``/``value`` must
    hold p.size entries. Returns (#corrections, sum p, #entered).
    """
    nch = n_chunks(p.size)
    sums = np.zeros(nch)
    counts = np.zeros((nch, 2), dtype=np.int64)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        nc = lo  # each chunk writes its corrections from its own first cell on
        total = 0.0
        entered = 0
        for i in range(lo, hi):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                trial = pi - tau * t[i]
                new = trial
                if new < 0.0:
                    new = 0.0
                elif new > hmax:
                    new = hmax
                if new != trial:
                    index[nc] = i
                    value[nc] = new - trial
                    nc += 1
            elif pi <= 0.0:
                new = 0.0
                di = d[i]
                if di < 0.0:
                    new = -tau * di
                    if new > hmax:
                        new = hmax
                    if new > 0.0:
                        index[nc] = i
                        value[nc] = new
                        nc += 1
                        entered += 1
                    else:
                        new = 0.0
            else:
                new = hmax
                di = d[i]
                if di > 0.0:
                    new = hmax - tau * di
                    if new < 0.0:
                        new = 0.0
                    index[nc] = i
                    value[nc] = new - hmax
                    nc += 1
                    entered += 1
            p[i] = new
            total += new
        sums[c] = total
        counts[c, 0] = nc - lo
        counts[c, 1] = entered
    total = 0.0
    entered = 0
    for c in range(nch):
        total += sums[c]
        entered += counts[c, 1]
    nc = compact(index, value, 0, counts[:, 0], nch, p.size)
    return nc, total, entered


@nb.njit(cache=True)
def capped_scale(p, target, hmax, index, value, nc):  # pragma: no cover - compiled
    """Scale the uncapped pressures by s so that the total is ``target``; record corrections.

    Points at the cap (p >= hmax) keep p = hmax; the others become min(s p, hmax). The
    corrections relative to the plain scaling s * p are recorded for the displacement
    update: those already in ``index/value[:nc]`` (made before the scaling) are multiplied
    by s, then (1 - s) hmax is appended for every capped point and hmax - s p for every
    point the scaling pushes over the cap, so ``index``/``value`` must hold ``nc + p.size``
    entries (a capped point may then carry two corrections). When no scaling can reach
    the target (the capped points alone carry more, or every loaded point is capped and
    they carry less), p is left as it is with s = 1: points must leave the cap or enter,
    which scaling cannot do; the caller checks the total. Returns (s, #corrections).
    """
    total, n_cap = uncapped_total(p, hmax)
    free_target = target - n_cap * hmax if n_cap > 0 else target
    if free_target <= 0.0 or total <= 0.0:
        # No scaling of the uncapped points can balance the load: the capped points
        # alone carry too much (some must leave the cap), or every loaded point is
        # capped and they carry too little (new points must enter). Leave p unchanged;
        # the caller sees the total and takes another kind of step.
        return 1.0, nc
    s = free_target / total
    if hmax < np.inf:
        # Newton on the piecewise-linear f(s) = sum min(s p, hmax) - free_target (exact
        # once the capped set stops changing; a handful of passes at most).
        for _ in range(60):
            f, df = scaled_total(p, s, hmax)
            f -= free_target
            if df <= 0.0 or abs(f) <= 1e-15 * target:
                break
            s_new = s - f / df
            if s_new == s:
                break
            s = s_new
    for k in range(nc):
        value[k] *= s
    return s, apply_scale(p, s, hmax, index, value, nc)


@nb.njit(cache=True, parallel=True)
def axpy_scale(u, r, tau, s):  # pragma: no cover - compiled
    """u = s (u - tau r), in place (r may be float32)."""
    for i in nb.prange(u.size):
        u[i] = s * (u[i] - tau * r[i])


@nb.njit(cache=True, parallel=True)
def sparse_convolve_add(u, index, value, nc, kernel, nx, periodic):  # pragma: no cover
    """u += K * c for a sparse c given as (index, value) pairs, by direct summation.

    ``kernel`` is the free-boundary quadrant K[|di|, |dj|] or, when ``periodic``, the
    wrapped periodic kernel K[di mod ny, dj mod nx]. Cost nc * u.size: the caller uses it
    only when a few points changed. Rows run on the threads; each cell adds the pairs in
    their order, as a serial pass would.
    """
    ny = u.size // nx
    for m in nb.prange(ny):
        base = m * nx
        for k in range(nc):
            ci = index[k] // nx
            cj = index[k] % nx
            v = value[k]
            if periodic:
                dm = (m - ci) % ny
                for n in range(nx):
                    u[base + n] += v * kernel[dm, (n - cj) % nx]
            else:
                dm = m - ci if m >= ci else ci - m
                for n in range(cj):
                    u[base + n] += v * kernel[dm, cj - n]
                for n in range(cj, nx):
                    u[base + n] += v * kernel[dm, n - cj]


@nb.njit(cache=True)
def scatter(buf, index, value, nc, value_mode):  # pragma: no cover - compiled
    """buf[index[:nc]] += value[:nc] (value_mode True) or = 0 (False); return the row span.

    Used to turn many corrections into a dense array for one FFT and to clear it after.
    A cell may carry several corrections (a capped cell changed by the step and then by
    the load rescaling): they add up, so ``buf`` must be zero on entry.
    """
    lo = buf.shape[0]
    hi = 0
    nx = buf.shape[1]
    for k in range(nc):
        r = index[k] // nx
        c = index[k] % nx
        if value_mode:
            buf[r, c] += value[k]
        else:
            buf[r, c] = 0.0
        if r < lo:
            lo = r
        if r + 1 > hi:
            hi = r + 1
    return lo, hi


@nb.njit(cache=True)
def masked_copy(d, p, hmax, out, nx):  # pragma: no cover - compiled
    """out = d on F, 0 elsewhere (out may be float32); return the rows [lo, hi) of F."""
    return _free_rows(d, None, 0.0, p, hmax, out, nx)


@nb.njit(cache=True, parallel=True)
def center_on_free(zin, z, d, p, hmax, subtract_mean):  # pragma: no cover - compiled
    """z = zin - mean_F(zin) on F (0 elsewhere); return rho = sum_F d z.

    The preconditioned residual must stay in the space of load-neutral pressure changes,
    hence the mean removal in load control.
    """
    zbar = _free_mean(zin, p, hmax) if subtract_mean else 0.0
    nch = n_chunks(p.size)
    sums = np.zeros(nch)
    for c in nb.prange(nch):
        lo, hi = bounds(c, nch, p.size)
        rho = 0.0
        for i in range(lo, hi):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                zi = zin[i] - zbar
                z[i] = zi
                rho += d[i] * zi
            else:
                z[i] = 0.0
        sums[c] = rho
    rho = 0.0
    for c in range(nch):
        rho += sums[c]
    return rho
