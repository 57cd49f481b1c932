"""Park Systems TIFF files (``.tiff``/``.tif``): the height data in private TIFF tags.

The file is a classic TIFF (a preview image for ordinary viewers) whose first image file
directory carries four private tags: 50432, the Park magic number ``0x0E031301``; 50433, the
version (``0x1000001`` or ``0x1000002``); 50434, the raw data; 50435, a binary header
(little endian; text fields are UTF-16). The TIFF directory is parsed here directly
(TIFF 6.0 specification, section 2: byte order mark, IFD offset, 12-byte entries).

Header fields used (byte offsets): the source name at 4 (32 characters), ``nx``, ``ny`` at
100 and 104 (uint32), the physical sizes in µm at 140 and 148 (float64), the data gain and
scale factor at 220 and 228 (float64), the data unit at 244 (8 characters) and, in version
2, the data type at 348 (0 int16, 1 int32, 2 float32; version 1 is int16). Height = value x
scale factor x gain in the data unit, the rule of SurfaceTopography's ``PSReader`` and of
Gwyddion's ``psia.c``.
"""

from __future__ import annotations

import struct
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "park"
_PARK_MAGIC = 0x0E031301
_VERSIONS = {0x1000001: 1, 0x1000002: 2}
_TAG_MAGIC, _TAG_VERSION, _TAG_DATA, _TAG_HEADER = 50432, 50433, 50434, 50435
_TIFF_TYPES = {1: 1, 2: 1, 3: 2, 4: 4, 5: 8, 6: 1, 7: 1, 8: 2, 9: 4, 10: 8, 11: 4, 12: 8}
_DTYPES = {0: "<i2", 1: "<i4", 2: "<f4"}


def _ifd0(buf: bytes) -> tuple[str, dict[int, tuple[int, int, int]]] | None:
    """Byte order and ``{tag: (type, count, value-or-offset field position)}`` of IFD 0."""
    if buf[:4] == b"II*\0":
        order = "<"
    elif buf[:4] == b"MM\0*":
        order = ">"
    else:
        return None
    (first,) = struct.unpack_from(order + "I", buf, 4)
    (n,) = struct.unpack_from(order + "H", buf, first)
    entries = {}
    for k in range(n):
        pos = first + 2 + 12 * k
        tag, kind, count = struct.unpack_from(order + "HHI", buf, pos)
        entries[tag] = (kind, count, pos + 8)
    return order, entries


def _value(buf: bytes, order: str, entry: tuple[int, int, int]) -> bytes:
    kind, count, field = entry
    size = _TIFF_TYPES.get(kind, 1) * count
    if size <= 4:
        return buf[field:field + size]
    (offset,) = struct.unpack_from(order + "I", buf, field)
    if offset + size > len(buf):
        raise struct.error(f"tag data at {offset} (+{size}) lie outside the file")
    return buf[offset:offset + size]


def _is_park(buf: bytes) -> bool:
    try:
        parsed = _ifd0(buf)
        if parsed is None or _TAG_MAGIC not in parsed[1]:
            return False
        order, entries = parsed
        return struct.unpack(order + "I", _value(buf, order, entries[_TAG_MAGIC])[:4])[0] \
            == _PARK_MAGIC
    except struct.error:
        return False


def _utf16(raw: bytes) -> str:
    return raw.decode("utf-16-le", errors="replace").split("\0", 1)[0].strip()


@register_reader(FORMAT, extensions=("tiff", "tif"), description="Park Systems TIFF",
                 magic=_is_park, priority=30)
def decode(buf: bytes, name: str) -> Topography:
    """Read the height map of a Park Systems TIFF."""
    r = ByteReader(buf, name, FORMAT)
    parsed = _ifd0(buf)
    if parsed is None:
        r.fail("not a TIFF file")
    order, entries = parsed
    for tag in (_TAG_MAGIC, _TAG_VERSION, _TAG_DATA, _TAG_HEADER):
        if tag not in entries:
            r.fail(f"TIFF tag {tag} is missing: not a Park Systems TIFF")
    if struct.unpack(order + "I", _value(buf, order, entries[_TAG_MAGIC])[:4])[0] != _PARK_MAGIC:
        r.fail("wrong Park magic number in tag 50432")
    (version,) = struct.unpack(order + "I", _value(buf, order, entries[_TAG_VERSION])[:4])
    if version not in _VERSIONS:
        r.fail(f"Park TIFF version {version:#x} (only 1 and 2 are read)")
    head = _value(buf, order, entries[_TAG_HEADER])
    if len(head) < (580 if _VERSIONS[version] == 2 else 356):
        r.fail(f"Park header of {len(head)} bytes is too short")
    h = ByteReader(head, name, FORMAT)
    px, py = h.unpack_at(100, "<II")
    nx, ny = check_grid(px, py, name, FORMAT)
    sx, sy = h.unpack_at(140, "<dd")
    gain, scale = h.unpack_at(220, "<dd")
    unit = _utf16(head[244:260])
    kind = h.unpack_at(348, "<I")[0] if _VERSIONS[version] == 2 else 0
    if kind not in _DTYPES:
        r.fail(f"data type {kind} (0 int16, 1 int32, 2 float32 expected)")
    try:
        zf = length_factor(unit)
    except SurfmetInputError:
        r.fail(f"data unit {unit!r} is not a length: not a height channel")
    data = _value(buf, order, entries[_TAG_DATA])
    raw = ByteReader(data, name, FORMAT).array(_DTYPES[kind], nx * ny, "height data")
    with np.errstate(invalid="ignore", over="ignore"):
        z = raw.reshape(ny, nx).astype(np.float64) * (scale * gain * zf)
    z[~np.isfinite(z)] = np.nan
    dx = check_step(sx * 1e-6 / nx, name, FORMAT, "x pixel size")
    dy = check_step(sy * 1e-6 / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"vendor": "Park Systems", "channel": _utf16(head[4:68]),
                          "mode": _utf16(head[68:84]), "height_unit": unit,
                          "lateral_unit": "µm", "lateral_calibrated": True,
                          "file_version": _VERSIONS[version]}
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
