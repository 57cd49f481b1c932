"""The one operator protocol of the half-space: what every solver asks of an influence operator.

An operator maps a pressure on a grid of cells to the surface displacement it causes,
u = K * p, for a composite modulus E* = 1 (divide by E* for metres). Every solver family
takes its operator through this protocol:

- :class:`~contact.halfspace.convolution.Convolution`: 3D, Love's uniform cells; free,
  periodic and extended-ahead domains (``kernel="love"``);
- :class:`~contact.halfspace.convolution.SpectralConvolution`: 3D, the spectral kernel
  2/|q| on the periodic domain (``kernel="spectral"``);
- :class:`~contact.halfspace.plane_strain.StripOperator`: plane strain, uniform strips on
  a free line (``kernel="love"``, its 2D form);
- :class:`~contact.halfspace.axisymmetric.RingOperator`: axisymmetric, uniform rings on a
  free radius (``kernel="love"``, its ring form).

:func:`contact.halfspace.convolution.convolution` is the one factory of the 3D ones.

The members:

- ``op(x, rows=None, single=False, workers=-1)``: u = K * x (``rows=(lo, hi)`` says x
  is zero outside those rows; ``single`` computes in float32);
- ``op.stiffness(single)``: the multiplier of the approximate inverse of K on the
  operator's unpadded grid (rfft layout, 0 at q = 0), the periodic stiffness |q|/2 of the
  kernel; ``op.precondition(x, rows, single, workers)`` applies it;
- ``op.self_influence``: the displacement of a cell per unit pressure on itself (the
  largest one where it varies from cell to cell, as on rings);
- ``op.shape`` (the grid the transforms or the matrix run on), ``op.periodic``,
  ``op.ahead`` (cells the displacement extends beyond the last column, +x), and the
  names ``op.kernel`` and ``op.geometry`` (:data:`KERNELS`, :data:`GEOMETRIES`), which
  the solvers write into their records.

The periodic spectral kernel is the one of Tamaas and ContactMechanics (the continuum
Westergaard stiffness at each discrete wavevector); the Love kernel integrates a uniform
pressure over each cell. Both converge to the continuum; see
:mod:`contact.halfspace.spectral` for how they differ on a grid.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np

#: The kernel names an operator may carry.
KERNELS = ("love", "spectral")
#: The geometries an operator may carry.
GEOMETRIES = ("3d", "plane strain", "axisymmetric")


@runtime_checkable
class Operator(Protocol):
    """u = K * p of one grid (E* = 1); see the module notes for each member."""

    kernel: str
    geometry: str
    periodic: bool
    ahead: int
    shape: tuple[int, ...]
    self_influence: float

    def __call__(self, x: np.ndarray, rows: tuple[int, int] | None = None,
                 single: bool = False, workers: int = -1) -> np.ndarray:
        """K * x."""

    def stiffness(self, single: bool) -> np.ndarray:
        """The approximate inverse's multiplier on the unpadded grid (0 at q = 0)."""

    def precondition(self, x: np.ndarray, rows: tuple[int, int], single: bool = False,
                     workers: int = -1) -> np.ndarray:
        """The approximate inverse of K applied to x."""


def line_stiffness(n: int, pitch: float, single: bool) -> np.ndarray:
    """|q|/2 on the rfft grid of n cells of ``pitch`` (0 at q = 0): the periodic stiffness
    of a half-plane under strip loads, 2/|q| being the transform of -2 ln|x| (E* = 1)."""
    q = 2.0 * np.pi * np.fft.rfftfreq(int(n), float(pitch))
    return (0.5 * q).astype(np.float32 if single else np.float64)


def line_precondition(x: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
    """irfft(rfft(x) * stiffness) along the last axis: the line operators' preconditioner."""
    n = x.shape[-1]
    return np.fft.irfft(np.fft.rfft(x, axis=-1) * stiffness, n=n, axis=-1)
