"""Zygo MetroPro ``.dat`` files (phase-measuring and scanning white-light interferometers).

Layout after the *MetroPro Reference Guide* (Zygo, OMP-0347, section "Data file format")
and Gwyddion's ``metropro.c``. The header is big endian:

======  =====  ===============================================================
offset  type   field
======  =====  ===============================================================
0       u32    magic: 0x881B036F (header format 1), 0x881B0370 (2), 0x881B0371 (3)
4       u16    header format (1, 2 or 3)
6       u32    header size (834 for formats 1 and 2, 4096 for format 3)
10      i16    software type; 12: 30-char software date; 42: version (3 x i16)
48      i16    intensity origin x, y; u16 width, height, bucket count; i16 range
60      u32    intensity bytes
64      i16    phase origin x, y; u16 width, height
72      u32    phase bytes
76      i32    time stamp (Unix seconds)
80      82s    comment
162     i16    source (0 instrument, 1 generated)
164     f32    interferometric scale factor S
168     f32    wavelength in metres
172     f32    numerical aperture
176     f32    obliquity factor O
180     f32    magnification
184     f32    lateral resolution (camera pixel size on the part, metres)
188     i16    acquisition type
218     i16    phase_res: 0 -> R = 4096, 1 -> R = 32768, 2 -> R = 131072
232     i16    sign (1: heights inverted)
234     i16    camera width, height
238     i16    system type, system board, system serial (u16), instrument id
246     12s    objective name
258     40s    part name
320     40s    part serial number
408     20s    scan description
======  =====  ===============================================================

The intensity data (``bucket count`` frames of width x height big-endian u16) follow the
header, then the phase data (width x height big-endian i32, row by row from the top).
Height = phase * S * O * wavelength / R; phase values >= 2147483640 are invalid and become
NaN.

``phase_res`` is an index, not a count: 1 means R = 32768. surfalize 0.19 maps 1 to 4096
(its table starts at 1), so its heights are 8 times too large; SurfaceTopography and
Gwyddion use R = 32768.
"""

from __future__ import annotations

import datetime as _dt
from typing import Any

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader

FORMAT = "metropro"
MAGICS = {b"\x88\x1b\x03\x6f": 1, b"\x88\x1b\x03\x70": 2, b"\x88\x1b\x03\x71": 3}
HEADER_SIZES = {1: 834, 2: 834, 3: 4096}
PHASE_RESOLUTION = {0: 4096, 1: 32768, 2: 131072}
INVALID_PHASE = 2147483640
INVALID_INTENSITY = 65535
SOFTWARE = {1: "MetroPro", 2: "MetroBasic", 3: "d2bug"}
SYSTEM_TYPES = {0: "software generated", 1: "Mark IVxp", 2: "Maxim 3D", 3: "Maxim NT",
                4: "GPI-XP", 5: "NewView", 6: "Maxim GP", 7: "NewView/GP",
                8: "Mark to GPI conversion"}


def _is_metropro(buf: bytes) -> bool:
    return buf[:4] in MAGICS


def _s(raw: bytes) -> str:
    return raw.split(b"\0", 1)[0].decode("latin-1").strip()


def _header(r: ByteReader, buf: bytes) -> dict[str, Any]:
    """The header fields surfmet uses, by their MetroPro names (big endian)."""
    if buf[:4] not in MAGICS:
        r.fail("missing the MetroPro magic number 0x881B036F/0370/0371")
    fmt_by_magic = MAGICS[buf[:4]]
    header_format, header_size = r.unpack_at(4, ">HI", "header format")
    if header_format != fmt_by_magic:
        r.fail(f"header format {header_format} contradicts the magic number (format "
               f"{fmt_by_magic})")
    if header_size != HEADER_SIZES[header_format]:
        r.fail(f"header size {header_size} is wrong for header format {header_format} "
               f"(expected {HEADER_SIZES[header_format]})")
    r.need(header_size, "header")

    def u(fmt: str, off: int) -> tuple[Any, ...]:
        return r.unpack_at(off, ">" + fmt, "header")

    h: dict[str, Any] = {"header_format": header_format, "header_size": header_size}
    (h["sw_type"],) = u("h", 10)
    h["sw_date"] = _s(buf[12:42])
    h["version"] = u("3h", 42)
    _, _, h["ac_w"], h["ac_h"], h["ac_buckets"], h["ac_range"], h["ac_bytes"] = u(
        "hhHHHhI", 48)
    _, _, h["cn_w"], h["cn_h"], h["cn_bytes"] = u("hhHHI", 64)
    (h["timestamp"],) = u("i", 76)
    h["comment"] = _s(buf[80:162])
    (h["source"],) = u("h", 162)
    (h["scale"], h["wavelength"], h["na"], h["obliquity"], h["magnification"],
     h["lateral"]) = u("6f", 164)
    (h["acq_type"],) = u("h", 188)
    (h["phase_res"],) = u("h", 218)
    (h["sign"],) = u("h", 232)
    (h["cam_w"], h["cam_h"], h["sys_type"], h["sys_board"], h["sys_serial"],
     h["inst_id"]) = u("hhhhHh", 234)
    h["objective"] = _s(buf[246:258])
    h["part"] = _s(buf[258:298])
    h["part_serial"] = _s(buf[320:360])
    h["scan_descr"] = _s(buf[408:428])
    return h


def _check_header(r: ByteReader, h: dict[str, Any]) -> None:
    if h["ac_bytes"] != 2 * h["ac_w"] * h["ac_h"] * h["ac_buckets"]:
        r.fail(f"intensity size {h['ac_bytes']} bytes does not match {h['ac_buckets']} "
               f"buckets of {h['ac_w']} x {h['ac_h']} points")
    if h["cn_w"] == 0 or h["cn_h"] == 0:
        r.fail("the file holds no phase data (phase map of zero size)")
    if h["cn_bytes"] != 4 * h["cn_w"] * h["cn_h"]:
        r.fail(f"phase size {h['cn_bytes']} bytes does not match {h['cn_w']} x {h['cn_h']} "
               "points")
    if h["phase_res"] not in PHASE_RESOLUTION:
        r.fail(f"phase_res {h['phase_res']} is not 0, 1 or 2")
    for key, what in (("scale", "interferometric scale factor"), ("wavelength", "wavelength"),
                      ("obliquity", "obliquity factor")):
        value = h[key]
        if not (np.isfinite(value) and value > 0):
            r.fail(f"{what} {value!r} is not a positive number")


def _metadata(h: dict[str, Any], factor: float, calibrated: bool) -> dict[str, Any]:
    vmaj, vmin, vbug = h["version"]
    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "Zygo",
        "software": SOFTWARE.get(h["sw_type"], f"type {h['sw_type']}"),
        "software_version": f"{vmaj}.{vmin}.{vbug}",
        "header_format": h["header_format"],
        "height_unit": "m",
        "lateral_unit": "m",
        "lateral_calibrated": calibrated,
        **assumed(False, not calibrated),
        "wavelength": float(h["wavelength"]),
        "interferometric_scale_factor": float(h["scale"]),
        "obliquity_factor": float(h["obliquity"]),
        "phase_res": h["phase_res"],
        "phase_resolution": PHASE_RESOLUTION[h["phase_res"]],
        "height_scale_factor": factor,
        "sign": h["sign"],
        "intensity_buckets": h["ac_buckets"],
        "intensity_range": h["ac_range"],
        "camera_size": (h["cam_w"], h["cam_h"]),
        "system_board": h["sys_board"],
        "instrument_serial": str(h["sys_serial"]),
        "instrument_id": h["inst_id"],
        "acquisition_type": h["acq_type"],
        "source_type": "instrument" if h["source"] == 0 else "generated",
    }
    if h["sys_type"] in SYSTEM_TYPES:
        md["instrument"] = SYSTEM_TYPES[h["sys_type"]]
    else:
        md["system_type"] = h["sys_type"]
    if h["na"] > 0:
        md["numerical_aperture"] = float(h["na"])
    if h["magnification"] > 0:
        md["magnification"] = float(h["magnification"])
    if 0 < h["timestamp"]:
        md["date"] = _dt.datetime.fromtimestamp(h["timestamp"], _dt.timezone.utc).isoformat()
    for key, value in (("software_date", h["sw_date"]), ("comment", h["comment"]),
                       ("objective", h["objective"]), ("part", h["part"]),
                       ("part_serial", h["part_serial"]),
                       ("scan_description", h["scan_descr"])):
        if value:
            md[key] = value
    return md

@register_reader(FORMAT, extensions=("dat",),
                 description="Zygo MetroPro DAT (interferometer phase map)",
                 magic=_is_metropro, priority=10)
def decode(buf: bytes, name: str) -> Topography:
    """Read the phase map of a MetroPro file as heights in metres."""
    r = ByteReader(buf, name, FORMAT)
    h = _header(r, buf)
    _check_header(r, h)
    nx, ny = check_grid(h["cn_w"], h["cn_h"], name, FORMAT)
    r.seek(h["header_size"] + h["ac_bytes"], "phase data")
    phase = r.array(">i4", nx * ny, "phase data")

    resolution = PHASE_RESOLUTION[h["phase_res"]]
    factor = float(h["scale"]) * float(h["obliquity"]) * float(h["wavelength"]) / resolution
    if h["sign"]:
        factor = -factor
    with np.errstate(over="ignore", invalid="ignore"):
        z = phase.astype(np.float64) * factor
    if not np.isfinite(factor) or np.isinf(z).any():
        r.fail("scale factor x obliquity x wavelength overflows")
    z[phase >= INVALID_PHASE] = np.nan
    lateral = h["lateral"]
    if lateral > 0 and np.isfinite(lateral):
        dx = check_step(float(lateral), name, FORMAT, "lateral resolution")
        calibrated = True
    else:
        # Without a lateral calibration the pixel is the only unit there is.
        dx, calibrated = 1.0, False
    return Topography(z.reshape(ny, nx), dx, dx, _metadata(h, factor, calibrated))

__all__ = ["decode"]
