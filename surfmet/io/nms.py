"""NanoFocus µsurf ``.nms`` files (confocal microscope; the instrument of Alaci et al. 2022).

Layout (little endian), established on a real µsurf file and consistent with the
``musurf-reader`` project of D. Mendroch (github.com/drocheam/musurf-reader), which reads
the OM_MS_2.0 version of the format:

======  =====  ===============================================================
offset  type   field
======  =====  ===============================================================
0       i32    data type (2 = unsigned 16-bit heights)
4       i32    dimension type (0 = profile, 1 = area)
8       i32    lowest raw value ``n_low``
12      i32    highest raw value ``n_high``
16      f64    height of ``n_low`` and of ``n_high`` in micrometres (2 x f64)
32      10s    format version ``OM_MS_2.0``
52      s      title, e.g. ``Confocal Height Image``
1076    s      acquisition date, ISO 8601 text (``2022-02-09T13:25``)
1096    s      operator
1352    i32    header size (3468: the offset of the heights)
1368    u32    points per line (nx), number of lines (ny)
1376    f64    lateral steps along x and y **in nanometres** (2 x f64)
1392    f64    stage position x, y, z (3 x f64)
1416    i32    1 when an 8-bit intensity image follows the heights
3468    u16    ny lines of nx raw heights
...     u8     ny x nx intensities (when present)
======  =====  ===============================================================

Height = ``f_low + (raw - n_low) * (f_high - f_low) / (n_high - n_low)`` micrometres.
Points whose intensity is 0 were not measured and become NaN.

The lateral step is in nanometres: 312.5 in the header is a 0.3125 µm pixel (a 160 µm field
for 512 points, that of a 50x objective). SurfaceTopography 1.27.1 reads it as millimetres
and reports 312 500 µm pixels (a 160 m wide field); surfalize reads it as nanometres.
SurfaceTopography also scales by 65534 instead of the header's ``n_high - n_low``
(= 65535), a 1.5e-5 relative error; surfalize adds ``f_high`` instead of ``f_low``.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from surfmet._model import Profile, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader

FORMAT = "nms"
VERSION_OFFSET = 32
VERSION_PREFIX = b"OM_MS_"
HEADER_SIZE = 3468
_HEADER_SIZE_FIELD = 1352


def _is_nms(buf: bytes) -> bool:
    return (len(buf) >= HEADER_SIZE
            and buf[VERSION_OFFSET:VERSION_OFFSET + len(VERSION_PREFIX)] == VERSION_PREFIX)


def _text(r: ByteReader, offset: int, size: int, what: str) -> str:
    r.seek(offset)
    return r.cstring(size, what)


@register_reader(FORMAT, extensions=("nms", "orginal"),
                 description="NanoFocus µsurf NMS (confocal, 16-bit heights)",
                 magic=_is_nms, priority=20)
def decode(buf: bytes, name: str) -> Topography | Profile:
    """Read a NanoFocus ``.nms`` file (heights in metres)."""
    r = ByteReader(buf, name, FORMAT)
    if buf[VERSION_OFFSET:VERSION_OFFSET + len(VERSION_PREFIX)] != VERSION_PREFIX:
        r.fail("missing the 'OM_MS_' format version at offset 32")
    version = _text(r, VERSION_OFFSET, 20, "format version")
    dtype_code, dim_code, n_low, n_high = r.unpack_at(0, "<4i", "data description")
    f_low, f_high = r.unpack_at(16, "<2d", "height range")
    if dtype_code != 2:
        r.fail(f"data type code {dtype_code} is not supported (2 = 16-bit heights)")
    if dim_code not in (0, 1):
        r.fail(f"dimension code {dim_code} is neither 0 (profile) nor 1 (area)")
    if not (0 <= n_low < n_high <= 65535):
        r.fail(f"raw height range {n_low}..{n_high} is not a valid 16-bit range")
    if not (np.isfinite(f_low) and np.isfinite(f_high)) or f_high == f_low:
        r.fail(f"height range {f_low!r}..{f_high!r} µm is unusable")
    (header_size,) = r.unpack_at(_HEADER_SIZE_FIELD, "<i", "header size")
    if header_size != HEADER_SIZE:
        r.fail(f"header size field says {header_size}, expected {HEADER_SIZE} for "
               f"{version or 'this version'}")
    nx, ny = r.unpack_at(1368, "<2I", "grid size")
    step_x, step_y = r.unpack_at(1376, "<2d", "lateral steps")
    stage = r.unpack_at(1392, "<3d", "stage position")
    (has_intensity,) = r.unpack_at(1416, "<i", "intensity flag")
    nx, ny = check_grid(nx, ny, name, FORMAT, available=len(buf) - HEADER_SIZE, itemsize=2)
    r.seek(HEADER_SIZE)
    raw = r.array("<u2", nx * ny, "heights")
    with np.errstate(over="ignore", invalid="ignore"):
        z = f_low + (raw.astype(np.float64) - n_low) * ((f_high - f_low) / (n_high - n_low))
        z *= 1e-6
    if not np.all(np.isfinite(z)):
        r.fail(f"height range {f_low!r}..{f_high!r} µm overflows")
    n_invalid = 0
    if has_intensity:
        intensity = r.array("u1", nx * ny, "intensity image")
        bad = intensity == 0
        n_invalid = int(np.count_nonzero(bad))
        z[bad] = np.nan
    dx = check_step(step_x * 1e-9, name, FORMAT, "x step (nm)")
    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "NanoFocus",
        "instrument": "µsurf",
        "format_version": version,
        "height_unit": "um",
        "lateral_unit": "nm",
        "lateral_calibrated": True,
        "raw_range": (n_low, n_high),
        "height_range_um": (f_low, f_high),
        "has_intensity": bool(has_intensity),
        "non_measured_points": n_invalid,
        "stage_position": tuple(float(s) for s in stage),
    }
    title = _text(r, 52, 200, "title")
    if title:
        md["title"] = title
    date = _text(r, 1076, 20, "date")
    if re.match(r"^\d{4}-\d{2}-\d{2}", date):
        md["date"] = date
    operator = _text(r, 1096, 64, "operator")
    if operator and operator.lower() != "unknown":
        md["operator"] = operator
    if dim_code == 0 or ny == 1:
        return Profile(z, dx, metadata=md)
    dy = check_step(step_y * 1e-9, name, FORMAT, "y step (nm)")
    return Topography(z.reshape(ny, nx), dx, dy, md)


__all__ = ["decode"]
