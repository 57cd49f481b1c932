"""Height matrices in text form: one line per row (along x), rows stacked along y.

Three flavours are recognised:

* **Interferometer matrix export** (as in SurfaceTopography's ``matrix-4.txt``)::

      h=305 w=75
      pixel size=3.69862e-007 m
      data unit=rad
      height conversion factor (-> m)=2.91818e-008
      -4.448661 -4.596037 ...

  ``h`` is the number of rows (points along y), ``w`` the number of columns (along x),
  ``pixel size`` the lateral step with its unit. The values are in ``data unit`` (here
  phase in radians); the ``height conversion factor (-> unit)`` turns them into lengths,
  and is applied: heights = value * factor (in the unit named in the arrow, metres here).
* **Gwyddion ASCII export**: ``# Channel:``, ``# Width: 10 µm``, ``# Height: 10 µm``,
  ``# Value units: m`` comment lines, then the matrix.
* **Bare matrix** of numbers separated by blanks, commas, semicolons or tabs. It carries
  no unit and no pixel size: it is read as heights in metres with ``dx = dy = 1`` m, both
  marked assumed (:class:`surfmet._model.Calibration`); ``height_unit=`` and ``dx=`` /
  ``dy=`` of :func:`surfmet.read` state them (a unit the header states cannot be
  contradicted: it is refused).

``nan``, ``bad``, ``inf`` and ``-inf`` tokens mark non-measured points (NaN).
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import ASSUMED, STATED, USER, Topography
from surfmet.io._binary import (
    MAX_POINTS,
    check_grid,
    check_step,
    decode_text,
    format_error,
    looks_like_text,
)
from surfmet.io._calibration import contradiction
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "asc"
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_SPLIT = re.compile(r"[\s,;]+")
_MISSING = {"nan", "bad", "inf", "-inf", "+inf", "infinite"}
_SIZE_RE = re.compile(r"^\s*h\s*=\s*(\d+)\s+w\s*=\s*(\d+)\s*$", re.I)
_PIXEL_RE = re.compile(rf"^\s*pixel\s+size\s*=\s*({_NUMBER})\s*(\S*)\s*$", re.I)
_DATA_UNIT_RE = re.compile(r"^\s*data\s+unit\s*=\s*(\S+)\s*$", re.I)
_FACTOR_RE = re.compile(
    rf"^\s*height\s+conversion\s+factor\s*\(\s*->\s*(\S+?)\s*\)\s*=\s*({_NUMBER})\s*$", re.I)
_GWY_RE = re.compile(r"^#\s*(Channel|Width|Height|Value units)\s*:\s*(.*?)\s*$", re.I)


def _first_lines(buf: bytes, n: int = 8) -> list[str]:
    head = decode_text(buf[:4096])
    return [ln.strip() for ln in head.splitlines()[:n] if ln.strip()]


def _numeric_row(line: str) -> list[str] | None:
    tokens = [t for t in _SPLIT.split(line.strip()) if t]
    if not tokens:
        return None
    for t in tokens:
        if t.lower() in _MISSING:
            continue
        try:
            float(t)
        except ValueError:
            return None
    return tokens


def _is_asc(buf: bytes) -> bool:
    if not looks_like_text(buf):
        return False
    lines = _first_lines(buf)
    if not lines:
        return False
    if _SIZE_RE.match(lines[0]):
        return True
    gwy = [ln for ln in lines if _GWY_RE.match(ln)]
    if len(gwy) >= 2:
        return True
    # A bare matrix: the first lines are all numeric with the same number (>= 4) of columns;
    # two or three columns are coordinate lists (the xyz reader's business).
    rows = [_numeric_row(ln) for ln in lines[:-1] or lines]
    if not rows or any(row is None for row in rows):
        return False
    widths = {len(row) for row in rows}  # type: ignore[arg-type]
    return len(widths) == 1 and widths.pop() >= 4


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _parse_matrix(lines: list[str], start: int, name: str) -> np.ndarray:
    rows: list[list[str]] = []
    width = None
    for k in range(start, len(lines)):
        line = lines[k].strip()
        if not line or line.startswith("#"):
            continue
        tokens = [t for t in _SPLIT.split(line) if t]
        if width is None:
            width = len(tokens)
        elif len(tokens) != width:
            raise _fail(name, f"line {k + 1} has {len(tokens)} values, the first data line "
                              f"has {width} (truncated or damaged file?)")
        rows.append(tokens)
    if not rows:
        raise _fail(name, "no height values found")
    flat = [("nan" if t.lower() in _MISSING else t) for row in rows for t in row]
    try:
        values = np.array(flat, dtype=np.float64)
    except ValueError:
        for i, tok in enumerate(flat):
            try:
                float(tok)
            except ValueError:
                raise _fail(name, f"value {tok[:30]!r} (data line {i // len(rows[0]) + 1}) "
                                  "is not a number") from None
        raise
    values[~np.isfinite(values)] = np.nan
    return values.reshape(len(rows), len(rows[0]))


def _length(text: str, name: str, what: str) -> float:
    m = re.match(rf"^\s*({_NUMBER})\s*(.*?)\s*$", text)
    if not m:
        raise _fail(name, f"{what} {text!r} is not a length")
    unit = m.group(2) or "m"
    try:
        return float(m.group(1)) * length_factor(unit)
    except SurfmetInputError:
        raise _fail(name, f"{what} {text!r} has an unknown unit") from None


def _matrix_header(lines: list[str], first: int, name: str
                   ) -> tuple[int, dict[str, Any], float | None, float | None, str | None]:
    """Parse the ``h = .. w = ..`` header; return (first data line, header, step, z factor,
    z unit text)."""
    step = zfactor = None
    zunit_text = None
    m = _SIZE_RE.match(lines[first])
    if m is None:  # the caller matched it already
        raise _fail(name, f"line {first + 1} is not 'h = .. w = ..'")
    header: dict[str, Any] = {"h": int(m.group(1)), "w": int(m.group(2))}
    start = first + 1
    while start < len(lines) and _numeric_row(lines[start]) is None:
        line = lines[start].strip()
        if (pm := _PIXEL_RE.match(line)) is not None:
            unit = pm.group(2) or "m"
            if not pm.group(2):
                header["pixel_unit_missing"] = True  # a bare number: metres assumed
            try:
                step = float(pm.group(1)) * length_factor(unit)
            except SurfmetInputError:
                raise _fail(name, f"pixel size unit {unit!r} is not a length") from None
            header["pixel_size"] = line.split("=", 1)[1].strip()
            header["lateral_unit"] = unit
        elif (um := _DATA_UNIT_RE.match(line)) is not None:
            header["data_unit"] = um.group(1)
        elif (fm := _FACTOR_RE.match(line)) is not None:
            zunit_text = fm.group(1)
            try:
                zfactor = float(fm.group(2)) * length_factor(zunit_text)
            except SurfmetInputError:
                raise _fail(name, f"height conversion unit {zunit_text!r} is not a "
                                  "length") from None
            header["height_conversion_factor"] = float(fm.group(2))
            header["height_conversion_unit"] = zunit_text
        elif line and "=" in line:
            key, value = line.split("=", 1)
            header[key.strip()] = value.strip()
        elif line:
            raise _fail(name, f"cannot read header line {line[:60]!r}")
        start += 1
    return start, header, step, zfactor, zunit_text


def _gwyddion_header(lines: list[str], start: int) -> tuple[int, dict[str, str]]:
    """Skip comment lines; collect Gwyddion's ``# Key: value`` entries."""
    gwy: dict[str, str] = {}
    while start < len(lines):
        line = lines[start].strip()
        if line.startswith("#") or not line:
            if (gm := _GWY_RE.match(line)) is not None:
                gwy[gm.group(1).lower()] = gm.group(2)
            start += 1
            continue
        break
    return start, gwy


def _pixel_sizes(flavour: str, header: dict[str, Any], step: float | None, nx: int, ny: int,
                 name: str) -> tuple[float, float, bool]:
    """Pixel sizes from the header, else 1 m; and whether the header states them."""
    sx = sy = None
    if flavour == "gwyddion":
        if "width" in header:
            sx = _length(header["width"], name, "Width") / nx
        if "height" in header:
            sy = _length(header["height"], name, "Height") / ny
    elif step is not None:
        sx = sy = step
    lateral_calibrated = sx is not None and not header.get("pixel_unit_missing")
    if sx is None:
        sx = 1.0
    if sy is None:
        sy = sx
    sx = check_step(sx, name, FORMAT, "x pixel size")
    sy = check_step(sy, name, FORMAT, "y pixel size")
    return sx, sy, lateral_calibrated


def _height_factor(flavour: str, header: dict[str, Any], zfactor: float | None,
                   zunit_text: str | None, height_unit: str | None, name: str
                   ) -> tuple[float, str, str]:
    """Factor from file values to metres, the unit it came from, and who stated it."""
    stated = zfactor is not None or (flavour == "matrix" and "data_unit" in header) or (
        flavour == "gwyddion" and "value units" in header)
    if height_unit is not None:
        if stated:
            factor, unit = _stated_height(flavour, header, zfactor, zunit_text, name)
            same = length_factor(unit)  # the stated unit (after any conversion factor)
            if abs(same - length_factor(height_unit)) > 1e-12 * same:
                raise contradiction(name, "height unit", unit, height_unit)
            return factor, unit, STATED
        return length_factor(height_unit), height_unit, USER
    factor, unit = _stated_height(flavour, header, zfactor, zunit_text, name)
    return factor, unit, STATED if stated else ASSUMED


def _stated_height(flavour: str, header: dict[str, Any], zfactor: float | None,
                   zunit_text: str | None, name: str) -> tuple[float, str]:
    if zfactor is not None:
        return zfactor, zunit_text or "m"
    if flavour == "matrix" and "data_unit" in header:
        unit_name = str(header["data_unit"])
        try:
            return length_factor(unit_name), unit_name
        except SurfmetInputError:
            raise _fail(name, f"data unit {unit_name!r} is not a length and the header gives no "
                              "height conversion factor; pass height_unit=") from None
    if flavour == "gwyddion" and "value units" in header:
        unit_name = header["value units"]
        try:
            return length_factor(unit_name), unit_name
        except SurfmetInputError:
            raise _fail(name, f"value unit {unit_name!r} is not a length; pass "
                              "height_unit=") from None
    return 1.0, "m"


@register_reader(FORMAT, extensions=("asc", "txt", "mat"), description="text height matrix",
                 magic=_is_asc, priority=70)
def decode(buf: bytes, name: str, height_unit: str | None = None) -> Topography:
    """Read a text height matrix (see the module docstring for the flavours)."""
    lines = decode_text(buf).splitlines()
    header: dict[str, Any] = {}
    first = 0
    while first < len(lines) and not lines[first].strip():
        first += 1
    step = zfactor = None
    zunit_text = None
    if first < len(lines) and _SIZE_RE.match(lines[first]):
        flavour = "matrix"
        start, header, step, zfactor, zunit_text = _matrix_header(lines, first, name)
    else:
        start, gwy = _gwyddion_header(lines, first)
        flavour = "gwyddion" if gwy else "bare"
        header.update(gwy)

    data = _parse_matrix(lines, start, name)
    ny, nx = data.shape
    check_grid(nx, ny, name, FORMAT)
    if flavour == "matrix" and (header["h"], header["w"]) != (ny, nx):
        raise _fail(name, f"the header announces h={header['h']} rows of w={header['w']} "
                          f"values but the file holds {ny} rows of {nx} (truncated?)")
    if nx * ny > MAX_POINTS:  # pragma: no cover - bounded by the file size anyway
        raise _fail(name, "absurd grid")

    metadata: dict[str, Any] = {"layout": flavour}
    if header:
        metadata["header"] = header
    sx, sy, lateral_calibrated = _pixel_sizes(flavour, header, step, nx, ny, name)
    factor, unit_name, height_source = _height_factor(flavour, header, zfactor, zunit_text,
                                                      height_unit, name)
    if flavour == "matrix" and "lateral_unit" in header:
        lateral_unit = header["lateral_unit"]
    else:
        lateral_unit = "m" if lateral_calibrated else ""
    metadata.update({
        "height_unit": unit_name,
        "lateral_unit": lateral_unit,
        "lateral_calibrated": bool(lateral_calibrated),
        "height_unit_source": height_source,
        "lateral_unit_source": STATED if lateral_calibrated else ASSUMED,
    })
    if flavour == "matrix" and "data_unit" in header:
        metadata["data_unit"] = header["data_unit"]
    return Topography(data * factor, sx, sy, metadata)

__all__ = ["decode"]
