"""Areal surface texture parameters (ISO 25178-2), computed on the measured points only.

Every parameter uses the valid (non-NaN) points of the scan and nothing else: a scan with
27 % non-measured points gives the statistics of the 73 % that were measured, never of a
grid padded with zeros. Heights are taken relative to the mean of the valid points (the
reference mean plane after the F-operator; see :func:`surfmet.form.remove_form`).

Families and definitions (ISO 25178-2:2012, with the discrete forms of its 2021 revision
where the 2012 text gives only integrals):

height
    Sa = mean |z|, Sq = sqrt(mean z²), Sp = max z, Sv = -min z (a positive depth),
    Sz = Sp + Sv, Ssk = mean z³ / Sq³, Sku = mean z⁴ / Sq⁴.
hybrid
    Sdq, the root mean square gradient, from forward differences on the grid:
    ``Sdq² = mean_x[(Δx z / dx)²] + mean_y[(Δy z / dy)²]``, each mean over the differences
    whose two end points are measured. Sdr, the developed interfacial area ratio, from the
    area of each grid cell taken as the mean of its two triangulations (ISO 25178-2:2021,
    Annex D, the "average of both diagonals" rule): with corner triangles spanned by one x
    edge ``(dx, 0, Δx z)`` and one y edge ``(0, dy, Δy z)``, the cell area is a quarter of
    the sum of the four cross-product norms; Sdr = (Σ cell areas / Σ projected areas - 1),
    over cells with four measured corners, in %. For small slopes Sdr ≈ Sdq²/2.
spatial
    Sal and Str from the autocorrelation function (ACF) computed by FFT with zero padding
    (a linear correlation) and normalised by the number of overlapping *valid* pairs at each
    lag; along rays from the origin (0.5° apart, lags up to half the scan size) the first
    crossing of the threshold s = 0.2 (ISO 25178-3 default) is found by linear
    interpolation. Sal = the shortest crossing distance, Str = shortest / longest. When
    the ACF does not fall to s in some direction within half the scan (a lay), Str uses that
    ray's length as its decay length (Str is then an upper bound) and a note says so.
    Std: the angle, counter-clockwise from +x (row index j increasing = +y), of the maximum
    of the angular power spectrum (ISO 25178-2 4.3.4: the spectrum's dominant *wave-vector*
    direction; grooves run perpendicular to it). A Hann window limits the leakage cross of
    a non-periodic scan. In [0°, 180°).
feature
    Spd (density of significant peaks) and Spc (their mean curvature) from a watershed
    segmentation of the surface into hills (scikit-image) with Wolf pruning at 5 % of Sz
    (ISO 25178-3 default): a hill survives when its peak rises at least 5 % Sz above the
    highest saddle leading to a higher peak, which is the h-dynamics criterion (Grimaud
    1992; Wolf 1991) computed by :func:`skimage.morphology.h_maxima`. Hills whose watershed
    region touches the scan border or a non-measured area are incomplete and are not
    counted by default (``exclude_edge=True``, as MountainsMap does). Spc = mean of
    ``-(∂²z/∂x² + ∂²z/∂y²)/2`` at the peaks (central second differences), in 1/m.
functional
    Smr(c), Smc(mr) and Sk, Spk, Svk, Smr1, Smr2 from the areal material ratio curve
    (ISO 25178-2 B.1 / ISO 13565-2): the 40 % wide central region is where the secant of
    the curve has the smallest gradient; the equivalent straight line is the least-squares
    line through the curve in that region; Sk is its height difference between Mr = 0 and
    100 %, Smr1/Smr2 the material ratios at those two heights, and Spk, Svk the heights of
    the triangles with the same area as the peak and dale zones.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from surfmet.errors import SurfmetInputError
from surfmet.model import Topography

PARAMETER_UNITS: dict[str, str] = {
    "Sa": "m",
    "Sq": "m",
    "Sp": "m",
    "Sv": "m",
    "Sz": "m",
    "Ssk": "",
    "Sku": "",
    "Sdq": "",
    "Sdr": "%",
    "Sal": "m",
    "Str": "",
    "Std": "°",
    "Spd": "1/m²",
    "Spc": "1/m",
    "Sk": "m",
    "Spk": "m",
    "Svk": "m",
    "Smr1": "%",
    "Smr2": "%",
}
"""Unit of each parameter as returned (SI lengths; ratios in %, angles in degrees)."""

GROUPS: dict[str, tuple[str, ...]] = {
    "height": ("Sa", "Sq", "Sp", "Sv", "Sz", "Ssk", "Sku"),
    "hybrid": ("Sdq", "Sdr"),
    "spatial": ("Sal", "Str", "Std"),
    "feature": ("Spd", "Spc"),
    "functional": ("Sk", "Spk", "Svk", "Smr1", "Smr2"),
}

ACF_THRESHOLD = 0.2
WOLF_PRUNING = 0.05


@dataclass(frozen=True)
class ArealParameters:
    """Areal parameters of one surface; ``None`` for parameters not requested.

    Units are in :data:`PARAMETER_UNITS`. ``notes`` explains values that are bounds or
    undefined (e.g. Str of a surface with a lay).
    """

    Sa: float | None = None
    Sq: float | None = None
    Sp: float | None = None
    Sv: float | None = None
    Sz: float | None = None
    Ssk: float | None = None
    Sku: float | None = None
    Sdq: float | None = None
    Sdr: float | None = None
    Sal: float | None = None
    Str: float | None = None
    Std: float | None = None
    Spd: float | None = None
    Spc: float | None = None
    Sk: float | None = None
    Spk: float | None = None
    Svk: float | None = None
    Smr1: float | None = None
    Smr2: float | None = None
    n_valid: int = 0
    notes: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` of the computed parameters, in the order of PARAMETER_UNITS."""
        return {f.name: getattr(self, f.name) for f in fields(self)
                if f.name in PARAMETER_UNITS and getattr(self, f.name) is not None}

    def with_units(self) -> dict[str, tuple[float, str]]:
        """``{symbol: (value, unit)}`` of the computed parameters."""
        return {k: (v, PARAMETER_UNITS[k]) for k, v in self.as_dict().items()}


# ---------------------------------------------------------------------------------------
# input handling


def _heights(topo: Topography) -> np.ndarray:
    if not isinstance(topo, Topography):
        raise SurfmetInputError(
            f"areal parameters need a Topography, got {type(topo).__name__}; for a profile "
            "use surfmet.roughness or profiles.analyze_profile"
        )
    return topo.heights


def _valid_values(z: np.ndarray) -> np.ndarray:
    v = z.ravel()
    if np.isnan(v).any():
        v = v[~np.isnan(v)]
    if v.size == 0:
        raise SurfmetInputError("the scan has no measured point")
    return v


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    # einsum sums in a fixed order on one thread, unlike BLAS ddot whose blocking follows
    # the thread count: results must be bitwise identical between a serial run and Dask
    # workers (which run single-threaded BLAS).
    return float(np.einsum("i,i->", a, b))


def _centred(z: np.ndarray) -> tuple[np.ndarray, np.ndarray, bool]:
    """(heights minus valid mean with NaN kept, valid mask, all-valid flag)."""
    valid = ~np.isnan(z)
    full = bool(valid.all())
    if not full and not valid.any():
        raise SurfmetInputError("the scan has no measured point")
    mean = float(z.mean()) if full else float(z[valid].mean())
    return z - mean, valid, full


# ---------------------------------------------------------------------------------------
# height parameters


def height_parameters(topo: Topography) -> dict[str, float]:
    """Sa, Sq, Sp, Sv, Sz, Ssk, Sku of the valid points (heights about their mean)."""
    v = _valid_values(_heights(topo))
    d = v - v.mean()
    d2 = d * d
    sq2 = float(d2.mean())
    sq = math.sqrt(sq2)
    sa = float(np.abs(d).mean())
    sp = float(d.max())
    sv = float(-d.min())
    if sq > 0:
        ssk = _dot(d2, d) / d.size / sq**3
        sku = _dot(d2, d2) / d.size / sq2**2
    else:
        ssk = sku = float("nan")
    return {"Sa": sa, "Sq": sq, "Sp": sp, "Sv": sv, "Sz": sp + sv, "Ssk": ssk, "Sku": sku}


# ---------------------------------------------------------------------------------------
# hybrid parameters


def gradient_parameters(topo: Topography) -> dict[str, float]:
    """Sdq (forward differences) and Sdr (cell areas, mean of both triangulations), in %."""
    z = _heights(topo)
    dx, dy = topo.dx, topo.dy
    if z.shape[0] < 2 or z.shape[1] < 2:
        raise SurfmetInputError("Sdq and Sdr need at least 2 × 2 points")
    gx = np.diff(z, axis=1)  # Δx z, shape (ny, nx-1)
    gy = np.diff(z, axis=0)  # Δy z, shape (ny-1, nx)
    full = not np.isnan(z).any()
    if full:
        mx = _dot(gx.ravel(), gx.ravel()) / gx.size
        my = _dot(gy.ravel(), gy.ravel()) / gy.size
    else:
        vx = gx[~np.isnan(gx)]
        vy = gy[~np.isnan(gy)]
        if vx.size == 0 or vy.size == 0:
            raise SurfmetInputError("no pair of adjacent measured points: Sdq is undefined")
        mx = _dot(vx, vx) / vx.size
        my = _dot(vy, vy) / vy.size
    sdq = math.sqrt(mx / dx**2 + my / dy**2)

    # Cell areas. |e_x × e_y|² = (dy Δx z)² + (dx Δy z)² + (dx dy)² for a corner triangle.
    ax = gx * dy
    ax *= ax
    ay = gy * dx
    ay *= ay
    c = (dx * dy) ** 2
    bottom, top = ax[:-1], ax[1:]
    left, right = ay[:, :-1], ay[:, 1:]
    s = np.sqrt(bottom + left + c)
    s += np.sqrt(bottom + right + c)
    s += np.sqrt(top + left + c)
    s += np.sqrt(top + right + c)
    if full:
        total = float(s.sum())
        n_cells = s.size
    else:
        ok = ~np.isnan(s)
        n_cells = int(np.count_nonzero(ok))
        if n_cells == 0:
            raise SurfmetInputError("no grid cell with four measured corners: Sdr is undefined")
        total = float(s[ok].sum())
    # Each cell: area = Σ|corner cross| / 4; Sdr = Σ area / (n dx dy) - 1.
    sdr = (0.25 * total / (n_cells * dx * dy) - 1.0) * 100.0
    return {"Sdq": sdq, "Sdr": sdr}


# ---------------------------------------------------------------------------------------
# spatial parameters


def autocorrelation(topo: Topography) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Normalised areal autocorrelation function of the valid points.

    Returns
    -------
    acf : ndarray, shape (2 ny - 1, 2 nx - 1)
        ``acf[ny-1+l, nx-1+k]`` is the ACF at lag ``(k dx, l dy)``, 1 at the origin;
        NaN at lags with fewer than 1 % of the points as overlapping valid pairs.
    tx, ty : ndarray
        Lags in metres along x (columns) and y (rows).
    """
    from scipy import fft

    z = _heights(topo)
    d, valid, full = _centred(z)
    ny, nx = z.shape
    shape = (fft.next_fast_len(2 * ny - 1), fft.next_fast_len(2 * nx - 1, real=True))
    zz = d if full else np.where(valid, d, 0.0)
    f = fft.rfft2(zz, s=shape, workers=-1)
    num = fft.irfft2(f.real**2 + f.imag**2, s=shape, workers=-1)
    rows = np.r_[shape[0] - ny + 1: shape[0], 0:ny]
    cols = np.r_[shape[1] - nx + 1: shape[1], 0:nx]
    num = num[np.ix_(rows, cols)]
    if full:
        lag_y = np.arange(2 * ny - 1) - (ny - 1)
        lag_x = np.arange(2 * nx - 1) - (nx - 1)
        count = np.outer(ny - np.abs(lag_y), nx - np.abs(lag_x)).astype(np.float64)
    else:
        fw = fft.rfft2(valid.astype(np.float64), s=shape, workers=-1)
        count = np.rint(fft.irfft2(fw.real**2 + fw.imag**2, s=shape, workers=-1))
        count = count[np.ix_(rows, cols)]
    n0 = count[ny - 1, nx - 1]
    with np.errstate(invalid="ignore", divide="ignore"):
        acf = (num / count) / (num[ny - 1, nx - 1] / n0)
    acf[count < max(0.01 * n0, 1.0)] = np.nan
    tx = (np.arange(2 * nx - 1) - (nx - 1)) * topo.dx
    ty = (np.arange(2 * ny - 1) - (ny - 1)) * topo.dy
    return acf, tx, ty


def decay_lengths(topo: Topography, s: float = ACF_THRESHOLD, angle_step: float = 0.5
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distance at which the ACF first falls to ``s`` along rays from the origin.

    Returns
    -------
    angles : ndarray, degrees in [0, 180)
    length : ndarray, metres (the ray's length where the ACF never falls to ``s``)
    decayed : bool ndarray, False where the ACF did not fall to ``s`` on that ray
    """
    from scipy.ndimage import map_coordinates

    if not 0 < s < 1:
        raise SurfmetInputError(f"the ACF threshold s must lie in (0, 1), got {s}")
    acf, _, _ = autocorrelation(topo)
    ny, nx = topo.shape
    dx, dy = topo.dx, topo.dy
    angles = np.arange(0.0, 180.0, angle_step)
    th = np.radians(angles)
    hx, hy = 0.5 * (nx - 1) * dx, 0.5 * (ny - 1) * dy  # rays reach half the scan size
    with np.errstate(divide="ignore"):
        rmax = np.minimum(hx / np.abs(np.cos(th)), hy / np.abs(np.sin(th)))
    step = 0.5 * min(dx, dy)
    nstep = int(np.ceil(rmax.max() / step)) + 1
    r = np.arange(nstep) * step
    cols = (nx - 1) + np.outer(np.cos(th), r) / dx
    rows = (ny - 1) + np.outer(np.sin(th), r) / dy
    # NaN (too few overlapping valid pairs) propagates through the bilinear weights and
    # ends a ray there, like the half-scan limit.
    vals = map_coordinates(acf, [rows.ravel(), cols.ravel()], order=1, mode="nearest")
    vals = vals.reshape(th.size, nstep)
    vals[r[None, :] > rmax[:, None]] = np.nan
    length = rmax.copy()
    decayed = np.zeros(th.size, dtype=bool)
    for k in range(th.size):
        row = vals[k]
        bad = np.flatnonzero(~np.isfinite(row))
        end = bad[0] if bad.size else nstep
        idx = np.flatnonzero(row[:end] <= s)
        if idx.size == 0 or idx[0] == 0:
            length[k] = min(rmax[k], r[max(end - 1, 0)])
            continue
        i = idx[0]
        v0, v1 = row[i - 1], row[i]
        length[k] = r[i - 1] + (v0 - s) / (v0 - v1) * step
        decayed[k] = True
    return angles, length, decayed


def spatial_parameters(topo: Topography, s: float = ACF_THRESHOLD
                       ) -> tuple[dict[str, float], list[str]]:
    """Sal, Str (ACF threshold ``s``) and Std; returns (values, notes)."""
    notes: list[str] = []
    _angles, length, decayed = decay_lengths(topo, s)
    if decayed.any():
        sal = float(length[decayed].min())
        longest = float(length.max())
        strv = sal / longest
        if not decayed.all():
            notes.append(
                f"Str: the ACF stays above {s} within half the scan in "
                f"{np.count_nonzero(~decayed)} of {decayed.size} directions (a lay); Str is "
                "an upper bound"
            )
    else:
        sal = strv = float("nan")
        notes.append(f"Sal, Str: the ACF never falls to {s} within half the scan")
    return {"Sal": sal, "Str": strv, "Std": texture_direction(topo)}, notes


def angular_spectrum(topo: Topography, angle_step: float = 0.5
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Angular power spectrum: power of the 2D DFT summed in angular bins of the wave vector.

    Heights about the valid mean, NaN points set to zero, a 2D Hann window applied.
    Returns (bin centre angles in degrees in [0, 180), power).
    """
    from scipy import fft

    z = _heights(topo)
    d, valid, full = _centred(z)
    ny, nx = z.shape
    win = np.outer(np.hanning(ny) if ny > 2 else np.ones(ny),
                   np.hanning(nx) if nx > 2 else np.ones(nx))
    zz = (d if full else np.where(valid, d, 0.0)) * win
    p = np.abs(fft.rfft2(zz, workers=-1)) ** 2
    fy = fft.fftfreq(ny, d=topo.dy)[:, None]
    fx = fft.rfftfreq(nx, d=topo.dx)[None, :]
    theta = np.degrees(np.arctan2(np.broadcast_to(fy, p.shape), np.broadcast_to(fx, p.shape)))
    theta = np.mod(theta, 180.0)
    nbin = round(180.0 / angle_step)
    idx = np.rint(theta / angle_step).astype(np.int64) % nbin
    p[0, 0] = 0.0
    power = np.bincount(idx.ravel(), weights=p.ravel(), minlength=nbin)
    return np.arange(nbin) * angle_step, power


def texture_direction(topo: Topography, angle_step: float = 0.5) -> float:
    """Std in degrees: angle of the maximum of :func:`angular_spectrum`."""
    angles, power = angular_spectrum(topo, angle_step)
    if not power.any():
        return float("nan")
    return float(angles[int(np.argmax(power))])


# ---------------------------------------------------------------------------------------
# feature parameters


@dataclass(frozen=True, eq=False)
class Hills:
    """Wolf-pruned hill segmentation: labels (0 = none), significant peak positions."""

    labels: np.ndarray
    peaks: np.ndarray  # (n, 2) int rows, cols of the counted peaks
    edge_peaks: np.ndarray  # peaks of hills that touch the border or a hole
    threshold: float  # pruning height, metres


def significant_hills(topo: Topography, pruning: float = WOLF_PRUNING,
                      exclude_edge: bool = True) -> Hills:
    """Watershed segmentation into hills with Wolf pruning at ``pruning`` × Sz."""
    from scipy import ndimage
    from skimage.morphology import h_maxima
    from skimage.segmentation import watershed

    z = _heights(topo)
    d, valid, full = _centred(z)
    sz = float(np.nanmax(d) - np.nanmin(d))
    h = pruning * sz
    if not sz > 0:
        empty = np.zeros((0, 2), dtype=int)
        return Hills(np.zeros(z.shape, dtype=np.int32), empty, empty, h)
    low = float(np.nanmin(d))
    filled = d if full else np.where(valid, d, low - sz)
    # h_maxima keeps the maxima whose dynamic is >= h: those are the hills Wolf pruning
    # leaves. Its float comparison can drop a hill whose dynamic equals h to the last bit;
    # shrinking h by a relative 1e-9 keeps the ">= h" semantics robust.
    markers_bin = h_maxima(filled, h * (1 - 1e-9)) if h > 0 else None
    markers, n = ndimage.label(markers_bin, structure=np.ones((3, 3)))
    labels = watershed(-filled, markers, mask=valid, connectivity=2)
    if n == 0:
        empty = np.zeros((0, 2), dtype=int)
        return Hills(labels, empty, empty, h)
    # One peak pixel per hill: the highest point of its marker.
    idx = np.arange(1, n + 1)
    pos = ndimage.maximum_position(filled, markers, idx)
    peaks = np.array(pos, dtype=int).reshape(-1, 2)
    touching = np.zeros(n + 1, dtype=bool)
    if exclude_edge:
        border = np.zeros(z.shape, dtype=bool)
        border[0, :] = border[-1, :] = border[:, 0] = border[:, -1] = True
        if not full:
            border |= ndimage.binary_dilation(~valid, structure=np.ones((3, 3)))
        touching[np.unique(labels[border & valid])] = True
    keep = ~touching[idx]
    return Hills(labels, peaks[keep], peaks[~keep], h)


def feature_parameters(topo: Topography, pruning: float = WOLF_PRUNING,
                       exclude_edge: bool = True) -> dict[str, float]:
    """Spd (1/m²) and Spc (1/m) of the significant hills."""
    z = _heights(topo)
    hills = significant_hills(topo, pruning, exclude_edge)
    n_valid = int(np.count_nonzero(~np.isnan(z)))
    area = n_valid * topo.dx * topo.dy
    spd = hills.peaks.shape[0] / area
    curv = []
    ny, nx = z.shape
    for j, i in hills.peaks:
        if 0 < j < ny - 1 and 0 < i < nx - 1:
            zxx = (z[j, i + 1] - 2 * z[j, i] + z[j, i - 1]) / topo.dx**2
            zyy = (z[j + 1, i] - 2 * z[j, i] + z[j - 1, i]) / topo.dy**2
            k = -0.5 * (zxx + zyy)
            if np.isfinite(k):
                curv.append(k)
    spc = float(np.mean(curv)) if curv else float("nan")
    return {"Spd": float(spd), "Spc": spc}


# ---------------------------------------------------------------------------------------
# functional parameters (material ratio)


def _sorted_desc(topo: Topography) -> np.ndarray:
    v = _valid_values(_heights(topo))
    return np.sort(v - v.mean())[::-1]


def material_ratio(topo: Topography, c: float) -> float:
    """Smr(c) in %: share of the valid points at or above height ``c`` (about the mean)."""
    v = _valid_values(_heights(topo))
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


# ---------------------------------------------------------------------------------------
# all together


def _resolve(which: Iterable[str] | str | None) -> list[str]:
    if which is None:
        return list(PARAMETER_UNITS)
    if isinstance(which, str):
        which = [w.strip() for w in which.split(",") if w.strip()]
    out: list[str] = []
    for w in which:
        if w in GROUPS:
            out.extend(GROUPS[w])
        elif w in PARAMETER_UNITS:
            out.append(w)
        else:
            raise SurfmetInputError(
                f"unknown areal parameter {w!r}; known: {', '.join(PARAMETER_UNITS)} or a "
                f"group ({', '.join(GROUPS)})"
            )
    return out


def areal_parameters(
    topo: Topography,
    which: Iterable[str] | str | None = None,
    *,
    acf_threshold: float = ACF_THRESHOLD,
    pruning: float = WOLF_PRUNING,
    exclude_edge: bool = True,
) -> ArealParameters:
    """Compute ISO 25178-2 areal parameters of a (levelled, filtered) topography.

    Parameters
    ----------
    topo : Topography
        The scale-limited surface; NaN points are ignored everywhere.
    which : iterable of str or comma-separated str, optional
        Symbols (``"Sa"``) or group names (``"height"``, ``"hybrid"``, ``"spatial"``,
        ``"feature"``, ``"functional"``); default all.
    acf_threshold : float
        s for Sal and Str (ISO 25178-3 default 0.2).
    pruning : float
        Wolf pruning height as a fraction of Sz (default 0.05).
    exclude_edge : bool
        Do not count hills that touch the border or a non-measured area (Spd, Spc).

    Returns
    -------
    ArealParameters

    Raises
    ------
    SurfmetInputError
        Not a Topography, no measured point, an unknown symbol.
    """
    wanted = _resolve(which)
    z = _heights(topo)
    n_valid = int(np.count_nonzero(~np.isnan(z)))
    if n_valid == 0:
        raise SurfmetInputError("the scan has no measured point")
    values: dict[str, Any] = {}
    notes: list[str] = []
    groups = {g for g, syms in GROUPS.items() if any(s in wanted for s in syms)}
    if "height" in groups:
        values.update(height_parameters(topo))
    if "hybrid" in groups:
        values.update(gradient_parameters(topo))
    if "spatial" in groups:
        if {"Sal", "Str"} & set(wanted):
            sp, nt = spatial_parameters(topo, acf_threshold)
            values.update(sp)
            notes.extend(nt)
        else:
            values["Std"] = texture_direction(topo)
    if "feature" in groups:
        values.update(feature_parameters(topo, pruning, exclude_edge))
    if "functional" in groups:
        values.update(functional_parameters(topo))
    kept = {k: float(values[k]) for k in wanted}
    return ArealParameters(**kept, n_valid=n_valid, notes=tuple(notes))
