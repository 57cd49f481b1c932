"""Material ratio: Rmr(c), the Abbott-Firestone curve and the Rk family.

Definitions: ISO 4287:1997 (Rmr(c), material ratio curve, Rδc); the ISO 13565 parameters
that build on the curve are in :mod:`profiles.rk`. Ratios are fractions in [0, 1] (not %),
heights in metres. Computed from the measured points only (NaN = not measured); for a
uniformly sampled profile the fraction of points at or above a level is the fraction of
the evaluation length.
"""

from __future__ import annotations

from typing import Any

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
