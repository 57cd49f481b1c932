"""Stratified-surface parameters: ISO 13565-2 (Rk family) and ISO 13565-3 (Rpq, Rvq, Rmq).

ISO 13565-2:1996. The material ratio curve (heights sorted from the top, ratio ``Mr`` from
0 to 100 %) has a central region 40 % wide in ``Mr`` where the secant of the curve has the
least gradient; the equivalent straight line through that region meets ``Mr = 0`` and
``Mr = 100 %`` at the top and bottom of the core. ``Rk`` is the height between them,
``Mr1``/``Mr2`` the material ratios where the curve crosses them, ``A1`` the area between
the curve and the top level over ``[0, Mr1]`` and ``A2`` the area between the curve and
the bottom level over ``[Mr2, 100 %]``; ``Rpk = 2 A1 / Mr1`` and
``Rvk = 2 A2 / (100 % - Mr2)`` are the heights of triangles of the same areas. Areas are
reported in metres × fraction (a height times a material ratio as a fraction; multiply by
100 for the µm·% of a printout when the height is in µm).

Constructions of the equivalent straight line (``construction``):

``"secant"`` (default)
    The least-gradient 40 % secant itself, searched on the exact curve of the measured
    points. This is the construction instrument makers document (e.g. Mitutoyo SurfTest
    SJ-410 manual, 23.5.29: "the line through two points of the curve 40 % apart with the
    smallest inclination").
``"least-squares"``
    The least-squares straight line through the curve over the central region (the
    construction the areal :mod:`surfmet.areal._material_ratio` uses for Sk).
``"levels"``
    The secant searched at whole-percent material ratios, and ``Mr1``, ``Mr2``, ``A1``,
    ``A2`` read off the curve tabulated at slice levels 1 % of Rt apart (``Mr`` at the
    slice level just above the line's intersection; ``A1``, ``A2`` as sums over the
    slices). Reproduces a Mitutoyo SurfTest printout: its exported material ratio curve is
    that table, and its Mr1, Mr2, A1, A2, Rpk, Rvk follow to the printed digit (see
    ``docs/parameters.md``).

ISO 13565-3:1998. On the material probability curve (height against the standard normal
quantile of ``Mr``) a stratified surface shows two straight regions: the plateau (upper)
and the valleys (lower). ``Rpq`` and ``Rvq`` are the slopes of the regression lines through
them (the rms roughness of each Gaussian component) and ``Rmq`` the material ratio (%) at
their intersection. Here both lines are found by one two-segment least-squares fit whose
break point minimises the total residual, over the curve between the 0.5 % and 99.5 %
ratios (the ends of the curve are dominated by single extreme points).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, ClassVar

import numpy as np

from profiles._arrays import as_heights, require_valid
from profiles._errors import ProfileError

CONSTRUCTIONS = ("secant", "least-squares", "levels")
_WIDTH = 0.4  # the central region's width in material ratio (ISO 13565-2)


@dataclass(frozen=True)
class RkParameters:
    """ISO 13565-2 parameters: heights in metres, Mr1/Mr2 as fractions, A1/A2 in m.

    See Also
    --------
    rk_parameters : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import rk_parameters
    >>> rk = rk_parameters(np.linspace(-1e-6, 1e-6, 2001))
    >>> print(f"Rk = {rk.Rk * 1e6:.2f} µm, Rvk = {rk.Rvk * 1e6:.2f} µm")
    Rk = 2.00 µm, Rvk = 0.00 µm
    """

    Rk: float
    Rpk: float
    Rvk: float
    Mr1: float
    Mr2: float
    A1: float
    A2: float
    construction: str = "secant"

    UNITS: ClassVar[Mapping[str, str]] = MappingProxyType(
        {"Rk": "m", "Rpk": "m", "Rvk": "m", "Mr1": "", "Mr2": "", "A1": "m", "A2": "m"}
    )

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` (SI; ratios as fractions)."""
        return {k: float(getattr(self, k)) for k in self.UNITS}


@dataclass(frozen=True)
class ProbabilityParameters:
    """ISO 13565-3 parameters: Rpq, Rvq in metres, Rmq as a fraction.

    See Also
    --------
    probability_parameters : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import probability_parameters
    >>> heights = np.random.default_rng(0).normal(0.0, 1e-6, 20000)
    >>> print(f"Rpq = {probability_parameters(heights).Rpq * 1e6:.1f} µm")
    Rpq = 1.0 µm
    """

    Rpq: float
    Rvq: float
    Rmq: float

    UNITS: ClassVar[Mapping[str, str]] = MappingProxyType({"Rpq": "m", "Rvq": "m", "Rmq": ""})

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` (SI; Rmq as a fraction)."""
        return {k: float(getattr(self, k)) for k in self.UNITS}


def _sorted_desc(z: Any, minimum: int) -> np.ndarray:
    z = as_heights(z)
    valid = require_valid(z, minimum, "the material ratio curve")
    h = np.sort(z[valid])[::-1]
    if not h[0] > h[-1]:
        raise ProfileError("material ratio curve is degenerate (flat profile)")
    return h


def _curve(h: np.ndarray, mr: np.ndarray) -> np.ndarray:
    """Height at material ratio(s) ``mr`` (fractions) on the curve of sorted points.

    Point ``k`` (0-based, heights descending) stands at ``(k + 0.5) / n``: the curve is the
    piecewise-linear inverse of the empirical distribution, as in ISO 13565-2 Fig. 1.
    """
    n = h.size
    return np.interp(mr, (np.arange(n) + 0.5) / n, h)


def _secant(h: np.ndarray, starts: np.ndarray) -> tuple[float, float]:
    """(start ratio, gradient) of the least-gradient 40 % secant among ``starts``."""
    drop = _curve(h, starts) - _curve(h, starts + _WIDTH)
    i = int(np.argmin(drop))  # first of equally flat secants
    return float(starts[i]), -float(drop[i]) / _WIDTH


def rk_parameters(z: Any, *, construction: str = "secant", resolution: float = 1e-4
                  ) -> RkParameters:
    """ISO 13565-2 Rk, Rpk, Rvk, Mr1, Mr2, A1, A2 of heights from the mean line.

    Parameters
    ----------
    z : array_like
        Heights in metres (NaN = not measured); at least 10 measured points.
    construction : {"secant", "least-squares", "levels"}
        How the equivalent straight line and the areas are built (module docstring).
    resolution : float
        Step (fraction of material ratio) of the secant search for ``"secant"`` and
        ``"least-squares"``.

    Raises
    ------
    ProfileError
        Fewer than 10 measured points, a flat profile, an unknown construction.

    See Also
    --------
    RkParameters : the result.
    probability_parameters : the ISO 13565-3 family.

    References
    ----------
    .. [1] ISO 13565-2:1996, Surfaces having stratified functional properties -- Part 2:
       Height characterization using the linear material ratio curve.

    Examples
    --------
    Heights spread evenly make a straight material ratio curve: all core, no peaks above it
    and no valleys below:

    >>> import numpy as np
    >>> from profiles import rk_parameters
    >>> rk = rk_parameters(np.linspace(-1e-6, 1e-6, 2001))
    >>> print(f"Rk = {rk.Rk * 1e6:.2f} µm, Rpk = {rk.Rpk * 1e6:.2f} µm, Mr2 = {rk.Mr2:.0%}")
    Rk = 2.00 µm, Rpk = 0.00 µm, Mr2 = 100%
    """
    if construction not in CONSTRUCTIONS:
        raise ProfileError(f"unknown Rk construction {construction!r}: use "
                           + ", ".join(CONSTRUCTIONS))
    h = _sorted_desc(z, 10)
    n = h.size
    step = 0.01 if construction == "levels" else float(resolution)
    starts = np.arange(0.0, 1.0 - _WIDTH + 0.5 * step, step)
    a0, gradient = _secant(h, starts)
    top = float(_curve(h, np.array(a0))) - gradient * a0  # line at Mr = 0
    if construction == "least-squares":
        mr = (np.arange(n) + 0.5) / n
        inside = (mr >= a0) & (mr <= a0 + _WIDTH)
        gradient, top = (float(c) for c in np.polyfit(mr[inside], h[inside], 1))
    bottom = top + gradient  # line at Mr = 100 %
    if construction == "levels":
        return _levels(h, top, bottom)
    above = h > top
    below = h < bottom
    mr1 = float(np.count_nonzero(above)) / n
    mr2 = 1.0 - float(np.count_nonzero(below)) / n
    a1 = float(np.sum(h[above] - top)) / n
    a2 = float(np.sum(bottom - h[below])) / n
    return _finish(top - bottom, mr1, mr2, a1, a2, construction)


def _levels(h: np.ndarray, top: float, bottom: float) -> RkParameters:
    """Mr1, Mr2, A1, A2 from the curve tabulated at slice levels 1 % of Rt apart."""
    n = h.size
    rt = float(h[0] - h[-1])
    depth = np.arange(101) / 100.0 * rt  # slice depths below the highest point
    asc = h[::-1]
    # material ratio at each slice: share of the points strictly above the slice level
    ratio = (n - np.searchsorted(asc, h[0] - depth, side="right")) / n
    k1 = int(np.clip(math.floor((h[0] - top) / rt * 100.0 + 1e-9), 0, 100))
    k2 = int(np.clip(math.floor((h[0] - bottom) / rt * 100.0 + 1e-9), 0, 100))
    slice_height = rt / 100.0
    a1 = float(np.sum(ratio[1 : k1 + 1])) * slice_height
    a2 = float(np.sum(1.0 - ratio[k2:100])) * slice_height
    return _finish(top - bottom, float(ratio[k1]), float(ratio[k2]), a1, a2, "levels")


def _finish(rk: float, mr1: float, mr2: float, a1: float, a2: float, construction: str
            ) -> RkParameters:
    if not math.isfinite(rk):
        raise ProfileError("material ratio curve is degenerate (flat profile)")
    rpk = 2.0 * a1 / mr1 if mr1 > 0 else 0.0
    rvk = 2.0 * a2 / (1.0 - mr2) if mr2 < 1 else 0.0
    return RkParameters(Rk=float(rk), Rpk=rpk, Rvk=rvk, Mr1=mr1, Mr2=mr2, A1=a1, A2=a2,
                        construction=construction)


def probability_parameters(z: Any, *, trim: float = 0.005) -> ProbabilityParameters:
    """ISO 13565-3 Rpq, Rvq, Rmq from the material probability curve (module docstring).

    Parameters
    ----------
    z : array_like
        Heights in metres (NaN = not measured); at least 20 measured points.
    trim : float
        Material ratio (fraction) left out at each end of the curve.

    See Also
    --------
    ProbabilityParameters : the result.
    rk_parameters : the ISO 13565-2 family.

    References
    ----------
    .. [1] ISO 13565-3:1998, Surfaces having stratified functional properties -- Part 3:
       Height characterization using the material probability curve.

    Examples
    --------
    Gaussian heights lie on a straight line of the probability plot whose slope is their
    standard deviation:

    >>> import numpy as np
    >>> from profiles import probability_parameters
    >>> heights = np.random.default_rng(0).normal(0.0, 1e-6, 20000)
    >>> pq = probability_parameters(heights)
    >>> print(f"Rpq = {pq.Rpq * 1e6:.1f} µm, Rvq = {pq.Rvq * 1e6:.1f} µm")
    Rpq = 1.0 µm, Rvq = 1.0 µm
    """
    from scipy.special import ndtri

    h = _sorted_desc(z, 20)
    n = h.size
    mr = (np.arange(n) + 0.5) / n
    keep = (mr >= trim) & (mr <= 1.0 - trim)
    x, y = ndtri(mr[keep]), h[keep]
    if x.size < 8:
        raise ProfileError("too few points for the material probability curve (ISO 13565-3)")
    # two least-squares lines, split at every candidate break: cumulative sums make each
    # candidate O(1)
    sx, sy = np.cumsum(x), np.cumsum(y)
    sxx, sxy, syy = np.cumsum(x * x), np.cumsum(x * y), np.cumsum(y * y)
    m = x.size
    k = np.arange(4, m - 3)  # at least 4 points on each side

    def sse(cnt, a, b, aa, ab, bb):
        with np.errstate(invalid="ignore", divide="ignore"):
            vxx = aa - a * a / cnt
            vxy = ab - a * b / cnt
            vyy = bb - b * b / cnt
            return vyy - vxy * vxy / vxx

    left = sse(k, sx[k - 1], sy[k - 1], sxx[k - 1], sxy[k - 1], syy[k - 1])
    right = sse(m - k, sx[-1] - sx[k - 1], sy[-1] - sy[k - 1], sxx[-1] - sxx[k - 1],
                sxy[-1] - sxy[k - 1], syy[-1] - syy[k - 1])
    b = int(k[int(np.nanargmin(left + right))])
    up = np.polyfit(x[:b], y[:b], 1)
    low = np.polyfit(x[b:], y[b:], 1)
    # heights fall as the quantile grows: the rms of each component is minus the slope
    rpq, rvq = -float(up[0]), -float(low[0])
    if abs(up[0] - low[0]) > 1e-300:
        xq = (low[1] - up[1]) / (up[0] - low[0])
        from scipy.special import ndtr

        rmq = float(ndtr(xq))
    else:
        rmq = math.nan
    return ProbabilityParameters(Rpq=rpq, Rvq=rvq, Rmq=rmq)
