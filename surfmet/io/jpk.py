"""JPK Instruments (now Bruker) AFM image scans (``.jpk``): a TIFF with one page per channel.

Layout, learnt from SurfaceTopography's ``JPK.py`` and AFMReader's ``jpk.py`` (both after
JPK's ``JPKImageSpec.txt``) and checked on AFMReader's ``sample_0.jpk``:

* page 0 is a thumbnail whose private tags hold the scan: the grid lengths in metres
  (``0x8042`` GridULength, fast axis; ``0x8043`` GridVLength, slow axis), the pixel counts
  (``0x8046``, ``0x8047``) and the start date (``0x8003``);
* every further page is a channel image (uncompressed strips, int32 here) with its name
  (``0x8050``, e.g. ``height``), a retrace flag (``0x8051``), the number of calibration
  slots (``0x8080``) and the name of the default slot (``0x8081``). Slot ``k`` occupies the
  tags ``0x8090 + 0x30 k`` on: its name (+0x00), its unit (+0x12), its scaling type (+0x13,
  ``LinearScaling`` or ``NullScaling``), multiplier (+0x14) and offset (+0x15).

Value = raw x multiplier + offset of the default slot (AFMReader's rule, which the peer's
test asserts through the image sum; SurfaceTopography drops the offset, which only shifts
the mean height). Channels are named ``<name>_trace`` / ``<name>_retrace`` as AFMReader
names them; the channels whose default slot has a length unit are the height channels. The
default is ``height_trace``, else the first height channel.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.io._binary import ByteReader, channel_index, check_step, format_error
from surfmet.io._registry import register_reader
from surfmet.io._tiff import Ifd, first_ifd_tags, read_ifds, strip_image
from surfmet.units import length_factor

FORMAT = "jpk"
_GRID_U, _GRID_V, _GRID_I, _GRID_J = 0x8042, 0x8043, 0x8046, 0x8047
_START = 0x8003
_NAME, _RETRACE, _NSLOTS, _DEFAULT_SLOT = 0x8050, 0x8051, 0x8080, 0x8081
_SLOT0, _SLOT_SIZE = 0x8090, 0x30
_UNIT, _SCALING, _MULTIPLY, _OFFSET = 0x12, 0x13, 0x14, 0x15


def _is_jpk(buf: bytes) -> bool:
    # A TIFF whose first directory carries JPK's grid-length tags.
    return {_GRID_U, _GRID_I} <= first_ifd_tags(buf)


def _slot(ifd: Ifd, name: str, fname: str) -> tuple[str, float, float]:
    """Unit, multiplier and offset of the channel's default slot."""
    wanted = ifd.text(_DEFAULT_SLOT)
    for k in range(int(ifd.number(_NSLOTS))):
        base = _SLOT0 + _SLOT_SIZE * k
        if ifd.has(base) and ifd.text(base) == wanted:
            scaling = ifd.text(base + _SCALING)
            unit = ifd.text(base + _UNIT) if ifd.has(base + _UNIT) else ""
            if scaling == "NullScaling":
                return unit, 1.0, 0.0
            if scaling != "LinearScaling":
                raise format_error(fname, FORMAT, f"channel {name!r}: scaling {scaling!r} "
                                   "(LinearScaling or NullScaling expected)")
            return unit, float(ifd.number(base + _MULTIPLY)), float(ifd.number(base + _OFFSET))
    raise format_error(fname, FORMAT, f"channel {name!r}: default slot {wanted!r} is missing")


def _channels(ifds: list[Ifd], fname: str) -> list[dict[str, Any]]:
    out = []
    for page, ifd in enumerate(ifds[1:], start=1):
        if not ifd.has(_NAME):
            continue
        retrace = ifd.has(_RETRACE) and ifd.number(_RETRACE)
        name = f"{ifd.text(_NAME)}_{'retrace' if retrace else 'trace'}"
        unit, mul, off = _slot(ifd, name, fname)
        try:
            factor = length_factor(unit)
        except SurfmetInputError:
            continue  # not a height channel (volts, degrees...)
        out.append({"name": name, "page": page, "unit": unit, "scale": mul * factor,
                    "offset": off * factor})
    return out


@register_reader(FORMAT, extensions=("jpk",), description="JPK Instruments AFM image (TIFF)",
                 magic=_is_jpk, priority=25)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read one height channel of a JPK image scan.

    Parameters
    ----------
    channel : int or str, optional
        Index among the height channels or a name such as ``"height_retrace"``. Default:
        ``height_trace``, else the first height channel.
    """
    ifds = read_ifds(buf, name, FORMAT)
    head = ifds[0]
    for tag in (_GRID_U, _GRID_V, _GRID_I, _GRID_J):
        if not head.has(tag):
            raise format_error(name, FORMAT, f"the first page lacks JPK grid tag {tag:#x}")
    chans = _channels(ifds, name)
    if not chans:
        raise format_error(name, FORMAT, "no channel with a length unit (no height data)")
    names = [c["name"] for c in chans]
    if channel is None:
        pick = chans[names.index("height_trace")] if "height_trace" in names else chans[0]
    else:
        pick = chans[channel_index(names, channel, ByteReader(buf, name, FORMAT),
                                   what="height channel")]
    raw = strip_image(buf, ifds[pick["page"]], name, FORMAT)
    z = raw.astype(np.float64) * pick["scale"] + pick["offset"]
    ny, nx = z.shape
    if (nx, ny) != (int(head.number(_GRID_I)), int(head.number(_GRID_J))):
        raise format_error(name, FORMAT, f"image of {nx} x {ny} pixels but the scan header "
                           f"says {head.number(_GRID_I)} x {head.number(_GRID_J)}")
    dx = check_step(float(head.number(_GRID_U)) / nx, name, FORMAT, "x pixel size")
    dy = check_step(float(head.number(_GRID_V)) / ny, name, FORMAT, "y pixel size")
    md: dict[str, Any] = {"vendor": "JPK Instruments", "channel": pick["name"],
                          "channels": names, "height_unit": pick["unit"], "lateral_unit": "m",
                          "lateral_calibrated": True}
    if head.has(_START):
        md["date"] = head.text(_START)
    return Topography(z, dx, dy, md)


__all__ = ["decode"]
