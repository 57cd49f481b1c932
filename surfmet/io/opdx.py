"""Bruker Dektak ``.opdx`` files (Vision64 "VCA DATA" item tree): profiles and maps.

Layout (little endian), learnt from SurfaceTopography's ``OPDx.py`` and Gwyddion's Dektak
VCA module, checked on a Dektak XT profile (``opdx-3.opdx``, 2021):

* 12-byte signature ``VCA DATA\\x01\\x00\\x00\\x55``;
* a sequence of *items*: a name (uint32 length + UTF-8 bytes), a one-byte type and a
  payload. Containers (types 0x7D, 0x46 raw data, 0x47 raw 2D data) hold further items up
  to a terminator item (empty name, type 0x7F) followed by two bytes. Sizes of variable
  payloads are "varlen": one byte giving the width (1, 2 or 4) and the unsigned length.

  =====  ==================================================================
  0x01   boolean (1 byte)          0x04/0x05 int16/uint16   0x06/0x07 int32/uint32
  0x0A   int64   0x0B uint64       0x0C float32             0x0D float64
  0x0E   type id: type name, varlen, bytes
  0x12   string: varlen, UTF-8
  0x13   quantity: varlen, float64 value, unit name, unit symbol, more bytes
  0x15   time stamp: 9 bytes (a flag byte and a Windows FILETIME)
  0x18   unit: varlen, unit name, unit symbol, float64 value, 12 bytes
  0x40   double array: type name, varlen, 5 bytes, float64 values
  0x42   string list: type name, varlen, names
  0x7C   position data: type name, varlen, then (1D) a unit, a uint64 count and the
         float64 positions, or (2D) two axis records
  0x00   matrix: type name, uint32, name, varlen, uint32 yres, uint32 xres, float32 data
  =====  ==================================================================

The tree gives ``/MetaData/DataKind`` (``Surface Profile`` or ``Surface Height``),
``/MetaData/1D_Channels/Height`` (the profile channel names), and per channel
``/1D_Data/<name>/{NumPoints, Extent, DataScale, Array, PositionFunction}``. Heights are
``Array * DataScale`` in the unit of ``DataScale``. The step comes from the stored
positions (``PositionFunction``) when they are evenly spaced, else they are kept as the
profile's ``x``; without positions ``dx = Extent / NumPoints``. Maps use
``/2D_Data/<name>/{Matrix, Dimension1/2Extent, Dimension1/2Points, DataScale}``.
"""

from __future__ import annotations

import datetime as _dt
import re
import struct
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._registry import register_reader
from surfmet.units import length_factor, quantity

FORMAT = "opdx"
MAGIC = b"VCA DATA\x01\x00\x00\x55"
_CONTAINERS = (0x7D, 0x46, 0x47)
_SCALARS = {0x01: "<?", 0x04: "<h", 0x05: "<H", 0x06: "<i", 0x07: "<I", 0x0A: "<q",
            0x0B: "<Q", 0x0C: "<f", 0x0D: "<d"}
_MAX_DEPTH = 32
_MAX_ITEMS = 1_000_000
_UNIFORM_RTOL = 1e-3


class Quantity(tuple):
    """``(value, unit name, unit symbol)`` of a quantity or unit item."""

    __slots__ = ()

    @property
    def value(self) -> float:
        return self[0]

    @property
    def symbol(self) -> str:
        return self[2]


def _is_opdx(buf: bytes) -> bool:
    return buf[: len(MAGIC)] == MAGIC


def _name(r: ByteReader, end: int) -> str:
    (n,) = r.unpack("<I", "name length")
    if n > end - r.pos:
        r.fail(f"truncated: a name of {n} bytes at offset {r.pos} overruns its container")
    return r.bytes(n, "name").decode("utf-8", errors="replace")


def _varlen(r: ByteReader, end: int) -> int:
    (width,) = r.unpack("<B", "length width")
    fmt = {1: "<B", 2: "<H", 4: "<I"}.get(width)
    if fmt is None:
        r.fail(f"unknown length width {width} at offset {r.pos - 1}")
    (n,) = r.unpack(fmt, "length")
    if n > end - r.pos:
        r.fail(f"truncated: a {n}-byte field at offset {r.pos} overruns its container")
    return n


def _symbol(text: str) -> str:
    return text.replace("\u03bc", "\u00b5").strip()


def _read_items(r: ByteReader, end: int, prefix: str, tree: dict[str, Any], depth: int,
                budget: list[int]) -> None:
    # Read items until the terminator (or the end of the enclosing block).
    if depth > _MAX_DEPTH:
        r.fail("items nested too deeply (corrupted file?)")
    while r.pos < end:
        budget[0] -= 1
        if budget[0] < 0:
            r.fail("too many items (corrupted file?)")
        name = _name(r, end)
        (kind,) = r.unpack("<B", f"type of item {name!r}")
        path = f"{prefix}/{name}"
        if kind == 0x7F:
            r.skip(min(2, end - r.pos), "terminator")
            return
        if kind in _CONTAINERS:
            n = _varlen(r, end)
            stop = r.pos + n
            _read_items(r, stop, path, tree, depth + 1, budget)
            r.seek(stop, "container end")
        elif kind in _SCALARS:
            fmt = _SCALARS[kind]
            if struct.calcsize(fmt) > end - r.pos:
                r.fail(f"truncated item {path!r}")
            tree[path] = r.unpack(fmt, path)[0]
        elif kind == 0x12:
            n = _varlen(r, end)
            tree[path] = r.bytes(n, path).decode("utf-8", errors="replace")
        elif kind == 0x13:
            n = _varlen(r, end)
            stop = r.pos + n
            (value,) = r.unpack("<d", path)
            unit_name = _name(r, stop)
            symbol = _symbol(_name(r, stop))
            tree[path] = Quantity((value, unit_name, symbol))
            r.seek(stop, "quantity end")
        elif kind == 0x18:
            n = _varlen(r, end)
            stop = r.pos + n
            unit_name = _name(r, stop)
            symbol = _symbol(_name(r, stop))
            (value,) = r.unpack("<d", path)
            tree[path] = Quantity((value, unit_name, symbol))
            r.seek(stop, "unit end")
        elif kind == 0x15:
            raw = r.bytes(9, path)
            tree[path] = raw
        elif kind == 0x0E:
            _name(r, end)
            n = _varlen(r, end)
            tree[path] = r.bytes(n, path)
        elif kind in (0x40, 0x7C):  # an array of doubles / of positions, read later
            _name(r, end)
            n = _varlen(r, end)
            tree[path] = ("doubles" if kind == 0x40 else "positions", r.pos, n)
            r.skip(n, path)
        elif kind == 0x42:
            _name(r, end)
            n = _varlen(r, end)
            stop = r.pos + n
            names = []
            while r.pos < stop:
                names.append(_name(r, stop))
            tree[path] = names
        elif kind == 0x00:
            _name(r, end)
            r.unpack("<I", path)
            _name(r, end)
            n = _varlen(r, end)
            if n < 8:
                r.fail(f"matrix {path!r} is too short")
            yres, xres = r.unpack("<II", path)
            tree[path] = ("matrix", r.pos, n - 8, int(xres), int(yres))
            r.skip(n - 8, path)
        else:
            r.fail(f"item {path!r} at offset {r.pos - 1} has unknown type 0x{kind:02x}")


def read_tree(buf: bytes, name: str = "<bytes>") -> dict[str, Any]:
    """Parse the item tree into ``{"/path/of/item": value}``.

    Arrays are not decoded: they appear as ``(kind, offset, size, ...)`` tuples.
    """
    r = ByteReader(buf, name, FORMAT)
    if r.bytes(len(MAGIC), "signature") != MAGIC:
        r.fail("missing the 'VCA DATA' signature")
    tree: dict[str, Any] = {}
    _read_items(r, len(buf), "", tree, 0, [_MAX_ITEMS])
    return tree


def _factor(r: ByteReader, symbol: str, what: str) -> float:
    try:
        return length_factor(symbol)
    except SurfmetInputError:
        r.fail(f"{what} unit {symbol!r} is not a length")


def _get(r: ByteReader, tree: dict[str, Any], path: str, kind: type | tuple) -> Any:
    value = tree.get(path)
    if not isinstance(value, kind):
        r.fail(f"item {path!r} is missing or malformed")
    return value


def _setting(q: Any) -> Any:
    """A measurement setting as JSON: a length in metres and a unit of the JSON vocabulary
    (:data:`surfmet.units.JSON_UNITS`) as quantities, anything else (``3 mg`` of stylus
    force, a mass the instrument states for a force) as the instrument's words."""
    from surfmet.units import JSON_UNITS, TYPED_LENGTH_UNITS

    if q.symbol in TYPED_LENGTH_UNITS:  # exact: "A" (an ampere) is no Ångström here
        return quantity(q.value * TYPED_LENGTH_UNITS[q.symbol], "m")
    if q.symbol in JSON_UNITS:
        return quantity(q.value, q.symbol)
    return f"{q.value:g} {q.symbol}"


def _filetime(raw: bytes) -> str | None:
    # A flag byte, then 100-ns ticks since 1601-01-01 (Windows FILETIME).
    if len(raw) != 9:
        return None
    (ticks,) = struct.unpack("<Q", raw[1:])
    try:
        epoch = _dt.datetime(1601, 1, 1, tzinfo=_dt.timezone.utc)
        t = epoch + _dt.timedelta(microseconds=ticks // 10)
    except OverflowError:
        return None
    return t.isoformat() if 1970 <= t.year <= 2200 else None


def _metadata(tree: dict[str, Any]) -> dict[str, Any]:
    md: dict[str, Any] = {"vendor": "Bruker"}
    name = tree.get("/MetaData/MeasurementSettings/InstrumentName")
    if isinstance(name, str) and name:
        md["instrument"] = name
    for key in ("InstrumentSerial", "SerialNumber"):
        serial = tree.get(f"/MetaData/MeasurementSettings/{key}")
        if isinstance(serial, str) and serial:
            md["serial"] = serial
    date, time = tree.get("/MetaData/Date"), tree.get("/MetaData/Time")
    stamp = tree.get("/MetaData/TimeStamp")
    text = (f"{date} {time}" if isinstance(time, str) else date) if isinstance(date, str) else None
    if text:
        # As written, in local time and a locale-dependent day/month order.
        md["date_text"] = text
    if isinstance(stamp, bytes) and (iso := _filetime(stamp)):
        md["date"] = iso
    elif text:
        md["date"] = text
    settings: dict[str, Any] = {}
    prefix = "/MetaData/MeasurementSettings/"
    for path, value in tree.items():
        if not path.startswith(prefix) or "/" in path[len(prefix):]:
            continue
        key = path[len(prefix):]
        if isinstance(value, Quantity):
            settings[key] = _setting(value)
        elif isinstance(value, (str, bool, int, float)):
            settings[key] = value
    if settings:
        md["measurement_settings"] = settings
    force = tree.get(prefix + "StylusForce")
    if isinstance(force, Quantity) and force.symbol.lower() == "mg":
        md["stylus_force"] = quantity(force.value * 1e-6 * 9.80665, "N")
    stylus = tree.get(prefix + "StylusType")
    if isinstance(stylus, str) and (m := re.search(r"Radius:\s*([0-9.eE+-]+)\s*(\S+)", stylus)):
        try:
            md["tip_radius"] = quantity(float(m.group(1)) * length_factor(_symbol(m.group(2))), "m")
        except (ValueError, SurfmetInputError):
            pass
    for key in ("DataKind", "Measurement", "DataSetName"):
        if isinstance(tree.get(f"/MetaData/{key}"), str):
            md[key[0].lower() + key[1:].replace("Kind", "_kind").replace("SetName", "_set")] = \
                tree[f"/MetaData/{key}"]
    return md


def _profile(buf: bytes, r: ByteReader, tree: dict[str, Any], channel: str | None) -> Profile:
    names = tree.get("/MetaData/1D_Channels/Height")
    if not isinstance(names, list) or not names:
        names = sorted({p.split("/")[2] for p in tree if p.startswith("/1D_Data/")
                        and p.endswith("/Array")})
    if not names:
        r.fail("no profile channel found (/MetaData/1D_Channels/Height)")
    if channel is not None:
        if channel not in names:
            r.fail(f"no profile channel {channel!r}; channels: {names}")
        names = [channel]
    prefix = f"/1D_Data/{names[0]}"
    n = int(_get(r, tree, prefix + "/NumPoints", (int, np.integer)))
    scale = _get(r, tree, prefix + "/DataScale", Quantity)
    zf = _factor(r, scale.symbol, "height")
    kind, offset, size = _get(r, tree, prefix + "/Array", tuple)
    if kind != "doubles" or size < 5 or (size - 5) % 8:
        r.fail(f"{prefix}/Array is not a float64 array")
    count = (size - 5) // 8
    if count != n or n < 2:
        r.fail(f"{prefix}: NumPoints is {n} but the array holds {count} values")
    r.seek(offset + 5, "array offset")
    z = _scaled(r, r.array("<f8", n), scale.value * zf, f"{prefix}/Array")

    md = _metadata(tree)
    md.update({"channel": names[0], "height_unit": scale.symbol,
               "height_scale": quantity(scale.value * zf, "m")})
    extent = tree.get(prefix + "/Extent")
    x = None
    pos = tree.get(prefix + "/PositionFunction")
    if isinstance(pos, tuple) and pos[0] == "positions":
        p = ByteReader(buf, r.name, FORMAT, pos[1])
        stop = pos[1] + pos[2]
        _name(p, stop)
        symbol = _symbol(_name(p, stop))
        p.unpack("<d", "position unit")
        p.skip(12, "position unit")
        (count,) = p.unpack("<Q", "position count")
        if count == n and p.pos + 8 * n <= stop:
            x = _scaled(r, p.array("<f8", n), _factor(r, symbol, "position"), "positions")
            md["lateral_unit"] = symbol
    if x is not None and np.all(np.isfinite(x)) and np.all(np.diff(x) > 0):
        _check_positions(r, x)
        step = float((x[-1] - x[0]) / (n - 1))
        md["x_offset"] = quantity(float(x[0]), "m")
        md["lateral_calibrated"] = True
        if np.max(np.abs(np.diff(x) - step)) > _UNIFORM_RTOL * step:
            return Profile(z, step, x - x[0], metadata=md)
        return Profile(z, check_step(step, r.name, FORMAT, "position step"), metadata=md)
    if not isinstance(extent, Quantity):
        r.fail(f"{prefix} has neither positions nor an Extent")
    length = extent.value * _factor(r, extent.symbol, "extent")
    md["lateral_unit"] = extent.symbol
    md["lateral_calibrated"] = True
    return Profile(z, check_step(length / n, r.name, FORMAT, "Extent / NumPoints"), metadata=md)


def _scaled(r: ByteReader, raw: np.ndarray, factor: float, what: str) -> np.ndarray:
    """``raw * factor`` with the file's non-finite values as NaN (not measured); a
    product out of the float range (a damaged value or scale) is one line, not numpy's
    overflow warnings followed by a scan of infinities."""
    with np.errstate(over="ignore", invalid="ignore"):
        out = raw * factor
    measured = np.isfinite(raw)
    if not np.isfinite(out[measured]).all():
        big = float(np.max(np.abs(raw[measured])))
        r.fail(f"{what}: a value {big:.3g} times the scale {factor:.3g} is beyond the float "
               "range (a damaged value or scale)")
    out[~measured] = np.nan
    return out


#: Largest ratio of a step between stored positions to their median step before the
#: positions are taken for damaged (a Dektak samples evenly; one flipped exponent bit in
#: a position makes a jump of hundreds of decades).
_MAX_STEP_RATIO = 1e3


def _check_positions(r: ByteReader, x: np.ndarray) -> None:
    steps = np.diff(x)
    typical = float(np.median(steps))
    if float(steps.max()) > _MAX_STEP_RATIO * typical:
        k = int(np.argmax(steps))
        r.fail(f"the stored positions jump by {steps[k]:.3g} m after point {k} where they "
               f"step {typical:.3g} m: a damaged position")


def _map(r: ByteReader, tree: dict[str, Any], channel: str | None) -> Topography:
    name = channel or tree.get("/MetaData/PrimaryData2D")
    if not isinstance(name, str):
        r.fail("no map channel named (/MetaData/PrimaryData2D)")
    prefix = f"/2D_Data/{name}"
    item = _get(r, tree, prefix + "/Matrix", tuple)
    if item[0] != "matrix":
        r.fail(f"{prefix}/Matrix is not a matrix")
    _, offset, size, xres, yres = item
    nx, ny = check_grid(xres, yres, r.name, FORMAT, available=size, itemsize=4)
    r.seek(offset, "matrix offset")
    raw = r.array("<f4", nx * ny).reshape(ny, nx).astype(np.float64)
    scale = _get(r, tree, prefix + "/DataScale", Quantity)
    heights = _scaled(r, raw, scale.value * _factor(r, scale.symbol, "height"),
                      f"{prefix}/Matrix")
    ext_y = _get(r, tree, prefix + "/Dimension1Extent", Quantity)
    ext_x = _get(r, tree, prefix + "/Dimension2Extent", Quantity)
    dx = check_step(ext_x.value * _factor(r, ext_x.symbol, "x extent") / nx, r.name, FORMAT)
    dy = check_step(ext_y.value * _factor(r, ext_y.symbol, "y extent") / ny, r.name, FORMAT)
    md = _metadata(tree)
    md.update({"channel": name, "height_unit": scale.symbol, "lateral_unit": ext_x.symbol,
               "lateral_calibrated": True})
    return Topography(heights, dx, dy, md)


@register_reader(FORMAT, extensions=("opdx",), description="Bruker Dektak OPDx",
                 magic=_is_opdx, priority=10)
def decode(buf: bytes, name: str, channel: str | None = None) -> Profile | Topography:
    """Read a Dektak ``.opdx`` file: a profile or a map depending on its data kind."""
    r = ByteReader(buf, name, FORMAT)
    tree = read_tree(buf, name)
    kind = tree.get("/MetaData/DataKind")
    if kind == "Surface Profile" or (kind is None and any(p.startswith("/1D_Data/") for p in tree)):
        return _profile(buf, r, tree, channel)
    if kind == "Surface Height" or (kind is None and any(p.startswith("/2D_Data/") for p in tree)):
        return _map(r, tree, channel)
    r.fail(f"unsupported data kind {kind!r}")


__all__ = ["Quantity", "decode", "read_tree"]
