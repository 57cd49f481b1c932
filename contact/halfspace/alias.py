"""The periodic alias sum: the Fourier coefficients of a half-space kernel periodised over a grid.

A kernel applied to uniform tractions on the cells of a periodic (ny, nx) grid of pitch
(dx, dy) has, at the wavevector q of the rfft grid, the coefficient (Johnson 1985,
*Contact Mechanics*, sec. 13.2; Stanley & Kato 1997, J. Tribol. 119:481)::

    K^(q) = sum_{m,n} S(q') sinc(qx' dx/2) sinc(qy' dy/2),   q' = q + G_mn,

the continuum symbol S times the transform of the uniform cell, summed over the aliases
G_mn = (2 pi m / dx, 2 pi n / dy), |m|, |n| <= n_alias. The terms alternate in sign, so
the truncation error falls fast; q = 0 (a rigid displacement of a periodic problem) is
zero. This is the one home of that sum; the symbols (the transforms of the point-load
kernels over pi, e^{-i q.x}; :mod:`contact.halfspace.cerruti`) are::

    one: 2/|q|          xx: 2 qy^2/|q|^3     yy: 2 qx^2/|q|^3
    xy: -2 qx qy/|q|^3  x: -2 qx/|q|^2       y: -2 qy/|q|^2

(:data:`SYMBOLS`, in that order). The normal (Love) one alone is
:func:`contact.halfspace.influence.periodic_kernel_spectrum`; the six together are the
pair operator's (:func:`contact.halfspace.cerruti.periodic_spectra`).

Rows follow numpy's fftfreq: the Nyquist row of an even ny is the wavenumber -pi/dy
(the sums even in qy do not see it; the odd ones change sign).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

#: The symbols :func:`alias_sums` returns with ``full=True``, in order.
SYMBOLS = ("one", "xx", "yy", "xy", "x", "y")


@nb.njit(cache=True)
def _alias_terms(a, n_alias, step, s, q):  # pragma: no cover - compiled
    """Fill s[k] = sinc(z) and q[k] = 2 z / step, z = a + pi m, m = k - n_alias.

    ``a`` is q step / 2 of the base wavenumber; z runs over its aliases. sin(z) is
    +-sin(a), so one sine serves every alias.
    """
    sa = math.sin(a)
    for k in range(2 * n_alias + 1):
        m = k - n_alias
        z = a + math.pi * m
        if z == 0.0:
            s[k] = 1.0
        else:
            s[k] = (sa if m % 2 == 0 else -sa) / z
        q[k] = 2.0 * z / step


@nb.njit(cache=True)
def alias_sums(ny, nx, dx, dy, n_alias, full):  # pragma: no cover - compiled
    """The alias sums on the rfft grid, shape (k, ny, nx//2 + 1) (E* = 1).

    ``full=False``: k = 1, the symbol 2/|q| alone (Love's normal kernel); ``full=True``:
    k = 6, the :data:`SYMBOLS` in order.
    """
    nxh = nx // 2 + 1
    na = 2 * n_alias + 1
    out = np.zeros((6 if full else 1, ny, nxh))
    # The same aliases serve every row: the x terms once per column, the y terms per row.
    sxs = np.empty((nxh, na))
    qxs = np.empty((nxh, na))
    for j in range(nxh):
        _alias_terms(math.pi * j / nx, n_alias, dx, sxs[j], qxs[j])
    sy = np.empty(na)
    qy = np.empty(na)
    # Every symbol is even or odd in qy: compute rows 0..ny/2 and mirror the others.
    for i in range(ny // 2 + 1):
        _alias_terms(math.pi * i / ny, n_alias, dy, sy, qy)
        for j in range(nxh):
            if i == 0 and j == 0:
                continue
            sx = sxs[j]
            qx = qxs[j]
            one = 0.0
            axx = 0.0
            ayy = 0.0
            axy = 0.0
            ax = 0.0
            ay = 0.0
            for kx in range(na):
                if sx[kx] == 0.0:
                    continue
                for ky in range(na):
                    if sy[ky] == 0.0:
                        continue
                    q2 = qx[kx] * qx[kx] + qy[ky] * qy[ky]
                    one += 2.0 / math.sqrt(q2) * sx[kx] * sy[ky]
                    if full:
                        w = sx[kx] * sy[ky] / q2
                        wq = w / math.sqrt(q2)
                        axx += 2.0 * qy[ky] * qy[ky] * wq
                        ayy += 2.0 * qx[kx] * qx[kx] * wq
                        axy -= 2.0 * qx[kx] * qy[ky] * wq
                        ax -= 2.0 * qx[kx] * w
                        ay -= 2.0 * qy[ky] * w
            out[0, i, j] = one
            if full:
                out[1, i, j] = axx
                out[2, i, j] = ayy
                out[3, i, j] = axy
                out[4, i, j] = ax
                out[5, i, j] = ay
    # sign of each symbol under qy -> -qy: xy and y are odd
    parity = np.array([1.0, 1.0, 1.0, -1.0, 1.0, -1.0])
    for k in range(out.shape[0]):
        for i in range(ny // 2 + 1, ny):
            for j in range(nxh):
                out[k, i, j] = parity[k] * out[k, ny - i, j]
        if ny % 2 == 0:
            # fftfreq's Nyquist row is -pi/dy
            for j in range(nxh):
                out[k, ny // 2, j] *= parity[k]
    return out
