"""Nanosurf easyScan / Nanosurf Studio data files (``.nid``, ``.ezd``).

An INI-style Latin-1 header (``[Section]`` lines and ``Key=Value`` lines, CR LF) ends with
the two bytes ``#!``; the binary data of every data set follow, one after the other, in the
order the ``[DataSet]`` section lists them (``Gr<i>-Ch<j>=DataSet-<i>:<j>`` for group ``i``
of ``Gr<i>-Count`` channels; missing channels take no bytes). Each ``[DataSet-i:j]``
section gives ``Points`` (per line) and ``Lines``, the physical size ``Dim0Range`` /
``Dim1Range`` with ``Dim0Unit``, the value axis ``Dim2Name``, ``Dim2Unit``, ``Dim2Range``,
``Dim2Min`` and the storage ``SaveBits``, ``SaveSign``, ``SaveOrder`` (Intel = little
endian).

Value = count x ``Dim2Range`` / 2^bits + ``Dim2Min`` + ``Dim2Range`` / 2 (signed counts,
centred; ``Dim2Min`` for unsigned). The channels whose value unit is a length are the
height channels, named ``"<Frame> (<Dim2Name>)"`` as in SurfaceTopography's ``EZDReader``;
the default is the first. Lines are flipped so that row 0 is the last stored line (the
orientation of SurfaceTopography).
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

FORMAT = "nid"
_MAGIC = b"[DataSet]\r\n"
_MAX_HEADER = 4 << 20


def _is_nid(buf: bytes) -> bool:
    return buf[:11] == _MAGIC and b"#!" in buf[:_MAX_HEADER]


def _sections(text: str, r: ByteReader) -> dict[str, dict[str, str]]:
    out: dict[str, dict[str, str]] = {}
    current: dict[str, str] | None = None
    for raw in text.splitlines():
        line = raw.strip()
        if not line:
            continue
        if line.startswith("[") and line.endswith("]"):
            current = out.setdefault(line[1:-1], {})
        elif current is not None and "=" in line:
            key, _, value = line.partition("=")
            current[key.strip()] = value.strip()
        else:
            r.fail(f"cannot read header line {line[:40]!r}")
    return out


def _length(unit: str) -> float | None:
    try:
        return length_factor(unit)
    except SurfmetInputError:
        return None


def _datasets(sections: dict[str, dict[str, str]], r: ByteReader) -> list[dict[str, Any]]:
    """Every stored data set in file order, with its byte offset after the ``#!``."""
    top = sections.get("DataSet", {})
    out: list[dict[str, Any]] = []
    offset = 0
    for i in range(int(top.get("GroupCount", "0"))):
        for j in range(int(top.get(f"Gr{i}-Count", "0"))):
            sec = sections.get(top.get(f"Gr{i}-Ch{j}", ""))
            if sec is None:
                continue
            if sec.get("SaveMode") != "Binary":
                r.fail(f"data set {i}:{j} is not stored in binary (SaveMode "
                       f"{sec.get('SaveMode')!r})")
            bits = int(sec.get("SaveBits", "0"))
            if bits not in (8, 16, 32, 64):
                r.fail(f"data set {i}:{j}: {bits} bits per value")
            kind = "i" if sec.get("SaveSign") == "Signed" else "u"
            order = "<" if sec.get("SaveOrder", "Intel") == "Intel" else ">"
            nx, ny = check_grid(sec.get("Points"), sec.get("Lines"), r.name, FORMAT)
            ds = {"section": sec, "nx": nx, "ny": ny, "offset": offset,
                  "dtype": np.dtype(f"{order}{kind}{bits // 8}"),
                  "name": f"{sec.get('Frame', '')} ({sec.get('Dim2Name', '')})"}
            offset += nx * ny * bits // 8
            out.append(ds)
    return out


def _pick(heights: list[dict[str, Any]], channel: int | str | None, r: ByteReader
          ) -> dict[str, Any]:
    names = [d["name"] for d in heights]
    if not heights:
        r.fail("no data set holds heights (no value unit is a length)")
    if channel is None:
        return heights[0]
    return heights[channel_index(names, channel, r, what="height channel")]


def _metadata(sections: dict[str, dict[str, str]], ds: dict[str, Any],
              names: list[str]) -> dict[str, Any]:
    sec = ds["section"]
    info = sections.get("DataSet-Info", {})
    md: dict[str, Any] = {"vendor": "Nanosurf", "channel": ds["name"], "channels": names,
                          "height_unit": sec.get("Dim2Unit"), "lateral_unit":
                          sec.get("Dim0Unit"), "lateral_calibrated": True}
    for key, label in (("Head type", "instrument"), ("Software ver.", "software_version"),
                       ("Op. mode", "mode"), ("Cantilever type", "cantilever")):
        if info.get(key):
            md[label] = info[key]
    try:
        md["date"] = _dt.datetime.strptime(f"{info.get('Date')} {info.get('Time')}",
                                           "%d-%m-%Y %H:%M:%S").isoformat()
    except ValueError:
        pass
    return md


@register_reader(FORMAT, extensions=("nid", "ezd"), description="Nanosurf easyScan (.nid)",
                 magic=_is_nid, priority=30)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one height channel of a Nanosurf file.

    Parameters
    ----------
    channel : int or str, optional
        Index among the height channels, or the name ``"Scan forward (Z-Axis)"``.
        Default: the first height channel.
    """
    r = ByteReader(buf, name, FORMAT)
    end = buf.find(b"#!", 0, _MAX_HEADER)
    if end < 0:
        r.fail("no '#!' end-of-header mark (truncated header?)")
    sections = _sections(buf[:end].decode("latin-1"), r)
    datasets = _datasets(sections, r)
    heights = [d for d in datasets if _length(d["section"].get("Dim2Unit", "")) is not None]
    ds = _pick(heights, channel, r)
    sec = ds["section"]
    nx, ny = ds["nx"], ds["ny"]
    r.seek(end + 2 + ds["offset"], "data set offset")
    counts = r.array(ds["dtype"], nx * ny, f"data set {ds['name']!r}").reshape(ny, nx)
    zf = _length(sec["Dim2Unit"])
    zrange = float(sec.get("Dim2Range", "nan"))
    zmin = float(sec.get("Dim2Min", "0"))
    zero = zmin + zrange / 2 if ds["dtype"].kind == "i" else zmin
    z = (counts[::-1, :].astype(np.float64) * (zrange / 2.0 ** (8 * ds["dtype"].itemsize))
         + zero) * zf
    xf = _length(sec.get("Dim0Unit", ""))
    if xf is None:
        r.fail(f"lateral unit {sec.get('Dim0Unit')!r} is not a length")
    dx = check_step(float(sec.get("Dim0Range", "nan")) * xf / nx, name, FORMAT, "x pixel size")
    dy = check_step(float(sec.get("Dim1Range", "nan")) * xf / ny, name, FORMAT, "y pixel size")
    if not np.isfinite(z).all():
        r.fail(f"height scale Dim2Range {zrange!r} / Dim2Min {zmin!r} is not finite")
    return Topography(z, dx, dy, _metadata(sections, ds, [d["name"] for d in heights]))


__all__ = ["decode"]
