"""A surface's averaged 1D PSD from several measurements, as contact.engineering averages it.

Conventions (read from SurfaceTopography 1.27's ``Uniform/PowerSpectrum.py``,
``Nonuniform/PowerSpectrum.py`` and ``Container/Averaging.py``; written anew here):

* **Per measurement**, the PSD on its own DFT wavevectors ``q_k = 2πk/L`` (``L = n Δx``,
  ``1 ≤ k < n/2``): ``C(q_k) = Δx² |Σ_i w_i h_i e^{-i q_k x_i}|² / L`` of the heights as
  levelled by the container (its ``detrend_mode``; no further centring; a measurement that
  states none is centred, contact.engineering's default ``center``), times a periodic
  Hann window ``w_i = √(2/3) (1 − cos 2πi/n)`` (mean square one) unless the data are
  periodic; a map gives the mean over its rows (along x).
* A **nonuniform profile** is the piecewise-linear curve through its points (levelled
  over the curve, :func:`continuous_level`, where the container states a detrending), sampled
  uniformly at ``M = 5 ⌊L/min Δx_i⌋`` points (pitch ``L/(M−1)``) and treated as above; it
  is kept for ``q < 2π/mean Δx_i`` (above, the interpolation's kinks, not the surface).
* **Reliability**: only ``q < 2π/λ_c`` is kept, ``λ_c`` the measurement's short cut-off
  (tip radius: :func:`profiles._scales.tip_cutoff`), and never above ``π/Δx``.
* **Binning**: each measurement's values are averaged in log bins of its own: from the
  decade below its smallest q to the decade above its largest, widened by 0.01 decade at
  each end and cut into ``N`` equal bins per decade; its bin ``j`` is the global bin
  ``N·floor(log10 q_min) + j``. A bin's abscissa is the mean of the wavevectors in it.
* **Average**: in each global bin, the unweighted mean over the measurements with data
  there, of the values and of the abscissas (one equal vote each).

The result is sampled at ``N`` bins per decade of q (default 10, contact.engineering's),
independent of the distance grid of the scale-dependent statistics: at low q every bin
holds a single DFT point of the longest measurement, so the average keeps the data's own
resolution there. Outside a measurement's reliable band nothing of it enters.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from profiles._scales import Scan

#: Bins per decade of q (contact.engineering's default).
PSD_PER_DECADE = 10
#: Interpolation points per smallest spacing of a nonuniform profile.
NONUNIFORM_OVERSAMPLING = 5
#: Widening of each measurement's bin range at both ends, in decades.
_WIDEN = 0.01


@dataclass(frozen=True)
class AveragedPSD:
    """The averaged PSD (``q`` rad/m, ``C`` m³) and each measurement's bin values on the
    same bins (``per_measurement``, NaN where a measurement has no data)."""

    q: np.ndarray
    C: np.ndarray
    per_measurement: tuple[np.ndarray, ...]
    per_decade: int


def _hann(n: int) -> np.ndarray:
    # periodic Hann (a DFT window), scaled to a mean square of one
    return math.sqrt(2.0 / 3.0) * (1.0 - np.cos(2.0 * np.pi * np.arange(n) / n))


def _uniform_psd(rows: np.ndarray, dx: float, periodic: bool) -> tuple[np.ndarray, np.ndarray]:
    """(q, C) at 1 <= k < n/2 of the rows' mean 1D PSD along their last axis."""
    n = rows.shape[-1]
    finite = np.all(np.isfinite(rows), axis=-1)
    # rows with holes have no DFT; a map without a full row has its holes at zero
    rows = rows[finite] if finite.any() else np.nan_to_num(rows)
    if not periodic:
        rows = rows * _hann(n)
    power = np.mean(np.abs(np.fft.rfft(rows, axis=-1)) ** 2, axis=0)
    k = np.arange(1, (n + 1) // 2)
    return 2.0 * np.pi * k / (n * dx), dx * power[k] / n


def continuous_level(x: np.ndarray, z: np.ndarray, degree: int) -> np.ndarray:
    """``z`` less the polynomial of ``degree`` closest to the piecewise-linear curve through
    (x, z) in the integral of the squared difference over the scan (not over the points).

    Each segment's squared residual is a polynomial of degree <= 4 for degree <= 2, so three
    Gauss-Legendre points per segment make the integral exact. Applied to a profile already
    levelled point-wise by a polynomial of the same degree it gives the same result as on
    the raw one (both are projections onto the same polynomials)."""
    nodes, weights = np.polynomial.legendre.leggauss(3)
    mid, half = 0.5 * (x[1:] + x[:-1]), 0.5 * np.diff(x)
    xs = (mid[:, None] + half[:, None] * nodes[None, :]).ravel()
    ws = np.sqrt((half[:, None] * weights[None, :]).ravel())
    zs = np.interp(xs, x, z)
    centre, scale = 0.5 * (x[0] + x[-1]), 0.5 * (x[-1] - x[0])
    basis = np.vander((xs - centre) / scale, degree + 1)
    coef = np.linalg.lstsq(basis * ws[:, None], zs * ws, rcond=None)[0]
    return z - np.vander((x - centre) / scale, degree + 1) @ coef


def measurement_psd(scan: Scan, cutoff: float | None = None, periodic: bool = False,
                    degree: int | None = None, centre: bool = False
                    ) -> tuple[np.ndarray, np.ndarray]:
    """One measurement's 1D PSD on its DFT wavevectors, reliable ones only (module notes).

    Parameters
    ----------
    scan : Scan
        The measurement as levelled (SI).
    cutoff : float, optional
        Short reliability cut-off λ_c (m); q < 2π/λ_c is kept.
    periodic : bool
        No window for periodic data.
    degree : int, optional
        The container's detrending degree; a nonuniform profile is then levelled over its
        curve (:func:`continuous_level`), as SurfaceTopography levels it.
    centre : bool
        Remove the mean first (for a measurement that states no levelling: the default
        ``center`` of a contact.engineering measurement).

    Returns
    -------
    (q rad/m, C m³), q > 0 ascending.
    """
    if centre and degree is None:
        degree = 0
    if scan.x is not None:
        x = scan.x - scan.x[0]
        steps = np.diff(x)
        m = NONUNIFORM_OVERSAMPLING * int(x[-1] / steps.min())
        pitch = x[-1] / (m - 1)
        z = scan.z if degree is None else continuous_level(x, scan.z, degree)
        z = np.interp(np.arange(m) * pitch, x, z)
        q, c = _uniform_psd(z[None, :], pitch, periodic)
        keep = q < 2.0 * np.pi / float(np.mean(steps))
        q, c = q[keep], c[keep]
    else:
        rows = scan.z if scan.is_map else scan.z[None, :]
        if centre:
            rows = rows - np.nanmean(rows)
        q, c = _uniform_psd(rows, scan.dx, periodic)
    if cutoff:
        keep = q < 2.0 * np.pi / cutoff
        q, c = q[keep], c[keep]
    return q, c


def _bins(q: np.ndarray, c: np.ndarray, per_decade: int
          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(global bin keys, mean q, mean C) of one measurement's values (module notes)."""
    low = math.floor(math.log10(q.min()))
    high = max(math.ceil(math.log10(q.max())), low + 1)
    edges = 10.0 ** np.linspace(low - _WIDEN, high + _WIDEN, (high - low) * per_decade + 1)
    j = np.searchsorted(edges, q) - 1
    inside = (j >= 0) & (j < edges.size - 1)
    j, q, c = j[inside], q[inside], c[inside]
    count = np.bincount(j, minlength=edges.size - 1)
    used = np.flatnonzero(count)
    qs = np.bincount(j, weights=q, minlength=edges.size - 1)[used] / count[used]
    cs = np.bincount(j, weights=c, minlength=edges.size - 1)[used] / count[used]
    return low * per_decade + used, qs, cs


def average_psd(spectra: list[tuple[np.ndarray, np.ndarray]],
                per_decade: int = PSD_PER_DECADE) -> AveragedPSD:
    """The measurements' PSDs ``spectra`` [(q, C), ...] averaged with equal votes per bin.

    A measurement with no reliable wavevector (empty arrays) has no vote anywhere.
    """
    binned = [_bins(q, c, per_decade) if q.size else None for q, c in spectra]
    keys = np.unique(np.concatenate([b[0] for b in binned if b is not None] + [[]])
                     ).astype(int)
    qs = np.full((len(spectra), keys.size), np.nan)
    cs = np.full((len(spectra), keys.size), np.nan)
    for i, b in enumerate(binned):
        if b is not None:
            at = np.searchsorted(keys, b[0])
            qs[i, at], cs[i, at] = b[1], b[2]
    with np.errstate(invalid="ignore"):
        q_mean = np.nanmean(qs, axis=0) if keys.size else np.zeros(0)
        c_mean = np.nanmean(cs, axis=0) if keys.size else np.zeros(0)
    return AveragedPSD(q_mean, c_mean, tuple(cs), per_decade)
