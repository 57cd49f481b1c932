"""Gwyddion native ``.gwy`` files (the GwyContainer serialisation of Gwyddion 2).

The format is documented in the Gwyddion user guide ("GWY file format"): the magic
``GWYP``, then one serialised object. An object is its type name (NUL-terminated), a
uint32 byte count and its components; a component is a name (NUL-terminated), a one-letter
type and the value, all little endian:

=====  ======================================  =====  ===============================
``b``  boolean (1 byte)                        ``B``  array of booleans
``c``  char (1 byte)                           ``C``  array of chars
``i``  int32                                   ``I``  array of int32
``q``  int64                                   ``Q``  array of int64
``d``  float64                                 ``D``  array of float64
``s``  NUL-terminated UTF-8 string             ``S``  array of strings
``o``  nested object                           ``O``  array of objects
=====  ======================================  =====  ===============================

Arrays are a uint32 item count followed by the items. The top object is a
``GwyContainer`` whose components are keyed like paths: ``/0/data`` is the first image
channel (a ``GwyDataField`` with ``xres``, ``yres``, ``xreal``, ``yreal``, ``xoff``,
``yoff``, ``si_unit_xy`` and ``si_unit_z`` (``GwySIUnit`` objects with a ``unitstr``) and
``data``: ``xres * yres`` doubles, row after row), ``/0/data/title`` its title, ``/0/mask``
an optional mask.

Values are in SI base units with the unit in ``unitstr``. surfmet reads the first height
channel: ``/0/data`` if its value unit is a length (or empty), else the first channel
whose value unit is a length. ``channel=`` selects another by number (``2`` for
``/2/data``) or by title.

**Files without units.** Some files (for instance the test file of the ``gwyfile``
package) carry empty ``si_unit_xy`` / ``si_unit_z``. Gwyddion then shows bare numbers.
surfmet reads the numbers as they are: heights taken as metres, ``dx = xreal / xres`` and
``dy = yreal / yres`` taken as metres, and records ``lateral_calibrated = False`` and
``height_unit = ""`` (with ``units_missing = True``) so that no one mistakes them for
calibrated values. ``data`` is stored row-major (``yres`` rows of ``xres``), as
``gwyfile`` and Gwyddion index it: row ``j`` is ``y = j * dy``.
"""

from __future__ import annotations

import re
import struct
from typing import Any

import numpy as np

from surfmet._model import Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader
from surfmet.units import quantity

FORMAT = "gwy"
MAGIC = b"GWYP"
_MAX_DEPTH = 64
_ARRAY_DTYPES: dict[str, np.dtype[Any]] = {
    "C": np.dtype("u1"), "B": np.dtype("u1"), "I": np.dtype("<i4"),
    "Q": np.dtype("<i8"), "D": np.dtype("<f8")}
_SCALARS = {"i": "<i", "q": "<q", "d": "<d"}
_CHANNEL_RE = re.compile(r"^/(\d+)/data$")


class GwyObject(dict):
    """A deserialised Gwyddion object: its components by name, plus ``type_name``."""

    def __init__(self, type_name: str) -> None:
        super().__init__()
        self.type_name = type_name


def _cstring(r: ByteReader, end: int, what: str) -> str:
    stop = r.buf.find(b"\0", r.pos, end)
    if stop < 0:
        r.fail(f"truncated: unterminated {what} at offset {r.pos}")
    raw = r.buf[r.pos : stop]
    r.pos = stop + 1
    return raw.decode("utf-8", errors="replace")


def _count(r: ByteReader, end: int, itemsize: int, what: str) -> int:
    (n,) = r.unpack("<I", f"{what} length")
    if n * itemsize > end - r.pos:
        r.fail(f"truncated: {what} claims {n} items, only {end - r.pos} bytes remain")
    return n


def read_object(r: ByteReader, end: int, depth: int = 0) -> GwyObject:
    """Deserialise the object at the cursor; ``end`` bounds the enclosing data."""
    if depth > _MAX_DEPTH:
        r.fail("objects nested too deeply (corrupted file?)")
    type_name = _cstring(r, end, "object type name")
    (size,) = r.unpack("<I", "object size")
    stop = r.pos + size
    if stop > end:
        r.fail(f"truncated: object {type_name!r} claims {size} bytes, only {end - r.pos} remain")
    obj = GwyObject(type_name)
    while r.pos < stop:
        key = _cstring(r, stop, "component name")
        code = r.bytes(1, f"type of component {key!r}").decode("latin-1")
        obj[key] = _component(r, code, stop, depth, key)
    if r.pos != stop:
        r.fail(f"object {type_name!r} components overrun its size")
    return obj


def _component(r: ByteReader, code: str, end: int, depth: int, key: str) -> Any:
    if r.pos > end:
        r.fail(f"component {key!r} overruns its object")
    if code == "b":
        return r.bytes(1, key)[0] != 0
    if code == "c":
        return r.bytes(1, key)
    if code in _SCALARS:
        if r.pos + struct.calcsize(_SCALARS[code]) > end:
            r.fail(f"truncated component {key!r}")
        return r.unpack(_SCALARS[code], key)[0]
    if code == "s":
        return _cstring(r, end, f"string {key!r}")
    if code == "o":
        return read_object(r, end, depth + 1)
    if code in _ARRAY_DTYPES:
        dt = _ARRAY_DTYPES[code]
        n = _count(r, end, dt.itemsize, f"array {key!r}")
        return r.array(dt, n, f"array {key!r}")
    if code == "S":
        n = _count(r, end, 1, f"string array {key!r}")
        return [_cstring(r, end, f"string array {key!r}") for _ in range(n)]
    if code == "O":
        n = _count(r, end, 6, f"object array {key!r}")
        return [read_object(r, end, depth + 1) for _ in range(n)]
    r.fail(f"component {key!r} has unknown type {code!r}")


def load(buf: bytes, name: str = "<bytes>") -> GwyObject:
    """Parse a whole ``.gwy`` file into nested :class:`GwyObject` dicts."""
    r = ByteReader(buf, name, FORMAT)
    magic = r.bytes(4, "signature")
    if magic == b"GWYO":
        r.fail("this is a Gwyddion 1.x file (GWYO); only Gwyddion 2 files (GWYP) are supported")
    if magic != MAGIC:
        r.fail("missing the 'GWYP' signature")
    return read_object(r, len(buf))


def _is_gwy(buf: bytes) -> bool:
    return buf[:4] == MAGIC and buf[4:17] == b"GwyContainer\0"


def _unit(field: GwyObject, key: str) -> str | None:
    u = field.get(key)
    if isinstance(u, GwyObject):
        s = u.get("unitstr", "")
        return s if isinstance(s, str) else ""
    return None


# Gwyddion writes SI unit strings, case-sensitive: "A" is the ampere, not the ångström.
_LENGTHS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "nm": 1e-9,
            "pm": 1e-12, "Å": 1e-10}


def _length_unit(unit: str | None) -> float | None:
    # Metres per unit; None if the unit is not a length. "" (no unit) also gives None.
    if not unit:
        return None
    return _LENGTHS.get(unit.strip())


def _number(value: Any) -> float:
    return float(value) if isinstance(value, (int, float)) else 0.0


def _channels(container: GwyObject) -> list[tuple[int, GwyObject, str]]:
    found = []
    for key, value in container.items():
        m = _CHANNEL_RE.match(key)
        if m and isinstance(value, GwyObject) and value.type_name == "GwyDataField":
            num = int(m.group(1))
            title = container.get(f"/{num}/data/title", "")
            found.append((num, value, title if isinstance(title, str) else ""))
    return sorted(found, key=lambda t: t[0])


@register_reader(FORMAT, extensions=("gwy",), description="Gwyddion native GWY",
                 magic=_is_gwy, priority=10)
def decode(buf: bytes, name: str, channel: int | str | None = None) -> Topography:
    """Read a height channel of a ``.gwy`` file.

    Parameters
    ----------
    channel : int or str, optional
        Channel number (``/N/data``) or title. Default: the first height channel.
    """
    r = ByteReader(buf, name, FORMAT)
    container = load(buf, name)
    if container.type_name != "GwyContainer":
        r.fail(f"the top object is a {container.type_name!r}, not a GwyContainer")
    channels = _channels(container)
    if not channels:
        r.fail("the file holds no image channel (/N/data)")
    if channel is not None:
        chosen = [c for c in channels
                  if (isinstance(channel, str) and not channel.isdigit() and c[2] == channel)
                  or (str(channel).isdigit() and c[0] == int(channel))]
        if not chosen:
            listing = ", ".join(f"{n} ({t or 'untitled'})" for n, _, t in channels)
            r.fail(f"no channel {channel!r}; channels: {listing}")
        num, field, title = chosen[0]
    else:
        lengths = [c for c in channels
                   if not _unit(c[1], "si_unit_z") or _length_unit(_unit(c[1], "si_unit_z"))]
        if not lengths:
            listing = ", ".join(f"{n} ({_unit(f, 'si_unit_z')})" for n, f, _ in channels)
            r.fail(f"no channel holds heights (value units: {listing}); pass channel=")
        num, field, title = lengths[0]

    try:
        xres, yres = int(field["xres"]), int(field["yres"])
        xreal, yreal = float(field["xreal"]), float(field["yreal"])
    except KeyError as exc:
        r.fail(f"channel {num} lacks the component {exc.args[0]!r}")
    except (TypeError, ValueError):
        r.fail(f"channel {num} has a malformed size")
    data = field.get("data")
    if not isinstance(data, np.ndarray) or data.dtype != np.float64:
        r.fail(f"channel {num} has no double array 'data'")
    nx, ny = check_grid(xres, yres, name, FORMAT)
    if data.size != nx * ny:
        r.fail(f"channel {num}: xres x yres = {nx} x {ny} but 'data' holds {data.size} values")

    zunit = _unit(field, "si_unit_z")
    xyunit = _unit(field, "si_unit_xy")
    zf = _length_unit(zunit)
    if zunit and zf is None:
        r.fail(f"channel {num} ({title or 'untitled'}) holds {zunit!r} values, not heights")
    xyf = _length_unit(xyunit)
    if xyunit and xyf is None:
        r.fail(f"channel {num} has lateral unit {xyunit!r}, not a length")
    dx = check_step(xreal / nx * (xyf or 1.0), name, FORMAT, "xreal / xres")
    dy = check_step(yreal / ny * (xyf or 1.0), name, FORMAT, "yreal / yres")
    heights = data.reshape(ny, nx) * (zf or 1.0)
    heights[~np.isfinite(heights)] = np.nan

    mask = container.get(f"/{num}/mask")
    masked = 0
    if isinstance(mask, GwyObject) and isinstance(mask.get("data"), np.ndarray):
        m = mask["data"]
        if m.size == nx * ny:
            # Gwyddion masks mark with 1 the points a module flagged (e.g. bad data).
            bad = m.reshape(ny, nx) > 0.5
            masked = int(bad.sum())

    units_missing = not zunit or not xyunit
    metadata: dict[str, Any] = {
        "software": "Gwyddion",
        "channel": num,
        "title": title,
        "height_unit": zunit or "",
        "lateral_unit": xyunit or "",
        "lateral_calibrated": bool(xyunit),
        "units_missing": units_missing,
        **assumed(not zunit, not xyunit),
        "x_offset": quantity(_number(field.get("xoff")) * (xyf or 1.0), "m"),
        "y_offset": quantity(_number(field.get("yoff")) * (xyf or 1.0), "m"),
        "channels": [{"number": n, "title": t, "unit": _unit(f, "si_unit_z") or ""}
                     for n, f, t in channels],
    }
    if masked:
        metadata["mask_points"] = masked
    return Topography(heights, dx, dy, metadata)


__all__ = ["GwyObject", "decode", "load", "read_object"]
