"""ISO 5436-2 softgauge files (``.smd``): the type-F reference data of NIST, NPL, PTB and the
MTS feature-characterisation test profiles.

ISO 5436-2:2001 (Geometrical product specifications - Surface texture: profile method;
measurement standards - Part 2: Software measurement standards), clause on the file format,
defines four records of Latin-1 text, each ended by the ETX character (0x03):

1. the header: a revision line (``ISO 5436 - 2000``), optionally the feature type
   (``PRF`` profile, ``SUR`` surface), and one line per axis ``<axis> <type> <points>
   <unit> <scale> <data type> [<increment>]``, e.g. ``CX I 8001 MM 1.0 D 0.0005`` (an
   incremental x axis: 8001 points 0.5 µm apart) and ``CZ A 8001 UM 1.0 D`` (absolute z
   values in µm); axis type ``I`` incremental, ``A`` absolute; units ``M``, ``MM``,
   ``UM``, ``NM`` (any case); data type ``I``/``L`` (integers), ``F``/``D`` (reals); fields
   are separated by blanks (some writers use NUL bytes);
2. free information (``DATE``, ``CREATED-BY``, comments);
3. the data, one point per line: z, or x and z when the x axis is absolute; for a surface
   (``CY`` present) x runs fastest;
4. optionally, a checksum: the sum of all bytes of records 1 to 3 modulo 65535 (counted to
   the end of the line holding the third ETX, as the MTS reader does; the sum up to the ETX
   itself is accepted too).

Real value = value x scale x unit. A profile with an incremental x axis becomes a uniform
:class:`~surfmet._model.Profile`; an absolute x axis keeps its positions (re-based to 0).
Areal files (CX and CY incremental) become a :class:`~surfmet._model.Topography`.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError
from surfmet._model import Profile, Topography
from surfmet.io._binary import (
    MAX_POINTS,
    check_grid,
    check_step,
    format_error,
    positions_profile,
)
from surfmet.io._registry import register_reader

FORMAT = "smd"
_ETX = b"\x03"
_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9}
_AXIS_RE = re.compile(rb"(?:^|[\r\n])[ \t\0]*C[XYZ][ \t\0]+[AI][ \t\0]")
_UNIFORM_RTOL = 1e-6


def _is_smd(buf: bytes) -> bool:
    head = buf[:4096]
    return _ETX in head and _AXIS_RE.search(head) is not None


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _axis(fields: list[str], name: str) -> dict[str, Any]:
    if len(fields) < 6:
        raise _fail(name, f"axis line {' '.join(fields)!r} has fewer than 6 fields")
    axis, kind, points, unit, scale, _dtype = fields[:6]
    if kind.upper() not in ("A", "I"):
        raise _fail(name, f"axis {axis}: type {kind!r} is neither A nor I")
    if unit.lower() not in _UNITS:
        raise _fail(name, f"axis {axis}: unit {unit!r} is not one of M, MM, UM, NM")
    try:
        out: dict[str, Any] = {"type": kind.upper(), "n": int(points),
               "factor": float(scale) * _UNITS[unit.lower()], "unit": unit}
        out["increment"] = float(fields[6]) if len(fields) > 6 else None
    except ValueError:
        raise _fail(name, f"axis line {' '.join(fields)!r} holds a field that is not a "
                          "number") from None
    if out["type"] == "I" and out["increment"] is None:
        raise _fail(name, f"incremental axis {axis} has no increment")
    if not np.isfinite(out["factor"]) or out["factor"] == 0:
        raise _fail(name, f"axis {axis}: scale {scale!r} is unusable")
    return out


def _header(text: str, name: str) -> tuple[dict[str, dict[str, Any]], list[str]]:
    axes: dict[str, dict[str, Any]] = {}
    other: list[str] = []
    for line in text.splitlines():
        fields = line.split()
        if not fields:
            continue
        if fields[0].upper() in ("CX", "CY", "CZ"):
            axes[fields[0].upper()] = _axis(fields, name)
        else:
            other.append(" ".join(fields))
    for need in ("CX", "CZ"):
        if need not in axes:
            raise _fail(name, f"the header defines no {need} axis")
    if axes["CZ"]["type"] != "A":
        raise _fail(name, "the CZ axis must be absolute (A)")
    return axes, other


def _check_sum(buf: bytes, etx: list[int], name: str) -> str:
    if len(etx) < 4:
        return "absent"
    text = buf[etx[2] + 1:etx[3]].decode("latin-1")
    eol = buf.find(b"\n", etx[2], etx[3])
    digits = text.strip().split()
    if not digits:
        return "absent"
    try:
        stated = int(digits[-1])
    except ValueError:
        raise _fail(name, f"checksum record {text.strip()[:20]!r} is not a number") from None
    sums = {sum(buf[:etx[2] + 1]) % 65535}
    if eol >= 0:
        sums.add(sum(buf[:eol + 1]) % 65535)
    if stated not in sums:
        raise _fail(name, f"checksum {stated} does not match the data ({min(sums)}): the "
                          "file is corrupted (pass verify_checksum=False to read it anyway)")
    return "ok"


def _values(text: str, columns: int, name: str) -> np.ndarray:
    rows = [ln.split() for ln in text.splitlines() if ln.strip()]
    if not rows:
        raise _fail(name, "the data record is empty")
    if len(rows) > MAX_POINTS:
        raise _fail(name, "absurd number of data lines")
    bad = next((i for i, r in enumerate(rows) if len(r) != columns), None)
    if bad is not None:
        raise _fail(name, f"data line {bad + 1} holds {len(rows[bad])} values, expected "
                          f"{columns}")
    try:
        return np.array(rows, dtype=np.float64)
    except ValueError:
        raise _fail(name, "a data value is not a number") from None


@register_reader(FORMAT, extensions=("smd",), description="ISO 5436-2 softgauge (.smd)",
                 magic=_is_smd, priority=45)
def decode(buf: bytes, name: str, verify_checksum: bool = True) -> Profile | Topography:
    """Read an ISO 5436-2 softgauge file.

    Parameters
    ----------
    verify_checksum : bool
        Check record 4's checksum when the file has one.
    """
    etx: list[int] = []
    pos = buf.find(_ETX)
    while pos >= 0 and len(etx) < 4:
        etx.append(pos)
        pos = buf.find(_ETX, pos + 1)
    if len(etx) < 3:
        raise _fail(name, f"{len(etx)} ETX record separators, at least 3 expected (truncated?)")
    header = buf[:etx[0]].replace(b"\0", b" ").decode("latin-1")
    axes, other = _header(header, name)
    info = buf[etx[0] + 1:etx[1]].replace(b"\0", b" ").decode("latin-1").strip()
    cx, cz = axes["CX"], axes["CZ"]
    areal = "CY" in axes and axes["CY"]["n"] > 1
    data = _values(buf[etx[1] + 1:etx[2]].decode("latin-1"),
                   2 if cx["type"] == "A" and not areal else 1, name)
    md: dict[str, Any] = {"height_unit": cz["unit"], "lateral_unit": cx["unit"],
                          "lateral_calibrated": True, "revision": other[0] if other else "",
                          "checksum": _check_sum(buf, etx, name) if verify_checksum else
                          "not checked"}
    if info:
        md["information"] = info
    z = data[:, -1] * cz["factor"]
    if cz["n"] != z.size:
        raise _fail(name, f"the header announces {cz['n']} points, the data record holds "
                          f"{z.size} (truncated?)")
    if areal:
        cy = axes["CY"]
        if cx["type"] != "I" or cy["type"] != "I":
            raise _fail(name, "areal data need incremental CX and CY axes")
        nx, ny = check_grid(cx["n"], cy["n"], name, FORMAT)
        if nx * ny != z.size:
            raise _fail(name, f"{nx} x {ny} points announced, {z.size} in the data record")
        dx = check_step(cx["increment"] * cx["factor"], name, FORMAT, "x increment")
        dy = check_step(cy["increment"] * cy["factor"], name, FORMAT, "y increment")
        return Topography(z.reshape(ny, nx), dx, dy, md)
    if cx["type"] == "I":
        dx = check_step(cx["increment"] * cx["factor"], name, FORMAT, "x increment")
        return Profile(z, dx, metadata=md)
    x = data[:, 0] * cx["factor"]
    if z.size < 2 or not np.all(np.isfinite(x)) or not np.all(np.diff(x) > 0):
        raise _fail(name, "absolute x positions must be finite and increasing")
    dx = check_step(float((x[-1] - x[0]) / (x.size - 1)), name, FORMAT, "mean x step")
    return positions_profile(z, x, dx, _UNIFORM_RTOL, md)


__all__ = ["decode"]
