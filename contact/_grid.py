"""The one grid of every contact solver: element centres, pitches, boundary and gap.

A :class:`Grid` is a regular grid of rectangular elements (cells): the centre coordinates
along x and y, the pitch, whether the domain is periodic, whether it is a line contact
(plane strain, one row, forces per unit length) and, where the problem has one, the
undeformed separation ``h`` (m, positive apart). The normal BEM (:mod:`contact.bem`), the
tangential solvers (:mod:`contact.tangential`), the viscoelastic rolling solver
(:mod:`contact.viscoelastic`) and the adhesive solves (:mod:`contact.adhesion`: periodic,
square cells; a line contact's grid is plane strain) take it or build it at their edge
from loose arrays.

Three ways of placing the centres are in use, each with its constructor:

- :func:`centred_grid`: ``n`` cells with the origin on the centre of cell ``n // 2``
  (the sphere's apex on a cell centre; the ball-on-plate setup);
- :func:`sphere_grid` / :func:`cylinder_grid`: ``n`` elements spanning
  ``[-half_width, half_width]`` symmetrically (CONTACT's potential contact area);
- :func:`scan_grid`: cell ``(0, 0)`` at a given ``origin``, as a scan's pixels
  (:func:`gap_grid`: the same around a gap array).

The composite roughness ``z`` is the sum of the two surfaces' heights, each measured
outward from its own body, so that it *closes* the gap: ``h = x^2/(2R) - z``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError


@dataclass(frozen=True, eq=False)
class Grid:
    """Element centres, pitches, boundary and the undeformed separation of a problem.

    Attributes
    ----------
    x, y : ndarray
        Element centre coordinates (m); a line contact has ``y = [0.0]``.
    h : ndarray, shape (len(y), len(x)), optional
        Undeformed separation (m), positive apart; None for a bare grid.
    line : bool
        Plane strain (a line contact along y): forces are per unit length.
    periodic : bool
        Periodic domain (else a free boundary: nothing acts outside the grid).
    pitch : (float, float), optional
        The pitch (dx, dy) exactly as the caller chose it; default the spacing of the
        first two centres.

    Examples
    --------
    A gap array of pitch 1 µm as the grid a solver takes (:func:`gap_grid`):

    >>> import numpy as np
    >>> from contact._grid import gap_grid
    >>> grid = gap_grid(np.zeros((4, 8)), 1e-6, periodic=True)
    >>> grid.shape, grid.dx, grid.periodic
    ((4, 8), 1e-06, True)
    """

    x: np.ndarray
    y: np.ndarray
    h: np.ndarray | None = None
    line: bool = False
    periodic: bool = False
    pitch: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        if self.h is not None and np.shape(self.h) != self.shape:
            raise ContactInputError(
                f"the gap has shape {np.shape(self.h)}, the grid {self.shape}")

    @property
    def shape(self) -> tuple[int, int]:
        """(ny, nx), the shape of every field on the grid."""
        return (len(self.y), len(self.x))

    @property
    def nx(self) -> int:
        """Elements along x."""
        return len(self.x)

    @property
    def ny(self) -> int:
        """Elements along y (1 for a line contact)."""
        return len(self.y)

    @property
    def dx(self) -> float:
        """Element size along x (m)."""
        return self.pitch[0] if self.pitch is not None else float(self.x[1] - self.x[0])

    @property
    def dy(self) -> float:
        """Element size along y (m); 1 for a line contact (forces per metre)."""
        if self.line:
            return 1.0
        return self.pitch[1] if self.pitch is not None else float(self.y[1] - self.y[0])

    @property
    def area(self) -> float:
        """Element area dx dy (m^2; m in plane strain)."""
        return self.dx * self.dy

    @property
    def origin(self) -> tuple[float, float]:
        """Coordinates (x, y) of the centre of element (0, 0) (m)."""
        return (float(self.x[0]), float(self.y[0]))

    def with_gap(self, h: np.ndarray) -> Grid:
        """The same grid with the undeformed separation ``h`` (m)."""
        return replace(self, h=np.asarray(h, dtype=float))


def centred_coordinates(n: int, d: float) -> np.ndarray:
    """Cell-centre coordinates of an n-cell axis with the origin on cell n//2."""
    return (np.arange(n) - n // 2) * d


def centres(n: int, half_width: float) -> np.ndarray:
    """n element centres spanning [-half_width, half_width] (m)."""
    d = 2.0 * half_width / n
    return -half_width + (np.arange(n) + 0.5) * d


def centred_grid(n: int, dx: float, *, ny: int | None = None, dy: float | None = None,
                 periodic: bool = False, h: np.ndarray | None = None) -> Grid:
    """(ny, n) cells of pitch (dx, dy) with the origin on the centre of cell (ny//2, n//2)."""
    ny = n if ny is None else ny
    dy = dx if dy is None else dy
    return Grid(x=centred_coordinates(n, dx), y=centred_coordinates(ny, dy), h=h,
                periodic=periodic, pitch=(float(dx), float(dy)))


def scan_grid(shape: tuple[int, int], dx: float, dy: float | None = None, *,
              origin: tuple[float, float] = (0.0, 0.0), periodic: bool = False,
              h: np.ndarray | None = None) -> Grid:
    """A grid laid like a scan's pixels: cell (i, j) at ``origin + (j dx, i dy)``."""
    ny, nx = shape
    dy = dx if dy is None else dy
    return Grid(x=origin[0] + np.arange(nx) * dx, y=origin[1] + np.arange(ny) * dy, h=h,
                periodic=periodic, pitch=(dx, dy))


def gap_grid(h: np.ndarray, dx: float, dy: float | None = None, *,
             origin: tuple[float, float] = (0.0, 0.0), periodic: bool = False) -> Grid:
    """The grid of a gap array ``h`` (m) laid like a scan's pixels (:func:`scan_grid`):
    the one way from loose arrays to the :class:`Grid` a solver takes."""
    h = np.asarray(h, dtype=float)
    if h.ndim != 2:
        raise ContactInputError(f"the gap must be a 2D array, got shape {h.shape}")
    return scan_grid(h.shape, dx, dy, origin=origin, periodic=periodic, h=h)


def _check_radius(radius: float, n: int, least: int) -> None:
    if not (math.isfinite(radius) and radius > 0):
        raise ContactInputError("radius must be a positive length in metres")
    if n < least:
        raise ContactInputError(f"the grid needs at least {least} elements a side")


def sphere_grid(radius: float, half_width: float, n: int,
                roughness: np.ndarray | None = None) -> Grid:
    """An n x n grid over [-half_width, half_width]^2 for a sphere of radius R on a flat.

    ``roughness`` (m, shape (n, n)) is the composite height: it closes the gap.
    """
    _check_radius(radius, n, 4)
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
    _check_radius(radius, n, 4)
    x = centres(n, half_width)
    h = (x**2 / (2.0 * radius))[None, :]
    if roughness is not None:
        r = np.asarray(roughness, dtype=float).reshape(1, -1)
        if r.shape != h.shape or not np.all(np.isfinite(r)):
            raise ContactInputError(f"roughness must be a finite profile of {n} points")
        h = h - r
    return Grid(x=x, y=np.zeros(1), h=h, line=True)
