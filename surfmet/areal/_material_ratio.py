"""Areal material ratio and the Sk family (ISO 25178-2 B.1 / ISO 13565-2).

Smr(c), Smc(mr) and Sk, Spk, Svk, Smr1, Smr2 from the areal material ratio curve
(ISO 25178-2 B.1 / ISO 13565-2): the 40 % wide central region is where the secant of
the curve has the smallest gradient; the equivalent straight line is the least-squares
line through the curve in that region; Sk is its height difference between Mr = 0 and
100 %, Smr1/Smr2 the material ratios at those two heights, and Spk, Svk the heights of
the triangles with the same area as the peak and dale zones.
"""

from __future__ import annotations

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._points import heights_of, valid_values


def _sorted_desc(topo: Topography) -> np.ndarray:
    v = valid_values(heights_of(topo))
    return np.sort(v - v.mean())[::-1]


def material_ratio(topo: Topography, c: float) -> float:
    """Smr(c) in %: share of the valid points at or above height ``c`` (about the mean)."""
    v = valid_values(heights_of(topo))
    d = v - v.mean()
    return float(100.0 * np.count_nonzero(d >= c) / d.size)


def inverse_material_ratio(topo: Topography, mr: float) -> float:
    """Smc(mr): height (about the mean) at which the material ratio is ``mr`` %."""
    if not 0 <= mr <= 100:
        raise SurfmetInputError(f"material ratio must lie in [0, 100] %, got {mr}")
    h = _sorted_desc(topo)
    n = h.size
    mrs = 100.0 * (np.arange(n) + 0.5) / n
    return float(np.interp(mr, mrs, h))


def functional_parameters(topo: Topography, width: float = 40.0, nclass: int = 10001
                          ) -> dict[str, float]:
    """Sk, Spk, Svk, Smr1, Smr2 from the material ratio curve (ISO 13565-2 / 25178-2 B.1)."""
    h = _sorted_desc(topo)
    n = h.size
    if n < 10:
        raise SurfmetInputError("the Sk family needs at least 10 measured points")
    mr_pts = 100.0 * (np.arange(n) + 0.5) / n
    # The curve at equally spaced material ratios (quantiles of the height distribution).
    mr = np.linspace(0.0, 100.0, nclass)
    curve = np.interp(mr, mr_pts, h)
    step = mr[1] - mr[0]
    w = round(width / step)
    drop = curve[:-w] - curve[w:]  # ≥ 0: secant height drop over a 40 % window
    i0 = int(np.argmin(drop))  # first occurrence of the smallest gradient
    seg_mr = mr[i0: i0 + w + 1]
    seg_h = curve[i0: i0 + w + 1]
    slope, icpt = np.polyfit(seg_mr, seg_h, 1)
    upper = float(icpt)
    lower = float(icpt + slope * 100.0)
    sk = upper - lower
    n_above = int(np.count_nonzero(h > upper))
    n_below = int(np.count_nonzero(h < lower))
    smr1 = 100.0 * n_above / n
    smr2 = 100.0 * (n - n_below) / n
    # Areas of the peak and dale zones in height × % (exact sums over the points).
    a1 = float(np.sum(h[:n_above] - upper)) * 100.0 / n
    a2 = float(np.sum(lower - h[n - n_below:])) * 100.0 / n if n_below else 0.0
    spk = 2.0 * a1 / smr1 if smr1 > 0 else 0.0
    svk = 2.0 * a2 / (100.0 - smr2) if smr2 < 100 else 0.0
    return {"Sk": sk, "Spk": spk, "Svk": svk, "Smr1": smr1, "Smr2": smr2}
