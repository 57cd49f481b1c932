"""BCR-STM and BCRF files (``.bcr``, ``.bcrf``), the image exchange format of Image
Metrology's SPIP and of MountainsMap exports.

A text header of ``key = value`` lines (``%`` and ``#`` lines are comments) fills the first
``headersize`` characters (2048 or 4096); in the ``*_unicode`` flavours it is UTF-16LE,
so the header takes twice as many bytes. Keys used: ``fileformat`` (``bcrstm``: int16
counts; ``bcrf``: float32), ``xpixels``, ``ypixels``, ``xlength``, ``ylength`` in
``xunit`` / ``yunit``, ``zunit``, ``bit2nm`` (the height scale), ``intelmode`` (1 = little
endian) and ``voidpixels`` (the value of a non-measured point). The data follow the header,
``ypixels`` lines of ``xpixels`` values.

Height = value x ``bit2nm`` in ``zunit``, SurfaceTopography's ``BCRReader`` rule (checked
there against MountainsMap's own export of the same scan, ``mnt-1.mnt``, which reads to the
same heights here too); void pixels become NaN.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "bcr"
_FLAVOURS = {"bcrstm": "i2", "bcrf": "f4", "bcrstm_unicode": "i2", "bcrf_unicode": "f4"}
_MAX_HEADER = 65536


def _encoding(buf: bytes) -> str | None:
    if buf[:10] == b"fileformat":
        return "latin-1"
    if buf[:20] == "fileformat".encode("utf-16-le"):
        return "utf-16-le"
    return None


def _is_bcr(buf: bytes) -> bool:
    return _encoding(buf) is not None


def _header(buf: bytes, r: ByteReader) -> tuple[dict[str, str], int]:
    enc = _encoding(buf)
    if enc is None:  # decode refused such a file already
        r.fail("does not start with 'fileformat'")
    width = 2 if enc == "utf-16-le" else 1
    head = buf[:_MAX_HEADER * width]
    if width == 2:
        head = head[: len(head) // 2 * 2]
    text = head.decode(enc, errors="replace")
    values: dict[str, str] = {}
    for raw in text.split("\n"):
        line = raw.strip().strip("\0")
        if not line or line.startswith(("%", "#")) or "=" not in line:
            continue
        key, _, value = line.partition("=")
        values.setdefault(key.strip().lower(), value.strip())
    try:
        size = int(values.get("headersize", ""))
    except ValueError:
        r.fail(f"headersize {values.get('headersize')!r} is missing or not an integer")
    if not 0 < size <= _MAX_HEADER:
        r.fail(f"headersize {size} is absurd")
    return values, size * width


def _unit(values: dict[str, str], key: str, r: ByteReader) -> float:
    try:
        return length_factor(values.get(key, ""))
    except SurfmetInputError:
        r.fail(f"{key} {values.get(key)!r} is not a length unit")


@register_reader(FORMAT, extensions=("bcr", "bcrf"), description="BCR-STM / BCRF (SPIP)",
                 magic=_is_bcr, priority=40)
def decode(buf: bytes, name: str) -> Topography:
    """Read a BCR-STM or BCRF height map."""
    r = ByteReader(buf, name, FORMAT)
    if _encoding(buf) is None:
        r.fail("does not start with 'fileformat'")
    values, data_start = _header(buf, r)
    flavour = values.get("fileformat", "").lower()
    if flavour not in _FLAVOURS:
        r.fail(f"unknown fileformat {flavour!r}")
    dtype = np.dtype(("<" if values.get("intelmode", "1") == "1" else ">") + _FLAVOURS[flavour])
    nx, ny = check_grid(values.get("xpixels"), values.get("ypixels"), name, FORMAT)
    xf, yf, zf = (_unit(values, k, r) for k in ("xunit", "yunit", "zunit"))
    scale = float(values.get("bit2nm", "1"))
    if not (np.isfinite(scale) and scale != 0):
        r.fail(f"bit2nm {values.get('bit2nm')!r} is not a usable scale")
    r.seek(data_start, "data")
    raw = r.array(dtype, nx * ny, "height data").reshape(ny, nx)
    with np.errstate(invalid="ignore", over="ignore"):
        z = raw.astype(np.float64) * (scale * zf)
    void = values.get("voidpixels")
    if void is not None:
        z[raw == dtype.type(float(void))] = np.nan
    z[~np.isfinite(z)] = np.nan
    dx = check_step(float(values.get("xlength", "nan")) * xf / nx, name, FORMAT, "x pixel size")
    dy = check_step(float(values.get("ylength", "nan")) * yf / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"file_type": flavour, "height_unit": values.get("zunit"),
                          "lateral_unit": values.get("xunit"), "lateral_calibrated": True,
                          "bit2nm": scale}
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
