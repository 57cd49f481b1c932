"""Who stated a scan's units: the file, nobody (assumed) or the user, and the text that says so.

A file that states no height unit or no pixel size is read with an assumed one; the readers
record which (``height_unit_source``, ``lateral_unit_source`` in the metadata, set through
:func:`unit_sources`), and :class:`Calibration` reads it back from any scan derived from the
file, for the caveats every output carries. :mod:`surfmet._model` re-exports these names.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from surfmet._errors import SurfmetInputError

#: Who stated a unit: the file (or the code that built the scan), nobody (assumed), the user.
STATED, ASSUMED, USER = "file", "assumed", "user"
UNIT_SOURCES = (STATED, ASSUMED, USER)
SOURCE_WORDS = {STATED: "stated by the file", ASSUMED: "assumed", USER: "stated by the user"}


def unit_text(unit: str) -> str:
    """A length unit as the text writes it (``µm``, not ``um``); others as they are."""
    from surfmet.units import length_factor

    try:
        factor = length_factor(unit)
    except SurfmetInputError:
        return unit
    names = {1.0: "m", 1e-3: "mm", 1e-6: "µm", 1e-9: "nm", 1e-10: "Å", 1e-12: "pm"}
    return next((n for f, n in names.items() if abs(factor - f) <= 1e-12 * f), unit)


def unit_sources(height: str = STATED, lateral: str = STATED) -> dict[str, str]:
    """The metadata entries a reader sets to say which units its file states."""
    for s in (height, lateral):
        if s not in UNIT_SOURCES:
            raise ValueError(f"unit source must be one of {UNIT_SOURCES}, got {s!r}")
    return {"height_unit_source": height, "lateral_unit_source": lateral}


@dataclass(frozen=True)
class Calibration:
    """Which of a scan's units its file stated, and what was taken where it stated none.

    Built from the scan's metadata (:attr:`Topography.calibration`), so it travels with
    every scan derived from it (levelled, cropped, an extracted profile).

    Attributes
    ----------
    height, lateral : {"file", "assumed", "user"}
        Who stated the height unit and the pixel size (lateral unit).
    height_unit : str
        The unit the file's height numbers were taken in (``"m"``, ``"mm"``...).
    lateral_unit : str
        The unit the file's lateral numbers were taken in; ``""`` where the file has no
        lateral number at all (a bare array: the pixel itself is assumed).
    dx, dy : float or None
        The pixel size (m) in use, for the text.
    """

    height: str = STATED
    height_unit: str = "m"
    lateral: str = STATED
    lateral_unit: str = "m"
    dx: float | None = None
    dy: float | None = None

    @classmethod
    def of(cls, metadata: Mapping[str, Any], dx: float | None = None,
           dy: float | None = None) -> Calibration:
        """The record of a scan's metadata: the readers' ``*_unit_source`` entries, else
        the older flags (``lateral_calibrated``, ``units_missing``, ``units_assumed``)."""
        md = dict(metadata or {})
        unit = str(md.get("height_unit") or "").strip()
        height = md.get("height_unit_source")
        if height not in UNIT_SOURCES:
            assumed = md.get("units_missing") or md.get("units_assumed") or (
                "height_unit" in md and not unit)
            height = ASSUMED if assumed else STATED
        lateral = md.get("lateral_unit_source")
        if lateral not in UNIT_SOURCES:
            lateral = ASSUMED if (md.get("lateral_calibrated") is False
                                  or md.get("units_assumed")) else STATED
        lat_unit = str(md.get("lateral_unit") or "").strip()
        return cls(height=height, height_unit=unit or "m", lateral=lateral,
                   lateral_unit=lat_unit, dx=dx, dy=dy)

    @property
    def stated(self) -> bool:
        """True when the file states both its height unit and its pixel size."""
        return self.height == STATED and self.lateral == STATED

    def pixel_text(self) -> str:
        """The pixel size as the text writes it (``"5 µm"``, ``"1 µm x 2 µm"``; ``""``
        when the record has none)."""
        if self.dx is None:
            return ""
        from surfmet.units import format_length

        if self.dy is None or abs(self.dy - self.dx) <= 1e-12 * self.dx:
            return format_length(self.dx)
        return f"{format_length(self.dx)} x {format_length(self.dy)}"

    def height_text(self) -> str:
        """One line on the height unit (``""`` when the file states it)."""
        if self.height == STATED:
            return ""
        if self.height == USER:
            return (f"height unit stated by the user: the file's heights are in "
                f"{unit_text(self.height_unit)} (the file states no unit)")
        return (f"height unit assumed: the file states none, so its heights are taken as "
                f"{unit_text(self.height_unit)}; every height (Sa, Sq, Sz, Ra, Rz...) rests "
                "on that (--height-unit states it)")

    def lateral_text(self) -> str:
        """One line on the pixel size (``""`` when the file states it)."""
        if self.lateral == STATED:
            return ""
        pixel = self.pixel_text()
        if self.lateral == USER:
            return f"pixel size stated by the user: {pixel or '?'} (the file states none)"
        if self.lateral_unit:
            what = (f"lateral unit assumed: the file states none, so its lengths are taken "
                    f"as {unit_text(self.lateral_unit)} (pixel {pixel or '?'})")
        else:
            what = f"pixel size assumed: the file states none, so it is taken as {pixel or '1 m'}"
        return (f"{what}; every lateral quantity (Sal, Rsm, Spd, slopes, Sdr, cut-offs) "
                "rests on that (--pixel states it)")

    def caveats(self) -> list[str]:
        """What the output must say: each unit that was assumed or stated by the user."""
        return [t for t in (self.height_text(), self.lateral_text()) if t]
