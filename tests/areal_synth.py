"""Synthetic areal scans with known clean statistics and hidden effects (test helper).

``gaussian_surface`` makes an isotropic Gaussian random surface by filtering white noise
with a Gaussian spectrum (correlation length ``corr`` in pixels) and scaling it to an
exact rms ``sq``; ``hide_effects`` adds a random tilt and curvature, random spikes and
random NaN holes and returns the truth about what it added.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def gaussian_surface(rng: np.random.Generator, ny: int, nx: int, sq: float,
                     corr: float) -> np.ndarray:
    """Zero-mean Gaussian random surface of rms ``sq`` with a Gaussian ACF of length corr px."""
    white = rng.standard_normal((ny, nx))
    fy = np.fft.fftfreq(ny)[:, None]
    fx = np.fft.rfftfreq(nx)[None, :]
    # ACF exp(-(r/corr)²) <-> spectrum amplitude exp(-(π corr f)² / 2)
    amp = np.exp(-((np.pi * corr) ** 2) * (fx**2 + fy**2) / 2.0)
    z = np.fft.irfft2(np.fft.rfft2(white) * amp, s=(ny, nx))
    z -= z.mean()
    return z * (sq / z.std())


@dataclass
class Hidden:
    tilt: tuple[float, float]
    curvature: float
    spike_pixels: np.ndarray  # (n, 2) row, col of each spike's main pixel
    spike_heights: np.ndarray
    n_spike_points: int
    holes: np.ndarray  # bool mask of NaN holes


def hide_effects(rng: np.random.Generator, z: np.ndarray, dx: float, *, spikes: bool = True,
                 holes: bool = True, form: bool = True) -> tuple[np.ndarray, Hidden]:
    """Add random tilt + curvature, spikes (10-40 Sq, 1-2 px) and NaN holes to ``z``."""
    ny, nx = z.shape
    sq = float(z.std())
    out = z.copy()
    y, x = np.mgrid[:ny, :nx] * dx
    tilt = (0.0, 0.0)
    curv = 0.0
    if form:
        tilt = tuple(rng.uniform(-1, 1, 2) * 200 * sq / (nx * dx))
        curv = float(rng.uniform(-1, 1) * 400 * sq / (nx * dx) ** 2)
        xc, yc = rng.uniform(0, nx * dx), rng.uniform(0, ny * dx)
        out += tilt[0] * x + tilt[1] * y + curv * ((x - xc) ** 2 + (y - yc) ** 2)
    hole = np.zeros((ny, nx), dtype=bool)
    if holes:
        for _ in range(rng.integers(1, 6)):
            cy, cx = rng.integers(0, ny), rng.integers(0, nx)
            r = rng.uniform(2, 0.08 * min(nx, ny))
            hole |= (np.mgrid[:ny, :nx][0] - cy) ** 2 + (np.mgrid[:ny, :nx][1] - cx) ** 2 < r * r
        hole |= rng.random((ny, nx)) < rng.uniform(0, 0.02)  # scattered dropouts
    pix = np.zeros((0, 2), dtype=int)
    hts = np.zeros(0)
    n_pts = 0
    if spikes:
        n = int(rng.integers(5, 60))
        taken = hole.copy()
        rows, cols, hh = [], [], []
        while len(rows) < n:
            j, i = int(rng.integers(3, ny - 3)), int(rng.integers(3, nx - 3))
            if taken[j - 3:j + 4, i - 3:i + 4].any():
                continue
            h = rng.choice([-1, 1]) * rng.uniform(10, 40) * sq
            out[j, i] += h
            n_pts += 1
            if rng.random() < 0.3:  # a 2-pixel spike
                out[j, i + 1] += 0.8 * h
                n_pts += 1
            taken[j - 3:j + 4, i - 3:i + 4] = True
            rows.append(j)
            cols.append(i)
            hh.append(h)
        pix = np.column_stack([rows, cols])
        hts = np.array(hh)
    out[hole] = np.nan
    return out, Hidden(tilt, curv, pix, hts, n_pts, hole)
