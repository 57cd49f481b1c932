"""Spikes: detection and removal as an explicit, reported step, and the Sq/Sa diagnosis.

Optical profilometers (confocal, focus variation, the NanoFocus µScan of Alaci et al.
2022) return isolated false heights — "spikes" or outliers — on steep flanks, dust and
specular spots. A handful of them is enough to dominate Sq, Sz, Ssk and Sku while Sa
barely moves. For a Gaussian height distribution ``Sq/Sa = sqrt(π/2) ≈ 1.2533``; smooth
non-Gaussian textures stay near it (a sine gives 1.11, a uniform distribution 1.15, a
Laplace distribution 1.41). The paper's Table 1 reports Sq/Sa up to 5.34/1.255 ≈ 4.3: no
real texture does that, spikes do. :func:`spike_diagnosis` says so on every result.

Detection (:func:`remove_spikes`) is a robust directional outlier test. For every point
and each of the four grid directions (x, y and both diagonals) the residual from the
straight line through its two neighbours, ``r_d = z - (z₋ + z₊)/2``, is formed; each
residual annihilates any plane (tilt) and feels curvature only at the scale of one pixel.
A point is a spike when **every** available direction (at least two) gives a residual of
the same sign beyond ``k × σ̂_d``, where σ̂_d = 1.4826 × MAD of that direction's residuals
over the scan (a robust standard deviation, Rousseeuw & Croux 1993). Requiring all
directions rejects the neighbours of a spike (one of their directions runs through the
spike, the others do not) and smooth peaks of the real texture (their residuals are the
Gaussian-tailed local curvature, not outliers). This is the same idea as Gwyddion's
outlier and scar marking, made direction-robust. Groups of flagged points (8-connected)
larger than ``max_points`` are real features and are left alone. Flagged points become
NaN (non-measured); nothing is interpolated. Points with fewer than two testable
directions (the outermost rows and columns, points between holes) are not tested, so a
spike on the very edge of a scan stays. The test ignores form, so spikes are removed
before the F-operator, whose least-squares fit they would bias.

A local median (Gwyddion's "median" outlier rule) was tried first and rejected: on
textures that are smooth at pixel scale, the median residual is zero on slopes and
large at every peak, a heavy-tailed distribution whose MAD is tiny, so real peaks became
"spikes".
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography

GAUSSIAN_SQ_OVER_SA = math.sqrt(math.pi / 2.0)
"""Sq/Sa of a Gaussian height distribution, sqrt(π/2) ≈ 1.2533."""

SUSPECT_SQ_OVER_SA = 1.5
"""Sq/Sa above this flags a surface as spiky (a Laplace distribution reaches 1.41)."""

OUTLIER_SIGMAS = 10.0

#: The advice a spike warning ends with (the option every scan command has; no API name).
REMOVE_ADVICE = ("remove the spikes before levelling (--spikes) or check the scan before "
                 "trusting them.")
"""Heights beyond this many robust σ of the height distribution count as outliers."""


@dataclass(frozen=True, eq=False)
class SpikeReport:
    """What :func:`remove_spikes` removed.

    Attributes
    ----------
    count : int
        Number of spikes (connected groups of flagged points).
    n_points : int
        Number of points set to NaN.
    fraction : float
        ``n_points`` over the measured points before removal.
    threshold : float
        Residual threshold in metres (``k × robust σ``, the largest over directions).
    sigma : float
        Largest robust σ of the four directional residuals, metres.
    k : float
        Threshold in robust σ.
    size : int
        Side of the neighbourhood the test looks at (3: the point and its 8 neighbours).
    positions : ndarray, shape (count, 2)
        ``(x, y)`` in metres of each spike's most extreme point.
    heights : ndarray, shape (count,)
        Smallest directional residual of each spike's extreme point, metres (signed).
    pixels : ndarray, shape (count, 2)
        ``(row, column)`` of each spike's most extreme point.
    """

    count: int
    n_points: int
    fraction: float
    threshold: float
    sigma: float
    k: float
    size: int
    positions: np.ndarray = field(repr=False)
    heights: np.ndarray = field(repr=False)
    pixels: np.ndarray = field(repr=False)


@dataclass(frozen=True)
class SpikeDiagnosis:
    """Why Sq/Sa looks the way it does.

    ``suspected`` is True when Sq/Sa exceeds :data:`SUSPECT_SQ_OVER_SA` or some heights lie
    beyond :data:`OUTLIER_SIGMAS` robust σ of the height distribution.
    """

    sq_over_sa: float
    gaussian_ratio: float
    kurtosis: float
    n_outliers: int
    suspected: bool
    message: str

    def as_dict(self) -> dict:
        return {
            "suspected": self.suspected,
            "sq_over_sa": self.sq_over_sa,
            "gaussian_sq_over_sa": self.gaussian_ratio,
            "Sku": self.kurtosis,
            "height_outliers": self.n_outliers,
            "message": self.message,
        }


def spike_diagnosis(heights: np.ndarray | Topography, prefix: str = "S") -> SpikeDiagnosis:
    """Diagnose spikes from the height distribution of a (levelled) surface.

    Parameters
    ----------
    heights : Topography or array
        Heights after form removal; NaN points are ignored.
    prefix : {"S", "R"}
        Parameter family named in the message: areal (Sq/Sa) or profile (Rq/Ra).
    """
    q, a, k, z_, p_ = (f"{prefix}q", f"{prefix}a", f"{prefix}ku", f"{prefix}z", f"{prefix}sk")
    z = heights.heights if isinstance(heights, Topography) else np.asarray(heights, float)
    v = z[np.isfinite(z)]
    if v.size < 3:
        raise SurfmetInputError("spike diagnosis needs at least 3 measured points")
    d = v - v.mean()
    sa = float(np.abs(d).mean())
    sq = float(np.sqrt(np.mean(d * d)))
    if not sa > 0:
        return SpikeDiagnosis(float("nan"), GAUSSIAN_SQ_OVER_SA, float("nan"), 0, False,
                              f"flat surface: {q}/{a} undefined")
    ratio = sq / sa
    sku = float(np.mean(d**4) / sq**4)
    med = float(np.median(v))
    mad = float(np.median(np.abs(v - med)))
    sigma = 1.4826 * mad
    n_out = int(np.count_nonzero(np.abs(v - med) > OUTLIER_SIGMAS * sigma)) if sigma > 0 else 0
    suspected = ratio > SUSPECT_SQ_OVER_SA or n_out > 0
    if suspected:
        msg = (
            f"{q}/{a} = {ratio:.3g}, against {GAUSSIAN_SQ_OVER_SA:.3g} (= sqrt(pi/2)) for a "
            f"Gaussian surface and at most ~1.4 for real textures; {k} = {sku:.3g}. "
            f"{n_out} point(s) lie beyond {OUTLIER_SIGMAS:g} robust sigma of the height "
            f"distribution. A few extreme heights (spikes, outliers, dust) dominate {q}, "
            f"{z_}, {p_} and {k}: " + REMOVE_ADVICE
        )
    else:
        msg = (
            f"{q}/{a} = {ratio:.3g} (Gaussian surface: {GAUSSIAN_SQ_OVER_SA:.3g}); no sign of "
            "spikes."
        )
    return SpikeDiagnosis(ratio, GAUSSIAN_SQ_OVER_SA, sku, n_out, bool(suspected), msg)


_DIRECTIONS = ((0, 1), (1, 0), (1, 1), (1, -1))


def _directional_residuals(z: np.ndarray) -> list[np.ndarray]:
    """``z - (z[p - d] + z[p + d]) / 2`` for the four directions; NaN where undefined."""
    ny, nx = z.shape
    pad = np.full((ny + 2, nx + 2), np.nan)
    pad[1:-1, 1:-1] = z
    out = []
    for dj, di in _DIRECTIONS:
        minus = pad[1 - dj: 1 - dj + ny, 1 - di: 1 - di + nx]
        plus = pad[1 + dj: 1 + dj + ny, 1 + di: 1 + di + nx]
        out.append(z - 0.5 * (minus + plus))
    return out


def _robust_sigma(r: np.ndarray) -> float:
    v = r[np.isfinite(r)]
    if v.size > 1_000_000:  # a regular subsample estimates the MAD to ~0.1 %
        v = v[:: v.size // 1_000_000]
    if not v.size:
        return 0.0
    sig = 1.4826 * float(np.median(np.abs(v - np.median(v))))
    if not sig > 0:
        # A quantised or synthetic flat scan: fall back on the smallest non-zero step.
        nz = np.abs(v[v != 0])
        sig = float(nz.min()) if nz.size else 0.0
    return sig


def _detect(z: np.ndarray, k: float, max_points: int
            ) -> tuple[np.ndarray, list[np.ndarray], list[float]]:
    """One detection pass: (spike mask, directional residuals, their robust σ)."""
    from scipy import ndimage

    resid = _directional_residuals(z)
    sigmas = [_robust_sigma(r) for r in resid]
    n_dir = np.zeros(z.shape, dtype=np.int8)
    n_up = np.zeros(z.shape, dtype=np.int8)
    n_down = np.zeros(z.shape, dtype=np.int8)
    for r, sig in zip(resid, sigmas):
        ok = np.isfinite(r)
        n_dir += ok
        if sig > 0:
            with np.errstate(invalid="ignore"):
                n_up += ok & (r > k * sig)
                n_down += ok & (r < -k * sig)
    # Seeds: every available direction (two at least; one on a single-row scan) agrees.
    need = 1 if min(z.shape) == 1 else 2
    seed_up = (n_dir >= need) & (n_up == n_dir)
    seed_down = (n_dir >= need) & (n_down == n_dir)
    # Grow each seed over neighbours that stand out the same way in two directions (the
    # second pixel of a wide spike, or the rim of a real pit whose corner seeded); a
    # spike's plain neighbours see it in one direction only, with the opposite sign.
    eight = np.ones((3, 3), dtype=bool)
    grown = np.zeros(z.shape, dtype=bool)
    for seed, count in ((seed_up, n_up), (seed_down, n_down)):
        if seed.any():
            grown |= ndimage.binary_propagation(seed, structure=eight,
                                                mask=seed | (count >= min(2, need + 1)))
    labels, n = ndimage.label(grown, structure=eight)
    if n:
        sizes = np.bincount(labels.ravel(), minlength=n + 1)
        small = sizes <= max_points
        small[0] = False
        grown = small[labels]
    return grown, resid, sigmas


def remove_spikes(
    topo: Topography,
    *,
    k: float = 6.0,
    max_points: int = 25,
    iterations: int = 3,
) -> tuple[Topography, SpikeReport]:
    """Detect spikes by the directional robust test and make them non-measured (NaN).

    Parameters
    ----------
    topo : Topography
        The scan (before or after form removal: the test ignores planes).
    k : float
        Threshold in robust σ of the directional residuals. All (≥ 2) directions must
        exceed it with one sign; for Gaussian residuals one direction alone exceeds 6σ
        with probability 2·10⁻⁹, so clean scans of millions of points report nothing.
    max_points : int
        Largest 8-connected group of flagged points still called a spike; larger groups
        are real features (a scratch, a step) and are left alone.
    iterations : int
        Detection passes; each pass sees the spikes found so far as non-measured, which
        unmasks spikes hidden next to others.

    Returns
    -------
    cleaned : Topography
        Spike points set to NaN; metadata ``spikes_removed`` = count.
    report : SpikeReport

    Raises
    ------
    SurfmetInputError
        A bad ``k``, or a scan with no measured point.
    """
    from scipy import ndimage

    if not (math.isfinite(k) and k > 0):
        raise SurfmetInputError(f"spike threshold k must be positive, got {k!r}")
    z = topo.heights
    valid = np.isfinite(z)
    n_valid = int(valid.sum())
    if n_valid == 0:
        raise SurfmetInputError("the scan has no measured point")
    flagged = np.zeros(z.shape, dtype=bool)
    work = z
    sigmas: list[float] = []
    for _ in range(max(int(iterations), 1)):
        new, resid, sig = _detect(work, k, max_points)
        if not sigmas:
            sigmas = sig  # the scale of the scan as given
        if not new.any():
            break
        flagged |= new
        work = np.where(flagged, np.nan, z)
    resid = _directional_residuals(z)
    labels, n = ndimage.label(flagged, structure=np.ones((3, 3)))
    if n:
        # Spike height: the directional residual smallest in magnitude (conservative).
        fj, fi = np.nonzero(flagged)
        stack = np.stack([np.where(np.isfinite(r[fj, fi]), r[fj, fi], np.nan) for r in resid])
        idx = np.nanargmin(np.where(np.isfinite(stack), np.abs(stack), np.inf), axis=0)
        fh = stack[idx, np.arange(fj.size)]
        height = np.zeros(z.shape)
        height[fj, fi] = fh
        score = np.where(flagged, np.abs(height), -1.0)
        pix = np.array(ndimage.maximum_position(score, labels, np.arange(1, n + 1)),
                       dtype=np.int64).reshape(-1, 2)
        positions = np.column_stack([pix[:, 1] * topo.dx, pix[:, 0] * topo.dy])
        heights = height[pix[:, 0], pix[:, 1]]
    else:
        pix = np.zeros((0, 2), dtype=np.int64)
        positions, heights = np.zeros((0, 2)), np.zeros(0)
    n_points = int(flagged.sum())
    cleaned = np.where(flagged, np.nan, z)
    if not np.isfinite(cleaned).any():
        raise SurfmetInputError("spike removal left no measured point")
    sigma = float(max(sigmas))
    report = SpikeReport(
        count=n, n_points=n_points, fraction=n_points / n_valid, threshold=float(k * sigma),
        sigma=sigma, k=float(k), size=3, positions=positions,
        heights=np.asarray(heights, dtype=float), pixels=pix,
    )
    return topo.replace(heights=cleaned).with_metadata(spikes_removed=n), report
