"""ISO 25178-71 Surface Data File (SDF, the Surfstand format), ASCII and binary.

Both variants start with a version signature: ``aISO-1.0`` (text) or ``bISO-1.0`` (binary).

The header fields (ISO 25178-71, clause 5) are ``ManufacID`` (10 characters),
``CreateDate`` and ``ModDate`` (12 characters, ``DDMMYYYYhhmm``), ``NumPoints`` (points
per profile, along x), ``NumProfiles`` (along y), ``Xscale``, ``Yscale``, ``Zscale`` (metres
per unit), ``Zresolution`` (metres, negative if unknown), ``Compression`` and ``CheckType``
(both 0: no compression, no checksum) and ``DataType``: 0 uint8, 1 uint16, 2 uint32,
3 float32, 4 int8, 5 int16, 6 int32, 7 float64.

* ASCII: one ``Key = value`` line per field, a line ``*``, the ``NumPoints * NumProfiles``
  values in row order (``BAD`` marks a non-measured point), a line ``*``, an optional
  trailer of ``< Tag > value < / Tag >`` records and a final ``*``.
* Binary: the same fields packed little endian (8 + 10 + 12 + 12 + 2 + 2 + 4 * 8 + 3 = 81
  bytes), then the values. Non-measured points are NaN for float types and the most
  negative value for signed integer types (-2**15, -2**31), as surfalize writes them.

Heights are ``value * Zscale``, ``dx = Xscale``, ``dy = Yscale``. A file with one profile
is returned as a :class:`~surfmet._model.Profile`.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from surfmet._model import Profile, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step, decode_text
from surfmet.io._registry import register_reader

FORMAT = "sdf"
MAGIC_ASCII = b"aISO-1.0"
MAGIC_BINARY = b"bISO-1.0"
BINARY_HEADER = "<8s10s12s12sHHddddBBB"
BINARY_HEADER_SIZE = 81

_DTYPES: dict[int, np.dtype[Any]] = {
    0: np.dtype("u1"), 1: np.dtype("<u2"), 2: np.dtype("<u4"), 3: np.dtype("<f4"),
    4: np.dtype("i1"), 5: np.dtype("<i2"), 6: np.dtype("<i4"), 7: np.dtype("<f8"),
}
_MISSING_INT = {5: -(2**15), 6: -(2**31)}
_FIELDS = ("ManufacID", "CreateDate", "ModDate", "NumPoints", "NumProfiles", "Xscale",
           "Yscale", "Zscale", "Zresolution", "Compression", "DataType", "CheckType")
_TRAILER_RE = re.compile(r"<\s*(\w+)\s*>(.*?)<\s*/\s*\1\s*>", re.S)
_UNIT_OF_SCALE = {1.0: "m", 1e-3: "mm", 1e-6: "um", 1e-9: "nm"}


def _is_sdf(buf: bytes) -> bool:
    return buf[:8] in (MAGIC_ASCII, MAGIC_BINARY)


def _unit_name(scale: float) -> str:
    # Name the file's unit when its scale is a plain power of ten; else say metres.
    for value, unit in _UNIT_OF_SCALE.items():
        if abs(abs(scale) - value) <= 1e-9 * value:
            return unit
    return "m"


def _date(text: str) -> str | None:
    # DDMMYYYYhhmm -> ISO 8601
    t = text.strip()
    if len(t) != 12 or not t.isdigit():
        return None
    day, month, year, hour, minute = t[0:2], t[2:4], t[4:8], t[8:10], t[10:12]
    if not (1 <= int(day) <= 31 and 1 <= int(month) <= 12 and int(hour) < 24 and int(minute) < 60):
        return None
    return f"{year}-{month}-{day}T{hour}:{minute}"


def _numbers(tokens: list[str], r: ByteReader) -> np.ndarray:
    # Fast path through numpy; on failure find the culprit for the message.
    cleaned = ["nan" if t.upper() == "BAD" else t for t in tokens]
    try:
        return np.array(cleaned, dtype=np.float64)
    except ValueError:
        for i, tok in enumerate(cleaned):
            try:
                float(tok)
            except ValueError:
                r.fail(f"data value {i} ({tok[:30]!r}) is not a number")
        raise


def _parse_ascii(buf: bytes, name: str, r: ByteReader) -> tuple[dict[str, Any], np.ndarray, str]:
    text = decode_text(buf)
    sections = text.split("*")
    if len(sections) < 2:
        r.fail("no '*' line closes the header")
    header_lines = sections[0].splitlines()[1:]
    header: dict[str, Any] = {}
    for line in header_lines:
        line = line.strip()
        if not line or line.startswith(";"):
            continue
        if "=" not in line:
            r.fail(f"header line {line[:60]!r} is not 'Key = value'")
        key, value = (s.strip() for s in line.split("=", 1))
        header[key] = value
    for key in _FIELDS:
        if key not in header:
            r.fail(f"the header has no {key!r} field")
    for key in ("NumPoints", "NumProfiles", "Compression", "DataType", "CheckType"):
        try:
            header[key] = int(header[key])
        except ValueError:
            r.fail(f"header field {key}={header[key]!r} is not an integer")
    for key in ("Xscale", "Yscale", "Zscale", "Zresolution"):
        try:
            header[key] = float(header[key])
        except ValueError:
            r.fail(f"header field {key}={header[key]!r} is not a number")
    if len(sections) < 3:
        r.fail("truncated: no '*' line closes the data section")
    nx, ny = check_grid(header["NumPoints"], header["NumProfiles"], name, FORMAT)
    tokens = sections[1].split()
    if len(tokens) != nx * ny:
        r.fail(f"the data section holds {len(tokens)} values, the header announces "
               f"{nx} x {ny} = {nx * ny}")
    values = _numbers(tokens, r)
    trailer = "*".join(sections[2:])
    return header, values, trailer


def _parse_binary(buf: bytes, name: str, r: ByteReader) -> tuple[dict[str, Any], np.ndarray, str]:
    fields = r.unpack(BINARY_HEADER, "binary header")
    header = {k: v for k, v in zip(_FIELDS, fields[1:])}
    for key in ("ManufacID", "CreateDate", "ModDate"):
        header[key] = header[key].split(b"\0", 1)[0].decode("latin-1").strip()
    dtype = _DTYPES.get(header["DataType"])
    if dtype is None:
        r.fail(f"unknown DataType {header['DataType']} (ISO 25178-71 defines 0 to 7)")
    nx, ny = check_grid(header["NumPoints"], header["NumProfiles"], name, FORMAT,
                        available=r.remaining, itemsize=dtype.itemsize)
    raw = r.array(dtype, nx * ny)
    values = raw.astype(np.float64)
    missing = _MISSING_INT.get(header["DataType"])
    if missing is not None:
        values[raw == missing] = np.nan
    trailer = buf[r.pos :].decode("latin-1", errors="replace") if r.remaining else ""
    return header, values, trailer


@register_reader(FORMAT, extensions=("sdf",), description="ISO 25178-71 SDF (ASCII or binary)",
                 magic=_is_sdf, priority=10)
def decode(buf: bytes, name: str) -> Topography | Profile:
    """Read an SDF file (either variant)."""
    r = ByteReader(buf, name, FORMAT)
    variant = buf[:8]
    if variant == MAGIC_ASCII:
        header, values, trailer = _parse_ascii(buf, name, r)
    elif variant == MAGIC_BINARY:
        header, values, trailer = _parse_binary(buf, name, r)
    else:
        r.fail("missing the 'aISO-1.0' / 'bISO-1.0' signature")
    if header["Compression"] != 0:
        r.fail(f"Compression={header['Compression']} is not supported (only 0, uncompressed)")
    nx, ny = int(header["NumPoints"]), int(header["NumProfiles"])
    zscale = header["Zscale"]
    if not (np.isfinite(zscale) and zscale != 0):
        r.fail(f"Zscale {zscale!r} is not a usable number")
    dx = check_step(header["Xscale"], name, FORMAT, "Xscale")
    heights = values * zscale
    metadata: dict[str, Any] = {
        "variant": "ascii" if variant == MAGIC_ASCII else "binary",
        "manufacturer_id": header["ManufacID"],
        "height_unit": _unit_name(zscale),
        "lateral_unit": _unit_name(header["Xscale"]),
        "lateral_calibrated": True,
        "z_resolution": header["Zresolution"] if header["Zresolution"] > 0 else None,
        "header": {k: header[k] for k in _FIELDS},
    }
    date = _date(str(header["CreateDate"]))
    if date:
        metadata["date"] = date
    extras = {k: v.strip() for k, v in _TRAILER_RE.findall(trailer)}
    if extras:
        metadata["trailer"] = extras
    if ny == 1:
        return Profile(heights, dx, metadata=metadata)
    dy = check_step(header["Yscale"], name, FORMAT, "Yscale")
    return Topography(heights.reshape(ny, nx), dx, dy, metadata)


__all__ = ["decode"]
