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

from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io.registry import register_reader
from surfmet.model import Topography

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


@register_reader(FORMAT, extensions=("dat",),
                 description="Zygo MetroPro DAT (interferometer phase map)",
                 magic=_is_metropro, priority=10)
def decode(buf: bytes, name: str) -> Topography:
    """Read the phase map of a MetroPro file as heights in metres."""
    r = ByteReader(buf, name, FORMAT)
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

    (sw_type,) = u("h", 10)
    sw_date = _s(buf[12:42])
    vmaj, vmin, vbug = u("3h", 42)
    _, _, ac_w, ac_h, ac_buckets, ac_range, ac_bytes = u("hhHHHhI", 48)
    _, _, cn_w, cn_h, cn_bytes = u("hhHHI", 64)
    (timestamp,) = u("i", 76)
    comment = _s(buf[80:162])
    (source,) = u("h", 162)
    scale, wavelength, na, obliquity, magnification, lateral = u("6f", 164)
    (acq_type,) = u("h", 188)
    (phase_res,) = u("h", 218)
    (sign,) = u("h", 232)
    cam_w, cam_h, sys_type, sys_board, sys_serial, inst_id = u("hhhhHh", 234)
    objective = _s(buf[246:258])
    part = _s(buf[258:298])
    part_serial = _s(buf[320:360])
    scan_descr = _s(buf[408:428])

    if ac_bytes != 2 * ac_w * ac_h * ac_buckets:
        r.fail(f"intensity size {ac_bytes} bytes does not match {ac_buckets} buckets of "
               f"{ac_w} x {ac_h} points")
    if cn_w == 0 or cn_h == 0:
        r.fail("the file holds no phase data (phase map of zero size)")
    if cn_bytes != 4 * cn_w * cn_h:
        r.fail(f"phase size {cn_bytes} bytes does not match {cn_w} x {cn_h} points")
    if phase_res not in PHASE_RESOLUTION:
        r.fail(f"phase_res {phase_res} is not 0, 1 or 2")
    for value, what in ((scale, "interferometric scale factor"), (wavelength, "wavelength"),
                        (obliquity, "obliquity factor")):
        if not (np.isfinite(value) and value > 0):
            r.fail(f"{what} {value!r} is not a positive number")
    nx, ny = check_grid(cn_w, cn_h, name, FORMAT)
    r.seek(header_size + ac_bytes, "phase data")
    phase = r.array(">i4", nx * ny, "phase data")

    resolution = PHASE_RESOLUTION[phase_res]
    factor = float(scale) * float(obliquity) * float(wavelength) / resolution
    if sign:
        factor = -factor
    with np.errstate(over="ignore", invalid="ignore"):
        z = phase.astype(np.float64) * factor
    if not np.isfinite(factor) or np.isinf(z).any():
        r.fail("scale factor x obliquity x wavelength overflows")
    z[phase >= INVALID_PHASE] = np.nan
    if lateral > 0 and np.isfinite(lateral):
        dx = check_step(float(lateral), name, FORMAT, "lateral resolution")
        calibrated = True
    else:
        # Without a lateral calibration the pixel is the only unit there is.
        dx, calibrated = 1.0, False

    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "Zygo",
        "software": SOFTWARE.get(sw_type, f"type {sw_type}"),
        "software_version": f"{vmaj}.{vmin}.{vbug}",
        "header_format": header_format,
        "height_unit": "m",
        "lateral_unit": "m",
        "lateral_calibrated": calibrated,
        "wavelength": float(wavelength),
        "interferometric_scale_factor": float(scale),
        "obliquity_factor": float(obliquity),
        "phase_res": phase_res,
        "phase_resolution": resolution,
        "height_scale_factor": factor,
        "sign": sign,
        "intensity_buckets": ac_buckets,
        "intensity_range": ac_range,
        "camera_size": (cam_w, cam_h),
        "system_board": sys_board,
        "instrument_serial": str(sys_serial),
        "instrument_id": inst_id,
        "acquisition_type": acq_type,
        "source_type": "instrument" if source == 0 else "generated",
    }
    if sys_type in SYSTEM_TYPES:
        md["instrument"] = SYSTEM_TYPES[sys_type]
    else:
        md["system_type"] = sys_type
    if na > 0:
        md["numerical_aperture"] = float(na)
    if magnification > 0:
        md["magnification"] = float(magnification)
    if 0 < timestamp:
        md["date"] = _dt.datetime.fromtimestamp(timestamp, _dt.timezone.utc).isoformat()
    for key, value in (("software_date", sw_date), ("comment", comment),
                       ("objective", objective), ("part", part),
                       ("part_serial", part_serial), ("scan_description", scan_descr)):
        if value:
            md[key] = value
    return Topography(z.reshape(ny, nx), dx, dx, md)


__all__ = ["decode"]
