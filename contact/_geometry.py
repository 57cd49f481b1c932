"""Gaps on a grid and the automatic choice of the computational domain.

Conventions: the grid has ``n`` cells of pitch ``dx`` per side; cell ``(i, j)`` has its
centre at ``x = (j - n//2) dx``, ``y = (i - n//2) dy``, so the sphere apex sits on the
centre of cell ``(n//2, n//2)`` (:func:`contact._grid.centred_grid`). Roughness arrays
follow the surfmet layout: row ``i`` at ``Y = i dy``, column ``j`` at ``X = j dx`` (scan
coordinates, metres); :func:`contact._sampling.sample_roughness` puts them on the grid.

The composite roughness ``z`` is the sum of the two surfaces' heights, each measured
outward from its own body, so that it *closes* the gap: ``h = x^2/(2R) - z``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.fft as sfft

from contact._errors import ContactInputError
from contact._grid import Grid, centred_coordinates, centred_grid
from contact._hertz import hertz_sphere
from contact._validate import positive


def sphere_gap(n: int, dx: float, radius: float, *, ny: int | None = None,
               dy: float | None = None, exact: bool = False) -> np.ndarray:
    """Initial gap of a sphere over a flat, (ny, n) cells, apex on the centre cell.

    ``exact=False`` gives the Hertz paraboloid r^2/(2R); ``exact=True`` the sphere
    R - sqrt(R^2 - r^2) (it differs by r^4/(8R^3), a relative 1e-5 at r = a for the
    paper's ball).

    Parameters
    ----------
    n : int
        Cells along x.
    dx : float
        Cell pitch along x (m).
    radius : float
        Sphere radius R (m).
    ny, dy : optional
        Cells and pitch along y (default ``n`` and ``dx``).
    exact : bool
        The true sphere instead of the paraboloid.

    Returns
    -------
    ndarray, shape (ny, n)
        The gap in metres, 0 at the apex.

    See Also
    --------
    cylinder_gap, contact.solve_normal

    Examples
    --------
    >>> from contact import sphere_gap
    >>> gap = sphere_gap(5, 1e-5, 0.01)
    >>> print(gap.shape, (gap[2] * 1e9).round(1))
    (5, 5) [20.  5.  0.  5. 20.]
    """
    radius = positive(radius, "the sphere radius", "m")
    ny = n if ny is None else ny
    dy = dx if dy is None else dy
    r2 = centred_coordinates(n, dx)[None, :] ** 2 + centred_coordinates(ny, dy)[:, None] ** 2
    if not exact:
        r2 /= 2.0 * radius  # in place: a fresh array of the grid's size is a page-fault pass
        return r2
    if r2.max() >= radius**2:
        raise ContactInputError("the domain is wider than the sphere; use a smaller size")
    return radius - np.sqrt(radius**2 - r2)


def cylinder_gap(n: int, dx: float, radius: float, *, ny: int | None = None) -> np.ndarray:
    """Initial gap x^2/(2R) of a cylinder with its axis along y, shape (ny, n).

    Parameters
    ----------
    n : int
        Cells along x (across the axis).
    dx : float
        Cell pitch (m).
    radius : float
        Cylinder radius R (m).
    ny : int, optional
        Cells along the axis (default ``n``).

    Returns
    -------
    ndarray, shape (ny, n)
        The gap in metres, 0 on the axis.

    See Also
    --------
    sphere_gap, contact.solve_cylinder

    Examples
    --------
    >>> from contact import cylinder_gap
    >>> print((cylinder_gap(5, 1e-5, 0.01, ny=2) * 1e9).round(1))
    [[20.  5.  0.  5. 20.]
     [20.  5.  0.  5. 20.]]
    """
    radius = positive(radius, "the cylinder radius", "m")
    ny = n if ny is None else ny
    x = centred_coordinates(n, dx)
    return np.broadcast_to(x[None, :] ** 2 / (2.0 * radius), (ny, n)).copy()


def plane_fit(z: np.ndarray, dx: float = 1.0, dy: float = 1.0) -> tuple[float, float, float]:
    """Least-squares plane ``c + bx X + by Y`` through the finite points of ``z``."""
    _ny, _nx = z.shape
    yy, xx = np.nonzero(np.isfinite(z))
    if yy.size < 3:
        raise ContactInputError("a roughness map needs at least 3 measured points")
    a = np.column_stack((np.ones(yy.size), xx * dx, yy * dy))
    coef, *_ = np.linalg.lstsq(a, z[yy, xx], rcond=None)
    return float(coef[0]), float(coef[1]), float(coef[2])


def remove_plane(z: np.ndarray, dx: float = 1.0, dy: float = 1.0) -> tuple[np.ndarray, tuple]:
    """``z`` minus its least-squares plane, and the plane (c, slope_x, slope_y)."""
    c, bx, by = plane_fit(z, dx, dy)
    ny, nx = z.shape
    plane = c + bx * np.arange(nx)[None, :] * dx + by * np.arange(ny)[:, None] * dy
    return z - plane, (c, bx, by)


def fast_even(n: int) -> int:
    """The smallest even n' >= n whose FFTs (of n' and 2n') are fast."""
    m = max(2, int(n))
    while True:
        m = sfft.next_fast_len(m, real=True)
        if m % 2 == 0 and sfft.next_fast_len(2 * m, real=True) == 2 * m:
            return m
        m += 1


@dataclass(frozen=True)
class Domain:
    """The choice of a square computational domain: ``n`` cells of pitch ``dx`` per side.

    ``reason`` says how it was chosen (shown to the user); :attr:`grid` is the grid it
    describes.
    """

    n: int
    dx: float
    reason: str = ""

    @property
    def size(self) -> float:
        """Side length n dx (m)."""
        return self.n * self.dx

    @property
    def grid(self) -> Grid:
        """The n x n grid of pitch dx, the origin on the centre of cell (n//2, n//2)."""
        return centred_grid(self.n, self.dx)


#: What a ball-on-plate solve may do when the contact reaches the domain's edge.
ON_EDGE = ("enlarge", "warn", "raise")


@dataclass(frozen=True)
class DomainSpec:
    """What a caller asks of a ball's computational domain (each field overrides a rule of
    :func:`auto_domain`; the defaults leave every choice to it).

    Attributes
    ----------
    grid : int, optional
        Cells per side (at least 8; rounded up to even).
    size : float, optional
        Side length (m).
    max_grid : int or None
        Largest automatic grid (cells per side); None: the roughness data's own pixel at
        any size that fits in memory (native resolution).
    smooth_grid : int
        Cells per side of a smooth ball (256 gives the Hertz peak pressure to ~4e-6).
    margin : float
        Half-side over the estimated contact radius.
    periodic : bool
        Periodic domain (the ball then has periodic images; meant for comparisons); not a
        rule of the size: the solvers read it.
    on_edge : {"enlarge", "warn", "raise"}
        What a ball-on-plate solve does when the contact pressure reaches the domain's edge
        (:class:`contact.setups._ball_on_plate.SphereContact`): enlarge the domain and solve
        again, return the truncated result with a warning, or raise.
    max_enlarge : int
        Most enlargements before giving up with :class:`contact._errors.EdgeContactError`.

    Examples
    --------
    >>> DomainSpec(grid=64).max_grid
    1024
    """

    grid: int | None = None
    size: float | None = None
    max_grid: int | None = 1024
    smooth_grid: int = 256
    margin: float = 1.25
    periodic: bool = False
    on_edge: str = "enlarge"
    max_enlarge: int = 4

    def __post_init__(self) -> None:
        if self.on_edge not in ON_EDGE:
            raise ContactInputError(f"on_edge must be one of {ON_EDGE}, got {self.on_edge!r}")
        if self.size is not None:
            positive(self.size, "the domain size", "m")
        if self.grid is not None and (int(self.grid) != self.grid or self.grid < 8):
            raise ContactInputError(
                f"the grid must be an integer of at least 8 cells per side, got {self.grid!r}")


def domain_spec(spec: DomainSpec | None) -> DomainSpec:
    """``spec``, or the automatic choice where None; anything else refused in one line."""
    if spec is None:
        return DomainSpec()
    if not isinstance(spec, DomainSpec):
        raise ContactInputError(
            f"domain must be a contact.DomainSpec, got {type(spec).__name__}")
    return spec


def contact_extent(radius: float, load: float, e_star: float, roughness_rms: float = 0.0,
                   hardness: float | None = None) -> float:
    """Estimated radius (m) inside which a rough ball may touch the plate.

    The smooth elastic ball touches within the Hertz radius a; with a hardness H the
    contact cannot be smaller than the fully plastic radius sqrt(W / (pi H)) (the mean
    pressure cannot exceed H). Roughness lets asperities up to about three standard
    deviations high touch further out, where the undeformed sphere stands x^2/(2R) above
    the plate: r^2 = a^2 + 2R (3 sigma).
    """
    a = hertz_sphere(radius, load, e_star).a
    if hardness is not None and hardness > 0:
        a = max(a, math.sqrt(load / (math.pi * hardness)))
    return math.sqrt(a**2 + 6.0 * radius * max(roughness_rms, 0.0))


def auto_domain(
    radius: float,
    load: float,
    e_star: float,
    *,
    roughness_rms: float = 0.0,
    roughness_dx: float | None = None,
    hardness: float | None = None,
    spec: DomainSpec | None = None,
) -> Domain:
    """Choose the domain side and grid for a ball of radius R under load W.

    Rules (each overridable by a field of ``spec``, :class:`DomainSpec`):

    - side = 2 * margin * r_c with r_c from :func:`contact_extent` (Hertz radius, or the
      fully plastic radius when a ``hardness`` makes it larger, widened by the roughness);
      ``size`` overrides it;
    - smooth ball: ``smooth_grid`` cells (256 gives the Hertz peak pressure to ~4e-6);
    - rough ball: the pitch of the roughness data, but at least 32 cells per Hertz radius,
      and at most ``max_grid`` cells per side (coarser than the scan past that);
      ``max_grid=None`` keeps the scan's own pixel at any size (native resolution; the
      side is rounded up to a whole, FFT-friendly number of pixels, and the caller checks
      the memory, :mod:`contact.bem._memory`), unless the pixel leaves fewer than 16 cells per
      Hertz radius;
    - ``grid`` overrides the cell count. Counts are rounded up to fast FFT sizes.

    Returns
    -------
    Domain
        Cells per side ``n``, pitch ``dx`` and the reason for the choice.

    See Also
    --------
    contact.SphereContact : uses it.

    Examples
    --------
    The paper's 20 mm ball at 10 N: 256 cells over 2.5 Hertz radii each side:

    >>> from contact import auto_domain
    >>> dom = auto_domain(0.02, 10.0, 58.6e9)
    >>> print(dom.n, f"{dom.dx * 1e6:.2f} µm", dom.reason)
    256 1.34 µm 2.5 x the Hertz radius; 256 cells for a smooth ball
    """
    spec = domain_spec(spec)
    grid, size, max_grid = spec.grid, spec.size, spec.max_grid
    smooth_grid, margin = spec.smooth_grid, spec.margin
    a = hertz_sphere(radius, load, e_star).a
    if size is not None:
        size = float(size)
    rough = roughness_rms > 0 and roughness_dx is not None
    side = size if size is not None else 2.0 * margin * contact_extent(
        radius, load, e_star, roughness_rms if rough else 0.0, hardness=hardness)
    why = "user size" if size is not None else (
        "2.5 x the contact radius estimated from Hertz and the roughness" if rough
        else "2.5 x the Hertz radius")
    if grid is not None:
        n = int(grid)
        if n % 2:
            n += 1
        return Domain(n, side / n, f"{why}; user grid")
    if not rough:
        n = fast_even(smooth_grid)
        return Domain(n, side / n, f"{why}; {n} cells for a smooth ball")
    if max_grid is None:
        # native: the scan's own pixel, unless it leaves fewer than 16 cells per Hertz radius
        dx = min(float(roughness_dx), a / 16.0)
        n = fast_even(math.ceil(side / dx - 1e-9))
        how = ("the scans' own pixel" if dx == float(roughness_dx)
               else "16 cells per Hertz radius (finer than the scans' pixel)")
        return Domain(n, dx, f"{why}; {how}")
    dx = min(float(roughness_dx), a / 32.0)
    n = fast_even(math.ceil(side / dx))
    if n > max_grid:
        n = fast_even(max_grid) if fast_even(max_grid) <= max_grid else max_grid
        return Domain(n, side / n, f"{why}; capped at {n} cells (coarser than the scan)")
    return Domain(n, side / n, f"{why}; pitch of the roughness data")


def max_centred_cells(shape: tuple[int, int], zdx: float, zdy: float,
                      centre: tuple[float, float], dx: float) -> int:
    """The largest even n whose centred n x n grid of pitch dx fits inside the data."""
    ny_r, nx_r = shape
    half_x = min(centre[0], (nx_r - 1) * zdx - centre[0])
    half_y = min(centre[1], (ny_r - 1) * zdy - centre[1])
    half = min(half_x, half_y)
    # cells run from -(n//2) to n - 1 - n//2: the low side is the binding one
    n = 2 * math.floor(half / dx + 1e-9)
    return max(n, 0)
