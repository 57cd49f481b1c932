"""Sensofar ``.plu`` files (PLu 2300 / 3300 / neox confocal and interferometric profilers).

Layout (little endian), after Gwyddion's ``sensofar.c`` and checked against a real PLu neox
file:

======  =====  ===============================================================
offset  type   field
======  =====  ===============================================================
0       128s   acquisition date as text (C ``ctime`` style, NUL padded)
128     u32    acquisition time (Unix seconds)
132     256s   user comment
388     u32    yres, xres, N_tall (3 x u32) of the calibration block
400     f32    dy_multip, mppx, mppy, x_0, y_0, mpp_tall, z_0 (7 x f32): microns
               per pixel along x and y, stage offsets
428     u32    measurement type (0 image, 1 profile, 2 multi-profile, 3 topography,
               4 coordinates, 5 thickness, 6 custom), algorithm, method,
               objective, area type (5 x u32)
448     40 B   scan settings (area sizes, NA, z increment, range, planes...)
488     u8     restore, number of layers, format version, hardware
               configuration, stack image count, 3 reserved bytes
496     u32    "factor delmacio"
500     u32    rows (y), columns (x) of the first layer
508     f32    rows x columns heights in micrometres, row by row
======  =====  ===============================================================

Non-measured points hold 1000001.0 and become NaN.

The layer's own (rows, columns) pair at offset 500 is part of the layer, not of the
heights: surfalize 0.19 reads the heights from offset 500, so its maps start with the two
dimension integers (read as tiny floats) and are shifted by two samples. Here the layer
grid is read from 500 and must agree with the calibration block; the heights start at 508.
"""

from __future__ import annotations

import datetime as _dt
import re
import struct
from typing import Any

import numpy as np

from surfmet._model import Profile, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader

FORMAT = "plu"
DATE_SIZE = 128
COMMENT_SIZE = 256
CALIBRATION_OFFSET = DATE_SIZE + 4 + COMMENT_SIZE  # 388
MEASURE_OFFSET = CALIBRATION_OFFSET + 40  # 428
LAYERS_OFFSET = 500
NON_MEASURED = np.float32(1000001.0)

MEASUREMENT_TYPES = {0: "image", 1: "profile", 2: "multi-profile", 3: "topography",
                     4: "coordinates", 5: "thickness", 6: "custom"}
ALGORITHMS = {0: "confocal intensity", 1: "confocal gradient", 2: "interferometric PSI",
              3: "interferometric VSI/ePSI", 4: "confocal thickness",
              5: "interferometric thickness"}
# Hardware codes as documented by Gwyddion; later instruments use codes beyond these.
HARDWARE = {0: "PLu", 1: "PLu 2300 XGA", 2: "PLu 2300 XGA T5", 3: "PLu 2300 SXGA",
            4: "PLu 3300"}

_CTIME_RE = re.compile(
    rb"^(Mon|Tue|Wed|Thu|Fri|Sat|Sun) (Jan|Feb|Mar|Apr|May|Jun|Jul|Aug|Sep|Oct|Nov|Dec) "
    rb"[ \d]\d \d\d:\d\d:\d\d \d{4}"
)
_DATE_LIKE_RE = re.compile(rb"^[\x20-\x7e]{8,127}$")


def _header_grid(buf: bytes) -> tuple[int, int, int, int] | None:
    if len(buf) < LAYERS_OFFSET + 8:
        return None
    yres, xres = struct.unpack_from("<II", buf, CALIBRATION_OFFSET)
    ly, lx = struct.unpack_from("<II", buf, LAYERS_OFFSET)
    return yres, xres, ly, lx


def _is_plu(buf: bytes) -> bool:
    # No signature: the file starts with a printable date (NUL padded to 128 bytes), and the
    # calibration grid equals the first layer's grid at offset 500, which must fit the file.
    if len(buf) < LAYERS_OFFSET + 12:
        return False
    date = buf[:DATE_SIZE].split(b"\0", 1)[0]
    datelike = _DATE_LIKE_RE.match(date) and re.search(rb"\d{4}", date)
    if not (_CTIME_RE.match(date) or datelike):
        return False
    if buf[len(date):DATE_SIZE].strip(b"\0"):
        return False
    grid = _header_grid(buf)
    if grid is None:
        return False
    yres, xres, ly, lx = grid
    if (ly, lx) != (yres, xres) or not (0 < xres and 0 < yres):
        return False
    return LAYERS_OFFSET + 8 + 4 * xres * yres <= len(buf)


def _iso_date(text: str, unix: int) -> str | None:
    try:
        return _dt.datetime.strptime(" ".join(text.split()), "%a %b %d %H:%M:%S %Y").isoformat()
    except ValueError:
        pass
    if 0 < unix < 2**31:
        return _dt.datetime.fromtimestamp(unix, _dt.timezone.utc).isoformat()
    return None


@register_reader(FORMAT, extensions=("plu", "apx"),
                 description="Sensofar PLu (confocal / interferometric profiler)",
                 magic=_is_plu, priority=60)
def decode(buf: bytes, name: str) -> Topography | Profile:
    """Read the first layer of a Sensofar ``.plu`` file (heights in metres)."""
    r = ByteReader(buf, name, FORMAT)
    date_text = r.cstring(DATE_SIZE, "date")
    (unix,) = r.unpack("<I", "time stamp")
    comment = r.cstring(COMMENT_SIZE, "comment")
    yres, xres, _n_tall = r.unpack("<3I", "calibration grid")
    _dy_multip, mppx, mppy, x0, y0, _mpp_tall, z0 = r.unpack("<7f", "calibration")
    mtype, algorithm, method, objective, area = r.unpack("<5I", "measurement configuration")
    r.seek(488, "layer settings")
    _restore, n_layers, version, hardware, _n_images = r.unpack("<5B", "layer settings")
    r.seek(LAYERS_OFFSET)
    ly, lx = r.unpack("<II", "layer grid")
    if mtype not in (1, 3, 5):
        kind = MEASUREMENT_TYPES.get(mtype, f"code {mtype}")
        r.fail(f"measurement type {kind!r} holds no heights (only topography, profile and "
               "thickness measurements are read)")
    if n_layers < 1:
        r.fail("the file declares no data layer")
    if (ly, lx) != (yres, xres):
        r.fail(f"the first layer's grid {lx} x {ly} differs from the calibration grid "
               f"{xres} x {yres}")
    nx, ny = check_grid(lx, ly, name, FORMAT, available=r.remaining, itemsize=4)
    raw = r.array("<f4", nx * ny)
    bad = (raw == NON_MEASURED) | ~np.isfinite(raw)
    with np.errstate(invalid="ignore"):  # signalling NaNs in a damaged file
        z = raw.astype(np.float64) * 1e-6
    z[bad] = np.nan
    dx = check_step(float(mppx) * 1e-6, name, FORMAT, "x pixel size (mppx)")
    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "Sensofar",
        "height_unit": "um",
        "lateral_unit": "um",
        "lateral_calibrated": True,
        "measurement_type": MEASUREMENT_TYPES[mtype],
        "algorithm": ALGORITHMS.get(algorithm, f"code {algorithm}"),
        "method_code": method,
        "objective_code": objective,
        "area_type_code": area,
        "hardware_code": hardware,
        "format_version_code": version,
        "n_layers": n_layers,
        "stage_x0_um": float(x0),
        "stage_y0_um": float(y0),
        "z0_um": float(z0),
    }
    if hardware in HARDWARE:
        md["instrument"] = HARDWARE[hardware]
    date = _iso_date(date_text, unix)
    if date:
        md["date"] = date
    if comment and comment != "(None)":
        md["comment"] = comment
    if ny == 1:
        return Profile(z, dx, metadata=md)
    dy = check_step(float(mppy) * 1e-6, name, FORMAT, "y pixel size (mppy)")
    return Topography(z.reshape(ny, nx), dx, dy, md)


__all__ = ["decode"]
