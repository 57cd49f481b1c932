"""Plain coordinate text: ``x z`` columns (a profile) or ``x y z`` columns (a map).

Columns may be separated by blanks, tabs, commas or semicolons (detected from the first
data line). Lines before the first numeric line (column titles...) and lines starting
with ``#`` or ``%`` are skipped; ``nan`` marks a non-measured height.

* **Two columns** ``x, z``: a :class:`~surfmet._model.Profile`. Positions must be strictly
  monotonic (a decreasing list is reversed). If the steps are constant to 1e-3 relative the
  profile is uniform with ``dx`` = that step, otherwise the positions are kept as ``x``.
* **Three columns** ``x, y, z``: a :class:`~surfmet._model.Topography`. The points must lie
  on a regular grid (constant steps along x and y, in any order); a grid node without a
  point becomes NaN. A grid node given twice, or points off the grid, are errors.

Units: the text states none. ``unit=`` is the unit of x and y (default ``"m"``, assumed),
``height_unit=`` the unit of z (default: the same as ``unit``); what is not given is marked
assumed (:class:`surfmet._model.Calibration`), what is given stated by the user.
Positions are shifted to start at 0; the original origin
is kept in ``metadata["x_offset"]`` (and ``"y_offset"``).

Detection is deliberately weak (a high ``priority`` number): any format with a specific
text signature (Dektak CSV, HFM, matrix headers) is tried first.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import ASSUMED, USER, Profile, Topography
from surfmet.io._binary import (
    MAX_POINTS,
    decode_text,
    format_error,
    looks_like_text,
    positions_profile,
)
from surfmet.io._registry import register_reader
from surfmet.units import length_factor, quantity

FORMAT = "xyz"
_DELIMS = {"\t": "tab", ";": "semicolon", ",": "comma"}
_UNIFORM_RTOL = 1e-3
_GRID_RTOL = 1e-3
# A grid may have holes, but not be mostly empty: that means the points are not on a grid.
_MAX_EMPTY_RATIO = 4


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _delimiter(line: str) -> str | None:
    # None = runs of blanks; a comma is a delimiter only if the line also splits into
    # numbers with it.
    for d in (";", "\t", ","):
        if d in line:
            return d
    return None


def _split(line: str, delim: str | None) -> list[str]:
    if delim is None:
        return line.split()
    return [c.strip() for c in line.strip().split(delim)]


def _numeric(cells: list[str]) -> bool:
    if not cells:
        return False
    for c in cells:
        try:
            float(c)
        except ValueError:
            return False
    return True


def _first_data(lines: list[str], limit: int = 50) -> tuple[int, str | None, int] | None:
    # Index of the first numeric line, its delimiter and column count (trailing empty cells
    # from a trailing delimiter are ignored).
    for k, line in enumerate(lines[:limit]):
        s = line.strip()
        if not s or s[0] in "#%":
            continue
        delim = _delimiter(s)
        cells = _split(s, delim)
        while cells and cells[-1] == "":
            cells.pop()
        if _numeric(cells):
            return k, delim, len(cells)
    return None


def _is_xyz(buf: bytes) -> bool:
    if not looks_like_text(buf):
        return False
    lines = decode_text(buf[:4096]).splitlines()
    if len(buf) > 4096 and lines:
        lines.pop()  # possibly cut in the middle
    found = _first_data(lines, 20)
    if found is None:
        return False
    k, delim, ncols = found
    if ncols not in (2, 3):
        return False
    # The next few lines must agree.
    for line in lines[k + 1 : k + 6]:
        s = line.strip()
        if not s:
            continue
        cells = _split(s, delim)
        while cells and cells[-1] == "":
            cells.pop()
        if len(cells) != ncols or not _numeric(cells):
            return False
    return True


def _factor(unit: str, what: str) -> float:
    try:
        return length_factor(unit)
    except SurfmetInputError as exc:
        raise SurfmetInputError(f"{what}: {exc}") from None


def _table(buf: bytes, name: str) -> tuple[np.ndarray, str | None, int]:
    lines = decode_text(buf).splitlines()
    found = _first_data(lines)
    if found is None:
        raise _fail(name, "no numeric data line found")
    start, delim, ncols = found
    if ncols not in (2, 3):
        raise _fail(name, f"expected 2 columns (x, z) or 3 (x, y, z), found {ncols}")
    cells: list[str] = []
    nrows = 0
    for k in range(start, len(lines)):
        s = lines[k].strip()
        if not s or s[0] in "#%":
            continue
        row = _split(s, delim)
        while len(row) > ncols and row[-1] == "":
            row.pop()
        if len(row) != ncols:
            raise _fail(name, f"line {k + 1} has {len(row)} columns, expected {ncols} "
                              "(truncated or damaged file?)")
        cells.extend(row)
        nrows += 1
    try:
        table = np.array(cells, dtype=np.float64).reshape(nrows, ncols)
    except ValueError:
        raise _fail(name, "a value is not a number (damaged file?)") from None
    return table, delim, start


def _profile(x: np.ndarray, z: np.ndarray, name: str, md: dict[str, Any]) -> Profile:
    if not np.all(np.isfinite(x)):
        raise _fail(name, "a position is not finite")
    if x.size < 2:
        raise _fail(name, "a profile needs at least two points")
    steps = np.diff(x)
    if not np.all(steps > 0):
        if np.all(steps < 0):
            x, z = x[::-1], z[::-1]
        else:
            raise _fail(name, "positions are neither strictly increasing nor decreasing")
    mean_step = float((x[-1] - x[0]) / (x.size - 1))
    md["x_offset"] = quantity(float(x[0]), "m")
    return positions_profile(z, x, mean_step, _UNIFORM_RTOL, md)


def _axis(v: np.ndarray, name: str, label: str) -> tuple[np.ndarray, float, float]:
    # Grid indices along one axis, the step and the origin.
    if not np.all(np.isfinite(v)):
        raise _fail(name, f"a {label} coordinate is not finite")
    u = np.unique(v)
    if u.size == 1:
        return np.zeros(v.size, dtype=np.int64), 0.0, float(u[0])
    span = float(u[-1] - u[0])
    diffs = np.diff(u)
    # Coordinates printed with few digits jitter: merge values closer than the tolerance.
    tol = _GRID_RTOL * float(np.max(diffs))
    step = float(np.min(diffs[diffs > tol])) if np.any(diffs > tol) else span
    idx_f = (v - u[0]) / step
    idx = np.rint(idx_f).astype(np.int64)
    if np.max(np.abs(idx_f - idx)) > 0.05:
        raise _fail(name, f"the {label} coordinates do not lie on a regular grid")
    # Refine the step from the whole span, which averages out print rounding.
    n = int(idx.max())
    if n > 0:
        step = span / n
    return idx, step, float(u[0])


def _grid(x: np.ndarray, y: np.ndarray, z: np.ndarray, name: str,
          md: dict[str, Any]) -> Topography:
    ix, dx, x0 = _axis(x, name, "x")
    iy, dy, y0 = _axis(y, name, "y")
    nx, ny = int(ix.max()) + 1, int(iy.max()) + 1
    if nx * ny > MAX_POINTS or nx * ny > _MAX_EMPTY_RATIO * z.size:
        raise _fail(name, f"{z.size} points would fill a {nx} x {ny} grid: the points do not "
                          "lie on a regular grid")
    if nx < 2 or ny < 2:
        raise _fail(name, "all points share one x or one y value: write a profile as two "
                          "columns (x, z)")
    flat = iy * nx + ix
    if np.unique(flat).size != flat.size:
        raise _fail(name, "a grid node is given more than once")
    heights = np.full(nx * ny, np.nan)
    heights[flat] = z
    md["x_offset"] = quantity(x0, "m")
    md["y_offset"] = quantity(y0, "m")
    return Topography(heights.reshape(ny, nx), dx, dy, md)


@register_reader(FORMAT, extensions=("xyz", "csv", "txt", "dat"),
                 description="x z / x y z coordinate text", magic=_is_xyz, priority=90)
def decode(buf: bytes, name: str, unit: str | None = None,
           height_unit: str | None = None) -> Profile | Topography:
    """Read coordinate text (see the module docstring).

    Parameters
    ----------
    unit : str
        Unit of the x (and y) column, default metres.
    height_unit : str, optional
        Unit of the z column; default ``unit``.
    """
    sources = {"height_unit_source": ASSUMED if unit is None and height_unit is None else USER,
               "lateral_unit_source": ASSUMED if unit is None else USER}
    unit = "m" if unit is None else unit
    lateral = _factor(unit, "unit=")
    zunit = unit if height_unit is None else height_unit
    vertical = _factor(zunit, "height_unit=")
    table, delim, _ = _table(buf, name)
    z = table[:, -1] * vertical
    z[~np.isfinite(z)] = np.nan
    md: dict[str, Any] = {
        "height_unit": zunit,
        "lateral_unit": unit,
        "lateral_calibrated": True,
        **sources,
        "delimiter": _DELIMS.get(delim, "whitespace") if delim else "whitespace",
    }
    if table.shape[1] == 2:
        return _profile(table[:, 0] * lateral, z, name, md)
    return _grid(table[:, 0] * lateral, table[:, 1] * lateral, z, name, md)


__all__ = ["decode"]
