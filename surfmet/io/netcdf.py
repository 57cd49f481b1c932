"""NetCDF classic files (``.nc``) in SurfaceTopography's layout.

The container is NetCDF-3 (classic, ``CDF\\x01``, or 64-bit offset, ``CDF\\x02``), read by
the small parser below from the format specification (Unidata, "The NetCDF Classic Format
Specification"): big-endian; a header of dimensions, global attributes and variables (name,
dimension ids, attributes, type, size, begin offset); the data of fixed-size variables at
their ``begin`` offsets. Record (unlimited) variables are refused.

The layout (SurfaceTopography's ``NCReader``/``to_netcdf``): a variable ``heights(x, y)``
(areal) or ``heights(x)`` (profile) whose first index is x; optional variables ``x`` and
``y`` whose attribute ``length`` is the physical size and ``unit`` (or ``length_unit``)
its unit; ``heights:unit`` the height unit; an optional ``mask`` variable (nonzero =
non-measured). ``scale_factor``, ``add_offset`` and ``_FillValue`` are applied.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet.io._binary import ByteReader, check_grid, check_step
from surfmet.io._calibration import assumed
from surfmet.io._registry import register_reader
from surfmet.units import length_factor

FORMAT = "nc"
_TYPES = {1: "i1", 2: "S1", 3: ">i2", 4: ">i4", 5: ">f4", 6: ">f8"}
_DIMENSION, _VARIABLE, _ATTRIBUTE = 10, 11, 12
_MAX_ITEMS = 1 << 16


def _is_nc(buf: bytes) -> bool:
    return buf[:3] == b"CDF" and buf[3:4] in (b"\x01", b"\x02")


class _Header:
    """The parsed header: dimensions, global attributes, variables."""

    def __init__(self, r: ByteReader) -> None:
        self.r = r
        self.offset64 = r.buf[3] == 2
        r.seek(4)
        (self.numrecs,) = r.unpack(">I", "header")
        self.dims = [(name, size) for name, size in self._list(_DIMENSION, self._dim)]
        self.attrs = dict(self._list(_ATTRIBUTE, self._attr))
        self.vars = dict(self._list(_VARIABLE, self._var))

    def _count(self, tag: int) -> int:
        kind, n = self.r.unpack(">ii", "header list")
        if kind == 0 and n == 0:
            return 0
        if kind != tag or not 0 <= n <= _MAX_ITEMS:
            self.r.fail(f"header list tag {kind} / count {n} is not a valid list")
        return n

    def _list(self, tag: int, item: Any) -> list[Any]:
        return [item() for _ in range(self._count(tag))]

    def _name(self) -> str:
        (n,) = self.r.unpack(">i", "name length")
        if not 0 <= n <= 4096:
            self.r.fail(f"name length {n} is absurd")
        raw = self.r.bytes(n, "name")
        self.r.skip(-n % 4, "padding")
        return raw.decode("utf-8", errors="replace")

    def _dim(self) -> tuple[str, int]:
        name = self._name()
        (size,) = self.r.unpack(">i", "dimension length")
        return name, size

    def _attr(self) -> tuple[str, Any]:
        name = self._name()
        kind, n = self.r.unpack(">ii", "attribute")
        if kind not in _TYPES or n < 0:
            self.r.fail(f"attribute {name!r} has type {kind} / {n} values")
        dtype = np.dtype(_TYPES[kind])
        raw = self.r.bytes(n * dtype.itemsize, f"attribute {name!r}")
        self.r.skip(-(n * dtype.itemsize) % 4, "padding")
        if kind == 2:
            return name, raw.split(b"\0", 1)[0].decode("utf-8", errors="replace")
        values = np.frombuffer(raw, dtype=dtype)
        return name, values[0].item() if n == 1 else values.tolist()

    def _var(self) -> tuple[str, dict[str, Any]]:
        name = self._name()
        (ndims,) = self.r.unpack(">i", "variable rank")
        if not 0 <= ndims <= 8:
            self.r.fail(f"variable {name!r} has {ndims} dimensions")
        dimids = self.r.unpack(f">{ndims}i", "dimension ids")
        attrs = dict(self._list(_ATTRIBUTE, self._attr))
        kind, _vsize = self.r.unpack(">iI", "variable type")
        (begin,) = self.r.unpack(">Q" if self.offset64 else ">I", "variable offset")
        if kind not in _TYPES or kind == 2:
            self.r.fail(f"variable {name!r} has type {kind}, not a number type")
        for d in dimids:
            if not 0 <= d < len(self.dims):
                self.r.fail(f"variable {name!r} names dimension {d} of {len(self.dims)}")
        return name, {"dims": dimids, "attrs": attrs, "dtype": np.dtype(_TYPES[kind]),
                      "begin": begin}

    def read(self, name: str) -> np.ndarray:
        var = self.vars[name]
        shape = tuple(self.dims[d][1] for d in var["dims"])
        if any(self.dims[d][1] == 0 for d in var["dims"][:1]):
            self.r.fail(f"variable {name!r} is a record (unlimited) variable; not supported")
        self.r.seek(var["begin"], f"offset of {name!r}")
        count = int(np.prod(shape, dtype=np.int64)) if shape else 1
        data = self.r.array(var["dtype"], count, f"variable {name!r}").reshape(shape)
        a = var["attrs"]
        out = data.astype(np.float64)
        if "_FillValue" in a:
            out[data == np.asarray(a["_FillValue"]).astype(var["dtype"])] = np.nan
        return out * float(a.get("scale_factor", 1.0)) + float(a.get("add_offset", 0.0))


def _factor(unit: Any, r: ByteReader, what: str) -> float | None:
    if unit in (None, ""):
        return None
    try:
        return length_factor(str(unit))
    except SurfmetInputError:
        r.fail(f"{what} unit {unit!r} is not a length")


def _axis(h: _Header, name: str, n: int, r: ByteReader) -> tuple[float, float | None]:
    """Pixel size (in the axis unit) and metres per unit of axis ``name``."""
    var = h.vars.get(name)
    if var is None or "length" not in var["attrs"]:
        return 1.0, None
    a = var["attrs"]
    return float(a["length"]) / n, _factor(a.get("unit", a.get("length_unit")), r, name)


@register_reader(FORMAT, extensions=("nc",), description="NetCDF-3 (SurfaceTopography layout)",
                 magic=_is_nc, priority=30)
def decode(buf: bytes, name: str) -> Topography | Profile:
    """Read the ``heights`` variable of a NetCDF classic file."""
    r = ByteReader(buf, name, FORMAT)
    if not _is_nc(buf):
        r.fail("not a NetCDF classic file (magic CDF\\x01 or CDF\\x02)")
    h = _Header(r)
    if "heights" not in h.vars:
        r.fail(f"no variable 'heights' (variables: {sorted(h.vars)})")
    z = h.read("heights")
    if "mask" in h.vars:
        mask = h.read("mask")
        if mask.shape != z.shape:
            r.fail("variable 'mask' does not have the shape of 'heights'")
        z[mask != 0] = np.nan
    z[~np.isfinite(z)] = np.nan
    if z.ndim not in (1, 2):
        r.fail(f"'heights' has {z.ndim} dimensions (1 or 2 expected)")
    hv = h.vars["heights"]["attrs"]
    zf = _factor(hv.get("unit"), r, "height")
    axes = [h.dims[d][0] for d in h.vars["heights"]["dims"]]
    steps = [_axis(h, axis, n, r) for axis, n in zip(axes, z.shape)]
    # An axis without its own unit shares the height unit (SurfaceTopography writes one).
    lateral = [f if f is not None else (zf or 1.0) for _, f in steps]
    md: dict[str, Any] = {
        "height_unit": hv.get("unit", ""),
        "lateral_unit": h.vars.get(axes[0], {}).get("attrs", {}).get("unit", hv.get("unit", "")),
        "lateral_calibrated": all(f is not None for _, f in steps) or zf is not None,
        # an axis without its own unit takes the heights' (SurfaceTopography's layout)
        **assumed(zf is None, not (all(f is not None for _, f in steps) or zf is not None)),
    }
    if zf is None:
        md["units_missing"] = True
    z = z * (zf or 1.0)
    dx = check_step(steps[0][0] * lateral[0], name, FORMAT, "x pixel size")
    if z.ndim == 1:
        return Profile(z, dx, metadata=md)
    check_grid(z.shape[0], z.shape[1], name, FORMAT)
    dy = check_step(steps[1][0] * lateral[1], name, FORMAT, "y pixel size")
    return Topography(z.T, dx, dy, md)

__all__ = ["decode"]
