"""Keyence VK-X / VR ``.zon`` files: a BMP preview followed by a zip of binary and XML members.

Layout, learnt from SurfaceTopography's ``ZON.py`` and surfalize's ``zon.py`` (after
Gwyddion's ``zonfile.c``) and checked on a VR-6100 file (surfalize's ``test_1.zon``):

* 4-byte magic ``KPK0`` (members stored as they are) or ``KPK1`` (every member one zstd
  frame, RFC 8878), then a BMP preview (``BM``, uint32 size at byte 2 of the BMP) and the
  zip archive, whose members are named by UUID;
* member ``686613b8-...`` is XML ``Calibration/XYCalibration/MeterPerPixel`` and
  ``Calibration/ZCalibration/MeterPerUnit``;
* member ``4cdb0c75-...`` is the height data: a 16-byte header (uint32 width, height, item
  size 4, row stride in bytes) and int32 rows; height = value x MeterPerUnit;
* the first binary member with item size 1 and the same grid is the mask of points the
  instrument did not measure (non-zero = not measured, read as NaN, as surfalize does).

Member sizes are checked before decompression and a zstd frame is never expanded beyond
what its grid header allows.
"""

from __future__ import annotations

import io
import struct
import zipfile
from typing import Any
from xml.etree import ElementTree

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import MAX_POINTS, ByteReader, check_grid, check_step, format_error
from surfmet.io._registry import register_reader
from surfmet.io._zip import open_zip, read_member

FORMAT = "zon"
_HEIGHT = "4cdb0c75-5706-48cc-a9a1-adf395d609ae"
_CALIBRATION = "686613b8-27b5-4a29-8ffc-438c2780873e"
_DEVICE = "cbc1d39b-215f-4d56-a20e-cf8e5f570755"
_ZSTD = b"\x28\xb5\x2f\xfd"
_MAX_XML = 1 << 20
_MAX_MEMBER = 4 * MAX_POINTS // 8  # int32 heights of MAX_POINTS / 8 points


def _is_zon(buf: bytes) -> bool:
    return buf[:4] in (b"KPK0", b"KPK1") and buf[8:10] == b"BM"


def _unpack(raw: bytes, compressed: bool, limit: int, name: str, member: str) -> bytes:
    if not compressed:
        return raw
    if raw[:4] != _ZSTD:
        raise format_error(name, FORMAT, f"member {member[:8]}... is not a zstd frame")
    import zstandard

    chunks, size = [], 0
    try:
        with zstandard.ZstdDecompressor().stream_reader(io.BytesIO(raw)) as r:
            # in chunks: a read(limit) would reserve the whole limit up front
            while size <= limit and (chunk := r.read(1 << 22)):
                chunks.append(chunk)
                size += len(chunk)
    except zstandard.ZstdError as exc:
        raise format_error(name, FORMAT, f"member {member[:8]}...: corrupted zstd data "
                           f"({exc})") from None
    if size > limit:
        raise format_error(name, FORMAT, f"member {member[:8]}... expands beyond {limit} bytes")
    return b"".join(chunks)


def _xml(zf: zipfile.ZipFile, member: str, compressed: bool, name: str) -> ElementTree.Element:
    raw = _unpack(read_member(zf, member, name, FORMAT, _MAX_XML, what="XML"), compressed,
                  _MAX_XML, name, member)
    try:
        return ElementTree.fromstring(raw.removeprefix(b"\xef\xbb\xbf"))
    except ElementTree.ParseError as exc:
        raise format_error(name, FORMAT, f"member {member[:8]}... is not XML ({exc})") from None


def _number(root: ElementTree.Element, path: str, name: str) -> float:
    node = root.find(path)
    if node is None or node.text is None or not node.text.strip():
        raise format_error(name, FORMAT, f"calibration lacks {path}")
    return float(node.text)


def _grid(data: bytes, itemsize: int, name: str, what: str) -> np.ndarray:
    r = ByteReader(data, name, FORMAT)
    nx, ny, size, stride = r.unpack("<IIII", f"{what} header")
    if size != itemsize:
        r.fail(f"{what} has {size}-byte items ({itemsize} expected)")
    nx, ny = check_grid(nx, ny, name, FORMAT)
    if stride < nx * size or stride % size:
        r.fail(f"{what} row stride {stride} does not fit {nx} items of {size} bytes")
    check_grid(stride // size, ny, name, FORMAT, available=r.remaining, itemsize=size)
    dtype = "<i4" if itemsize == 4 else "u1"
    rows = r.array(dtype, (stride // size) * ny, what).reshape(ny, stride // size)
    return rows[:, :nx]


def _mask(zf: zipfile.ZipFile, compressed: bool, shape: tuple[int, int], name: str
          ) -> np.ndarray | None:
    limit = 16 + shape[0] * shape[1] * 4
    for info in zf.infolist():
        if info.filename == _HEIGHT or info.file_size < 16:
            continue
        data = _unpack(read_member(zf, info.filename, name, FORMAT, _MAX_MEMBER), compressed,
                       limit, name, info.filename)
        if len(data) < 16 or data[:1] == b"<" or data[:3] == b"\xef\xbb\xbf":
            continue
        nx, ny, size = struct.unpack_from("<III", data)
        if size == 1 and (ny, nx) == shape:
            return _grid(data, 1, name, "mask") != 0
    return None


@register_reader(FORMAT, extensions=("zon",), description="Keyence VK-X/VR ZON",
                 magic=_is_zon, priority=20)
def decode(buf: bytes, name: str) -> Topography:
    """Read the height map of a Keyence ``.zon`` file (non-measured points NaN)."""
    r = ByteReader(buf, name, FORMAT)
    magic, = r.unpack("4s", "magic")
    if magic not in (b"KPK0", b"KPK1") or buf[8:10] != b"BM":
        r.fail("no KPK magic and BMP preview at the start")
    compressed = magic == b"KPK1"
    (bmp,) = r.unpack_at(10, "<I", "BMP size")
    r.seek(8 + bmp, "zip archive")
    zf = open_zip(buf[8 + bmp:], name, FORMAT)
    cal = _xml(zf, _CALIBRATION, compressed, name)
    step = check_step(_number(cal, "XYCalibration/MeterPerPixel", name), name, FORMAT)
    z_unit = _number(cal, "ZCalibration/MeterPerUnit", name)
    if not (np.isfinite(z_unit) and z_unit > 0):
        r.fail(f"height calibration {z_unit!r} m per unit is not a positive number")
    if _HEIGHT not in zf.namelist():
        r.fail("the archive has no height data member")
    raw = read_member(zf, _HEIGHT, name, FORMAT, _MAX_MEMBER, what="height data")
    data = _unpack(raw, compressed, _MAX_MEMBER, name, _HEIGHT)
    heights = _grid(data, 4, name, "height data").astype(np.float64) * z_unit
    mask = _mask(zf, compressed, heights.shape, name)
    if mask is not None:
        heights[mask] = np.nan
    md: dict[str, Any] = {"vendor": "Keyence", "height_unit": "m", "lateral_unit": "m",
                          "lateral_calibrated": True, "height_calibration": z_unit,
                          "compressed": compressed}
    if _DEVICE in zf.namelist():
        dev = _xml(zf, _DEVICE, compressed, name)
        md["instrument"] = (dev.findtext("DeviceModelName") or "").strip()
        md["instrument_serial"] = (dev.findtext("DeviceSerialId") or "").strip()
    return Topography(heights, step, step, md)


__all__ = ["decode"]
