"""Digital Surf ``.sur`` files (MountainsMap, and instruments exporting to it).

A file is a sequence of *objects*; each object is a 512-byte header, a comment zone, a
private zone and the points. The layout of the header (little endian for files of
``format`` 0, "PC"; big endian for ``format`` 257, "Macintosh") follows the MountainsMap
SDK description as implemented by Gwyddion's ``surffile.c`` and RosettaSciIO's
``digitalsurf.py``:

======  =====  ==============================================================
offset  type   field
======  =====  ==============================================================
0       12s    signature ``DIGITAL SURF`` (plain) or ``DSCOMPRESSED`` (zlib)
12      u16    format (0 = PC, 257 = Macintosh)
14      u16    number of objects
16      u16    version
18      u16    object type (1 profile, 2 surface, 3 binary image, 4 series of
               profiles, 5 series of surfaces, ... 10 intensity image, 12 RGB
               image, 16 surface + RGB/intensity image)
20      30s    object name
50      30s    operator name
80      u16    material code
82      u16    acquisition type (0 unknown, 1 stylus, 2 optical, ... 9
               interferometer, 10 structured light)
84      u16    range type
86      u16    special points (1: non-measured points present)
88      u16    absolute
90      f32    gauge resolution
94      u32    W size (spectral data)
98      u16    bits per point (16 or 32)
100     i32    zmin
104     i32    zmax
108     i32    points per line (nx)
112     i32    number of lines (ny)
116     i32    total number of points
120     f32    x, y, z spacing (3 x f32)
132     16s    x, y, z axis names (3 x 16s)
180     16s    x, y, z step units (3 x 16s)
228     16s    x, y, z length units (3 x 16s)
276     f32    x, y, z unit ratios (3 x f32)
288     u16    imprint, inversion, levelling (3 x u16)
306     u16    seconds, minutes, hours, day, month, year, day of week
320     f32    measurement duration
324     u32    compressed data size
334     u16    comment size
336     u16    private zone size
338     128s   client zone
466     f32    x, y, z offsets (3 x f32)
======  =====  ==============================================================

Heights are ``value * z_spacing + z_offset`` in the z step unit (Gwyddion, surfalize; the
RosettaSciIO reader subtracts zmin first, which only shifts the heights). When the
special-points flag is set, points holding ``zmin - 2`` are non-measured and become NaN.
The ``inversion`` field is recorded but not applied (SurfaceTopography, surfalize and
RosettaSciIO ignore it too). A compressed object's data are a u32 stream count, that many
(raw length, zipped length) u32 pairs, then the zlib streams.

The first object holding heights (profile, surface, series or multilayer of them, surface
with image) is read; images (binary, intensity, RGB) are skipped. A "profile" object with
more than one line (as written by Gwyddion's exporter) is read as a surface.
"""

from __future__ import annotations

import datetime as _dt
import struct
import zlib
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io._binary import MAX_DEFLATE_RATIO, MAX_POINTS, ByteReader, check_grid, check_step
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "sur"
MAGIC_PLAIN = b"DIGITAL SURF"
MAGIC_COMPRESSED = b"DSCOMPRESSED"
HEADER_SIZE = 512
# At most this many objects are walked through to find the heights.
_MAX_OBJECTS = 4096
_MAX_STREAMS = 1 << 16

OBJECT_TYPES = {
    1: "profile", 2: "surface", 3: "binary image", 4: "series of profiles",
    5: "series of surfaces", 6: "meridian disc", 7: "multilayer profile",
    8: "multilayer surface", 9: "parallel disc", 10: "intensity image",
    11: "intensity surface", 12: "RGB image", 13: "RGB surface", 14: "force curve",
    15: "series of force curves", 16: "RGB intensity surface", 17: "contour profile",
    18: "series of RGB images", 20: "spectrum", 21: "hyperspectral card",
}
_HEIGHT_TYPES = {1: "profile", 2: "areal", 4: "profile", 5: "areal", 7: "profile",
                 8: "areal", 11: "areal", 13: "areal", 16: "areal", 17: "profile"}
ACQUISITION_TYPES = {
    0: "unknown", 1: "contact stylus", 2: "scanning optical gauge", 3: "thermocouple",
    4: "unknown", 5: "contact stylus with skid", 6: "AFM", 7: "STM", 8: "video",
    9: "interferometer", 10: "structured light projection",
}


def _is_sur(buf: bytes) -> bool:
    return buf[:12] in (MAGIC_PLAIN, MAGIC_COMPRESSED)


def _text(raw: bytes) -> str:
    return raw.split(b"\0", 1)[0].decode("latin-1").strip()


def _header(r: ByteReader, start: int, index: int) -> dict[str, Any]:
    """Parse the 512-byte header of the object starting at ``start``."""
    if start + HEADER_SIZE > len(r.buf):
        r.fail(f"truncated: object {index} header at offset {start} needs {HEADER_SIZE} "
               f"bytes, the file has {len(r.buf)}")
    raw = r.buf[start:start + HEADER_SIZE]
    sig = raw[:12]
    if sig not in (MAGIC_PLAIN, MAGIC_COMPRESSED):
        r.fail(f"object {index} at offset {start} lacks the DIGITAL SURF signature "
               f"(found {sig!r})")
    (fmt_code,) = struct.unpack_from("<H", raw, 12)
    if fmt_code not in (0, 257):
        r.fail(f"object {index}: unknown byte-order code {fmt_code} (0 = PC, 257 = Mac)")
    e = ">" if fmt_code == 257 else "<"

    def u(fmt: str, off: int) -> Any:
        return struct.unpack_from(e + fmt, raw, off)

    h: dict[str, Any] = {"compressed": sig == MAGIC_COMPRESSED, "endian": e}
    h["n_objects"], h["version"], h["type"] = u("HHH", 14)
    h["object_name"] = _text(raw[20:50])
    h["operator"] = _text(raw[50:80])
    (h["material_code"], h["acquisition"], h["range_type"], h["special_points"],
     h["absolute"]) = u("5H", 80)
    (h["gauge_resolution"],) = u("f", 90)
    (h["w_size"],) = u("I", 94)
    (h["bits"],) = u("H", 98)
    h["zmin"], h["zmax"], h["nx"], h["ny"], h["n_total"] = u("5i", 100)
    h["spacing"] = u("3f", 120)
    h["axis_names"] = tuple(_text(raw[132 + 16 * i:148 + 16 * i]) for i in range(3))
    h["step_units"] = tuple(_text(raw[180 + 16 * i:196 + 16 * i]) for i in range(3))
    h["length_units"] = tuple(_text(raw[228 + 16 * i:244 + 16 * i]) for i in range(3))
    h["unit_ratios"] = u("3f", 276)
    h["imprint"], h["inversion"], h["leveling"] = u("3H", 288)
    sec, minute, hour, day, month, year, _weekday = u("7H", 306)
    h["time"] = (year, month, day, hour, minute, sec)
    (h["duration"],) = u("f", 320)
    (h["compressed_size"],) = u("I", 324)
    h["comment_size"], h["private_size"] = u("HH", 334)
    h["client_zone"] = _text(raw[338:466])
    h["offsets"] = u("3f", 466)
    return h


def _data_size(h: dict[str, Any]) -> int:
    return h["n_total"] * (h["bits"] // 8) * max(h["w_size"], 1)


def _read_points(r: ByteReader, h: dict[str, Any], pos: int, index: int
                 ) -> tuple[np.ndarray, int]:
    """The object's raw integer points and the offset just after them."""
    dtype = np.dtype(f"{h['endian']}i{h['bits'] // 8}")
    n = h["n_total"]
    nbytes = n * dtype.itemsize
    if not h["compressed"]:
        r.seek(pos)
        return r.array(dtype, n, f"object {index} points"), pos + _data_size(h)
    r.seek(pos)
    (count,) = r.unpack("<I", f"object {index} stream count")
    if count == 0 or count > _MAX_STREAMS:
        r.fail(f"object {index}: absurd number of compressed streams {count}")
    r.need(8 * count, f"object {index} stream directory")
    dirs = [r.unpack("<II", "stream directory") for _ in range(count)]
    total_raw = sum(d[0] for d in dirs)
    total_zip = sum(d[1] for d in dirs)
    if total_raw != _data_size(h):
        r.fail(f"object {index}: the compressed streams hold {total_raw} bytes but the "
               f"header implies {_data_size(h)}")
    r.need(total_zip, f"object {index} compressed points")
    if total_raw > MAX_DEFLATE_RATIO * total_zip + 1024:
        r.fail(f"object {index}: {total_zip} compressed bytes cannot hold {total_raw} bytes "
               "(corrupted header or decompression bomb)")
    chunks = []
    for raw_len, zip_len in dirs:
        blob = r.bytes(zip_len, "compressed stream")
        d = zlib.decompressobj()
        try:
            out = d.decompress(blob, raw_len)
        except zlib.error as exc:
            r.fail(f"object {index}: corrupted compressed stream ({exc})")
        if len(out) != raw_len:
            r.fail(f"object {index}: a compressed stream gave {len(out)} bytes instead of "
                   f"{raw_len}")
        chunks.append(out)
    raw = b"".join(chunks)[:nbytes]
    return np.frombuffer(raw, dtype=dtype, count=n).copy(), r.pos


def _unit_factor(unit: str, what: str, r: ByteReader) -> float | None:
    if not unit:
        return None
    try:
        return length_factor(unit)
    except SurfmetInputError:
        r.fail(f"unknown {what} unit {unit!r}")


def _date(t: tuple[int, int, int, int, int, int]) -> str | None:
    try:
        return _dt.datetime(*t).isoformat()
    except (ValueError, OverflowError):
        return None


@register_reader(FORMAT, extensions=("sur", "pro"),
                 description="Digital Surf SUR / MountainsMap (binary, plain or compressed)",
                 magic=_is_sur, priority=10)
def decode(buf: bytes, name: str) -> Topography | Profile:
    """Read the first height object of a Digital Surf file."""
    r = ByteReader(buf, name, FORMAT)
    if not _is_sur(buf):
        r.fail("missing the 'DIGITAL SURF' / 'DSCOMPRESSED' signature")
    pos = 0
    first = None
    index = 0
    while True:
        h = _header(r, pos, index)
        if first is None:
            first = h
            if h["n_objects"] > _MAX_OBJECTS:
                r.fail(f"absurd number of objects {h['n_objects']}")
        if h["bits"] not in (16, 32):
            r.fail(f"object {index}: {h['bits']} bits per point (expected 16 or 32)")
        if h["n_total"] < 0:
            r.fail(f"object {index}: negative point count {h['n_total']}")
        if h["w_size"] > MAX_POINTS:
            r.fail(f"object {index}: absurd number of values per point {h['w_size']}")
        data_pos = pos + HEADER_SIZE + h["comment_size"] + h["private_size"]
        r.seek(pos + HEADER_SIZE)
        comment = r.bytes(h["comment_size"], f"object {index} comment")
        r.skip(h["private_size"], f"object {index} private zone")
        kind = _HEIGHT_TYPES.get(h["type"])
        if kind is not None:
            return _build(r, h, data_pos, index, kind, comment, first)
        # Not heights: skip over the points to the next object, if any.
        if h["compressed"]:
            _, end = _read_points(r, h, data_pos, index)
        else:
            end = data_pos + _data_size(h)
        index += 1
        if index >= max(first["n_objects"], 1) or end >= len(buf):
            kinds = OBJECT_TYPES.get(first["type"], f"type {first['type']}")
            r.fail(f"no height data: the file holds a {kinds} and no profile or surface")
        pos = end


def _build(r: ByteReader, h: dict[str, Any], data_pos: int, index: int, kind: str,
           comment: bytes, first: dict[str, Any]) -> Topography | Profile:
    nx, ny = h["nx"], h["ny"]
    if kind == "profile" and ny > 1:
        # Gwyddion exports surfaces with the profile type.
        kind = "areal"
    nx, ny = check_grid(nx, ny, r.name, FORMAT)
    if h["n_total"] != nx * ny:
        r.fail(f"header says {h['n_total']} points but the grid is {nx} x {ny}")
    if h["w_size"] > 1:
        r.fail(f"object {index} holds {h['w_size']} values per point (spectral data), "
               "not heights")
    if not h["compressed"]:
        check_grid(nx, ny, r.name, FORMAT, available=len(r.buf) - data_pos,
                   itemsize=h["bits"] // 8)
    raw, _ = _read_points(r, h, data_pos, index)

    sx, sy, sz = h["spacing"]
    ux, uy, uz = h["step_units"]
    fx = _unit_factor(ux, "x step", r)
    fy = _unit_factor(uy, "y step", r)
    fz = _unit_factor(uz, "z step", r)
    calibrated = fx is not None and (fy is not None or kind == "profile")
    if not (np.isfinite(sz) and sz != 0):
        r.fail(f"z spacing {sz!r} is not a usable scale")
    zoff = h["offsets"][2]
    if not np.isfinite(zoff):
        r.fail(f"z offset {zoff!r} is not finite")
    scale = float(sz) * (fz if fz is not None else 1.0)
    with np.errstate(over="ignore", invalid="ignore"):
        z = raw.astype(np.float64) * scale + float(zoff) * (fz if fz is not None else 1.0)
    if not np.all(np.isfinite(z)):
        r.fail(f"z spacing {sz!r} and offset {zoff!r} overflow the height range")
    n_invalid = 0
    if h["special_points"] == 1:
        bad = raw == h["zmin"] - 2
        n_invalid = int(np.count_nonzero(bad))
        z[bad] = np.nan
    dx = check_step(abs(float(sx)) * (fx or 1.0), r.name, FORMAT, "x spacing")

    md: dict[str, Any] = {
        "format": FORMAT,
        "vendor": "Digital Surf",
        "object_type": OBJECT_TYPES.get(h["type"], str(h["type"])),
        "object_index": index,
        "n_objects": first["n_objects"],
        "compressed": h["compressed"],
        "height_unit": uz,
        "lateral_unit": ux,
        "lateral_calibrated": calibrated,
        **assumed(fz is None, not calibrated),
        "acquisition": ACQUISITION_TYPES.get(h["acquisition"], str(h["acquisition"])),
        "bits_per_point": h["bits"],
        "z_spacing": scale,
        "z_offset": float(zoff) * (fz or 1.0),
        "zmin_raw": h["zmin"],
        "zmax_raw": h["zmax"],
        "non_measured_flag": bool(h["special_points"] == 1),
        "non_measured_points": n_invalid,
        "inversion": h["inversion"],
        "leveling": h["leveling"],
        "version": h["version"],
        "unit_ratios": tuple(float(v) for v in h["unit_ratios"]),
    }
    for key in ("object_name", "operator", "client_zone"):
        if h[key]:
            md[key] = h[key]
    date = _date(h["time"])
    if date:
        md["date"] = date
    text = comment.split(b"\0", 1)[0].decode("latin-1").strip()
    if text:
        md["comment"] = text
    if h["duration"] and np.isfinite(h["duration"]):
        md["measurement_duration_s"] = float(h["duration"])
    if kind == "profile":
        return Profile(z, dx, metadata=md)
    dy = check_step(abs(float(sy)) * (fy or 1.0), r.name, FORMAT, "y spacing")
    return Topography(z.reshape(ny, nx), dx, dy, md)


__all__ = ["decode"]
