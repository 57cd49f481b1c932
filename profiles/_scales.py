"""Scale-dependent statistics: derivatives taken over a distance, and what limits them.

Definitions (Sanner, Nöhring, Thimons, Jacobs, Pastewka, "Scale-dependent roughness
parameters for topography analysis", Appl. Surf. Sci. Adv. 7 (2022) 100190), as
SurfaceTopography 1.27 implements them (``Uniform/Derivative.py``,
``Nonuniform/Derivative.py``, ``Generic/ScanningProbe.py``):

* the derivative of order ``n`` at distance ``d`` is the finite difference whose stencil
  spans ``d`` in total: slope (n = 1) one-sided, ``[h(x + d) - h(x)] / d``; curvature
  (n = 2) central, ``[h(x - d/2) - 2 h(x) + h(x + d/2)] / (d/2)²``;
* heights between pixels come from linear interpolation along x; derivatives are taken
  along x only, for maps too (every row);
* the points whose stencil leaves the (non-periodic) scan are dropped: ``ceil(s)`` points
  at the end (slope) or at both ends (curvature), ``s = d / (n Δ)``, along x and, for maps,
  along y with ``s = d / (n Δy)`` as well (the peer trims its two-dimensional stencil in
  both directions);
* a nonuniform profile is first resampled, for each distance, by linear interpolation onto
  the grid of step ``d / (n k)``, ``k = ceil(d / mean step)``, from its first position;
  the stencil then spans ``k`` of those steps;
* the scale-dependent rms slope / curvature is the square root of the variance (mean
  removed) of all remaining finite derivative values; fewer than 4 values give NaN;
* the height-difference autocorrelation is ``A(d) = ½ <[h(x + d) - h(x)]²>`` over the same
  pairs, so the mean square slope is ``2 A(d) / d²``;
* the bandwidth of a scan is (pixel, size): mean pixel and mean side for maps, mean step
  and ``x[-1] - x[0]`` for nonuniform profiles;
* the scanning-probe reliability cut-off for a tip of radius ``R`` is the distance at which
  the most negative curvature at that distance equals ``-1/(2R)`` (safety factor ½ of
  Sanner et al.), searched between twice the pixel and half the size; ``None`` if even
  twice the pixel is reliable, the size if nothing is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from profiles._errors import ProfileError

MIN_VALUES = 4  # SurfaceTopography's ``threshold``: fewer derivative values give NaN


@dataclass(frozen=True)
class Scan:
    """Heights and sampling of one measurement, in SI.

    ``z`` is 1D (a profile) or 2D ``(ny, nx)`` (a map, x along axis 1); ``x`` are the
    positions of a nonuniform profile (None when uniform at ``dx``).
    """

    z: np.ndarray
    dx: float
    dy: float | None = None
    x: np.ndarray | None = None

    @property
    def is_map(self) -> bool:
        return self.z.ndim == 2

    def bandwidth(self) -> tuple[float, float]:
        """(shortest, longest) distance the scan resolves, metres."""
        if self.x is not None:
            return float(np.mean(np.diff(self.x))), float(self.x[-1] - self.x[0])
        if self.is_map:
            ny, nx = self.z.shape
            dy = self.dx if self.dy is None else self.dy  # square pixels, as make_scan
            return 0.5 * (self.dx + dy), 0.5 * (nx * self.dx + ny * dy)
        return self.dx, self.z.size * self.dx


def make_scan(z: Any, dx: float, dy: float | None = None, x: Any = None) -> Scan:
    """Validate arrays into a :class:`Scan` (heights float64, NaN = not measured)."""
    arr = np.asarray(z, dtype=np.float64)
    if arr.ndim not in (1, 2) or arr.size < 2:
        raise ProfileError(f"heights must be a 1D profile or a 2D map, got shape {arr.shape}")
    if not (math.isfinite(dx) and dx > 0):
        raise ProfileError(f"the pixel size must be a positive length, got {dx!r}")
    if arr.ndim == 2:
        dy = dx if dy is None else float(dy)
    pos = None
    if x is not None:
        pos = np.asarray(x, dtype=np.float64)
        if arr.ndim != 1 or pos.shape != arr.shape or not np.all(np.diff(pos) > 0):
            raise ProfileError("positions must increase strictly, one per height")
    return Scan(arr, float(dx), dy, pos)


def _shift(row_block: np.ndarray, s: float, start: int, m: int) -> np.ndarray:
    """Heights at ``index + s`` (linear interpolation along the last axis) for the ``m``
    indices from ``start``."""
    k = math.floor(s)
    f = s - k
    lo = row_block[..., start + k:start + k + m]
    if f == 0.0:
        return lo
    hi = row_block[..., start + k + 1:start + k + 1 + m]
    return (1.0 - f) * lo + f * hi


def _uniform_derivative(z: np.ndarray, dx: float, dy: float | None, d: float, n: int
                        ) -> np.ndarray:
    s = d / (n * dx)
    c = math.ceil(s)
    nx = z.shape[-1]
    if n == 1:
        m = nx - c
        if m <= 0:
            return np.empty(0)
        out = (_shift(z, s, 0, m) - z[..., :m]) / (s * dx)
    else:
        m = nx - 2 * c
        if m <= 0:
            return np.empty(0)
        centre = z[..., c:c + m]
        out = (_shift(z, -s, c, m) - 2.0 * centre + _shift(z, s, c, m)) / (s * dx) ** 2
    if z.ndim == 2:
        cy = math.ceil(d / (n * (dx if dy is None else dy)))  # square pixels, as make_scan
        ny = z.shape[0]
        rows = slice(0, ny - cy) if n == 1 else slice(cy, ny - cy)
        out = out[rows]
    return out


def resample(x: np.ndarray, z: np.ndarray, step: float) -> np.ndarray:
    """Heights at ``x[0] + i step`` (``i = 0 .. floor(L / step)``) by linear interpolation."""
    length = x[-1] - x[0]
    count = int(length / step) + 1
    return np.interp(np.arange(count) * step, x - x[0], z)


def derivative(scan: Scan, distance: float, order: int) -> np.ndarray:
    """Derivative values of ``order`` (1 slope, 2 curvature) at ``distance`` along x.

    Returns the finite values left after trimming (1D), in m⁻⁰ (slope) or 1/m (curvature).
    """
    if order not in (1, 2):
        raise ProfileError(f"derivative order {order} (1 or 2 expected)")
    if not (math.isfinite(distance) and distance > 0):
        raise ProfileError(f"distance {distance!r} is not a positive length")
    if scan.x is not None:
        lower, _ = scan.bandwidth()
        k = math.ceil(distance / lower)
        step = distance / (order * k)
        z = resample(scan.x, scan.z, step)
        vals = _uniform_derivative(z, step, None, order * k * step, order)
    else:
        vals = _uniform_derivative(scan.z, scan.dx, scan.dy, distance, order)
    vals = np.ravel(vals)
    return vals[np.isfinite(vals)]


def scale_variance(scan: Scan, distances: Any, order: int) -> np.ndarray:
    """Variance (mean removed) of the derivative of ``order`` at each distance; NaN where
    fewer than :data:`MIN_VALUES` values remain."""
    out = np.full(np.size(distances), np.nan)
    for i, d in enumerate(np.atleast_1d(distances)):
        vals = derivative(scan, float(d), order)
        if vals.size >= MIN_VALUES:
            out[i] = np.var(vals)
    return out


def height_difference_acf(scan: Scan, distances: Any) -> np.ndarray:
    """``A(d) = ½ <[h(x + d) - h(x)]²>`` (m²) over the pairs of the slope at ``d``."""
    out = np.full(np.size(distances), np.nan)
    for i, d in enumerate(np.atleast_1d(distances)):
        vals = derivative(scan, float(d), 1)
        if vals.size >= MIN_VALUES:
            out[i] = 0.5 * float(d) ** 2 * np.mean(vals**2)
    return out


def tip_cutoff(scan: Scan, tip_radius: float, safety: float = 0.5) -> float | None:
    """Scanning-probe reliability cut-off (m) for a tip of ``tip_radius`` (m).

    The distance at which the most negative curvature along x equals ``-safety / R``;
    None when even twice the pixel is reliable; the scan size when nothing is.
    """
    from scipy.optimize import brentq

    if not (math.isfinite(tip_radius) and tip_radius > 0):
        raise ProfileError(f"tip radius {tip_radius!r} is not a positive length")
    lower, upper = scan.bandwidth()
    target = safety / tip_radius
    # Work in units of the pixel so the root finder's tolerances are scale-free.
    def objective(t: float) -> float:
        vals = derivative(scan, t * lower, 2)
        return target if vals.size == 0 else target + float(np.min(vals))

    a, b = 2.0, upper / (2.0 * lower)
    if b <= a or objective(a) > 0:
        return None
    if objective(b) < 0:
        return upper
    return lower * brentq(objective, a, b, xtol=1e-12, rtol=1e-10)


def _line_residual(x: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Each row of ``z`` minus its least-squares line in ``x`` (NaN points ignored)."""
    w = np.isfinite(z)
    zw = np.where(w, z, 0.0)
    n = w.sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        xm = (w * x).sum(axis=1) / n
        zm = zw.sum(axis=1) / n
        dxr = np.where(w, x - xm[:, None], 0.0)
        slope = (dxr * zw).sum(axis=1) / (dxr**2).sum(axis=1)
    slope = np.where(n >= 2, slope, np.nan)
    return z - zm[:, None] - slope[:, None] * (x - xm[:, None])


def variable_bandwidth(scan: Scan, min_points: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """Variable-bandwidth rms height: bandwidths ``L / 2^k`` and the rms height after
    removing a least-squares line from each of the ``2^k`` segments (of every row, for
    maps), while a segment keeps ``min_points`` points. A nonuniform profile is resampled
    at its mean step first."""
    if scan.x is not None:
        lower, _ = scan.bandwidth()
        z, dx = resample(scan.x, scan.z, lower)[None, :], lower
    else:
        z, dx = np.atleast_2d(scan.z), scan.dx
    nx = z.shape[1]
    xs = np.arange(nx) * dx
    widths, rms = [], []
    k = 1
    while nx // k >= min_points:
        region = np.arange(nx) * k // nx
        res = np.empty_like(z)
        for r in range(k):
            cols = region == r
            res[:, cols] = _line_residual(xs[cols], z[:, cols])
        widths.append(nx * dx / k)
        rms.append(float(np.sqrt(np.nanmean(res**2))))
        k *= 2
    return np.array(widths), np.array(rms)
