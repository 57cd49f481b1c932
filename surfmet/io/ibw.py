"""Igor Pro binary wave files (``.ibw``, version 5), as Asylum Research AFMs write them.

Layout (WaveMetrics, Igor Technical Note PTN003 "Igor Binary Format"): a 64-byte
``BinHeader5`` (version, checksum, then the sizes of the wave record, formula, note,
extended data units, extended dimension units x 4, dimension labels x 4, sorted indices and
two option blocks), a 320-byte ``WaveHeader5`` (``npnts`` at 12, ``type`` at 16, the name
at 28, ``nDim[4]`` at 68, ``sfA[4]`` (deltas) at 84, ``sfB[4]`` (offsets) at 116,
``dataUnits`` at 148, ``dimUnits[4][4]`` at 152), then the data, then the formula, the
note, the extended units and the dimension labels, each as long as the binary header says.
The byte order is the one in which ``version`` reads 5.

Data are stored with the first dimension (x, ``nDim[0]`` points) varying fastest, then y,
then the layer: Asylum files hold one channel per layer, named by the labels of dimension 2
(32 bytes each; the first label names the dimension itself). Rows are flipped so that
row 0 is the last stored row, the orientation of SurfaceTopography's ``IBWReader``.

The default channel is the first whose label starts with ``Height``, else the first.
Units: ``dataUnits`` (or the extended data units) for heights, ``dimUnits`` for x and y.
A file without units (Igor's default) is read as bare numbers: ``height_unit = ""``,
``units_missing = True``, ``lateral_calibrated = False``.
"""

from __future__ import annotations

import struct
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, channel_index, check_grid, check_step
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "ibw"
_BIN = "hhiiii4i4iiii"  # BinHeader5
_BIN_SIZE = 64
_WAVE_SIZE = 320
_TYPES = {2: "f4", 4: "f8", 8: "i1", 0x10: "i2", 0x20: "i4", 0x48: "u1", 0x50: "u2",
          0x60: "u4"}
_LABEL = 32


def _order(buf: bytes) -> str | None:
    if len(buf) < 2:
        return None
    if struct.unpack_from("<h", buf)[0] == 5:
        return "<"
    if struct.unpack_from(">h", buf)[0] == 5:
        return ">"
    return None


def _is_ibw(buf: bytes) -> bool:
    order = _order(buf)
    if order is None or len(buf) < _BIN_SIZE + _WAVE_SIZE:
        return False
    # The checksum makes the 16-bit sum of both headers zero (PTN003).
    shorts = np.frombuffer(buf[:_BIN_SIZE + _WAVE_SIZE], dtype=order + "i2")
    return int(shorts.astype(np.int64).sum()) & 0xFFFF == 0


def _text(raw: bytes) -> str:
    return raw.split(b"\0", 1)[0].decode("latin-1").strip()


def _unit(text: str, r: ByteReader, what: str) -> float | None:
    """Metres per unit; None when the wave has no unit."""
    if not text:
        return None
    try:
        return length_factor(text)
    except SurfmetInputError:
        r.fail(f"{what} unit {text!r} is not a length")


def _channel_names(labels: bytes, nlayers: int) -> list[str]:
    names = [_text(labels[i:i + _LABEL]) for i in range(_LABEL, len(labels), _LABEL)]
    names = names[:nlayers]
    names += [f"no name ({k + 1})" for k in range(nlayers - len(names))]
    return names


def _pick(names: list[str], channel: int | str | None, r: ByteReader) -> int:
    if channel is None:
        return next((i for i, n in enumerate(names) if n.lower().startswith("height")), 0)
    return channel_index(names, channel, r)


def _note(note: str) -> dict[str, Any]:
    """A few fields of Asylum's ``Key: value`` note (CR separated)."""
    md: dict[str, Any] = {}
    for line in note.replace("\r", "\n").splitlines():
        key, sep, value = line.partition(":")
        if not sep:
            continue
        key, value = key.strip(), value.strip()
        if key == "MicroscopeModel" and value:
            md["instrument"] = value
        elif key == "Version" and value:
            md["software_version"] = value
        elif key == "Date" and value and "date" not in md:
            md["date"] = value
    return md


@register_reader(FORMAT, extensions=("ibw",), description="Igor Pro binary wave (Asylum AFM)",
                 magic=_is_ibw, priority=35)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one channel (layer) of an Igor binary wave.

    Parameters
    ----------
    channel : int or str, optional
        Layer index or label (``"HeightRetrace"``). Default: the first ``Height*`` layer.
    """
    r = ByteReader(buf, name, FORMAT)
    order = _order(buf)
    if order is None:
        r.fail("version field is not 5 (only Igor binary wave version 5 is read)")
    (_, _, wfm_size, formula_size, note_size, data_eunits_size, *rest) = r.unpack_at(
        0, order + _BIN, "binary header")
    dim_eunits, dim_labels = rest[0:4], rest[4:8]
    w = _BIN_SIZE
    (wtype,) = r.unpack_at(w + 16, order + "h", "wave header")
    ndim = r.unpack_at(w + 68, order + "4i", "wave header")
    sfa = r.unpack_at(w + 84, order + "4d", "wave header")
    if wtype not in _TYPES:
        r.fail(f"wave type {wtype:#x} is not a real number type (complex or text wave?)")
    dtype = np.dtype(order + _TYPES[wtype])
    nx, ny = check_grid(ndim[0], ndim[1], name, FORMAT)
    if ndim[3] not in (0, 1):
        r.fail("4-dimensional waves are not read")
    nlayers = max(1, ndim[2])
    count = nx * ny * nlayers
    if count * dtype.itemsize > wfm_size - _WAVE_SIZE:
        r.fail(f"{nx} x {ny} x {nlayers} points do not fit the wave record of {wfm_size} bytes")
    tail = _BIN_SIZE + wfm_size  # formula, note, units and labels follow the wave record
    r.seek(tail + formula_size, "note")
    note = _text(r.bytes(note_size, "note"))
    data_unit = _text(r.bytes(data_eunits_size, "units")) if data_eunits_size else \
        _text(buf[w + 148:w + 152])
    dim_unit = _text(r.bytes(dim_eunits[0], "units")) if dim_eunits[0] else \
        _text(buf[w + 152:w + 156])
    r.skip(sum(dim_eunits[1:]), "units")
    r.skip(dim_labels[0] + dim_labels[1], "dimension labels")
    names = _channel_names(r.bytes(dim_labels[2], "dimension labels"), nlayers)
    index = _pick(names, channel, r)
    r.seek(_BIN_SIZE + _WAVE_SIZE, "data")
    data = r.array(dtype, count, "wave data").reshape(nlayers, ny, nx)
    zf = _unit(data_unit, r, "data")
    xf = _unit(dim_unit, r, "x")
    with np.errstate(invalid="ignore", over="ignore"):
        heights = data[index, ::-1, :].astype(np.float64) * (zf or 1.0)
    heights[~np.isfinite(heights)] = np.nan
    dx = check_step(abs(sfa[0]) * (xf or 1.0), name, FORMAT, "x delta (sfA[0])")
    dy = check_step(abs(sfa[1]) * (xf or 1.0), name, FORMAT, "y delta (sfA[1])")
    md: dict[str, Any] = {"channel": names[index], "channels": names, "height_unit": data_unit,
                          "lateral_unit": dim_unit or "m",
                          "lateral_calibrated": xf is not None,
                          **assumed(zf is None, xf is None)}
    if zf is None:
        md["units_missing"] = True
    if note:
        md["vendor"] = "Asylum Research"  # Igor itself writes no note
        md.update(_note(note))
    return Topography(heights, dx, dy, md)


__all__ = ["decode"]
