"""FFT convolution with the half-space kernel: the displacement u = K * p of a pressure grid.

Three domains, with the kernels of :mod:`contact.halfspace.influence` and the padded
transforms of :mod:`contact.halfspace.padding`:

- **free boundary** (DC-FFT; Liu, Wang & Liu 2000, Wear 243:101): the pressure is
  zero-padded to a grid of twice the size and the first quadrant of the cyclic
  convolution is the exact linear convolution;
- **extended ahead** (``ahead = m`` cells): the same, with the displacement also on the
  m cells beyond the last column (+x), which the steady-rolling operators of
  :mod:`contact.viscoelastic` integrate along the rolling direction;
- **periodic**: the unpadded cyclic convolution with the periodised Love kernel, or
  (:class:`SpectralConvolution`) with the spectral kernel 2/|q| of
  :mod:`contact.halfspace.spectral`, the peers' choice.

What keeps a convolution cheap inside an iterative solver:

- pruned transforms: only the rows that carry pressure are transformed forward (the caller
  says which), and the padded half of the result is never transformed back;
- float32 or float64 on request (the periodic spectrum is kept in both precisions, the
  free one in float64, rounded to float32 block by block);
- by blocks (:func:`contact.halfspace.padding.convolve_padded`), on the FFT's threads: the
  padded grid is never held whole, and one complex work buffer of the grid's own rows
  per thread is reused between calls during a solve;
- :func:`convolution` caches the operator (and so its spectra and FFT plans) by grid,
  pitch and periodicity.

:meth:`Convolution.precondition` applies the approximate inverse of K (the periodic
stiffness |q|/2; Vollebregt 2014, J. Comput. Phys. 257:333), used by the solver of
:mod:`contact.bem` to precondition its conjugate gradient.
"""

from __future__ import annotations

import threading
from functools import lru_cache

import numpy as np
from scipy.fft import irfft2

from contact._errors import ContactInputError
from contact.halfspace.influence import (
    extended_kernel_spectrum,
    free_kernel_quadrant,
    free_kernel_spectrum,
    periodic_kernel_real,
    periodic_kernel_spectrum,
    periodic_love_spectrum,
)
from contact.halfspace.padding import convolve_padded, forward, inverse, padded_shape, real_types
from contact.halfspace.spectral import spectral_kernel_spectrum, spectral_wavenumbers


class Convolution:
    """u = K * p for one grid (E* = 1), with its spectrum cached.

    Parameters
    ----------
    ny, nx : int
        Grid shape.
    dx, dy : float
        Cell pitch (m).
    periodic : bool
        Periodic domain instead of a free (zero-padded) boundary.
    ahead : int
        Free boundary only: the displacement is also wanted on this many cells beyond the
        last column (+x); the result then has nx + ahead columns.

    Notes
    -----
    One implementation of :class:`contact.halfspace.operator.Operator` (3D, the Love
    kernel); :class:`SpectralConvolution` is the spectral one.
    """

    #: the operator protocol's names (:mod:`contact.halfspace.operator`)
    kernel = "love"
    geometry = "3d"

    def __init__(self, ny: int, nx: int, dx: float, dy: float, periodic: bool,
                 ahead: int = 0):
        self.ny, self.nx = int(ny), int(nx)
        self.dx, self.dy = float(dx), float(dy)
        self.periodic = bool(periodic)
        self.ahead = int(ahead)
        if self.ahead < 0 or (periodic and self.ahead):
            raise ContactInputError("the grid extends ahead by a whole number of cells >= 0, "
                                    "and only with a free boundary")
        self.shape = (self.ny, self.nx) if periodic else padded_shape(self.ny, self.nx,
                                                                       self.ahead)
        if periodic:
            self.spec64 = periodic_kernel_spectrum(self.ny, self.nx, self.dx, self.dy)
            self.real = periodic_kernel_real(self.ny, self.nx, self.dx, self.dy)
        else:
            self.spec64 = (extended_kernel_spectrum(self.ny, self.nx, self.ahead, self.dx,
                                                    self.dy) if self.ahead else
                           free_kernel_spectrum(self.ny, self.nx, self.dx, self.dy))
            self.real = free_kernel_quadrant(self.ny, self.nx, self.dx, self.dy)
        # the float32 copy serves the periodic transform only: the padded one rounds the
        # float64 spectrum block by block (4 bytes a cell less to keep)
        self.spec32 = (self.spec64.astype(np.complex64 if np.iscomplexobj(self.spec64)
                                          else np.float32) if periodic else None)
        # displacement of a cell per unit pressure on itself (the kernel at offset 0)
        self.self_influence = float(self.real[0, 0])
        self._stiff: dict[bool, np.ndarray] = {}
        # one spectral work buffer per thread, kept during a solve (see _buffer)
        self._work = threading.local()

    def _buffer(self, rows: int, cols: int, complex_type: type) -> np.ndarray:
        """A (rows, cols) complex work array (its content is left as it was).

        Fresh arrays of this size come from the kernel as untouched pages: every
        convolution would page-fault its buffer in again (a third of the wall time of a
        4096^2 solve went to the system). One buffer, sized for the complex128 spectrum
        of the grid's own rows (the padded rows are transformed by blocks, see
        :func:`contact.halfspace.padding.convolve_padded`) and viewed as complex64 for the
        float32 transforms, is kept per thread while a solve runs (:meth:`release` drops
        it): no more memory than one transient.
        """
        nbytes = self.ny * (self.shape[1] // 2 + 1) * 16
        raw = getattr(self._work, "raw", None)
        if raw is None or raw.size < nbytes:
            raw = self._work.raw = np.empty(nbytes, dtype=np.uint8)
        return np.ndarray((rows, cols), dtype=complex_type, buffer=raw)

    def release(self) -> None:
        """Drop this thread's work buffer (the end of a solve)."""
        self._work.raw = None

    def stiffness(self, single: bool) -> np.ndarray:
        """1 / K^ of the periodic kernel on this (unpadded) grid, 0 at q = 0."""
        if single not in self._stiff:
            # the alias sum itself is not kept (the lru cache of periodic_kernel_spectrum
            # would hold it beside the stiffness: 4 bytes a cell)
            stiff = periodic_love_spectrum(self.ny, self.nx, self.dx, self.dy, 2)
            positive = stiff > 0
            np.divide(1.0, stiff, out=stiff, where=positive)
            stiff[~positive] = 0.0
            self._stiff[single] = stiff.astype(np.float32) if single else stiff
        return self._stiff[single]

    def spectrum(self, x: np.ndarray, single: bool = False, workers: int = -1) -> np.ndarray:
        """rfft2(x) on this periodic grid (a new array, complex64 where ``single``)."""
        if not self.periodic:
            raise ContactInputError("a spectrum is taken on a periodic grid")
        return forward(x, (self.ny, self.nx), None, single, workers)

    def spectral(self, x: np.ndarray, multiplier: np.ndarray, single: bool = False,
                 workers: int = -1, minus: np.ndarray | None = None) -> np.ndarray:
        """irfft2(rfft2(x) * ``multiplier`` - ``minus``) on this periodic grid, shape
        (ny, nx), with the operator's transforms and work buffer.

        The adhesive solve of :mod:`contact.adhesion` applies its elastic stiffness with
        it: by default the exact inverse of this operator's spectrum (E* / ``spec64``, the
        q = 0 entry its mean-plane spring; not :meth:`stiffness`, the preconditioner's,
        whose kernel is summed over fewer images), ``minus`` the stiffness times the
        :meth:`spectrum` of the undeformed gap. ``multiplier`` (real) and ``minus``
        (complex) have the rfft grid's shape, in the transform's precision.
        """
        if not self.periodic:
            raise ContactInputError("a spectral multiplier is applied on a periodic grid")
        ny, nx = self.ny, self.nx
        _, complex_type = real_types(single)
        buf = forward(x, (ny, nx), None, single, workers,
                      out=self._buffer(ny, nx // 2 + 1, complex_type))
        buf *= multiplier
        if minus is not None:
            buf -= minus
        return inverse(buf, ny, nx, nx, workers)

    def _cyclic(self, x: np.ndarray, rows: tuple[int, int], multiplier: np.ndarray,
                single: bool, workers: int, out: np.ndarray | None = None) -> np.ndarray:
        """The unpadded cyclic convolution: irfft2(rfft2(x) * multiplier), pruned to ``rows``."""
        ny, nx = self.ny, self.nx
        lo, hi = rows
        real_type, complex_type = real_types(single)
        if hi <= lo:
            if out is None:
                return np.zeros((ny, nx), dtype=real_type)
            out.fill(0.0)
            return out
        # the same blocked transform as the padded one, with nothing padded: the cyclic
        # convolution shifts with its input exactly
        return convolve_padded(x, multiplier, (ny, nx), rows, nx,
                               self._buffer(ny, nx // 2 + 1, complex_type), workers, out)

    def _padded(self, x: np.ndarray, rows: tuple[int, int], single: bool,
                workers: int, out: np.ndarray | None = None) -> np.ndarray:
        """The free-boundary (DC-FFT) convolution: x zero-padded to the cyclic grid."""
        lo, hi = rows
        keep = self.nx + self.ahead
        real_type, complex_type = real_types(single)
        if hi <= lo:
            if out is None:
                return np.zeros((self.ny, keep), dtype=real_type)
            out.fill(0.0)
            return out
        work = self._buffer(self.ny, self.shape[1] // 2 + 1, complex_type)
        return convolve_padded(x, self.spec64, self.shape, rows, keep, work, workers, out)

    def precondition(self, x: np.ndarray, rows: tuple[int, int], single: bool = False,
                     workers: int = -1) -> np.ndarray:
        """Approximate inverse of K: the periodic stiffness |q|/2 applied by FFT."""
        return self._cyclic(x, (int(rows[0]), int(rows[1])), self.stiffness(single), single,
                            workers)

    def __call__(
        self,
        x: np.ndarray,
        rows: tuple[int, int] | None = None,
        single: bool = False,
        workers: int = -1,
        out: np.ndarray | None = None,
    ) -> np.ndarray:
        """K * x on the grid, shape (ny, nx + ahead), C-contiguous.

        ``rows=(lo, hi)`` says that x is zero outside rows [lo, hi) (only those rows are
        transformed). ``single`` computes in float32 and returns float32. ``out`` (a
        C-contiguous array of the result's shape and precision, not overlapping x)
        receives the result instead of a new array.
        """
        span = (0, self.ny) if rows is None else (int(rows[0]), int(rows[1]))
        if self.periodic:
            return self._cyclic(x, span, self.spec32 if single else self.spec64, single,
                                workers, out)
        return self._padded(x, span, single, workers, out)


class SpectralConvolution(Convolution):
    """u = K * p on a periodic grid with the spectral kernel K^(q) = 2/|q| (E* = 1).

    A :class:`Convolution` in every use (the same pruned
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
        real = irfft2(self.spec64, s=self.shape)
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


def convolution(ny: int, nx: int, dx: float, dy: float, periodic: bool,
                ahead: int = 0, kernel: str = "love") -> Convolution:
    """The cached 3D operator of a grid (kept between calls): the one factory.

    ``kernel="love"`` (uniform pressure on each cell, every domain) gives a
    :class:`Convolution`; ``kernel="spectral"`` (2/|q| at each wavevector, the peers'
    choice, :mod:`contact.halfspace.spectral`; periodic only) a :class:`SpectralConvolution`.
    Both implement :class:`contact.halfspace.operator.Operator`.

    Raises
    ------
    ContactInputError
        An unknown kernel, or the spectral kernel on a free or extended-ahead domain.
    """
    if kernel not in ("love", "spectral"):
        raise ContactInputError(f"the half-space kernel is 'love' or 'spectral', got {kernel!r}")
    if kernel == "spectral" and (not periodic or ahead):
        raise ContactInputError("the spectral kernel is periodic only: use kernel='love' for "
                                "a free or extended-ahead domain")
    return _cached(int(ny), int(nx), float(dx), float(dy), bool(periodic), int(ahead), kernel)


@lru_cache(maxsize=6)
def _cached(ny: int, nx: int, dx: float, dy: float, periodic: bool, ahead: int,
            kernel: str) -> Convolution:
    if kernel == "spectral":
        return SpectralConvolution(ny, nx, dx, dy, periodic, ahead)
    return Convolution(ny, nx, dx, dy, periodic, ahead)


# the factory's cache, cleared as before (benchmarks time cold operators)
convolution.cache_clear = _cached.cache_clear  # type: ignore[attr-defined]


def drop_cached() -> None:
    """Forget every cached operator and kernel (their arrays go with the last user).

    A nested solve of a large grid calls it between its coarse levels and its own
    operator: the coarse kernels (quadrant, half spectrum and stiffness of n/2, n/4, ...:
    6 bytes a fine cell) are not kept through the fine solve. Rebuilding them costs a
    third of the fine kernel's construction, once per cold solve; warm-started solves
    (a load sweep) do not nest and keep their operator.
    """
    _cached.cache_clear()
    for cached in (free_kernel_quadrant, free_kernel_spectrum, extended_kernel_spectrum,
                   periodic_kernel_spectrum, periodic_kernel_real):
        cached.cache_clear()
