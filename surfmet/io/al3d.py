"""Alicona Imaging ``.al3d`` (InfiniteFocus / MeasureSuite) areal scans.

Layout (little endian), as documented by Gwyddion's ``alicona.c`` module and checked on a
MeasureSuite 5.3.6 file:

* 17-byte signature ``AliconaImaging\\0\\r\\n``;
* a header of 52-byte tags: a 20-byte NUL-padded key, a 30-byte NUL-padded text value and
  ``\\r\\n``. The first two tags are ``Version`` and ``TagCount``; ``TagCount`` more follow,
  then a 256-byte comment ending in ``\\r\\n``;
* the depth image at ``DepthImageOffset``: ``Rows`` rows of ``Cols`` float32 heights in
  metres, each row padded to a multiple of 8 bytes;
* optionally an icon (``IconOffset``, 0 = none) and a texture (``TextureImageOffset``:
  ``NumberOfPlanes`` planes of 8-bit colour). Only their presence and size are recorded in
  the metadata; the texture is not a height.

Non-measured points hold ``InvalidPixelValue`` (often NaN, or a huge number such as 3e15)
and become NaN. The header keys ``PixelSizeXMeter`` / ``PixelSizeYMeter`` give dx and dy.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader

FORMAT = "al3d"
MAGIC = b"AliconaImaging\x00\r\n"
KEY_SIZE, VALUE_SIZE = 20, 30
TAG_SIZE = KEY_SIZE + VALUE_SIZE + 2
COMMENT_SIZE = 256
# The texture planes and icon are 8-bit images; MeasureSuite pads their rows like the depth
# rows, to 8 bytes.
_ROW_ALIGN = 8
# A float32 copy of the marker can differ from the decimal text in the last bit.
_INVALID_RTOL = 1e-6


def _is_al3d(buf: bytes) -> bool:
    return buf[: len(MAGIC)] == MAGIC


def _read_tag(r: ByteReader, index: int) -> tuple[str, str]:
    raw = r.bytes(TAG_SIZE, f"header tag {index}")
    if raw[-2:] != b"\r\n":
        r.fail(f"header tag {index} at offset {r.pos - TAG_SIZE} lacks its CRLF terminator")
    key = raw[:KEY_SIZE].split(b"\0", 1)[0].decode("latin-1").strip()
    value = raw[KEY_SIZE : KEY_SIZE + VALUE_SIZE].split(b"\0", 1)[0].decode("latin-1").strip()
    if not key:
        r.fail(f"header tag {index} has an empty key")
    return key, value


def read_header(buf: bytes, name: str) -> tuple[dict[str, str], int]:
    """Parse the tag header; returns the tags and the offset just after the comment."""
    r = ByteReader(buf, name, FORMAT)
    if r.bytes(len(MAGIC), "signature") != MAGIC:
        r.fail("missing the 'AliconaImaging' signature")
    tags: dict[str, str] = {}
    key, value = _read_tag(r, 0)
    if key != "Version":
        r.fail(f"the first tag must be 'Version', found {key!r}")
    tags[key] = value
    key, value = _read_tag(r, 1)
    if key != "TagCount":
        r.fail(f"the second tag must be 'TagCount', found {key!r}")
    count = _int(value, "TagCount", r)
    if count < 0 or count * TAG_SIZE > r.remaining:
        r.fail(f"TagCount {count} does not fit in the {len(buf)}-byte file (truncated header?)")
    tags[key] = value
    for i in range(count):
        key, value = _read_tag(r, i + 2)
        tags[key] = value
    comment = r.bytes(COMMENT_SIZE, "header comment") if r.remaining >= COMMENT_SIZE else b""
    if comment:
        tags.setdefault("Comment", comment.split(b"\0", 1)[0].decode("latin-1").strip())
    return tags, r.pos


def _int(text: str, key: str, r: ByteReader) -> int:
    try:
        return int(text.strip())
    except ValueError:
        r.fail(f"header value {key}={text!r} is not an integer")


def _float(text: str, key: str, r: ByteReader) -> float:
    try:
        return float(text.strip())
    except ValueError:
        r.fail(f"header value {key}={text!r} is not a number")


def _need(tags: dict[str, str], key: str, r: ByteReader) -> str:
    if key not in tags:
        r.fail(f"the header has no {key!r} tag")
    return tags[key]


def _image_block(r: ByteReader, tags: dict[str, str], key: str, row_bytes: int, rows: int,
                 planes: int) -> dict[str, Any] | None:
    # Describe an optional 8-bit image block (icon or texture) without decoding it.
    if key not in tags:
        return None
    offset = _int(tags[key], key, r)
    if offset <= 0:
        return None
    stride = -(-row_bytes // _ROW_ALIGN) * _ROW_ALIGN
    size = stride * rows * planes
    return {"offset": offset, "planes": planes, "bytes": size,
            "complete": offset + size <= len(r.buf)}


@register_reader(FORMAT, extensions=("al3d",), description="Alicona Imaging AL3D",
                 magic=_is_al3d, priority=10)
def decode(buf: bytes, name: str) -> Topography:
    """Read an Alicona ``.al3d`` file into a :class:`~surfmet._model.Topography`."""
    tags, header_end = read_header(buf, name)
    r = ByteReader(buf, name, FORMAT)
    nx = _int(_need(tags, "Cols", r), "Cols", r)
    ny = _int(_need(tags, "Rows", r), "Rows", r)
    nx, ny = check_grid(nx, ny, name, FORMAT)
    dx = check_step(abs(_float(_need(tags, "PixelSizeXMeter", r), "PixelSizeXMeter", r)), name,
                    FORMAT, "PixelSizeXMeter")
    dy = check_step(abs(_float(_need(tags, "PixelSizeYMeter", r), "PixelSizeYMeter", r)), name,
                    FORMAT, "PixelSizeYMeter")
    offset = _int(_need(tags, "DepthImageOffset", r), "DepthImageOffset", r)
    if offset < header_end - COMMENT_SIZE:
        r.fail(f"DepthImageOffset {offset} points inside the header")
    stride = -(-nx * 4 // _ROW_ALIGN) * _ROW_ALIGN
    needed = stride * (ny - 1) + nx * 4
    if offset + needed > len(buf):
        r.fail(f"truncated: the {nx} x {ny} depth image at offset {offset} needs {needed} bytes, "
               f"the file has {len(buf)}")
    rows = np.lib.stride_tricks.as_strided(
        np.frombuffer(buf, dtype="<f4", count=needed // 4, offset=offset),
        shape=(ny, nx), strides=(stride, 4), writeable=False)
    with np.errstate(invalid="ignore"):  # signalling NaNs in damaged files
        heights = rows.astype(np.float64)

    invalid_text = tags.get("InvalidPixelValue", "nan")
    invalid = _float(invalid_text, "InvalidPixelValue", r) if invalid_text else math.nan
    bad = ~np.isfinite(heights)
    if math.isfinite(invalid):
        marker = float(np.float32(invalid))
        bad |= np.abs(heights - marker) <= _INVALID_RTOL * abs(marker)
    heights[bad] = np.nan

    planes = 0
    if "NumberOfPlanes" in tags:
        planes = max(_int(tags["NumberOfPlanes"], "NumberOfPlanes", r), 0)
    metadata: dict[str, Any] = {
        "vendor": "Alicona Imaging",
        "height_unit": "m",
        "lateral_unit": "m",
        "lateral_calibrated": True,
        "header": dict(tags),
    }
    if tags.get("CreatingApplication"):
        metadata["instrument"] = tags["CreatingApplication"]
        metadata["software"] = tags["CreatingApplication"]
    texture = _image_block(r, tags, "TextureImageOffset", nx, ny, planes) if planes else None
    if texture is not None:
        metadata["texture"] = texture
    icon = _image_block(r, tags, "IconOffset", 0, 0, 0)
    if icon is not None:
        metadata["icon"] = {"offset": icon["offset"]}
    return Topography(heights, dx, dy, metadata)


__all__ = ["decode", "read_header"]
