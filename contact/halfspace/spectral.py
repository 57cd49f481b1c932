"""The spectral kernel: the periodic half-space as the continuum stiffness at each wavevector.

A periodic pressure p(x) = sum_q p^(q) e^{i q.x} on an elastic half-space displaces the
surface by u^(q) = 2 p^(q) / (E* |q|) (Johnson 1985, *Contact Mechanics*, sec. 13.2,
Westergaard's wavy surface; E* = 1 here, divide by E* for metres). Applied at the
discrete wavevectors q = 2 pi (m / (nx dx), n / (ny dy)) of the grid, this treats the
pressure as samples of a band-limited field: the choice of Tamaas (its Westergaard
operator) and of ContactMechanics (PeriodicFFTElasticHalfSpace), which agree with each
other to 1e-10 on periodic rough contact.

The Love kernel of :class:`contact.halfspace.convolution.Convolution` instead integrates
a uniform pressure over each cell, which multiplies each mode by the cell's transform
and sums its aliases (:mod:`contact.halfspace.alias`): the same as 2/|q| at long
wavelengths, 22 % more compliant at the grid's corner wavevector. On a rough periodic
surface that leaves 0.6-1.0 % less contact area than the peers (tests/test_tamaas_adhesion.py).

The q = 0 coefficient (the mean displacement, a rigid-body motion of a periodic problem)
is zero, as in the Love operator and in Tamaas: the solver's approach carries the mean.
The kernel's own inverse, |q|/2, is its stiffness (the solver's preconditioner). The
operator that applies it is
:class:`contact.halfspace.convolution.SpectralConvolution`, beside the Love one.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np


@lru_cache(maxsize=8)
def spectral_kernel_spectrum(ny: int, nx: int, dx: float, dy: float) -> np.ndarray:
    """2/|q| on the rfft grid, shape (ny, nx//2 + 1), 0 at q = 0 (E* = 1; read-only)."""
    q = spectral_wavenumbers(ny, nx, dx, dy)
    with np.errstate(divide="ignore"):
        spec = np.where(q > 0, 2.0 / np.where(q > 0, q, 1.0), 0.0)
    spec.setflags(write=False)
    return spec


def spectral_wavenumbers(ny: int, nx: int, dx: float, dy: float) -> np.ndarray:
    """|q| (1/m) on the rfft grid of a (ny, nx) grid of pitch (dx, dy)."""
    qy = 2.0 * np.pi * np.fft.fftfreq(int(ny), float(dy))[:, None]
    qx = 2.0 * np.pi * np.fft.rfftfreq(int(nx), float(dx))[None, :]
    return np.hypot(qx, qy)
