"""Profile feature characterisation (ISO 21920-2:2021, 5.4 and Annex on features).

The five steps of feature characterisation:

1. feature type: ``"D"`` dales (motifs between two peaks, with one pit), ``"V"`` pits (the
   lowest point of each dale), ``"H"`` hills and ``"P"`` peaks (the same on ``-z``);
2. segmentation: watershed segmentation of the profile into motifs, then pruning; Wolf
   pruning merges, while the smallest motif height is below a threshold (default 5 % of
   Rz), the smallest motif with the neighbour on the side of its lower bounding peak (the
   way water filling the dale would spill over its lower rim); a motif whose lower rim is
   the profile's end is dropped;
3. significant features: all, the N with the largest peak/pit height (``("top", N)``), or
   those open or closed at a height ``c`` (``("open", c)``, ``("closed", c)``; ``c`` in
   metres or as a material ratio ``"p %"``), see :func:`significant_motifs`;
4. attributes: ``"HDh"`` motif height (lower rim minus pit), ``"HDw"`` width (from the
   lower rim to the farthest crossing of the rim level), ``"HDv"`` area below the rim level
   divided by the evaluation length, ``"HDl"`` developed length over that width, ``"PVh"``
   peak height or pit depth from the mean line, ``"curvature"`` at the peak or pit
   (seven-point first and second derivatives, ``z'' / (1 + z'²)^1.5`` of ``z`` at pits and
   of ``-z`` at peaks, so that both are positive for a rounded feature), ``"count"``;
5. statistics: mean, max, min, std (n - 1), sum, density (per metre of evaluation length).

Named parameters (ISO 21920-2, Table of feature parameters):

``Rpd``  density of peaks: H, Wolf 5 % Rz, all, count, density (1/m)
``Rvd``  density of dales: D, Wolf 5 % Rz, all, count, density (1/m)
``Rmpc`` mean peak curvature: P, Wolf 5 % Rz, all, curvature, mean (1/m)
``Rmvc`` mean pit curvature: V, Wolf 5 % Rz, all, curvature, mean (1/m)
``R5p``  five-point peak height: P, Wolf 5 % Rz, top 5, PVh, mean (m)
``R5v``  five-point pit depth: V, Wolf 5 % Rz, top 5, PVh, mean (m)
``R10z`` ten-point height: R5p + R5v (m)

Plateaus (runs of equal heights) count as one point at their middle. The segmentation
follows Müller et al., "Feature characterization for profile surface texture", Surf. Topogr.:
Metrol. Prop. 13 (2025) 015003 (doi:10.1088/2051-672X/adaa07), whose reference
implementation (RPTU / MTS, MIT) the tests compare with; the code here is written anew: the
pruning keeps the motifs in a linked list with a heap keyed by height, so a 100 000-point
profile is segmented in well under a second.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, ClassVar

import numpy as np

from profiles._arrays import as_heights, as_step, require_valid
from profiles._errors import ProfileError

FEATURE_TYPES = ("D", "V", "H", "P")
ATTRIBUTES = ("HDh", "HDw", "HDv", "HDl", "PVh", "curvature", "count")
STATISTICS = ("mean", "max", "min", "std", "sum", "density")
WOLF_DEFAULT = 0.05  # of Rz

# seven-point derivatives (ISO 4287 first derivative; matching second derivative)
_D1 = np.array([-1.0, 9.0, -45.0, 0.0, 45.0, -9.0, 1.0]) / 60.0
_D2 = np.array([2.0, -27.0, 270.0, -490.0, 270.0, -27.0, 2.0]) / 180.0


@dataclass(frozen=True, eq=False)
class Motifs:
    """Motifs of a profile after pruning, in order along x (indices may be half-integers).

    ``pit`` is the feature point (pit of a dale, or peak of a hill on ``-z``), ``low`` and
    ``high`` the lower and higher bounding peaks; ``z`` is the profile the segmentation
    ran on (``-z`` for hills and peaks).
    """

    pit: np.ndarray
    low: np.ndarray
    high: np.ndarray
    z: np.ndarray
    hills: bool


def _extrema(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(peaks, pits) as possibly half-integer indices; plateaus count at their middle."""
    first = np.concatenate(([0], np.flatnonzero(z[1:] != z[:-1]) + 1))
    runs = np.diff(np.concatenate((first, [z.size])))
    s = np.sign(np.diff(z[first]))
    turn = np.diff(s)
    peak_i = np.flatnonzero(turn == -2) + 1
    pit_i = np.flatnonzero(turn == 2) + 1
    centre = first + (runs - 1) / 2.0
    return centre[peak_i], centre[pit_i]


def segment(z: Any, dx: float, feature: str = "D", *, wolf: float | None = WOLF_DEFAULT,
            rz: float | None = None) -> Motifs:
    """Watershed segmentation with Wolf pruning at ``wolf`` × Rz (None: no pruning).

    Parameters
    ----------
    z : array_like
        Roughness profile (heights from the mean line, metres); no NaN.
    dx : float
        Sampling step, metres.
    feature : {"D", "V", "H", "P"}
        Dales/pits segment ``z``, hills/peaks segment ``-z``.
    wolf : float or None
        Pruning threshold as a fraction of ``rz``.
    rz : float, optional
        Rz for the threshold; default: mean of five sections' max - min.
    """
    z = as_heights(z)
    as_step(dx)
    require_valid(z, 3, "feature characterisation")
    if not np.isfinite(z).all():
        raise ProfileError("feature characterisation needs a profile without "
                           "non-measured points")
    if feature not in FEATURE_TYPES:
        raise ProfileError(f"unknown feature type {feature!r}: use D, V, H or P")
    hills = feature in ("H", "P")
    w = -z if hills else z
    peaks, pits = _extrema(w)
    if peaks.size < 2:
        return Motifs(np.empty(0), np.empty(0), np.empty(0), w, hills)
    pits = pits[(pits > peaks[0]) & (pits < peaks[-1])]
    left, right = peaks[:-1], peaks[1:]
    at = w[np.floor(left).astype(int)] <= w[np.floor(right).astype(int)]
    low = np.where(at, left, right)
    high = np.where(at, right, left)
    if wolf is not None and pits.size:
        if rz is None:
            rz = _rz(z)
        pits, low, high = _wolf_prune(w, pits, low, high, wolf * rz)
    return Motifs(pits, low, high, w, hills)


def _rz(z: np.ndarray, sections: int = 5) -> float:
    parts = np.array_split(z, sections)
    return float(np.mean([p.max() - p.min() for p in parts if p.size]))


def _wolf_prune(w: np.ndarray, pit: np.ndarray, low: np.ndarray, high: np.ndarray,
                threshold: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Merge motifs smaller than ``threshold`` into the neighbour across their lower rim."""
    n = pit.size
    # heights at the (half-)indices: the floor lies on the plateau
    pit_z = w[pit.astype(int)].tolist()
    low_z = w[low.astype(int)].tolist()
    high_z = w[high.astype(int)].tolist()
    pit_l, low_l, high_l = pit.tolist(), low.tolist(), high.tolist()
    height = [a - b for a, b in zip(low_z, pit_z, strict=True)]
    prev = list(range(-1, n - 1))
    nxt = list(range(1, n + 1))
    nxt[-1] = -1
    alive = [True] * n
    heap = [(h, k) for k, h in enumerate(height) if h < threshold]
    heapq.heapify(heap)
    pop, push = heapq.heappop, heapq.heappush
    while heap:
        h, k = pop(heap)
        if not alive[k] or h != height[k]:
            continue  # a stale entry: the motif was merged or its height changed
        alive[k] = False
        p, q = prev[k], nxt[k]
        if p >= 0:
            nxt[p] = q
        if q >= 0:
            prev[q] = p
        u = p if low_l[k] < pit_l[k] else q  # the neighbour across the lower rim
        if u < 0:
            continue  # the lower rim is the profile's end: the motif spills out
        if low_l[u] == low_l[k]:
            # the shared rim was the neighbour's lower rim too: its new rims are its high
            # rim and the removed motif's high rim
            if high_z[u] <= high_z[k]:
                low_l[u], low_z[u] = high_l[u], high_z[u]
                high_l[u], high_z[u] = high_l[k], high_z[k]
            else:
                low_l[u], low_z[u] = high_l[k], high_z[k]
            height[u] = low_z[u] - pit_z[u]
            if height[u] < threshold:
                push(heap, (height[u], u))
        else:
            high_l[u], high_z[u] = high_l[k], high_z[k]
    keep = [k for k in range(n) if alive[k]]
    return (np.array([pit_l[k] for k in keep]), np.array([low_l[k] for k in keep]),
            np.array([high_l[k] for k in keep]))


def _crossings(w: np.ndarray, low: float, high: float) -> np.ndarray:
    """Positions (half-integer-aware indices) where ``w`` crosses the level of the rim
    ``low`` between ``low`` and ``high`` (crossing-the-line segmentation)."""
    level = w[int(low)]
    step = 1 if high > low else -1
    i0 = round(float(low))
    i1 = int(high)
    while i0 != i1 and w[i0] == level:  # leave the rim's plateau first
        i0 += step
    idx = np.arange(i0, i1, step)
    a, b = w[idx], w[idx + step]
    below_a, below_b = a < level, b < level
    hit = below_a != below_b
    j = idx[hit]
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = (level - w[j]) / (w[j + step] - w[j])
    return j + step * frac


def _curvature_at(z: np.ndarray, at: np.ndarray, dx: float) -> np.ndarray:
    """Signed curvature z'' / (1 + z'²)^1.5 at (half-)indices ``at``.

    Seven-point derivatives inside, three-point central differences within three points of
    an end; a two-point plateau (half-integer index) gets the mean of its two points.
    """
    n = z.size
    idx = np.concatenate((np.floor(at), np.ceil(at))).astype(int)
    inner = (idx >= 3) & (idx <= n - 4)
    d1 = np.empty(idx.size)
    d2 = np.empty(idx.size)
    if inner.any():
        win = np.lib.stride_tricks.sliding_window_view(z, 7)[idx[inner] - 3]
        d1[inner] = win @ _D1 / dx
        d2[inner] = win @ _D2 / dx**2
    if (~inner).any():
        j = np.clip(idx[~inner], 1, n - 2)
        d1[~inner] = (z[j + 1] - z[j - 1]) / (2 * dx)
        d2[~inner] = (z[j + 1] - 2 * z[j] + z[j - 1]) / dx**2
    k = d2 / (1.0 + d1 * d1) ** 1.5
    half = at.size
    return 0.5 * (k[:half] + k[half:])


def attribute(m: Motifs, dx: float, name: str) -> np.ndarray:
    """Attribute ``name`` of every motif in ``m`` (SI)."""
    w = m.z
    n = m.pit.size
    if name == "count":
        return np.ones(n)
    if name == "HDh":
        return w[m.low.astype(int)] - w[m.pit.astype(int)]
    if name == "PVh":
        return -w[m.pit.astype(int)]
    if name == "curvature":
        # on the segmented profile (-z for hills): positive at pits and at peaks
        return _curvature_at(w, m.pit, dx)
    out = np.empty(n)
    length = w.size * dx
    for k in range(n):
        cross = _crossings(w, m.low[k], m.high[k])
        far = cross[np.argmax(np.abs(cross - m.low[k]))] if cross.size else m.low[k]
        if name == "HDw":
            out[k] = abs(far - m.low[k]) * dx
            continue
        a, b = sorted((m.low[k], far))
        i = np.arange(math.ceil(a), math.floor(b) + 1)
        xs = np.concatenate(([a], i, [b])) * dx
        level = w[int(m.low[k])]
        ws = np.concatenate(([level], w[i], [level]))
        if name == "HDv":
            out[k] = float(np.trapezoid(np.clip(level - ws, 0, None), xs)) / length
        elif name == "HDl":
            out[k] = float(np.sum(np.hypot(np.diff(xs), np.diff(ws))))
        else:
            raise ProfileError(f"unknown attribute {name!r}: use one of {', '.join(ATTRIBUTES)}")
    return out


def significance_level(z: np.ndarray, c: float | str) -> float:
    """The height ``c`` of an open/closed rule: metres, or a material ratio ``"p %"``.

    A material ratio is turned into the level at which that share of the profile lies at
    or above it (ISO 21920-2 Rcm, :func:`profiles._material_ratio.material_ratio_height`).
    """
    from profiles._material_ratio import material_ratio_height

    if isinstance(c, str):
        text = c.strip()
        if not text.endswith("%"):
            raise ProfileError(f"a significance level is a height in metres or a material "
                               f"ratio such as '10 %', got {c!r}")
        try:
            p = float(text[:-1]) / 100.0
        except ValueError:
            raise ProfileError(f"bad material ratio {c!r}: use e.g. '10 %'") from None
        return float(np.max(z) + material_ratio_height(z, p))
    level = float(c)
    if not math.isfinite(level):
        raise ProfileError(f"a significance level must be finite, got {c!r}")
    return level


def significant_motifs(m: Motifs, dx: float, significant: tuple[str, Any] | str,
                       z: np.ndarray) -> Motifs:
    """Step 3 of feature characterisation: keep the significant motifs.

    ``"all"``; ``("top", N)`` / ``("bot", N)``: the N features with the largest peak height
    or pit depth (PVh; both keep the largest, as the reference implementation does);
    ``("open", c)``: the motifs open at height ``c``, i.e. a dale whose lower rim lies at
    or below ``c`` (a hill whose lower rim, on the profile, lies at or above ``c``): water
    at level ``c`` would not be held by it; ``("closed", c)``: the motifs closed at ``c``,
    a dale whose pit lies at or below ``c`` and whose lower rim at or above ``c`` (a hill
    whose peak lies at or above ``c`` and whose lower rim at or below ``c``): the section
    at ``c`` cuts it in a closed contour. ``c`` is a height in metres from the mean line
    or a material ratio ``"p %"`` (:func:`significance_level`). ISO 21920-2:2021,
    feature characterisation; the rules as in the RPTU / MTS reference implementation.
    """
    if significant == "all":
        return m
    try:
        if isinstance(significant, str):  # a word other than "all" is no (kind, value) pair
            raise ValueError(significant)
        kind, value = significant
    except (TypeError, ValueError):
        raise ProfileError(f"significant features must be 'all', ('top', N), ('bot', N), "
                           f"('open', c) or ('closed', c), got {significant!r}") from None
    kind = str(kind).lower()
    if kind in ("top", "bot"):
        order = np.argsort(-attribute(m, dx, "PVh"), kind="stable")[: int(value)]
        keep = np.sort(order)
    elif kind in ("open", "closed"):
        # on the segmented profile w (-z for hills) every motif is a dale: the level is
        # mirrored with it
        level = significance_level(z, value)
        level = -level if m.hills else level
        rim = m.z[m.low.astype(int)]
        if kind == "open":
            keep = np.flatnonzero(rim <= level)
        else:
            pit = m.z[m.pit.astype(int)]
            keep = np.flatnonzero((rim >= level) & (pit <= level))
    else:
        raise ProfileError(f"significant features must be 'all', ('top', N), ('bot', N), "
                           f"('open', c) or ('closed', c), got {significant!r}")
    return Motifs(m.pit[keep], m.low[keep], m.high[keep], m.z, m.hills)


def feature_characterization(
    z: Any,
    dx: float,
    feature: str = "D",
    *,
    wolf: float | None = WOLF_DEFAULT,
    significant: tuple[str, Any] | str = "all",
    attr: str = "count",
    statistic: str = "density",
    rz: float | None = None,
) -> float:
    """One feature parameter by the five steps of ISO 21920-2 (module docstring).

    ``significant`` is one of the rules of :func:`significant_motifs`. Returns NaN when no
    (significant) feature is found.
    """
    if attr not in ATTRIBUTES:
        raise ProfileError(f"unknown attribute {attr!r}: use one of {', '.join(ATTRIBUTES)}")
    if statistic not in STATISTICS:
        raise ProfileError(f"unknown statistic {statistic!r}: use one of "
                           f"{', '.join(STATISTICS)}")
    z = as_heights(z)
    m = significant_motifs(segment(z, dx, feature, wolf=wolf, rz=rz), dx, significant, z)
    if m.pit.size == 0:
        return math.nan
    values = attribute(m, dx, attr)
    if statistic == "mean":
        return float(np.mean(values))
    if statistic == "max":
        return float(np.max(values))
    if statistic == "min":
        return float(np.min(values))
    if statistic == "std":
        return float(np.std(values, ddof=1)) if values.size > 1 else math.nan
    if statistic == "sum":
        return float(np.sum(values))
    return float(np.sum(values)) / (m.z.size * dx)


@dataclass(frozen=True)
class FeatureParameters:
    """The named feature parameters of ISO 21920-2 (SI; NaN where no feature exists).

    See Also
    --------
    feature_parameters : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import feature_parameters
    >>> x = np.arange(4000) * 1e-6
    >>> fp = feature_parameters(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6)
    >>> print(f"Rpd = {fp.Rpd:.0f} peaks/m, R5p = {fp.R5p * 1e6:.2f} µm")
    Rpd = 9750 peaks/m, R5p = 1.00 µm
    """

    Rpd: float
    Rvd: float
    Rmpc: float
    Rmvc: float
    R5p: float
    R5v: float
    R10z: float

    UNITS: ClassVar[Mapping[str, str]] = MappingProxyType(
        {"Rpd": "1/m", "Rvd": "1/m", "Rmpc": "1/m", "Rmvc": "1/m", "R5p": "m", "R5v": "m",
         "R10z": "m"}
    )

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` (SI)."""
        return {k: float(getattr(self, k)) for k in self.UNITS}


def feature_parameters(z: Any, dx: float, *, wolf: float = WOLF_DEFAULT,
                       rz: float | None = None) -> FeatureParameters:
    """Rpd, Rvd, Rmpc, Rmvc, R5p, R5v, R10z of a roughness profile (ISO 21920-2 defaults).

    Each feature type is segmented once and all its parameters read from that segmentation.

    See Also
    --------
    FeatureParameters : the result.
    profile_parameters : the amplitude parameters.

    References
    ----------
    .. [1] ISO 21920-2:2021, Geometrical product specifications (GPS) -- Surface texture:
       Profile -- Part 2: Terms, definitions and surface texture parameters.
    .. [2] ISO 16610-85:2013, Filtration -- Part 85: Morphological areal filters:
       Segmentation (Wolf pruning).

    Examples
    --------
    A sine of 100 µm wavelength and 1 µm amplitude over 4 mm: 39 complete hills (the
    partial ones at the ends do not count) in 4 mm, each 1 µm high:

    >>> import numpy as np
    >>> from profiles import feature_parameters
    >>> x = np.arange(4000) * 1e-6
    >>> fp = feature_parameters(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6)
    >>> print(f"Rpd = {fp.Rpd:.0f} 1/m, R5p = {fp.R5p * 1e6:.2f} µm, R10z = {fp.R10z * 1e6:.2f} µm")
    Rpd = 9750 1/m, R5p = 1.00 µm, R10z = 2.00 µm
    """
    z = as_heights(z)
    rz = _rz(z) if rz is None else rz
    hills = segment(z, dx, "H", wolf=wolf, rz=rz)
    dales = segment(z, dx, "D", wolf=wolf, rz=rz)
    length = z.size * dx

    def top5(m: Motifs) -> float:
        if m.pit.size == 0:
            return math.nan
        v = np.sort(attribute(m, dx, "PVh"))[::-1][:5]
        return float(np.mean(v))

    def mean_curv(m: Motifs) -> float:
        return float(np.mean(attribute(m, dx, "curvature"))) if m.pit.size else math.nan

    r5p, r5v = top5(hills), top5(dales)
    return FeatureParameters(
        Rpd=hills.pit.size / length, Rvd=dales.pit.size / length,
        Rmpc=mean_curv(hills), Rmvc=mean_curv(dales), R5p=r5p, R5v=r5v, R10z=r5p + r5v,
    )
