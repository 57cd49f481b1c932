"""FRT MicroProf ``.frt`` areal scans (binary, versions 1.00 and 1.01).

Layout (little endian), after Gwyddion's ``microprof.c`` and SurfaceTopography's
``FRT.py``, checked on a MicroProf file (serial SN_1036, 2023):

* 16-byte signature ``FRTM_GLIDERV1.00`` (or ``1.01``), then a uint16;
* a sequence of blocks ``(uint16 id, size, payload)``; ``size`` is uint32 in version 1.00
  and uint64 in 1.01. Blocks used here:

  ``0x000b``  single image: ``xres * yres`` samples (uint16 for 16 bpp, int32 for 32 bpp)
  ``0x0065``  description text; ``0x0077``: parameter-set name
  ``0x0066``  ``xres, yres, bpp`` (uint32)
  ``0x0067``  ``xrange, yrange`` (float64, metres; the scan size), offsets, scan direction
  ``0x006c``  ``meas_range`` (uint32), ``zscale`` (float64, metres per count)
  ``0x0070``  ``first_valid, last_valid`` (uint32): counts outside this range are
              undefined
  ``0x0072``  measurement start/end (Unix seconds) and duration
  ``0x007d``  multi-image buffer: 8 bytes of ids, then images, each
              ``datatype, xres, yres, bpp`` (uint32) followed by its samples
  ``0x008e``  sensor serial number (uint32 length + text)

Heights are ``count * zscale`` (block 0x006c). Undefined points are the counts outside
``[first_valid, last_valid]`` (block 0x0070); in the files seen they carry the count 1,
which is the marker Gwyddion and SurfaceTopography hard-code, and which this reader uses
only when block 0x0070 is absent (``metadata["invalid_rule"]`` says which rule applied).
Rows are kept in file order (row ``j`` at ``y = j * dy``), as SurfaceTopography does;
Gwyddion flips them for display. ``dx = xrange / xres``, ``dy = yrange / yres``.

The multi-image buffer holds the topography and other channels (intensity...). The first
topography image is read by default; ``channel=i`` picks image ``i`` of the buffer, which
must be a height channel (topography, thickness or AFM).
"""

from __future__ import annotations

import datetime as _dt
import struct
from typing import Any

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader

FORMAT = "frt"
MAGIC = b"FRTM_GLIDERV"

# Image data types of the multi-image buffer (low 16 bits, flags masked out).
_TYPE_MASK = 0x0000FFDF
_HEIGHT_TYPES = 0x0004 | 0x0080 | 0x0800 | 0x1000  # topography, thickness, sample thickn., AFM
_TYPE_NAMES = {
    0x0001: "piezo", 0x0002: "intensity", 0x0004: "topography", 0x0008: "real part",
    0x0010: "imaginary part", 0x0040: "camera", 0x0080: "thickness", 0x0100: "DIB from file",
    0x0200: "absolute value", 0x0400: "phase", 0x0800: "sample thickness", 0x1000: "AFM",
    0x2000: "quality",
}
_DTYPES: dict[int, np.dtype[Any]] = {16: np.dtype("<u2"), 32: np.dtype("<i4")}
_MAX_BLOCKS = 100_000


def _is_frt(buf: bytes) -> bool:
    return (buf[:12] == MAGIC and len(buf) >= 16 and buf[12:13] == b"1" and buf[13:14] == b"."
            and buf[14:16].isdigit())


def read_blocks(buf: bytes, name: str) -> tuple[str, dict[int, tuple[int, int]]]:
    """Return the version text and ``{block id: (payload offset, size)}``."""
    r = ByteReader(buf, name, FORMAT)
    if not _is_frt(buf):
        r.fail("missing the 'FRTM_GLIDERV1.xx' signature")
    version = buf[12:16].decode("ascii")
    if version not in ("1.00", "1.01"):
        r.fail(f"unsupported version {version} (this reader knows 1.00 and 1.01)")
    r.seek(16)
    r.unpack("<H", "block count")
    head = "<HI" if version == "1.00" else "<HQ"
    blocks: dict[int, tuple[int, int]] = {}
    for _ in range(_MAX_BLOCKS):
        if r.remaining == 0:
            break
        if r.remaining < struct.calcsize(head):
            # Gwyddion tolerates a few stray bytes at the end; so do we.
            break
        block_id, size = r.unpack(head, "block header")
        if size > r.remaining:
            r.fail(f"truncated: block 0x{block_id:04x} at offset {r.pos} claims {size} bytes, "
                   f"{r.remaining} remain")
        blocks.setdefault(block_id, (r.pos, size))
        r.skip(size, f"block 0x{block_id:04x}")
    else:
        r.fail("too many blocks (corrupted block sizes?)")
    return version, blocks


def _block(r: ByteReader, blocks: dict[int, tuple[int, int]], block_id: int, fmt: str,
           what: str) -> tuple[Any, ...]:
    if block_id not in blocks:
        r.fail(f"block 0x{block_id:04x} ({what}) is missing")
    offset, size = blocks[block_id]
    if size < struct.calcsize(fmt):
        r.fail(f"block 0x{block_id:04x} ({what}) is {size} bytes, too short")
    return r.unpack_at(offset, fmt, what)


def _optional_block(r: ByteReader, blocks: dict[int, tuple[int, int]], block_id: int,
                    fmt: str, what: str) -> tuple[Any, ...] | None:
    """:func:`_block`, or None where the file has no such block."""
    return _block(r, blocks, block_id, fmt, what) if block_id in blocks else None


def _text_block(buf: bytes, blocks: dict[int, tuple[int, int]], block_id: int) -> str:
    if block_id not in blocks:
        return ""
    offset, size = blocks[block_id]
    return buf[offset : offset + min(size, 4096)].split(b"\0", 1)[0].decode("latin-1").strip()


def _images(r: ByteReader, blocks: dict[int, tuple[int, int]]) -> list[dict[str, Any]]:
    # The images of the multi-image buffer (block 0x007d), described but not decoded.
    if 0x007D not in blocks:
        return []
    offset, size = blocks[0x007D]
    end = offset + size
    pos = offset + 8
    images: list[dict[str, Any]] = []
    while end - pos > 16:
        datatype, xres, yres, bpp = r.unpack_at(pos, "<IIII", "image header")
        pos += 16
        if bpp not in _DTYPES:
            r.fail(f"image {len(images)} has {bpp} bits per sample (expected 16 or 32)")
        xres, yres = check_grid(xres, yres, r.name, FORMAT)
        nbytes = xres * yres * bpp // 8
        if pos + nbytes > end:
            r.fail(f"truncated: image {len(images)} ({xres} x {yres}, {bpp} bpp) overruns "
                   f"the image block")
        images.append({"datatype": datatype, "xres": xres, "yres": yres, "bpp": bpp,
                       "offset": pos})
        pos += nbytes
    return images


def _type_name(datatype: int) -> str:
    return _TYPE_NAMES.get(datatype & _TYPE_MASK & 0x3FFF, f"type 0x{datatype:08x}")


def _pick_image(r: ByteReader, blocks: dict[int, tuple[int, int]],
                images: list[dict[str, Any]], channel: int | None, name: str
                ) -> dict[str, Any]:
    """The requested image, else the first topography image, else block 0x000b's image."""
    if channel is not None:
        try:
            index = int(channel)
        except (TypeError, ValueError):
            r.fail(f"channel must be an image index, got {channel!r}")
        if not 0 <= index < len(images):
            r.fail(f"channel {index} does not exist: the file holds {len(images)} images")
        image = images[index]
    else:
        heights_ = [im for im in images if im["datatype"] & _TYPE_MASK & _HEIGHT_TYPES]
        if heights_:
            image = heights_[0]
        elif 0x000B in blocks:
            xres, yres, bpp = _block(r, blocks, 0x0066, "<III", "image size")
            if bpp not in _DTYPES:
                r.fail(f"image has {bpp} bits per sample (expected 16 or 32)")
            xres, yres = check_grid(xres, yres, name, FORMAT)
            offset, size = blocks[0x000B]
            if xres * yres * bpp // 8 > size:
                r.fail(f"truncated: {xres} x {yres} image needs {xres * yres * bpp // 8} bytes, "
                       f"block 0x000b holds {size}")
            image = {"datatype": 0x0004, "xres": xres, "yres": yres, "bpp": bpp,
                     "offset": offset}
        else:
            r.fail("the file holds no topography image")
    return image


@register_reader(FORMAT, extensions=("frt",), description="FRT MicroProf",
                 magic=_is_frt, priority=10)
def decode(buf: bytes, name: str, channel: int | None = None) -> Topography:
    """Read a MicroProf ``.frt`` file into a :class:`~surfmet._model.Topography`.

    Parameters
    ----------
    channel : int, optional
        Index of an image of the multi-image buffer (block 0x007d). Default: the first
        topography image, else the single image of block 0x000b.
    """
    version, blocks = read_blocks(buf, name)
    r = ByteReader(buf, name, FORMAT)
    xrange_, yrange_ = _block(r, blocks, 0x0067, "<dd", "scan size")
    (_, zscale) = _block(r, blocks, 0x006C, "<Id", "z scale")
    if not (np.isfinite(zscale) and zscale != 0):
        r.fail(f"z scale {zscale!r} (block 0x006c) is not a usable number")

    image = _pick_image(r, blocks, _images(r, blocks), channel, name)
    if not image["datatype"] & _TYPE_MASK & _HEIGHT_TYPES:
        r.fail(f"image {channel} is a {_type_name(image['datatype'])} channel, not heights")

    nx, ny = image["xres"], image["yres"]
    dtype = _DTYPES[image["bpp"]]
    r.seek(image["offset"], "image offset")
    counts = r.array(dtype, nx * ny, "height data").reshape(ny, nx)

    valid_range = _optional_block(r, blocks, 0x0070, "<II", "valid range")
    if valid_range is not None:
        first, last = valid_range
        if dtype.kind == "i":  # int32 data: the range is stored as uint32 bit patterns
            first, last = np.int32(np.uint32(first)), np.int32(np.uint32(last))
        invalid = (counts < first) | (counts > last)
        rule = f"count outside [{int(first)}, {int(last)}] (block 0x0070)"
    else:
        invalid = counts == 1
        rule = "count == 1 (no block 0x0070)"
    heights = counts.astype(np.float64) * zscale
    heights[invalid] = np.nan

    dx = check_step(abs(xrange_) / nx, name, FORMAT, "x pixel size (block 0x0067)")
    dy = check_step(abs(yrange_) / ny, name, FORMAT, "y pixel size (block 0x0067)")
    metadata: dict[str, Any] = {
        "vendor": "FRT",
        "instrument": "FRT MicroProf",
        "file_version": version,
        "height_unit": "m",
        "lateral_unit": "m",
        "lateral_calibrated": True,
        "channel": _type_name(image["datatype"]),
        "z_scale": zscale,
        "invalid_rule": rule,
    }
    times = _optional_block(r, blocks, 0x0072, "<III", "time")
    if times is not None and times[0] > 0:
        try:
            metadata["date"] = _dt.datetime.fromtimestamp(times[0], _dt.timezone.utc).isoformat()
        except (OverflowError, OSError, ValueError):
            pass
    if 0x008E in blocks:
        offset, size = blocks[0x008E]
        if size >= 4:
            (n,) = r.unpack_at(offset, "<I", "serial number length")
            if 0 < n <= size - 4:
                metadata["serial"] = buf[offset + 4 : offset + 4 + n].split(b"\0", 1)[0] \
                    .decode("latin-1").strip()
    for key, block_id in (("description", 0x0065), ("parameter_set", 0x0077)):
        text = _text_block(buf, blocks, block_id)
        if text:
            metadata[key] = text
    return Topography(heights, dx, dy, metadata)


__all__ = ["decode", "read_blocks"]
