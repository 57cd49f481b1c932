"""Plain-numpy twins of the numba kernels: what each kernel computes, in a few lines.

The twin of ``kernel`` is ``kernel_reference``; ``tests/test_contact_kernels.py`` runs both
on small inputs. The kernels are those of :mod:`contact.bem._kernels` and the periodised
Love spectrum of :mod:`contact.halfspace.influence`. The twins are written independently
of the loops (whole-array numpy, bisection where the kernels use Newton), so that a kernel
and its twin share no code.
"""

from __future__ import annotations

import numpy as np


def periodic_love_spectrum_reference(ny, nx, dx, dy, n_alias):
    """numpy twin of :func:`contact.halfspace.influence.periodic_love_spectrum`."""
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


def pk_gap_mean_reference(p, u, h, hmax):
    """numpy twin of :func:`contact.bem._kernels.pk_gap_mean`."""
    free = (p > 0) & (p < hmax)
    contact = p > 0
    return (float((u + h)[free].sum()), int(free.sum()), float(p[contact].sum()),
            int(contact.sum()))


def pk_residual_reference(p, u, h, gbar, hmax):
    """numpy twin of :func:`contact.bem._kernels.pk_residual`; returns (d, G, viol, nviol)."""
    d = u + h - gbar
    free = (p > 0) & (p < hmax)
    bad = ((p <= 0) & (d < 0)) | ((p >= hmax) & (d > 0))
    return d, float((d[free] ** 2).sum()), float((d[bad] ** 2).sum()), int(bad.sum())


def pk_direction_reference(d, p, t, beta, hmax, nx):
    """numpy twin of :func:`contact.bem._kernels.pk_direction`; returns (t_new, lo, hi)."""
    free = (p > 0) & (p < hmax)
    t_new = np.where(free, d + beta * t, 0.0)
    rows = np.nonzero(free.reshape(-1, nx).any(axis=1))[0]
    lo, hi = (int(rows[0]), int(rows[-1]) + 1) if rows.size else (0, 0)
    return t_new, lo, hi


def pk_step_length_reference(r, t, d, p, hmax, subtract_mean):
    """numpy twin of :func:`contact.bem._kernels.pk_step_length`."""
    free = (p > 0) & (p < hmax)
    r = r.astype(float)
    rbar = float(r[free].mean()) if (subtract_mean and free.any()) else 0.0
    den = float(((r[free] - rbar) * t[free]).sum())
    tau = float((d[free] * t[free]).sum()) / den if den != 0 else 0.0
    return tau, rbar


def pk_update_pressure_reference(p, t, d, tau, hmax):
    """numpy twin of :func:`contact.bem._kernels.pk_update_pressure`.

    Returns (p_new, correction, entered).
    """
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


def capped_scale_reference(p, target, hmax):
    """numpy twin of :func:`contact.bem._kernels.capped_scale`, s by bisection.

    Returns (s, new p).
    """
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


def axpy_scale_reference(u, r, tau, s):
    """numpy twin of :func:`contact.bem._kernels.axpy_scale`."""
    return s * (u - tau * r.astype(float))


def sparse_convolve_add_reference(u, index, value, kernel, nx, periodic):
    """numpy twin of :func:`contact.bem._kernels.sparse_convolve_add` (returns a new array)."""
    ny = u.size // nx
    out = u.reshape(ny, nx).copy()
    rows = np.arange(ny)[:, None]
    cols = np.arange(nx)[None, :]
    for idx, v in zip(index, value):
        ci, cj = divmod(int(idx), nx)
        if periodic:
            out += v * kernel[(rows - ci) % ny, (cols - cj) % nx]
        else:
            out += v * kernel[np.abs(rows - ci), np.abs(cols - cj)]
    return out.ravel()


def masked_copy_reference(d, p, hmax, nx):
    """numpy twin of :func:`contact.bem._kernels.masked_copy`; returns (out, lo, hi)."""
    free = (p > 0) & (p < hmax)
    rows = np.nonzero(free.reshape(-1, nx).any(axis=1))[0]
    lo, hi = (int(rows[0]), int(rows[-1]) + 1) if rows.size else (0, 0)
    return np.where(free, d, 0.0), lo, hi


def center_on_free_reference(zin, d, p, hmax, subtract_mean):
    """numpy twin of :func:`contact.bem._kernels.center_on_free`; returns (z, rho)."""
    free = (p > 0) & (p < hmax)
    zin = zin.astype(float)
    zbar = float(zin[free].mean()) if (subtract_mean and free.any()) else 0.0
    z = np.where(free, zin - zbar, 0.0)
    return z, float((d * z)[free].sum())


def projected_gradient_reference(p, d, alpha, target, hmax, load_control):
    """numpy twin of :func:`contact.bem._kernels.projected_gradient`, mu by bisection.

    Returns (s, gs, ss, mu).
    """
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


def add_step_reference(p, s, u, w, theta, hmax):
    """numpy twin of :func:`contact.bem._kernels.add_step`; returns (p, u)."""
    v = np.clip(p + theta * s, 0.0, hmax)
    v[v >= hmax * (1 - 1e-14)] = hmax
    return np.where(s != 0, v, p), u + theta * w.astype(float)


def step_terms_reference(p, p_old, u, u_old, d):
    """numpy twin of :func:`contact.bem._kernels.step_terms`."""
    s = p - p_old
    return float(d @ s), float(s @ (u - u_old)), float(p.sum())


def blend_reference(p, p_old, u, u_old, theta):
    """numpy twin of :func:`contact.bem._kernels.blend`; returns (p, u)."""
    return p_old + theta * (p - p_old), u_old + theta * (u - u_old)
