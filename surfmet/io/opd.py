"""Wyko / Veeco / Bruker Vision ``.opd`` files (white-light and phase-shifting interferometry).

The file starts with two bytes (``01 00``) and a *directory*: a list of 24-byte entries,
each a 16-byte NUL-padded name, a u16 type, a u32 length and a u16 flags word (little
endian). The first entry describes the directory itself (name ``Directory``, type 1,
flags 0xffff); its length is the size of the whole directory. The blocks' contents follow
the directory, in directory order. Layout as documented by Gwyddion's ``opdfile.c``.

Block types: 1 directory, 3 array (u16 x-size, u16 y-size, u16 bytes per element, then the
elements), 5 text, 6 int16, 7 float32, 8 float64, 12 int32. Newer Vision versions add
other types (15 is a small tagged serialisation, e.g. ``PrimaryData2D``); they are kept
as raw bytes, or as text when they hold a tagged string, and never stop the reader
(surfalize 0.19 crashes on them: "15 is not a valid BlockType").

Heights: the array named by ``PrimaryData2D`` (else the first of ``RAW_DATA``,
``RAW DATA``, ``OPD``, ``SAMPLE_DATA``, ``Raw``) holds x-size columns of y-size values
(column after column), as float32 or int16 in units of ``Wavelength / Mult``
(``Wavelength`` in nanometres; ``Mult`` is optional, default 1, and read with whatever
numeric type its block has). Invalid points are float32 values ``>= 1e38`` compared in
float32 (Vision writes 2**127 = 1.7e38; a float32 "1e38" is 9.99999968e37, which a float64
comparison would miss), non-finite values, or int16 values ``>= 32766``. Lateral: ``Pixel_size``
in millimetres along x, times ``Aspect`` along y. Date and time are the ``Date``
(month/day/year) and ``Time`` text blocks.
"""

from __future__ import annotations

import datetime as _dt
import struct
from typing import Any

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader

FORMAT = "opd"
MAGIC = b"\x01\x00Directory"
ENTRY_SIZE = 24
BAD_FLOAT = 1e38
BAD_INT16 = 32766
DATA_NAMES = ("RAW_DATA", "RAW DATA", "OPD", "SAMPLE_DATA", "Raw")
# Directory entries beyond this are nonsense for a real file (Vision writes a few hundred).
_MAX_ENTRIES = 1 << 16

BLOCK_TYPES = {1: "directory", 3: "array", 5: "text", 6: "int16", 7: "float32",
               8: "float64", 12: "int32"}
_NUMERIC = {6: "<h", 7: "<f", 8: "<d", 12: "<i"}
_ARRAY_DTYPES: dict[int, np.dtype[Any]] = {
    1: np.dtype("u1"), 2: np.dtype("<i2"), 4: np.dtype("<f4")}


def _is_opd(buf: bytes) -> bool:
    return buf[: len(MAGIC)] == MAGIC


def _directory(r: ByteReader) -> list[dict[str, Any]]:
    r.seek(2)
    name = r.cstring(16, "directory name")
    btype, length, flags = r.unpack("<HIH", "directory entry")
    if name != "Directory" or btype != 1:
        r.fail(f"the first block is {name!r} of type {btype}, not the Directory")
    if length % ENTRY_SIZE or length < ENTRY_SIZE:
        r.fail(f"directory length {length} is not a positive multiple of {ENTRY_SIZE}")
    count = length // ENTRY_SIZE
    if count > _MAX_ENTRIES:
        r.fail(f"absurd directory of {count} entries")
    r.need(length - ENTRY_SIZE, "directory")
    blocks = []
    offset = 2 + length
    for i in range(count - 1):
        raw_name = r.bytes(16, f"directory entry {i + 1}")
        btype, size, flags = r.unpack("<HIH", f"directory entry {i + 1}")
        if size == 0:
            continue
        if offset + size > len(r.buf):
            label = raw_name.split(b"\0", 1)[0].decode("latin-1", "replace").strip()
            r.fail(f"truncated: block {label!r} ({size} bytes at offset {offset}) runs past "
                   f"the end of the {len(r.buf)}-byte file")
        blocks.append({
            "name": raw_name.split(b"\0", 1)[0].decode("latin-1", "replace").strip(),
            "type": btype,
            "size": size,
            "flags": flags,
            "offset": offset,
        })
        offset += size
    return blocks


def _value(buf: bytes, b: dict[str, Any]) -> Any:
    """Decode a scalar or text block; None for anything else."""
    raw = buf[b["offset"]: b["offset"] + b["size"]]
    t = b["type"]
    if t in _NUMERIC:
        fmt = _NUMERIC[t]
        if len(raw) < struct.calcsize(fmt):
            return None
        return struct.unpack_from(fmt, raw)[0]
    if t == 5:
        return raw.split(b"\0", 1)[0].decode("latin-1").strip()
    if t == 15 and len(raw) >= 3 and raw[:2] == b"\x12\x01" and raw[2] == len(raw) - 3:
        # Tagged string: 0x12 0x01, a length byte, the characters.
        return raw[3:].decode("latin-1").strip()
    return None


def _date(date: Any, time: Any) -> str | None:
    if not isinstance(date, str) or not date:
        return None
    text = f"{date} {time}" if isinstance(time, str) and time else date
    for fmt in ("%m/%d/%Y %H:%M:%S", "%m/%d/%y %H:%M:%S", "%m/%d/%Y", "%m/%d/%y"):
        try:
            return _dt.datetime.strptime(text, fmt).isoformat()
        except ValueError:
            continue
    return None


def _height_array(r: ByteReader, by_name: dict[str, dict[str, Any]],
                  values: dict[str, Any], name: str
                  ) -> tuple[dict[str, Any], np.ndarray, int, int, int, np.dtype]:
    """The primary height array: its block, raw values, nx, ny, element size, dtype."""
    primary = values.get("PrimaryData2D")
    candidates = ([primary] if isinstance(primary, str) else []) + list(DATA_NAMES)
    data_block = None
    for cand in candidates:
        b = by_name.get(cand)
        if b is not None and b["type"] == 3:
            data_block = b
            break
    if data_block is None:
        r.fail("no height array (PrimaryData2D, RAW_DATA, OPD, SAMPLE_DATA or Raw) found")

    r.seek(data_block["offset"])
    ncols, nrows, elsize = r.unpack("<HHH", "array header")
    if elsize not in _ARRAY_DTYPES:
        r.fail(f"array {data_block['name']!r} has {elsize}-byte elements (1, 2 or 4 expected)")
    if elsize == 1:
        r.fail(f"array {data_block['name']!r} holds bytes (an image), not heights")
    dtype = _ARRAY_DTYPES[elsize]
    nx, ny = check_grid(ncols, nrows, name, FORMAT, available=data_block["size"] - 6,
                        itemsize=elsize)
    raw = r.array(dtype, nx * ny, f"array {data_block['name']!r}")

    return data_block, raw, nx, ny, elsize, dtype


def _add_optional_metadata(md: dict[str, Any], values: dict[str, Any],
                           blocks: list[dict[str, Any]]) -> None:
    date = _date(values.get("Date"), values.get("Time"))
    if date:
        md["date"] = date
    for key, label in (("Magnification", "magnification"), ("DataSetName", "title"),
                       ("Title", "title"), ("MeasMode", "measurement_mode"),
                       ("DataKind", "data_kind"), ("DataFormat", "data_format")):
        v = values.get(key)
        if v not in (None, "") and label not in md:
            md[label] = v
    unknown = sorted({b["type"] for b in blocks} - set(BLOCK_TYPES) - {15})
    md["block_types"] = sorted({b["type"] for b in blocks})
    if unknown:
        md["unknown_block_types"] = unknown


@register_reader(FORMAT, extensions=("opd",),
                 description="Wyko / Bruker Vision OPD (interferometer)",
                 magic=_is_opd, priority=10)
def decode(buf: bytes, name: str) -> Topography:
    """Read the primary height array of an OPD file (heights in metres)."""
    r = ByteReader(buf, name, FORMAT)
    if not _is_opd(buf):
        r.fail("missing the '\\x01\\x00Directory' signature")
    blocks = _directory(r)
    by_name: dict[str, dict[str, Any]] = {}
    for b in blocks:
        by_name.setdefault(b["name"], b)
    values = {b["name"]: _value(buf, b) for b in blocks}

    data_block, raw, nx, ny, elsize, dtype = _height_array(r, by_name, values, name)

    wavelength = values.get("Wavelength")
    if not isinstance(wavelength, (int, float)) or not np.isfinite(wavelength) \
            or wavelength <= 0:
        r.fail(f"missing or unusable Wavelength block ({wavelength!r}); the height scale "
               "cannot be derived")
    mult = values.get("Mult", 1)
    if mult is None:
        mult = 1
    if not isinstance(mult, (int, float)) or not np.isfinite(mult) or mult == 0:
        r.fail(f"unusable Mult block ({mult!r})")
    aspect = values.get("Aspect", 1.0)
    if aspect is None:
        aspect = 1.0
    pixel = values.get("Pixel_size")
    if not isinstance(pixel, (int, float)):
        r.fail("missing Pixel_size block (lateral scale)")
    dx = check_step(float(pixel) * 1e-3, name, FORMAT, "Pixel_size")
    dy = check_step(float(pixel) * float(aspect) * 1e-3, name, FORMAT, "Pixel_size x Aspect")

    # Height per stored unit: the wavelength (nm) divided by the multiplier.
    scale = float(wavelength) * 1e-9 / float(mult)
    if elsize == 4:
        # Compare in float32: the marker written as float32(1e38) is 9.99999968e37.
        bad = ~np.isfinite(raw) | (raw >= np.float32(BAD_FLOAT))
    else:
        bad = raw >= BAD_INT16
    with np.errstate(invalid="ignore", over="ignore"):  # signalling NaNs, huge markers
        z = raw.astype(np.float64) * scale
    z[bad] = np.nan
    # Stored column by column (x slowest); the values of a column run against the y axis,
    # so transpose and flip, which gives the orientation of Gwyddion and SurfaceTopography.
    heights = z.reshape(nx, ny).T[::-1, :]

    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "Bruker (Wyko)",
        # The file stores heights in waves of Wavelength / Mult.
        "height_unit": "waves",
        "lateral_unit": "mm",
        "lateral_calibrated": True,
        "wavelength": float(wavelength) * 1e-9,
        "mult": float(mult),
        "aspect": float(aspect),
        "height_scale_factor": scale,
        "data_block": data_block["name"],
        "data_type": str(dtype),
    }
    _add_optional_metadata(md, values, blocks)
    return Topography(heights, dx, dy, md)


__all__ = ["decode"]
