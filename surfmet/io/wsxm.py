"""WSxM image files (``.top``, ``.stp``, ``.tom``, ``.cur``), the format of the WSxM SPM
software (Horcas et al., Rev. Sci. Instrum. 78, 013705 (2007)).

A Latin-1 text header: ``WSxM file copyright ...``, ``SxM Image file``, ``Image header size:
N``, then ``[Section]`` lines and indented ``Key: value`` lines up to ``[Header end]``; the
data start at byte N: ``Number of rows`` lines of ``Number of columns`` values of the
``Image Data Type`` (``short``/``integer``: int16, ``float``, ``double``), little endian.

Heights: value x ``Z Amplitude`` / (``Maximum`` - ``Minimum``) of ``[Miscellaneous]`` (the
extreme stored values), in the unit of ``Z Amplitude``, the rule of SurfaceTopography's
``WSXMReader``; the physical size is ``X Amplitude`` x ``Y Amplitude`` of ``[Control]``.
"""

from __future__ import annotations

import datetime as _dt
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "wsxm"
_DTYPES = {"short": "<i2", "integer": "<i2", "float": "<f4", "double": "<f8"}
_MAX_HEADER = 1 << 20


def _is_wsxm(buf: bytes) -> bool:
    return buf.startswith(b"WSxM file copyright") and b"SxM Image file" in buf[:200]


def _header(buf: bytes, r: ByteReader) -> tuple[dict[str, dict[str, str]], int]:
    lines = buf[:600].decode("latin-1").splitlines()
    size_line = next((ln for ln in lines[:4] if ln.startswith("Image header size:")), None)
    if size_line is None:
        r.fail("no 'Image header size:' line")
    try:
        size = int(size_line.split(":", 1)[1])
    except ValueError:
        r.fail(f"{size_line.strip()!r}: the size is not an integer")
    if not 0 < size <= min(len(buf), _MAX_HEADER):
        r.fail(f"header size {size} does not fit the file ({len(buf)} bytes)")
    sections: dict[str, dict[str, str]] = {}
    current: dict[str, str] | None = None
    for raw in buf[:size].decode("latin-1").splitlines()[3:]:
        line = raw.strip()
        if line.startswith("[") and line.endswith("]"):
            current = sections.setdefault(line[1:-1], {})
        elif current is not None and ":" in line:
            key, _, value = line.partition(":")
            current[key.strip()] = value.strip()
    return sections, size


def _quantity(text: str | None, r: ByteReader, what: str) -> tuple[float, str]:
    parts = (text or "").split()
    if len(parts) != 2:
        r.fail(f"{what} {text!r} is not 'value unit'")
    try:
        return float(parts[0]) * length_factor(parts[1]), parts[1]
    except (ValueError, SurfmetInputError):
        r.fail(f"{what} {text!r} is not a length")


@register_reader(FORMAT, extensions=("top", "stp", "tom", "cur"), description="WSxM image",
                 magic=_is_wsxm, priority=30)
def decode(buf: bytes, name: str) -> Topography:
    """Read a WSxM image."""
    r = ByteReader(buf, name, FORMAT)
    if not _is_wsxm(buf):
        r.fail("does not start with 'WSxM file copyright' and 'SxM Image file'")
    sections, start = _header(buf, r)
    info = sections.get("General Info", {})
    control = sections.get("Control", {})
    misc = sections.get("Miscellaneous", {})
    kind = info.get("Image Data Type", "short").lower()
    if kind not in _DTYPES:
        r.fail(f"image data type {kind!r} is not short, integer, float or double")
    nx, ny = check_grid(info.get("Number of columns"), info.get("Number of rows"), name, FORMAT)
    r.seek(start, "data")
    raw = r.array(_DTYPES[kind], nx * ny, "image data").reshape(ny, nx)
    sx, xunit = _quantity(control.get("X Amplitude"), r, "X Amplitude")
    sy, _ = _quantity(control.get("Y Amplitude"), r, "Y Amplitude")
    zamp, zunit = _quantity(info.get("Z Amplitude"), r, "Z Amplitude")
    try:
        span = float(misc["Maximum"]) - float(misc["Minimum"])
    except (KeyError, ValueError):
        r.fail("[Miscellaneous] Maximum / Minimum are missing: the height scale is unknown")
    if not (np.isfinite(span) and span > 0):
        r.fail(f"Maximum - Minimum = {span!r}: the height scale is unusable")
    with np.errstate(invalid="ignore", over="ignore"):
        z = raw.astype(np.float64) * (zamp / span)
    z[~np.isfinite(z)] = np.nan
    dx = check_step(sx / nx, name, FORMAT, "x pixel size")
    dy = check_step(sy / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"height_unit": zunit, "lateral_unit": xunit,
                          "lateral_calibrated": True, "data_type": kind}
    for key, label in (("Acquisition channel", "channel"), ("Head type", "instrument")):
        if info.get(key):
            md[label] = info[key]
    try:
        when = info.get("Acquisition time", "")
        md["date"] = _dt.datetime.strptime(when.split(".")[0], "%d/%m/%Y, %H:%M:%S").isoformat()
    except ValueError:
        pass
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
