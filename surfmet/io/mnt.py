"""MountainsMap documents (``.mnt``, Digital Surf): the first studiable's height map.

The document is a compound (OLE2) file (:mod:`surfmet.io._cfb`); its ``ScopedContents``
stream holds an 8-byte size, then tag-length-value entries (``uint16`` tag, ``uint64``
length, payload), nested. The path to the surface, as SurfaceTopography's ``MNTReader``
documents it and as this reader follows it on the sample:

* top-level tag ``0x0001`` (the document) -> ``0x02BD`` (height data): ``0x0001`` the data
  type byte (12: a count of 0 marks a non-measured point; 39: every count is valid) and
  ``0x0002`` -> ``0x0001`` a list of sections, each an ``uint64`` look-ahead size followed by
  one TLV entry; the first section is the surface;
* in the surface section: ``0x0002`` -> ``0x0001`` -> ``0x0002`` -> ``0xFFFF`` holds the axes
  (``0xFFFF`` -> ``0x0001`` x and ``0x0002`` y, each ``0xFFFF`` -> its point count
  ``0x0001`` (``uint32``) and ``0xFFFF``, the description), the data (``0x0001``) and the z
  axis (``0x0002`` -> ``0xFFFF``, the description). A description holds the step
  (``0x0001``, ``float64``) in unit ``0x0002``, the display unit ``0x0003``, the step unit
  per display unit ``0x0004`` and the offset ``0x0005`` in the display unit (units are
  UTF-16 strings after a type byte 4);
* the data: ``0x0002`` -> ``0x0002`` holds the total byte count (``uint64``), then blocks of
  (``uint64`` first element, ``uint32`` element count, ``uint32`` compressed size, zlib
  stream) of ``int32`` counts, x fastest.

Height = count x z step + z offset. The sample (``mnt-1.mnt``) is MountainsMap's document of
the scan exported as ``bcrf-1.bcrf``; the two read to the same heights (tests).
"""

from __future__ import annotations

import struct
import zlib
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import MAX_POINTS, check_grid, check_step, format_error
from surfmet.io._cfb import SIGNATURE, CompoundFile
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "mnt"


def _is_mnt(buf: bytes) -> bool:
    # The stream name sits in a directory sector, near the start or the end of the file.
    key = "ScopedContents".encode("utf-16-le")
    return buf[:8] == SIGNATURE and (key in buf[:1 << 20] or key in buf[-(1 << 20):])


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _entries(data: bytes, name: str, where: str) -> list[tuple[int, bytes]]:
    out = []
    i = 0
    while i < len(data):
        if i + 10 > len(data):
            raise _fail(name, f"{where}: truncated entry header")
        tag, size = struct.unpack_from("<HQ", data, i)
        if i + 10 + size > len(data):
            raise _fail(name, f"{where}: entry {tag:#06x} of {size} bytes overruns its parent")
        out.append((tag, data[i + 10:i + 10 + size]))
        i += 10 + size
    return out


def _child(data: bytes, path: tuple[int, ...], name: str, what: str) -> bytes:
    """Follow ``path`` (the first entry with each tag) down the TLV tree."""
    for depth, tag in enumerate(path):
        hit = next((d for t, d in _entries(data, name, what) if t == tag), None)
        if hit is None:
            trail = "/".join(f"{t:#06x}" for t in path[:depth + 1])
            raise _fail(name, f"{what}: no entry {trail} (not a surface document?)")
        data = hit
    return data


def _text(data: bytes) -> str:
    return data[1:].decode("utf-16-le", errors="replace") if data[:1] == b"\x04" else ""


def _axis(info: bytes, name: str, what: str) -> dict[str, Any]:
    """Step and offset (m) of an axis description, with its units."""
    step = struct.unpack("<d", _child(info, (0x0001,), name, what)[:8])[0]
    unit = _text(_child(info, (0x0002,), name, what))
    shown = _text(_child(info, (0x0003,), name, what))
    offset = struct.unpack("<d", _child(info, (0x0005,), name, what)[:8])[0]
    try:
        return {"step": step * length_factor(unit), "unit": unit,
                "offset": offset * length_factor(shown), "display_unit": shown}
    except SurfmetInputError:
        raise _fail(name, f"{what}: unit {unit!r} / {shown!r} is not a length") from None


def _lateral(axes: bytes, tag: int, name: str, what: str) -> dict[str, Any]:
    wrapper = _child(axes, (tag, 0xFFFF), name, what)
    out = _axis(_child(wrapper, (0xFFFF,), name, what), name, what)
    out["n"] = struct.unpack("<I", _child(wrapper, (0x0001,), name, what)[:4])[0]
    return out


def _counts(data: bytes, n: int, name: str) -> np.ndarray:
    """The int32 counts from the zlib blocks, each placed at its first element."""
    (total,) = struct.unpack_from("<Q", data, 0)
    if total != 4 * n:
        raise _fail(name, f"the data hold {total} bytes, {n} int32 points need {4 * n}")
    out = np.zeros(n, dtype="<i4")
    filled = 0
    i = 8
    while i < len(data):
        first, count, size = struct.unpack_from("<QII", data, i)
        if first + count > n or i + 16 + size > len(data):
            raise _fail(name, f"data block at {i} ({first}+{count}) lies outside the grid")
        raw = zlib.decompressobj().decompress(data[i + 16:i + 16 + size], 4 * count + 1)
        if len(raw) != 4 * count:
            raise _fail(name, f"data block at {i} inflates to {len(raw)} bytes, not {4 * count}")
        out[first:first + count] = np.frombuffer(raw, "<i4")
        filled += count
        i += 16 + size
    if filled != n:
        raise _fail(name, f"the data blocks hold {filled} of the {n} points")
    return out


@register_reader(FORMAT, extensions=("mnt",), description="MountainsMap document (.mnt)",
                 magic=_is_mnt, priority=30)
def decode(buf: bytes, name: str) -> Topography:
    """Read the surface of a MountainsMap document."""
    stream = CompoundFile(buf, name, FORMAT).stream("ScopedContents")
    height = _child(stream[8:], (0x0001, 0x02BD), name, "document")
    kind = _child(height, (0x0001,), name, "height data")[:1]
    sections = _child(height, (0x0002, 0x0001), name, "height data")
    if len(sections) < 18:
        raise _fail(name, "the height data hold no section")
    # Each section: a uint64 look-ahead size, then one TLV entry; the first is the surface.
    tag, size = struct.unpack_from("<HQ", sections, 8)
    if tag != 0x0001 or 18 + size > len(sections):
        raise _fail(name, "the first section is not a complete surface entry")
    body = _child(sections[18:18 + size], (0x0002, 0x0001, 0x0002, 0xFFFF), name, "surface")
    axes = _child(body, (0xFFFF,), name, "surface")
    ax = _lateral(axes, 0x0001, name, "x axis")
    ay = _lateral(axes, 0x0002, name, "y axis")
    az = _axis(_child(body, (0x0002, 0xFFFF), name, "z axis"), name, "z axis")
    nx, ny = check_grid(ax["n"], ay["n"], name, FORMAT)
    if nx * ny > MAX_POINTS:  # pragma: no cover - check_grid bounds it
        raise _fail(name, "absurd grid")
    counts = _counts(_child(body, (0x0001, 0x0002, 0x0002), name, "data"), nx * ny, name)
    z = counts.reshape(ny, nx).astype(np.float64) * az["step"] + az["offset"]
    if kind == b"\x0c":
        z[counts.reshape(ny, nx) == 0] = np.nan
    dx = check_step(ax["step"], name, FORMAT, "x step")
    dy = check_step(ay["step"], name, FORMAT, "y step")
    md: dict[str, Any] = {"vendor": "Digital Surf", "software": "MountainsMap",
                          "height_unit": az["display_unit"], "lateral_unit": ax["display_unit"],
                          "lateral_calibrated": True, "x_offset": ax["offset"],
                          "y_offset": ay["offset"], "data_type": kind[0] if kind else None}
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
