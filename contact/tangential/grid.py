"""The grid of a tangential problem: element centres and the undeformed separation.

The grid holds the contact area with a small margin, as in CONTACT's potential contact
area: tractions outside it are zero. For a sphere (or the composite radius R of the
pair) on a flat, h = (x^2 + y^2)/(2R) minus the composite roughness; for a cylinder
(a line contact, plane strain), h = x^2/(2R) on a single row.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact.errors import ContactInputError


@dataclass(frozen=True)
class Grid:
    """Element centres and the undeformed separation h (m).

    Attributes
    ----------
    x, y : ndarray
        Element centre coordinates (m); a line contact has ``y = [0.0]``.
    h : ndarray, shape (len(y), len(x))
        Undeformed separation (m), positive apart.
    line : bool
        Plane strain (a line contact along y): forces are per unit length.
    """

    x: np.ndarray
    y: np.ndarray
    h: np.ndarray
    line: bool = False

    @property
    def dx(self) -> float:
        """Element size along x (m)."""
        return float(self.x[1] - self.x[0])

    @property
    def dy(self) -> float:
        """Element size along y (m); 1 for a line contact (forces per metre)."""
        return 1.0 if self.line else float(self.y[1] - self.y[0])

    @property
    def area(self) -> float:
        """Element area dx dy (m^2; m in plane strain)."""
        return self.dx * self.dy


def centres(n: int, half_width: float) -> np.ndarray:
    """n element centres spanning [-half_width, half_width] (m)."""
    d = 2.0 * half_width / n
    return -half_width + (np.arange(n) + 0.5) * d


def sphere_grid(radius: float, half_width: float, n: int,
                roughness: np.ndarray | None = None) -> Grid:
    """An n x n grid over [-half_width, half_width]^2 for a sphere of radius R on a flat.

    ``roughness`` (m, shape (n, n)) is the composite height: it closes the gap.
    """
    if not (math.isfinite(radius) and radius > 0):
        raise ContactInputError("radius must be a positive length in metres")
    if n < 4:
        raise ContactInputError("the grid needs at least 4 elements a side")
    x = centres(n, half_width)
    h = (x[None, :] ** 2 + x[:, None] ** 2) / (2.0 * radius)
    if roughness is not None:
        r = np.asarray(roughness, dtype=float)
        if r.shape != h.shape or not np.all(np.isfinite(r)):
            raise ContactInputError(f"roughness must be a finite array of shape {h.shape}")
        h = h - r
    return Grid(x=x, y=x.copy(), h=h)


def cylinder_grid(radius: float, half_width: float, n: int,
                  roughness: np.ndarray | None = None) -> Grid:
    """A line-contact grid of n elements over [-half_width, half_width] (plane strain)."""
    if not (math.isfinite(radius) and radius > 0):
        raise ContactInputError("radius must be a positive length in metres")
    if n < 4:
        raise ContactInputError("the grid needs at least 4 elements")
    x = centres(n, half_width)
    h = (x**2 / (2.0 * radius))[None, :]
    if roughness is not None:
        r = np.asarray(roughness, dtype=float).reshape(1, -1)
        if r.shape != h.shape or not np.all(np.isfinite(r)):
            raise ContactInputError(f"roughness must be a finite profile of {n} points")
        h = h - r
    return Grid(x=x, y=np.zeros(1), h=h, line=True)


def sample_roughness(z: np.ndarray, zdx: float, zdy: float, x: np.ndarray,
                     y: np.ndarray) -> np.ndarray:
    """A height map (pitch zdx, zdy, centred on the contact) sampled at the grid points
    (x, y) by bilinear interpolation; the map must cover the grid. Non-measured points
    (NaN) take the value of the nearest measured one."""
    from scipy.ndimage import distance_transform_edt, map_coordinates

    z = np.asarray(z, dtype=float)
    bad = ~np.isfinite(z)
    if bad.all():
        raise ContactInputError("the roughness map has no measured point")
    if bad.any():
        idx = distance_transform_edt(bad, return_distances=False, return_indices=True)
        z = z[tuple(idx)]
    ny, nx = z.shape
    cols = np.asarray(x, float) / zdx + 0.5 * (nx - 1)
    rows = np.asarray(y, float) / zdy + 0.5 * (ny - 1)
    if cols.min() < 0 or cols.max() > nx - 1 or rows.min() < 0 or rows.max() > ny - 1:
        raise ContactInputError(
            "the scans do not cover the contact grid: use larger scans or a smaller grid")
    rr, cc = np.meshgrid(rows, cols, indexing="ij")
    return map_coordinates(z, [rr, cc], order=1, mode="nearest")
