"""Agilent / Keysight (Molecular Imaging) PicoView image files (``.mi``).

A text header of fixed-width lines, the key in the first 14 characters and the value after
(``xPixels       256``, ``xLength       2.0e-005``, ``scanUp        TRUE``), first line
``fileType      Image``; then one block per channel, opened by ``bufferLabel`` and holding
``bufferRange`` and ``bufferUnit``; then the line ``data          BINARY`` (int16) or
``BINARY_32`` (int32) and the channels' counts, one ``xPixels x yPixels`` block after the
other, little endian, a line at a time.

Value = count / 2^15 (2^31 for 32-bit) x ``bufferRange`` in ``bufferUnit``, the rule of
SurfaceTopography's ``MIReader`` and Gwyddion's ``mifile.c``. Lengths (``xLength``) are in
metres. When ``scanUp`` is TRUE the lines were acquired bottom to top and are flipped, as in
both programs. Spectroscopy files and ASCII data are refused.
"""

from __future__ import annotations

import datetime as _dt
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, channel_index, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "mi"
_MAGIC = b"fileType      Image"
_DATA: dict[bytes, tuple[np.dtype[Any], float]] = {
    b"data          BINARY": (np.dtype("<i2"), 2.0**15),
    b"data          BINARY_32": (np.dtype("<i4"), 2.0**31)}
_MAX_HEADER = 1 << 20


def _is_mi(buf: bytes) -> bool:
    return buf[:19] == _MAGIC or buf[:25] == b"fileType      Spectroscopy"


def _header(buf: bytes, r: ByteReader) -> tuple[dict[str, str], list[dict[str, str]], int,
                                                 tuple[np.dtype, float]]:
    """Global keys, channel blocks, offset of the data and (dtype, full scale)."""
    glob: dict[str, str] = {}
    channels: list[dict[str, str]] = []
    pos = 0
    while pos < min(len(buf), _MAX_HEADER):
        end = buf.find(b"\n", pos)
        if end < 0:
            break
        line = buf[pos:end].rstrip(b"\r")
        pos = end + 1
        if line.startswith(b"data "):
            if line.rstrip() == b"data":
                r.fail("ASCII data are not supported (only BINARY and BINARY_32)")
            kind = _DATA.get(line.rstrip())
            if kind is None:
                r.fail(f"unknown data line {line[:40]!r}")
            return glob, channels, pos, kind
        text = line.decode("latin-1")
        key, value = text[:14].strip(), text[14:].strip()
        if key == "bufferLabel":
            channels.append({})
        (channels[-1] if channels else glob)[key] = value
    r.fail("no 'data' line ending the header (truncated?)")


def _pick(channels: list[dict[str, str]], channel: int | str | None, r: ByteReader) -> int:
    labels = [c.get("bufferLabel", "") for c in channels]

    def is_height(c: dict[str, str]) -> bool:
        try:
            length_factor(c.get("bufferUnit", ""))
        except SurfmetInputError:
            return False
        return True

    if channel is None:
        for i, c in enumerate(channels):
            if is_height(c):
                return i
        r.fail(f"no channel holds heights (channels: {labels})")
    index = channel_index(labels, channel, r)
    if not is_height(channels[index]):
        r.fail(f"channel {index} ({labels[index]}) is in {channels[index].get('bufferUnit')!r}, "
               "not a length")
    return index


@register_reader(FORMAT, extensions=("mi",), description="Agilent PicoView image (.mi)",
                 magic=_is_mi, priority=30)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one height channel of a PicoView image.

    Parameters
    ----------
    channel : int or str, optional
        Channel index or ``bufferLabel``. Default: the first channel in a length unit.
    """
    r = ByteReader(buf, name, FORMAT)
    if buf[:19] != _MAGIC:
        r.fail("not an image file (spectroscopy files are not read)")
    glob, channels, start, (dtype, full) = _header(buf, r)
    if not channels:
        r.fail("the header describes no channel (bufferLabel)")
    index = _pick(channels, channel, r)
    ch = channels[index]
    nx, ny = check_grid(glob.get("xPixels"), glob.get("yPixels"), name, FORMAT)
    r.seek(start + index * nx * ny * dtype.itemsize, "channel data")
    counts = r.array(dtype, nx * ny, f"channel {ch.get('bufferLabel')!r}").reshape(ny, nx)
    if glob.get("scanUp", "").upper() == "TRUE":
        counts = counts[::-1, :]
    zrange = float(ch.get("bufferRange", "nan"))
    z = counts.astype(np.float64) * (zrange / full * length_factor(ch["bufferUnit"]))
    if not np.isfinite(zrange):
        r.fail(f"bufferRange {ch.get('bufferRange')!r} is not a number")
    dx = check_step(float(glob.get("xLength", "nan")) / nx, name, FORMAT, "x pixel size")
    dy = check_step(float(glob.get("yLength", "nan")) / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"vendor": "Agilent", "channel": ch.get("bufferLabel"),
                          "channels": [c.get("bufferLabel") for c in channels],
                          "height_unit": ch.get("bufferUnit"), "lateral_unit": "m",
                          "lateral_calibrated": True}
    for key, label in (("version", "software_version"), ("mode", "mode"),
                       ("direction", "direction"), ("filter", "filter")):
        value = ch.get(key) or glob.get(key)
        if value:
            md[label] = value
    try:
        md["date"] = _dt.datetime.strptime(" ".join(glob.get("dateAcquired", "").split()),
                                           "%a %b %d %H:%M:%S %Y").isoformat()
    except ValueError:
        pass
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
