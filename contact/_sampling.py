"""A measured height map sampled onto a solver's grid: the one ``sample_roughness``.

Every solver family puts a scan (or a composite of two) under its grid the same way:
non-measured points take the nearest measured value, the map is averaged over one grid
cell where the grid is coarser than the data (a box filter, so that the grid sees the
cell-mean roughness instead of an aliased sample), and the map is interpolated
bilinearly at the element centres.
"""

from __future__ import annotations

import numpy as np

from contact._errors import ContactInputError
from contact._grid import Grid

#: A grid this many times coarser than the data (either way) is averaged before sampling.
COARSER = 1.5


def fill_nan(z: np.ndarray) -> tuple[np.ndarray, float]:
    """Fill non-measured points with the nearest measured value; return the filled fraction.

    Raises
    ------
    ContactInputError
        If nothing is measured.
    """
    from scipy.ndimage import distance_transform_edt

    z = np.asarray(z, dtype=float)
    bad = ~np.isfinite(z)
    if not bad.any():
        return z, 0.0
    if bad.all():
        raise ContactInputError("the roughness map is NaN everywhere: nothing was measured")
    idx = distance_transform_edt(bad, return_distances=False, return_indices=True)
    return z[tuple(idx)], float(bad.mean())


def sample_roughness(z: np.ndarray, zdx: float, zdy: float, grid: Grid, *,
                     centre: tuple[float, float] | None = None,
                     average: bool = True) -> np.ndarray:
    """The height map ``z`` (pitch zdx, zdy) at the element centres of ``grid``.

    Parameters
    ----------
    z : ndarray, shape (ny, nx)
        Heights (m); row i at Y = i zdy, column j at X = j zdx. NaN marks points not
        measured: they take the nearest measured value.
    zdx, zdy : float
        The map's pitch (m).
    grid : Grid
        The solver's grid; its coordinates are relative to the point ``centre`` of the map.
    centre : (float, float), optional
        Map coordinates (X, Y) of the grid's origin (m); default the middle of the map.
    average : bool
        Average the map over one grid cell first where the grid is more than
        :data:`COARSER` times coarser than the data.

    Returns
    -------
    ndarray, shape grid.shape
        Bilinear interpolation of the (averaged) map at the centres.

    Raises
    ------
    ContactInputError
        If the map has no measured point or does not cover the grid.
    """
    from scipy.ndimage import uniform_filter

    z = np.asarray(z, dtype=float)
    if z.ndim != 2:
        raise ContactInputError("the roughness must be a 2D map")
    z, _ = fill_nan(z)
    ny_r, nx_r = z.shape
    x, y = np.asarray(grid.x, dtype=float), np.asarray(grid.y, dtype=float)
    if centre is None:
        cols = x / zdx + 0.5 * (nx_r - 1)
        rows = y / zdy + 0.5 * (ny_r - 1)
    else:
        cols = (centre[0] + x) / zdx
        rows = (centre[1] + y) / zdy
    # a grid that ends on the map's last point within rounding still fits
    tol = 1e-9 * max(zdx, zdy, grid.dx, 1.0 if grid.line else grid.dy)
    if (cols.min() < -tol / zdx or rows.min() < -tol / zdy or cols.max() > nx_r - 1 + tol / zdx
            or rows.max() > ny_r - 1 + tol / zdy):
        span_x = float(x.max() - x.min())
        span_y = 0.0 if grid.line else float(y.max() - y.min())
        raise ContactInputError(
            f"the roughness data ({(nx_r - 1) * zdx * 1e6:.4g} µm x "
            f"{(ny_r - 1) * zdy * 1e6:.4g} µm between their first and last points) do not "
            f"cover the contact grid (its element centres span {span_x * 1e6:.4g} µm x "
            f"{span_y * 1e6:.4g} µm): use larger scans or a smaller domain")
    fx = grid.dx / zdx
    fy = 1.0 if grid.line else grid.dy / zdy
    if average and (fx > COARSER or fy > COARSER):
        z = uniform_filter(z, size=(max(1, round(fy)), max(1, round(fx))), mode="nearest")
    return bilinear(z, np.clip(rows, 0, ny_r - 1), np.clip(cols, 0, nx_r - 1))


def _linear_weights(pos: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Lower and upper neighbours and the upper weight of positions in [0, n - 1]."""
    lo = np.clip(np.floor(pos).astype(np.intp), 0, max(n - 2, 0))
    hi = np.minimum(lo + 1, n - 1)
    return lo, hi, pos - lo


def bilinear(z: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """``z`` interpolated bilinearly at every (row, column) pair of a regular grid.

    ``rows`` (m,) and ``cols`` (k,) are fractional indices inside the map (clipped by the
    caller); the result has shape (m, k). Separable, one axis then the other: the same
    interpolation as ``scipy.ndimage.map_coordinates(order=1)`` on the meshgrid of the
    two, to rounding, without the meshgrid's two coordinate arrays of the grid's size (a
    tenth of the time at 4096^2).
    """
    r0, r1, wr = _linear_weights(np.asarray(rows, dtype=float), z.shape[0])
    c0, c1, wc = _linear_weights(np.asarray(cols, dtype=float), z.shape[1])
    # along x first, on the map's rows the grid needs only
    need = np.unique(np.concatenate((r0, r1)))
    sub = z[need]
    along = sub[:, c0]
    along *= 1.0 - wc
    along += sub[:, c1] * wc
    out = along[np.searchsorted(need, r0)]
    out *= (1.0 - wr)[:, None]
    upper = along[np.searchsorted(need, r1)]
    upper *= wr[:, None]
    out += upper
    return out
