"""numba kernels of the contact engine, each with a plain-numpy twin.

The twins (``*_reference``) state what each kernel computes in a few lines of numpy; the
tests run both on small inputs. The solver (:mod:`contact.bem`) calls only the compiled
ones: each fuses several whole-array numpy operations into one pass over memory, which is
what keeps the element-wise work of a conjugate-gradient iteration small next to its FFT.

Arrays are C-contiguous and flattened (``ravel``) unless a kernel needs rows. ``hmax`` is
the pressure cap (hardness), ``inf`` for a purely elastic contact. Sets used below:

- free points ``F``: 0 < p < hmax (in contact, pressure not capped);
- zero points ``Z``: p = 0 (out of contact);
- yielded points ``Y``: p = hmax (plastic).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

# --------------------------------------------------------------------------------------
# Periodic influence spectrum
# --------------------------------------------------------------------------------------


@nb.njit(cache=True)
def periodic_love_spectrum(ny, nx, dx, dy, n_alias):  # pragma: no cover - compiled
    """Alias sum of 2/|q'| sinc(qx' dx/2) sinc(qy' dy/2) on the rfft grid (E* = 1)."""
    nxh = nx // 2 + 1
    out = np.zeros((ny, nxh))
    # The sum is even in qy: compute rows 0..ny/2 and mirror the others.
    for i in range(ny // 2 + 1):
        ky = i
        ay = math.pi * ky / ny  # qy dy / 2
        say = math.sin(ay)
        for j in range(nxh):
            if i == 0 and j == 0:
                continue
            ax = math.pi * j / nx  # qx dx / 2
            sax = math.sin(ax)
            acc = 0.0
            for m in range(-n_alias, n_alias + 1):
                zx = ax + math.pi * m
                if zx == 0.0:
                    sx = 1.0
                else:
                    sx = (sax if m % 2 == 0 else -sax) / zx
                if sx == 0.0:
                    continue
                qx = 2.0 * zx / dx
                for n in range(-n_alias, n_alias + 1):
                    zy = ay + math.pi * n
                    if zy == 0.0:
                        sy = 1.0
                    else:
                        sy = (say if n % 2 == 0 else -say) / zy
                    if sy == 0.0:
                        continue
                    qy = 2.0 * zy / dy
                    acc += 2.0 / math.sqrt(qx * qx + qy * qy) * sx * sy
            out[i, j] = acc
    for i in range(ny // 2 + 1, ny):
        for j in range(nxh):
            out[i, j] = out[ny - i, j]
    return out


def periodic_love_spectrum_reference(ny, nx, dx, dy, n_alias):
    """numpy twin of :func:`periodic_love_spectrum`."""
    qy = 2 * np.pi * np.fft.fftfreq(ny, dy)[:, None, None, None]
    qx = 2 * np.pi * np.fft.rfftfreq(nx, dx)[None, :, None, None]
    m = np.arange(-n_alias, n_alias + 1)
    gx = (2 * np.pi * m / dx)[None, None, :, None]
    gy = (2 * np.pi * m / dy)[None, None, None, :]
    qxm, qyn = qx + gx, qy + gy
    with np.errstate(divide="ignore", invalid="ignore"):
        terms = 2.0 / np.hypot(qxm, qyn) * np.sinc(qxm * dx / (2 * np.pi)) * np.sinc(
            qyn * dy / (2 * np.pi)
        )
    terms = np.where(np.isfinite(terms), terms, 0.0)
    out = terms.sum(axis=(2, 3))
    out[0, 0] = 0.0
    return out


# --------------------------------------------------------------------------------------
# Polonsky-Keer conjugate gradient passes
# --------------------------------------------------------------------------------------


@nb.njit(cache=True)
def pk_gap_mean(p, u, h, hmax):  # pragma: no cover - compiled
    """Sum of the gap u + h over F, |F|, sum of p over the contact F+Y, |F+Y|."""
    s = 0.0
    n = 0
    sp = 0.0
    nc = 0
    for i in range(p.size):
        pi = p[i]
        if pi > 0.0:
            nc += 1
            sp += pi
            if pi < hmax:
                s += u[i] + h[i]
                n += 1
    return s, n, sp, nc


def pk_gap_mean_reference(p, u, h, hmax):
    """numpy twin of :func:`pk_gap_mean`."""
    free = (p > 0) & (p < hmax)
    contact = p > 0
    return (float((u + h)[free].sum()), int(free.sum()), float(p[contact].sum()),
            int(contact.sum()))


@nb.njit(cache=True)
def pk_residual(p, u, h, gbar, hmax, d):  # pragma: no cover - compiled
    """Write d = u + h - gbar; return (sum_F d^2, sum of squared violations, #violations).

    A violation is an overlap out of contact (p = 0, d < 0) or a yielded point that
    separates (p = hmax, d > 0).
    """
    G = 0.0
    viol = 0.0
    nviol = 0
    for i in range(p.size):
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
    return G, viol, nviol


def pk_residual_reference(p, u, h, gbar, hmax):
    """numpy twin of :func:`pk_residual`; returns (d, G, viol, nviol)."""
    d = u + h - gbar
    free = (p > 0) & (p < hmax)
    bad = ((p <= 0) & (d < 0)) | ((p >= hmax) & (d > 0))
    return d, float((d[free] ** 2).sum()), float((d[bad] ** 2).sum()), int(bad.sum())


@nb.njit(cache=True)
def pk_direction(d, p, t, beta, hmax, t32, nx):  # pragma: no cover - compiled
    """t = d + beta t on F, 0 elsewhere; copy t to ``t32``; return the rows [lo, hi) of F."""
    ny = p.size // nx
    lo = ny
    hi = 0
    for r in range(ny):
        row_has = False
        base = r * nx
        for c in range(nx):
            i = base + c
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                ti = d[i] + beta * t[i]
                t[i] = ti
                t32[i] = ti
                row_has = True
            else:
                t[i] = 0.0
                t32[i] = 0.0
        if row_has:
            if r < lo:
                lo = r
            hi = r + 1
    if hi == 0:
        lo = 0
    return lo, hi


def pk_direction_reference(d, p, t, beta, hmax, nx):
    """numpy twin of :func:`pk_direction`; returns (t_new, lo, hi)."""
    free = (p > 0) & (p < hmax)
    t_new = np.where(free, d + beta * t, 0.0)
    rows = np.nonzero(free.reshape(-1, nx).any(axis=1))[0]
    lo, hi = (int(rows[0]), int(rows[-1]) + 1) if rows.size else (0, 0)
    return t_new, lo, hi


@nb.njit(cache=True)
def pk_step_length(r, t, d, p, hmax, subtract_mean):  # pragma: no cover - compiled
    """The CG step tau = sum_F d t / sum_F (r - rbar) t, with rbar the mean of r on F.

    Returns (tau, rbar). In approach control the mean is not subtracted (rbar = 0).
    """
    rs = 0.0
    n = 0
    if subtract_mean:
        for i in range(p.size):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                rs += r[i]
                n += 1
    rbar = rs / n if n > 0 else 0.0
    num = 0.0
    den = 0.0
    for i in range(p.size):
        pi = p[i]
        if pi > 0.0 and pi < hmax:
            ti = t[i]
            num += d[i] * ti
            den += (r[i] - rbar) * ti
    tau = num / den if den != 0.0 else 0.0
    return tau, rbar


def pk_step_length_reference(r, t, d, p, hmax, subtract_mean):
    """numpy twin of :func:`pk_step_length`."""
    free = (p > 0) & (p < hmax)
    r = r.astype(float)
    rbar = float(r[free].mean()) if (subtract_mean and free.any()) else 0.0
    den = float(((r[free] - rbar) * t[free]).sum())
    tau = float((d[free] * t[free]).sum()) / den if den != 0 else 0.0
    return tau, rbar


@nb.njit(cache=True)
def pk_update_pressure(p, t, d, tau, hmax, cidx, cval):  # pragma: no cover - compiled
    """Step p -= tau t on F, project onto [0, hmax], let violating points enter.

    The linear trial step is p - tau t; everything the projection changes relative to it
    is recorded as a correction (index in ``cidx``, value in ``cval``) so that the caller
    can update the displacement by superposition. Returns (#corrections, sum p, #entered).
    """
    nc = 0
    total = 0.0
    entered = 0
    for i in range(p.size):
        pi = p[i]
        if pi > 0.0 and pi < hmax:
            trial = pi - tau * t[i]
            new = trial
            if new < 0.0:
                new = 0.0
            elif new > hmax:
                new = hmax
            if new != trial:
                cidx[nc] = i
                cval[nc] = new - trial
                nc += 1
        elif pi <= 0.0:
            new = 0.0
            di = d[i]
            if di < 0.0:
                new = -tau * di
                if new > hmax:
                    new = hmax
                if new > 0.0:
                    cidx[nc] = i
                    cval[nc] = new
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
                cidx[nc] = i
                cval[nc] = new - hmax
                nc += 1
                entered += 1
        p[i] = new
        total += new
    return nc, total, entered


def pk_update_pressure_reference(p, t, d, tau, hmax):
    """numpy twin of :func:`pk_update_pressure`; returns (p_new, correction, entered)."""
    free = (p > 0) & (p < hmax)
    zero = p <= 0
    yielded = p >= hmax
    trial = np.where(free, p - tau * t, np.where(yielded, hmax, 0.0))
    new = trial.copy()
    new[free] = np.clip(trial[free], 0.0, hmax)
    enter = zero & (d < 0) & (-tau * d > 0)
    new[enter] = np.minimum(-tau * d[enter], hmax)
    release = yielded & (d > 0)
    new[release] = np.maximum(hmax - tau * d[release], 0.0)
    return new, new - trial, int(enter.sum() + release.sum())


@nb.njit(cache=True)
def capped_scale(p, target, hmax, cidx, cval, nc):  # pragma: no cover - compiled
    """Scale the uncapped pressures by s so that the total is ``target``; record corrections.

    Points at the cap (p >= hmax) keep p = hmax; the others become min(s p, hmax). The
    corrections relative to the plain scaling s * p are recorded for the displacement
    update: those already in ``cidx/cval[:nc]`` (made before the scaling) are multiplied
    by s, then (1 - s) hmax is appended for every capped point and hmax - s p for every
    point the scaling pushes over the cap. Returns (s, #corrections).
    """
    total = 0.0
    n_cap = 0
    for i in range(p.size):
        if p[i] >= hmax:
            n_cap += 1
        else:
            total += p[i]
    free_target = target - n_cap * hmax if n_cap > 0 else target
    if total <= 0.0 or free_target <= 0.0:
        # The capped points alone carry too much: scale every point down (s < 1 keeps
        # all of them below the cap, and the cap is met again as the iteration goes on).
        grand = total + n_cap * hmax
        if grand <= 0.0:
            return 1.0, nc
        s = target / grand
        for k in range(nc):
            cval[k] *= s
        for i in range(p.size):
            p[i] *= s
        return s, nc
    s = free_target / total
    if hmax < np.inf:
        # Newton on the piecewise-linear f(s) = sum min(s p, hmax) - free_target (exact
        # once the capped set stops changing; a handful of passes at most).
        for _ in range(60):
            f = -free_target
            df = 0.0
            for i in range(p.size):
                pi = p[i]
                if pi >= hmax:
                    continue
                v = s * pi
                if v >= hmax:
                    f += hmax
                else:
                    f += v
                    df += pi
            if df <= 0.0 or abs(f) <= 1e-15 * target:
                break
            s_new = s - f / df
            if s_new == s:
                break
            s = s_new
    for k in range(nc):
        cval[k] *= s
    for i in range(p.size):
        pi = p[i]
        if pi >= hmax:
            if s != 1.0:
                cidx[nc] = i
                cval[nc] = (1.0 - s) * hmax
                nc += 1
            continue
        v = s * pi
        if v > hmax:
            cidx[nc] = i
            cval[nc] = hmax - v
            nc += 1
            v = hmax
        p[i] = v
    return s, nc


def capped_scale_reference(p, target, hmax):
    """numpy twin of :func:`capped_scale`: s by bisection; returns (s, new p)."""
    capped = p >= hmax
    free_target = target - capped.sum() * hmax if capped.any() else target
    if free_target <= 0 or not (p[~capped] > 0).any():
        s = target / p.sum()
        return s, s * p
    lo, hi = 0.0, 1.0
    while np.minimum(hi * p[~capped], hmax).sum() < free_target:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if np.minimum(mid * p[~capped], hmax).sum() < free_target:
            lo = mid
        else:
            hi = mid
    s = 0.5 * (lo + hi)
    return s, np.where(capped, hmax, np.minimum(s * p, hmax))


@nb.njit(cache=True)
def axpy_scale(u, r, tau, s):  # pragma: no cover - compiled
    """u = s (u - tau r), in place (r may be float32)."""
    for i in range(u.size):
        u[i] = s * (u[i] - tau * r[i])


def axpy_scale_reference(u, r, tau, s):
    """numpy twin of :func:`axpy_scale`."""
    return s * (u - tau * r.astype(float))


@nb.njit(cache=True)
def sparse_convolve_add(u, cidx, cval, nc, kernel, nx, periodic):  # pragma: no cover
    """u += K * c for a sparse c given as (index, value) pairs, by direct summation.

    ``kernel`` is the free-boundary quadrant K[|di|, |dj|] or, when ``periodic``, the
    wrapped periodic kernel K[di mod ny, dj mod nx]. Cost nc * u.size: the caller uses it
    only when a few points changed.
    """
    ny = u.size // nx
    for k in range(nc):
        ci = cidx[k] // nx
        cj = cidx[k] % nx
        v = cval[k]
        for m in range(ny):
            if periodic:
                dm = (m - ci) % ny
            else:
                dm = m - ci if m >= ci else ci - m
            base = m * nx
            if periodic:
                for n in range(nx):
                    u[base + n] += v * kernel[dm, (n - cj) % nx]
            else:
                for n in range(cj):
                    u[base + n] += v * kernel[dm, cj - n]
                for n in range(cj, nx):
                    u[base + n] += v * kernel[dm, n - cj]


def sparse_convolve_add_reference(u, cidx, cval, kernel, nx, periodic):
    """numpy twin of :func:`sparse_convolve_add` (returns a new array)."""
    ny = u.size // nx
    out = u.reshape(ny, nx).copy()
    rows = np.arange(ny)[:, None]
    cols = np.arange(nx)[None, :]
    for idx, v in zip(cidx, cval):
        ci, cj = divmod(int(idx), nx)
        if periodic:
            out += v * kernel[(rows - ci) % ny, (cols - cj) % nx]
        else:
            out += v * kernel[np.abs(rows - ci), np.abs(cols - cj)]
    return out.ravel()


@nb.njit(cache=True)
def scatter(buf, cidx, cval, nc, value_mode):  # pragma: no cover - compiled
    """buf[cidx[:nc]] = cval[:nc] (value_mode True) or 0 (False); return the row span.

    Used to turn many corrections into a dense array for one FFT and to clear it after.
    """
    lo = buf.shape[0]
    hi = 0
    nx = buf.shape[1]
    for k in range(nc):
        r = cidx[k] // nx
        c = cidx[k] % nx
        buf[r, c] = cval[k] if value_mode else 0.0
        if r < lo:
            lo = r
        if r + 1 > hi:
            hi = r + 1
    return lo, hi


@nb.njit(cache=True)
def masked_copy(d, p, hmax, out, nx):  # pragma: no cover - compiled
    """out = d on F, 0 elsewhere (out may be float32); return the rows [lo, hi) of F."""
    ny = p.size // nx
    lo = ny
    hi = 0
    for r in range(ny):
        row_has = False
        base = r * nx
        for c in range(nx):
            i = base + c
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                out[i] = d[i]
                row_has = True
            else:
                out[i] = 0.0
        if row_has:
            if r < lo:
                lo = r
            hi = r + 1
    if hi == 0:
        lo = 0
    return lo, hi


def masked_copy_reference(d, p, hmax, nx):
    """numpy twin of :func:`masked_copy`; returns (out, lo, hi)."""
    free = (p > 0) & (p < hmax)
    rows = np.nonzero(free.reshape(-1, nx).any(axis=1))[0]
    lo, hi = (int(rows[0]), int(rows[-1]) + 1) if rows.size else (0, 0)
    return np.where(free, d, 0.0), lo, hi


@nb.njit(cache=True)
def center_on_free(zin, z, d, p, hmax, subtract_mean):  # pragma: no cover - compiled
    """z = zin - mean_F(zin) on F (0 elsewhere); return rho = sum_F d z.

    The preconditioned residual must stay in the space of load-neutral pressure changes,
    hence the mean removal in load control.
    """
    s = 0.0
    n = 0
    if subtract_mean:
        for i in range(p.size):
            pi = p[i]
            if pi > 0.0 and pi < hmax:
                s += zin[i]
                n += 1
    zbar = s / n if n > 0 else 0.0
    rho = 0.0
    for i in range(p.size):
        pi = p[i]
        if pi > 0.0 and pi < hmax:
            zi = zin[i] - zbar
            z[i] = zi
            rho += d[i] * zi
        else:
            z[i] = 0.0
    return rho


def center_on_free_reference(zin, d, p, hmax, subtract_mean):
    """numpy twin of :func:`center_on_free`; returns (z, rho)."""
    free = (p > 0) & (p < hmax)
    zin = zin.astype(float)
    zbar = float(zin[free].mean()) if (subtract_mean and free.any()) else 0.0
    z = np.where(free, zin - zbar, 0.0)
    return z, float((d * z)[free].sum())
