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
    point the scaling pushes over the cap, so ``cidx``/``cval`` must hold ``nc + p.size``
    entries (a capped point may then carry two corrections). When no scaling can reach
    the target (the capped points alone carry more, or every loaded point is capped and
    they carry less), p is left as it is with s = 1: points must leave the cap or enter,
    which scaling cannot do; the caller checks the total. Returns (s, #corrections).
    """
    total = 0.0
    n_cap = 0
    for i in range(p.size):
        if p[i] >= hmax:
            n_cap += 1
        else:
            total += p[i]
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
        return 1.0, p.copy()
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
    """buf[cidx[:nc]] += cval[:nc] (value_mode True) or = 0 (False); return the row span.

    Used to turn many corrections into a dense array for one FFT and to clear it after.
    A cell may carry several corrections (a capped cell changed by the step and then by
    the load rescaling): they add up, so ``buf`` must be zero on entry.
    """
    lo = buf.shape[0]
    hi = 0
    nx = buf.shape[1]
    for k in range(nc):
        r = cidx[k] // nx
        c = cidx[k] % nx
        if value_mode:
            buf[r, c] += cval[k]
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


# --------------------------------------------------------------------------------------
# Elastic-perfectly-plastic safeguards: projected-gradient step and exact line search
# --------------------------------------------------------------------------------------


@nb.njit(cache=True)
def _capped_sum(x, cand, m, mu, hmax):  # pragma: no cover - compiled
    """sum over the candidates of clip(x - mu, 0, hmax) and the count strictly inside."""
    f = 0.0
    cnt = 0
    for k in range(m):
        v = x[cand[k]] - mu
        if v >= hmax:
            f += hmax
        elif v > 0.0:
            f += v
            cnt += 1
    return f, cnt


@nb.njit(cache=True)
def projected_gradient(p, d, alpha, target, hmax, load_control, s, cand,
                       nx):  # pragma: no cover - compiled
    """s = P(p - alpha d) - p, the step to the projection of a gradient step.

    P is the Euclidean projection onto the feasible pressures: the box 0 <= p <= hmax
    and, in load control, the hyperplane sum(p) = target. That projection is
    clip(x - mu, 0, hmax) with the one shift mu that restores the total (the Lagrange
    multiplier of the load; it plays the role of the approach), found by safeguarded
    Newton on the piecewise-linear, non-increasing total. Only points with x above a
    lower bound of mu can carry pressure; they are gathered in ``cand`` first, so that
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
        # At mu = min over the loaded points of x minus hmax every loaded point would sit
        # at the cap, which carries at least the current total when that is feasible
        # (sum p = target, p <= hmax): a lower bound of mu. Otherwise (a start that
        # overloads its points) the bound comes from all points.
        a = (xmin_c if xmin_c < np.inf else xmin) - hmax
        b = xmax
        m = 0
        for i in range(n):
            if s[i] > a:
                cand[m] = i
                m += 1
        f, _ = _capped_sum(s, cand, m, a, hmax)
        if f < target:
            a = xmin - hmax
            for i in range(n):
                cand[i] = i
            m = n
        mu = min(max(0.0, a), b)
        for _ in range(200):
            f, cnt = _capped_sum(s, cand, m, mu, hmax)
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


def projected_gradient_reference(p, d, alpha, target, hmax, load_control):
    """numpy twin of :func:`projected_gradient` (mu by bisection); returns (s, gs, ss, mu)."""
    x = p - alpha * d
    mu = 0.0
    if load_control:
        lo, hi = x.min() - hmax, x.max()
        for _ in range(300):
            mid = 0.5 * (lo + hi)
            if np.clip(x - mid, 0.0, hmax).sum() > target:
                lo = mid
            else:
                hi = mid
        mu = 0.5 * (lo + hi)
    s = np.clip(x - mu, 0.0, hmax) - p
    return s, float(d @ s), float(s @ s), mu


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


def add_step_reference(p, s, u, w, theta, hmax):
    """numpy twin of :func:`add_step`; returns (p, u)."""
    v = np.clip(p + theta * s, 0.0, hmax)
    v[v >= hmax * (1 - 1e-14)] = hmax
    return np.where(s != 0, v, p), u + theta * w.astype(float)


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


def step_terms_reference(p, p_old, u, u_old, d):
    """numpy twin of :func:`step_terms`."""
    s = p - p_old
    return float(d @ s), float(s @ (u - u_old)), float(p.sum())


@nb.njit(cache=True)
def blend(p, p_old, u, u_old, theta):  # pragma: no cover - compiled
    """p = p_old + theta (p - p_old), u likewise, in place (a damped step)."""
    for i in range(p.size):
        po = p_old[i]
        if p[i] != po:
            p[i] = po + theta * (p[i] - po)
        uo = u_old[i]
        u[i] = uo + theta * (u[i] - uo)


def blend_reference(p, p_old, u, u_old, theta):
    """numpy twin of :func:`blend`; returns (p, u)."""
    return p_old + theta * (p - p_old), u_old + theta * (u - u_old)
