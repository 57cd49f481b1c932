"""Material ratio: Rmr(c), the Abbott-Firestone curve and the Rk family.

Definitions: ISO 4287:1997 (Rmr(c), material ratio curve, Rδc) and
ISO 13565-2:1996 (Rk, Rpk, Rvk, Mr1, Mr2). Ratios are fractions in [0, 1] (not %),
heights in metres. Computed from the measured points only (NaN = not measured); for a
uniformly sampled profile the fraction of points at or above a level is the fraction of
the evaluation length.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, ClassVar

import numpy as np

from profiles._arrays import as_heights, require_valid
from profiles.errors import ProfileError


def _heights(z: Any, minimum: int = 1) -> np.ndarray:
    z = as_heights(z)
    valid = require_valid(z, minimum, "the material ratio")
    return z[valid]


def material_ratio(z: Any, c: Any, *, reference: str = "mean") -> float | np.ndarray:
    """Rmr(c): fraction of the profile at or above the section level ``c``.

    Parameters
    ----------
    z : array_like
        Heights in metres from the mean line; NaN where not measured.
    c : float or array_like
        Section level(s) in metres.
    reference : {"mean", "peak"}
        ``"mean"``: ``c`` is a height above the mean line (z = 0).
        ``"peak"``: ``c`` is a depth below the highest point (ISO 4287 practice of
        measuring section levels from the top of the profile).

    Returns
    -------
    float or ndarray
        Material ratio(s) in [0, 1].
    """
    zv = np.sort(_heights(z))
    levels = np.asarray(c, dtype=float)
    if reference == "peak":
        levels = zv[-1] - levels
    elif reference != "mean":
        raise ProfileError(f"reference must be 'mean' or 'peak', got {reference!r}")
    above = zv.size - np.searchsorted(zv, levels, side="left")
    out = above / zv.size
    return float(out) if np.ndim(out) == 0 else out


def material_ratio_curve(z: Any, n: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The Abbott-Firestone (material ratio) curve.

    Returns
    -------
    (mr, height) : ndarrays
        ``height[i]`` is the level at which the material ratio is ``mr[i]``; heights
        decrease as ``mr`` goes from ``1/N`` to 1 (``N`` measured points). With ``n``
        given, the curve is interpolated at ``n`` evenly spaced ratios in [0, 1].
    """
    zv = np.sort(_heights(z))[::-1]
    mr = np.arange(1, zv.size + 1) / zv.size
    if n is None:
        return mr, zv
    grid = np.linspace(0.0, 1.0, int(n))
    return grid, height_at_ratio(z, grid)


def height_at_ratio(z: Any, mr: Any) -> float | np.ndarray:
    """Inverse material ratio curve: the level at which the ratio is ``mr`` (0..1)."""
    zv = np.sort(_heights(z))[::-1]
    m = np.asarray(mr, dtype=float)
    if np.any((m < 0) | (m > 1)):
        raise ProfileError("material ratios must lie between 0 and 1")
    # points (k/N, zv[k-1]) with the top at (0, max): a piecewise-linear inverse
    grid = np.concatenate(([0.0], np.arange(1, zv.size + 1) / zv.size))
    heights = np.concatenate(([zv[0]], zv))
    out = np.interp(m, grid, heights)
    return float(out) if np.ndim(out) == 0 else out


def section_height_difference(z: Any, mr1: float, mr2: float) -> float:
    """Rδc: height difference between the levels of material ratios ``mr1 < mr2``."""
    return float(height_at_ratio(z, mr1) - height_at_ratio(z, mr2))


@dataclass(frozen=True)
class RkParameters:
    """ISO 13565-2 parameters (heights in metres, Mr1/Mr2 as fractions)."""

    Rk: float
    Rpk: float
    Rvk: float
    Mr1: float
    Mr2: float

    UNITS: ClassVar[Mapping[str, str]] = MappingProxyType(
        {"Rk": "m", "Rpk": "m", "Rvk": "m", "Mr1": "", "Mr2": ""}
    )

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}``."""
        return {k: float(getattr(self, k)) for k in self.UNITS}


def rk_parameters(z: Any, *, samples: int = 4001) -> RkParameters:
    """Core roughness depth and reduced peak/valley heights (ISO 13565-2).

    The material ratio curve is sampled at ``samples`` evenly spaced ratios; the 40 %
    secant with the smallest slope defines the equivalent straight line; its heights at
    0 % and 100 % bound the core (``Rk``); ``Mr1``/``Mr2`` are the ratios where the curve
    crosses these bounds; ``Rpk``/``Rvk`` are the heights of the triangles with the same
    area as the peak/valley regions beyond the core.
    """
    zv = _heights(z, 10)
    grid = np.linspace(0.0, 1.0, samples)
    h = np.asarray(height_at_ratio(zv, grid))
    w = round(0.4 * (samples - 1))
    slopes = (h[w:] - h[:-w]) / 0.4
    i = int(np.argmin(np.abs(slopes)))  # first of equally flat secants
    slope = slopes[i]
    top = h[i] - slope * grid[i]  # line value at mr = 0
    bottom = top + slope  # at mr = 1
    Rk = float(top - bottom)
    Mr1 = float(material_ratio(zv, top))
    Mr2 = float(material_ratio(zv, bottom))

    def area(lo: float, hi: float, level: float, sign: float) -> float:
        m = np.linspace(lo, hi, 2001)
        excess = np.clip(sign * (np.asarray(height_at_ratio(zv, m)) - level), 0.0, None)
        return float(np.trapezoid(excess, m)) if hasattr(np, "trapezoid") else float(
            np.trapz(excess, m)  # noqa: NPY201 - numpy < 2
        )

    Rpk = 2.0 * area(0.0, Mr1, top, 1.0) / Mr1 if Mr1 > 0 else 0.0
    Rvk = 2.0 * area(Mr2, 1.0, bottom, -1.0) / (1.0 - Mr2) if Mr2 < 1 else 0.0
    if not math.isfinite(Rk):
        raise ProfileError("material ratio curve is degenerate (flat profile)")
    return RkParameters(Rk=Rk, Rpk=Rpk, Rvk=Rvk, Mr1=Mr1, Mr2=Mr2)
