"""Bruker / Veeco / Digital Instruments Nanoscope files (``.di``, ``.spm``, ``.001``).

The file starts with a Latin-1 text header of ``\\*Section`` lines and ``\\Key: value``
lines (CR LF), opened by ``\\*File list`` and closed by ``\\*File list end``. Each
``\\*Ciao image list`` section describes one channel:

* ``Data offset`` and ``Data length``: the channel's bytes (absolute offset);
* ``Samps/line``, ``Number of lines``, ``Bytes/pixel`` (2 = int16, 4 = int32), little endian;
* ``Scan Size: 500 500 nm``: the physical width and height;
* ``@2:Image Data: S [Height] "Height"``: the channel name;
* ``@2:Z scale: V [Sens. Zsens] (0.0050354 V/LSB) 2.910461 V``: the hard scale, in volts per
  2^16 counts, and the name of the soft scale, a ``\\@Sens. Zsens: V 20.82646 nm/V`` entry of
  the scanner lists, which turns volts into a length.

Height per count = hard value / 65536 x soft scale (and / 65536 more for 32-bit data, which
spans the 16-bit range 65536 times finer), as SurfaceTopography's ``DIReader`` reads it
(its test suite checks the resulting rms heights of these files, and Gwyddion's
``nanoscope.c`` uses the same rule). Lines are stored top line first (``Frame direction:
Down``); they are flipped so that row 0 is the bottom line, the orientation of Gwyddion and
SurfaceTopography.
"""

from __future__ import annotations

import datetime as _dt
import re
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, channel_index, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "di"
_MAGIC = b"\\*File list"
_MAX_HEADER = 1 << 20
_SCALE_RE = re.compile(
    r"^V\s*(?:\[(.*?)\])?\s*\(([-+0-9.eE]+)\s*(\S*)/LSB\)\s*([-+0-9.eE]+)\s*(\S*)")
_NAME_RE = re.compile(r'^S\s*\[(.*?)\]\s*"?(.*?)"?\s*$')
_DTYPES = {2: np.dtype("<i2"), 4: np.dtype("<i4")}


def _is_di(buf: bytes) -> bool:
    return buf[:11] == _MAGIC


def _header(buf: bytes, r: ByteReader) -> list[tuple[str, dict[str, str]]]:
    """The header sections in order, keys in lower case."""
    end = buf.find(b"\\*File list end", 0, _MAX_HEADER)
    if end < 0:
        r.fail("no '\\*File list end' line within the first MiB (truncated header?)")
    sections: list[tuple[str, dict[str, str]]] = []
    for raw in buf[:end].decode("latin-1").splitlines():
        line = raw.strip()
        if not line:
            continue
        if line.startswith("\\*"):
            sections.append((line[2:].strip().lower(), {}))
        elif line.startswith("\\") and sections:
            # Keys may hold colons ("@2:Z scale"): the separator is ": ".
            key, _, value = line[1:].rstrip(":").partition(": ")
            sections[-1][1][key.strip().lower()] = value.strip()
        else:
            r.fail(f"header line {line[:40]!r} does not start with a backslash")
    if not sections or sections[0][0] != "file list":
        r.fail("the header does not start with the 'File list' section")
    return sections


def _soft_scales(sections: list[tuple[str, dict[str, str]]]) -> dict[str, str]:
    soft: dict[str, str] = {}
    for sname, values in sections:
        if sname in ("scanner list", "ciao scan list"):
            soft.update({k: v for k, v in values.items() if k.startswith("@")})
    return soft


def _channel(values: dict[str, str], soft: dict[str, str], r: ByteReader) -> dict[str, Any]:
    """One ``Ciao image list`` section: name, grid, size, offsets and scale."""
    m = _NAME_RE.match(values.get("@2:image data", ""))
    ch: dict[str, Any] = {"name": (m.group(1) or m.group(2)) if m else "unnamed"}
    ch["nx"], ch["ny"] = check_grid(values.get("samps/line"), values.get("number of lines"),
                                    r.name, FORMAT)
    ch["offset"] = int(values.get("data offset", "-1"))
    ch["length"] = int(values.get("data length", "-1"))
    ch["elsize"] = int(values.get("bytes/pixel", "2"))
    if ch["elsize"] not in _DTYPES:
        r.fail(f"channel {ch['name']!r}: {ch['elsize']} bytes per pixel (2 or 4 expected)")
    size = values.get("scan size", "").split()
    if len(size) != 3:
        r.fail(f"channel {ch['name']!r}: scan size {values.get('scan size')!r} is not "
               "'width height unit'")
    try:
        xy = length_factor(size[2].replace("~m", "µm"))
    except SurfmetInputError:
        r.fail(f"channel {ch['name']!r}: scan size unit {size[2]!r} is not a length")
    ch["sx"], ch["sy"] = float(size[0]) * xy, float(size[1]) * xy
    ch["xy_unit"] = size[2]
    ch["scale"], ch["unit"] = _z_scale(values.get("@2:z scale", ""), soft, ch["elsize"])
    return ch


def _z_scale(text: str, soft: dict[str, str], elsize: int) -> tuple[float | None, str | None]:
    """Metres per count and the file's height unit; (None, None) for non-length channels."""
    m = _SCALE_RE.match(text)
    if m is None:
        return None, None
    hard = float(m.group(4)) / 65536.0
    if elsize == 4:
        hard /= 65536.0
    if m.group(1) is None:
        return None, None
    parts = soft.get("@" + m.group(1).lower(), "").split()
    if len(parts) < 3 or parts[0] != "V" or "/" not in parts[2]:
        return None, None
    unit, _, per = parts[2].partition("/")
    if per != m.group(5):  # soft scale must be per the hard scale's unit (V)
        return None, None
    try:
        factor = length_factor(unit.replace("~m", "µm"))
    except SurfmetInputError:
        return None, None
    return hard * float(parts[1]) * factor, unit


def _pick(channels: list[dict[str, Any]], channel: int | str | None, r: ByteReader
          ) -> dict[str, Any]:
    if channel is None:
        for ch in channels:
            if ch["scale"] is not None:
                return ch
        r.fail(f"no height channel among {[c['name'] for c in channels]}")
    ch = channels[channel_index([c["name"] for c in channels], channel, r)]
    if ch["scale"] is None:
        r.fail(f"channel {ch['name']!r} does not hold heights (its scale is not a length)")
    return ch


def _metadata(sections: list[tuple[str, dict[str, str]]], ch: dict[str, Any],
              channels: list[dict[str, Any]]) -> dict[str, Any]:
    merged: dict[str, str] = {}
    for sname, values in sections:
        if sname in ("file list", "equipment list", "scanner list"):
            merged.update(values)
    md: dict[str, Any] = {"vendor": "Bruker", "height_unit": ch["unit"],
                          "lateral_unit": ch["xy_unit"], "lateral_calibrated": True,
                          "channel": ch["name"],
                          "channels": [c["name"] for c in channels],
                          "height_scale_factor": ch["scale"]}
    inst = merged.get("microscope") or merged.get("description")
    if inst:
        md["instrument"] = inst
    if merged.get("serial number"):
        md["instrument_serial"] = merged["serial number"]
    if merged.get("version"):
        md["file_version"] = merged["version"]
    try:
        date = _dt.datetime.strptime(" ".join(merged.get("date", "").split()),
                                     "%I:%M:%S %p %a %b %d %Y")
        md["date"] = date.isoformat()
    except ValueError:
        pass
    return md


@register_reader(FORMAT, extensions=("di", "spm"),
                 description="Bruker/Veeco/Digital Instruments Nanoscope (.di, .spm)",
                 magic=_is_di, priority=30)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one height channel of a Nanoscope file.

    Parameters
    ----------
    channel : int or str, optional
        Channel index (in header order) or name (``"Height"``). Default: the first channel
        whose scale is a length.
    """
    r = ByteReader(buf, name, FORMAT)
    sections = _header(buf, r)
    soft = _soft_scales(sections)
    channels = [_channel(v, soft, r) for s, v in sections if s == "ciao image list"]
    if not channels:
        r.fail("the header describes no image ('Ciao image list' section)")
    ch = _pick(channels, channel, r)
    nx, ny, elsize = ch["nx"], ch["ny"], ch["elsize"]
    if nx * ny * elsize > ch["length"]:
        r.fail(f"channel {ch['name']!r}: {nx} x {ny} points of {elsize} bytes do not fit its "
               f"data length {ch['length']}")
    r.seek(ch["offset"], "data offset")
    counts = r.array(_DTYPES[elsize], nx * ny, f"channel {ch['name']!r}").reshape(ny, nx)
    heights = counts[::-1, :].astype(np.float64) * ch["scale"]
    dx = check_step(ch["sx"] / nx, name, FORMAT, "x pixel size")
    dy = check_step(ch["sy"] / ny, name, FORMAT, "y pixel size")
    return Topography(heights, dx, dy, _metadata(sections, ch, channels))


__all__ = ["decode"]
