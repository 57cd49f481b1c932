"""The user's statement of a scan's units: ``height_unit=``, ``dx=`` / ``dy=`` of
:func:`surfmet.read` (``--height-unit`` and ``--pixel`` on the command line).

A file that states no height unit or no pixel size is read with an assumed one, and says so
(:class:`surfmet._model.Calibration`). What the user states replaces the assumption, and the
scan then says "stated by the user". A file that states its own unit keeps it: a different
one given for it is refused (one of the two is wrong, and only the user can tell which),
the same one is accepted as it is.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import ASSUMED, STATED, USER, Profile, Topography, unit_text
from surfmet.units import format_length, length_factor

Scan = Topography | Profile

#: Relative difference below which a stated pixel and the user's are the same number.
PIXEL_RTOL = 1e-6


class UnitContradiction(SurfmetInputError):
    """A unit or pixel the user gives for a file that states a different one: the user's
    mistake (or the file's), never damage in the file."""


def contradiction(name: str, what: str, stated: str, given: str) -> UnitContradiction:
    """The one error for a unit the file states and the user contradicts."""
    return UnitContradiction(f"{name}: the file states its {what} ({stated}); a {what} given "
                             f"for it ({given}) would contradict it: give one only for a "
                             "file that states none")


def _factor(unit: str) -> float | None:
    try:
        return length_factor(unit or "m")
    except SurfmetInputError:
        return None  # a stated unit that is no length ("waves"): nothing to compare with


def state_height_unit(scan: Scan, unit: str, name: str) -> Scan:
    """``scan`` with its heights in ``unit`` (the unit of the file's numbers)."""
    new = length_factor(str(unit))  # an unknown unit is the user's error, in one line
    cal = scan.calibration
    taken = _factor(cal.height_unit)
    if cal.height == STATED:
        if taken is not None and abs(taken - new) <= 1e-12 * new:
            return scan
        raise contradiction(name, "height unit", unit_text(cal.height_unit),
                            unit_text(str(unit)))
    scale = new / (taken or 1.0)
    md = {**dict(scan.metadata), "height_unit": str(unit), "height_unit_source": USER,
          "units_missing": False}
    md.pop("height_range", None)  # the span is judged again on the stated heights
    if isinstance(scan, Topography):
        return scan.replace(heights=scan.heights * scale, metadata=md)
    return scan.replace(z=scan.z * scale, metadata=md)


def _same(a: float, b: float) -> bool:
    return abs(a - b) <= PIXEL_RTOL * max(abs(a), abs(b))


def state_pixel(scan: Scan, dx: float, dy: float | None, name: str) -> Scan:
    """``scan`` with the pixel size ``dx`` (and ``dy``, default ``dx``) in metres."""
    dx = float(dx)
    if not (np.isfinite(dx) and dx > 0):
        raise SurfmetInputError(f"{name}: the pixel size must be a positive length, got {dx!r}")
    if isinstance(scan, Profile) and dy is not None and not _same(float(dy), dx):
        raise SurfmetInputError(f"{name}: a profile has one step: give one pixel size, "
                                f"not {format_length(dx)} x {format_length(float(dy))}")
    dy = dx if dy is None else float(dy)
    if not (np.isfinite(dy) and dy > 0):
        raise SurfmetInputError(f"{name}: the pixel size must be a positive length, got {dy!r}")
    cal = scan.calibration
    old_dy = scan.dy if isinstance(scan, Topography) else scan.dx
    if cal.lateral == STATED:
        if _same(scan.dx, dx) and _same(old_dy, dy):
            return scan
        given = format_length(dx) + ("" if dy == dx else " x " + format_length(dy))
        raise contradiction(name, "pixel size", cal.pixel_text(), given)
    md = {**dict(scan.metadata), "lateral_unit_source": USER, "lateral_calibrated": True,
          "lateral_unit": "m"}
    if isinstance(scan, Topography):
        return scan.replace(dx=dx, dy=dy, metadata=md)
    x = None if scan.x is None else scan.x * (dx / scan.dx)
    return scan.replace(dx=dx, x=x, metadata=md)


def state_units(scan: Scan, name: str, *, height_unit: str | None = None,
                dx: float | None = None, dy: float | None = None) -> Scan:
    """The scan with the units the user states (each argument None: not stated)."""
    if height_unit is not None:
        scan = state_height_unit(scan, height_unit, name)
    if dy is not None and dx is None:
        raise SurfmetInputError(f"{name}: a pixel dy needs its dx")
    if dx is not None:
        scan = state_pixel(scan, dx, dy, name)
    return scan


def assumed(height: bool, lateral: bool) -> dict[str, Any]:
    """Reader shorthand: the ``*_unit_source`` entries, True meaning assumed."""
    return {"height_unit_source": ASSUMED if height else STATED,
            "lateral_unit_source": ASSUMED if lateral else STATED}


__all__ = ["PIXEL_RTOL", "UnitContradiction", "assumed", "contradiction", "state_height_unit",
           "state_pixel", "state_units"]
