"""``HFM`` text profiles: semicolon-separated ``X;Y;valid`` columns.

The layout (as in SurfaceTopography's ``hfm-1.hfm``; the instrument is not stated)::

    X;Y;valid
    [mm];[mm];[1/0]
    8.672200;106.606853;1
    8.672700;106.606860;1
    ...

``X`` is the lateral position and ``Y`` the height, each in the unit given in brackets on
the second line; ``valid`` is 1 for a measured point and 0 for a point the instrument could
not measure (read as NaN). Decimal commas are not used (the separator is ``;``).

The positions are checked for a constant step (to 1e-3 relative): a uniform profile is
returned with ``dx`` = that step, otherwise explicit ``x`` positions are kept. The first
position is recorded as ``metadata["x_offset"]`` and positions start at 0.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet._model import Profile
from surfmet.io._binary import decode_text, format_error, looks_like_text, positions_profile
from surfmet.io._registry import register_reader
from surfmet.units import length_factor, quantity

FORMAT = "hfm"
_SIGNATURE = "x;y;valid"
_UNIFORM_RTOL = 1e-3


def _fail(name: str, problem: str) -> SurfmetFormatError:
    return format_error(name, FORMAT, problem)


def _is_hfm(buf: bytes) -> bool:
    if not looks_like_text(buf[:512]):
        return False
    first = decode_text(buf[:64]).lstrip().split("\n", 1)[0]
    return first.strip().replace(" ", "").lower() == _SIGNATURE


def _unit(cell: str, name: str, what: str) -> tuple[str, float]:
    unit = cell.strip().strip("[]").strip()
    try:
        return unit, length_factor(unit)
    except SurfmetInputError:
        raise _fail(name, f"the {what} unit {cell.strip()!r} is not a length unit") from None


@register_reader(FORMAT, extensions=("hfm",), description="HFM text profile (X;Y;valid)",
                 magic=_is_hfm, priority=40)
def decode(buf: bytes, name: str) -> Profile:
    """Read an HFM profile into a :class:`~surfmet._model.Profile` (metres)."""
    lines = [ln for ln in decode_text(buf).splitlines() if ln.strip()]
    if not lines or lines[0].strip().replace(" ", "").lower() != _SIGNATURE:
        raise _fail(name, "the first line must be 'X;Y;valid'")
    if len(lines) < 2:
        raise _fail(name, "truncated: the unit line is missing")
    units = lines[1].split(";")
    if len(units) < 2:
        raise _fail(name, f"cannot read the unit line {lines[1][:60]!r}")
    xunit, xf = _unit(units[0], name, "X")
    zunit, zf = _unit(units[1], name, "Y (height)")
    rows = [ln.split(";") for ln in lines[2:]]
    if not rows:
        raise _fail(name, "the file holds no data lines")
    for k, row in enumerate(rows):
        if len(row) != 3:
            raise _fail(name, f"data line {k + 3} has {len(row)} fields, expected 3 "
                              "(truncated or damaged file?)")
    try:
        table = np.array(rows, dtype=np.float64)
    except ValueError:
        raise _fail(name, "a data value is not a number (damaged file?)") from None
    x = table[:, 0] * xf
    z = table[:, 1] * zf
    valid = table[:, 2]
    if not np.all(np.isin(valid, (0.0, 1.0))):
        raise _fail(name, "the 'valid' column holds values other than 0 and 1")
    if not np.all(np.isfinite(x)):
        raise _fail(name, "a position is not finite")
    z[(valid == 0) | ~np.isfinite(z)] = np.nan
    if x.size < 2:
        raise _fail(name, "a profile needs at least two points")
    steps = np.diff(x)
    if not np.all(steps > 0):
        if np.all(steps < 0):  # recorded backwards: keep the physical order
            x, z = x[::-1], z[::-1]
        else:
            bad = int(np.argmax(~(steps > 0)))
            raise _fail(name, f"positions must be monotonic; data line {bad + 4} breaks the order")
    mean_step = float((x[-1] - x[0]) / (x.size - 1))
    md: dict[str, Any] = {
        "height_unit": zunit,
        "lateral_unit": xunit,
        "lateral_calibrated": True,
        "x_offset": quantity(float(x[0]), "m"),
    }
    return positions_profile(z, x, mean_step, _UNIFORM_RTOL, md)


__all__ = ["decode"]
