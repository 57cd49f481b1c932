"""The plane-strain half-space: the strip integral and the line operator built on it.

A line load along y on a half-plane displaces the surface by -2 ln|x| / (pi E*) (Johnson
1985, *Contact Mechanics*, eq. 2.25b, sec. 4.3; the point load 1/(pi E* rho) integrated
over y). A uniform pressure on the strip [-dx/2, dx/2] integrates it in closed form::

    int_{-dx/2}^{dx/2} -2 ln|x - s| ds = -2 [F(x + dx/2) - F(x - dx/2)],  F(v) = v ln|v| - v

(:func:`strip_log`, the one home of that integral: the normal line contact of
:mod:`contact.bem._line` and the plane-strain blocks of the pair operator,
:func:`contact.halfspace.cerruti.line_integrals`, both take it from here).

A half-plane has no displacement datum: the displacement grows like log(distance), and
the integral takes it as zero one metre from a unit line load; only differences of
displacement are physical.

:class:`StripOperator` is the plane-strain implementation of
:class:`contact.halfspace.operator.Operator`: the dense influence matrix of a line of
cells (a line contact has a few hundred to a few thousand unknowns, solved exactly).
"""

from __future__ import annotations

import math

import numpy as np

from contact._errors import ContactInputError
from contact.halfspace.operator import line_precondition, line_stiffness


def strip_primitive(v: np.ndarray) -> np.ndarray:
    """F(v) = v ln|v| - v, the primitive of ln|v| (0 at v = 0)."""
    av = np.abs(v)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(av > 0, v * np.log(np.where(av > 0, av, 1.0)) - v, 0.0)


def strip_log(x: np.ndarray, dx: float) -> np.ndarray:
    """The integral of -2 ln|x - s| over the strip s in [-dx/2, dx/2], at offsets ``x`` (m)."""
    x = np.asarray(x, dtype=float)
    hx = 0.5 * dx
    return -2.0 * (strip_primitive(x + hx) - strip_primitive(x - hx))


def line_column(d: np.ndarray, dx: float) -> np.ndarray:
    """Displacement at offsets ``d`` (m) from a uniform-pressure cell of width ``dx`` on a
    half-plane, E* = 1 (m per Pa; the datum of the module notes)."""
    return strip_log(d, dx) / math.pi


def line_influence(n: int, dx: float) -> np.ndarray:
    """Dense (n, n) influence matrix of a uniform-pressure cell on a half-plane, E* = 1.

    ``u = K @ p`` gives the combined displacement (m per Pa of pressure, times 1/E*).
    """
    if n < 1 or not (math.isfinite(dx) and dx > 0):
        raise ContactInputError("the line grid needs n >= 1 cells of positive pitch")
    col = line_column(np.arange(n) * dx, dx)
    idx = np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])
    return col[idx]


class StripOperator:
    """u = K p on a free line of n uniform strips of pitch dx (plane strain, E* = 1).

    Parameters
    ----------
    n : int
        Cells along the line.
    dx : float
        Cell pitch (m).
    """

    kernel = "love"
    geometry = "plane strain"
    periodic = False
    ahead = 0

    def __init__(self, n: int, dx: float):
        self.matrix = line_influence(int(n), float(dx))
        self.matrix.setflags(write=False)
        self.n, self.dx = int(n), float(dx)
        self.shape = (self.n,)
        self.self_influence = float(self.matrix[0, 0])

    def __call__(self, x: np.ndarray, rows: tuple[int, int] | None = None,
                 single: bool = False, workers: int = -1) -> np.ndarray:
        """K x along the last axis (``rows`` and ``workers`` have no use on a line)."""
        k = self.matrix.astype(np.float32) if single else self.matrix
        return np.asarray(x, dtype=k.dtype) @ k.T

    def stiffness(self, single: bool) -> np.ndarray:
        """|q|/2 on the rfft grid of the line, 0 at q = 0."""
        return line_stiffness(self.n, self.dx, single)

    def precondition(self, x: np.ndarray, rows: tuple[int, int] | None = None,
                     single: bool = False, workers: int = -1) -> np.ndarray:
        """The periodic stiffness applied by FFT along the line."""
        return line_precondition(np.asarray(x), self.stiffness(single))
