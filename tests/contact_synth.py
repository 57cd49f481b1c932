"""Synthetic rough surfaces for the contact tests (seeded, with a known rms)."""

from __future__ import annotations

import numpy as np


def rough_surface(n: int, dx: float, rms: float, seed: int, corr: float = 20e-6) -> np.ndarray:
    """Gaussian random surface, n x n, pitch dx, isotropic PSD ~ (1 + (q corr)^2)^-2."""
    rng = np.random.default_rng(seed)
    qx = np.fft.fftfreq(n, dx)[None, :]
    qy = np.fft.fftfreq(n, dx)[:, None]
    psd = 1.0 / (1.0 + (np.hypot(qx, qy) * corr) ** 2) ** 2
    z = np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n))) * np.sqrt(psd)).real
    z -= z.mean()
    return z / z.std() * rms
