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
The operator's own inverse, |q|/2, is its stiffness (the solver's preconditioner).
"""

from __future__ import annotations

import threading
from functools import lru_cache

import numpy as np
import scipy.fft as sfft

from contact.errors import ContactInputError
from contact.halfspace.convolution import Convolution


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


class SpectralConvolution(Convolution):
    """u = K * p on a periodic grid with the spectral kernel K^(q) = 2/|q| (E* = 1).

    A :class:`~contact.halfspace.convolution.Convolution` in every use (the same pruned
    cyclic transform, work buffer and float32 path), built on the spectral kernel
    instead of the periodised Love one; periodic only.

    Parameters
    ----------
    ny, nx : int
        Grid shape.
    dx, dy : float
        Cell pitch (m).
    periodic : bool
        Must be True: the spectral kernel is a periodic operator.
    ahead : int
        Must be 0.
    """

    kernel = "spectral"

    def __init__(self, ny: int, nx: int, dx: float, dy: float, periodic: bool = True,
                 ahead: int = 0):
        # Convolution's own __init__ would build the Love spectra first (an alias sum
        # per mode): the attributes are set here instead, the same ones
        if not periodic or ahead:
            raise ContactInputError(
                "the spectral kernel is periodic only: use kernel='love' for a free or "
                "extended-ahead domain")
        self.ny, self.nx = int(ny), int(nx)
        self.dx, self.dy = float(dx), float(dy)
        self.periodic = True
        self.ahead = 0
        self.shape = (self.ny, self.nx)
        self.spec64 = spectral_kernel_spectrum(self.ny, self.nx, self.dx, self.dy)
        self.spec32 = self.spec64.astype(np.float32)
        real = sfft.irfft2(self.spec64, s=self.shape)
        real.setflags(write=False)
        self.real = real
        self.self_influence = float(self.real[0, 0])
        self._stiff: dict[bool, np.ndarray] = {}
        # one spectral work buffer per thread, as Convolution keeps
        self._work = threading.local()

    def stiffness(self, single: bool) -> np.ndarray:
        """|q|/2 on this grid, 0 at q = 0: the exact inverse of the spectral kernel."""
        if single not in self._stiff:
            stiff = 0.5 * spectral_wavenumbers(self.ny, self.nx, self.dx, self.dy)
            self._stiff[single] = stiff.astype(np.float32 if single else np.float64)
        return self._stiff[single]
