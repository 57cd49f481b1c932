"""The axisymmetric half-space: uniform pressures on rings, and the ring operator built on them.

A uniform pressure on a disc of radius b displaces the surface of a half-space at radius r
by (Johnson 1985, *Contact Mechanics*, eq. 3.39, with (1 - nu^2)/E of both bodies summed
to 1/E*)::

    u = 4 b E(r/b) / (pi E*)                          for r <= b,
    u = 4 r [E(b/r) - (1 - b^2/r^2) K(b/r)] / (pi E*)  for r > b,

with the complete elliptic integrals K and E (scipy's parameter m = k^2). A uniform
annulus is the difference of two discs, so the displacement of piecewise-constant
pressure rings is exact: the discretisation error is that of the pressure only.

:class:`RingOperator` is the axisymmetric implementation of
:class:`contact.halfspace.operator.Operator`, the dense matrix of the rings (a few
hundred); the Greenwood-Tripp rough sphere (:mod:`contact.roughcontact._greenwood_tripp`)
solves on it.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipe, ellipk

from contact._errors import ContactInputError
from contact.halfspace.operator import line_precondition, line_stiffness


def disc_displacement(r: np.ndarray, b: float, e_star: float = 1.0) -> np.ndarray:
    """Combined surface displacement at ``r`` of a unit uniform pressure on a disc of radius b
    (m per Pa; the module notes' formula)."""
    r = np.asarray(r, dtype=float)
    out = np.empty_like(r)
    inside = r <= b
    out[inside] = 4.0 * b * ellipe((r[inside] / b) ** 2) / (math.pi * e_star)
    ro = r[~inside]
    m = (b / ro) ** 2
    out[~inside] = 4.0 * ro * (ellipe(m) - (1.0 - m) * ellipk(m)) / (math.pi * e_star)
    return out


def ring_influence(edges: np.ndarray, r: np.ndarray, e_star: float = 1.0) -> np.ndarray:
    """Matrix K[i, j]: displacement at r[i] of a unit pressure on ring j (edges[j], edges[j+1])."""
    discs = np.stack([disc_displacement(r, float(b), e_star) for b in edges[1:]], axis=1)
    out = discs.copy()
    out[:, 1:] -= discs[:, :-1]
    return out


class RingOperator:
    """u = K p on rings between ``edges`` (from 0, increasing), at the ring centres (E* = 1).

    Parameters
    ----------
    edges : array_like
        Ring edges (m), n + 1 values, the first 0.
    """

    kernel = "love"
    geometry = "axisymmetric"
    periodic = False
    ahead = 0

    def __init__(self, edges: np.ndarray):
        edges = np.asarray(edges, dtype=float)
        if edges.ndim != 1 or edges.size < 2 or edges[0] != 0.0 or np.any(np.diff(edges) <= 0):
            raise ContactInputError("the ring edges must start at 0 and increase")
        self.edges = edges
        self.r = 0.5 * (edges[1:] + edges[:-1])
        self.matrix = ring_influence(edges, self.r)
        self.matrix.setflags(write=False)
        self.shape = (self.r.size,)
        # the diagonal varies from ring to ring: the largest is the one for step sizes
        self.self_influence = float(np.max(np.diag(self.matrix)))

    def __call__(self, x: np.ndarray, rows: tuple[int, int] | None = None,
                 single: bool = False, workers: int = -1) -> np.ndarray:
        """K x along the last axis (``rows`` and ``workers`` have no use on rings)."""
        k = self.matrix.astype(np.float32) if single else self.matrix
        return np.asarray(x, dtype=k.dtype) @ k.T

    def stiffness(self, single: bool) -> np.ndarray:
        """|q|/2 over the rings at their mean pitch (rfft layout, 0 at q = 0): the local
        stiffness of the half-space, right for wavelengths short against the radius."""
        return line_stiffness(self.r.size, float(self.edges[-1]) / self.r.size, single)

    def precondition(self, x: np.ndarray, rows: tuple[int, int] | None = None,
                     single: bool = False, workers: int = -1) -> np.ndarray:
        """The stiffness applied by FFT along the rings."""
        return line_precondition(np.asarray(x), self.stiffness(single))
