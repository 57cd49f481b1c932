"""TrueMap binary data files (``.tmd``, version 2.0), written by TrueMap (TrueGage) 3D
surface scanners.

Layout (little endian), as read by SurfaceTopography's ``TMDReader``: a 32-byte magic
``"Binary TrueMap Data File v2.0\\r\\n"``, a 24-byte comment (``"Created by TrueMap v6"``),
``uint32`` nx and ny, ``float32`` physical lengths x and y and offsets x and y, then ny rows of
nx ``float32`` heights.

**Units.** The file states none. TrueMap scanners image fields of about 20 mm, and the sample's
18.96 x 18.96 field with heights 0 to 1 is a millimetre-scale relief, so lengths and heights are
read as millimetres (SurfaceTopography 1.27 also reports mm; its current reader says µm, which
would make a 19 µm field); both are marked assumed (:class:`surfmet._model.Calibration`), so
every output says so. Pass ``unit="um"`` to read them as micrometres instead (then stated by
the user), or state either alone with ``height_unit=`` / ``dx=``. Non-finite heights become
NaN.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._model import ASSUMED, USER, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "tmd"
_MAGIC = b"Binary TrueMap Data File v2.0"


def _is_tmd(buf: bytes) -> bool:
    return buf.startswith(_MAGIC)


@register_reader(FORMAT, extensions=("tmd",), description="TrueMap data file v2.0",
                 magic=_is_tmd, priority=30)
def decode(buf: bytes, name: str, unit: str | None = None) -> Topography:
    """Read a TrueMap height map.

    Parameters
    ----------
    unit : str, optional
        Unit of the file's lengths and heights (the file does not say); default ``"mm"``,
        assumed.
    """
    source = ASSUMED if unit is None else USER
    unit = "mm" if unit is None else unit
    factor = length_factor(unit)
    r = ByteReader(buf, name, FORMAT)
    if not _is_tmd(buf):
        r.fail("missing the 'Binary TrueMap Data File v2.0' signature")
    r.seek(32)
    comment = r.cstring(24, "comment", encoding="utf-8")
    nx, ny, lx, ly, ox, oy = r.unpack("<IIffff", "header")
    nx, ny = check_grid(nx, ny, name, FORMAT, available=r.remaining, itemsize=4)
    data = r.array("<f4", nx * ny, "height data").reshape(ny, nx)
    with np.errstate(invalid="ignore", over="ignore"):
        z = data.astype(np.float64) * factor
    z[~np.isfinite(z)] = np.nan
    dx = check_step(float(lx) * factor / nx, name, FORMAT, "x pixel size")
    dy = check_step(float(ly) * factor / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"vendor": "TrueMap", "height_unit": unit, "lateral_unit": unit,
                          "lateral_calibrated": True, "units_assumed": source == ASSUMED,
                          "height_unit_source": source, "lateral_unit_source": source,
                          "x_offset": float(ox) * factor, "y_offset": float(oy) * factor}
    if comment:
        md["comment"] = comment
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
