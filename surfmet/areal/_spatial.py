"""Areal spatial parameters Sal, Str, Std (ISO 25178-2:2012, 4.3; thresholds ISO 25178-3).

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
"""

from __future__ import annotations

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._points import centred, heights_of

ACF_THRESHOLD = 0.2
"""ISO 25178-3 default threshold s of the autocorrelation for Sal and Str."""


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

    z = heights_of(topo)
    d, valid, full = centred(z)
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
    # each ray is sampled every half cell of the grid along its own direction (half a
    # pixel for square pixels): a step set by the smaller pixel alone would sample the
    # rays along the larger one (dx/dy) times too finely, and a 1 mm x 0.1 µm pixel would
    # ask for 1e4 x more samples (memory and time growing with the anisotropy)
    step = 0.5 / np.hypot(np.cos(th) / dx, np.sin(th) / dy)
    nstep = int(np.ceil((rmax / step).max())) + 1
    r = np.arange(nstep)[None, :] * step[:, None]
    cols = (nx - 1) + np.cos(th)[:, None] * r / dx
    rows = (ny - 1) + np.sin(th)[:, None] * r / dy
    # NaN (too few overlapping valid pairs) propagates through the bilinear weights and
    # ends a ray there, like the half-scan limit.
    vals = map_coordinates(acf, [rows.ravel(), cols.ravel()], order=1, mode="nearest")
    vals = vals.reshape(th.size, nstep)
    vals[r > rmax[:, None]] = np.nan
    length = rmax.copy()
    decayed = np.zeros(th.size, dtype=bool)
    for k in range(th.size):
        row = vals[k]
        bad = np.flatnonzero(~np.isfinite(row))
        end = bad[0] if bad.size else nstep
        idx = np.flatnonzero(row[:end] <= s)
        if idx.size == 0 or idx[0] == 0:
            length[k] = min(rmax[k], r[k, max(end - 1, 0)])
            continue
        i = idx[0]
        v0, v1 = row[i - 1], row[i]
        length[k] = r[k, i - 1] + (v0 - s) / (v0 - v1) * step[k]
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

    z = heights_of(topo)
    d, valid, full = centred(z)
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
