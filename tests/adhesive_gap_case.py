"""The adhesive rough flat case of issue 38 (item 2), generated with numpy alone.

Both codes are fed this very array: benchmarks/tamaas_adhesive_gap.py gives it to Tamaas in
a separate virtualenv (tests/data/tamaas_adhesive_gap.json holds its answers and the
array's fingerprints), tests/test_adhesive_gap.py to surfmet. A periodic random-phase
self-affine surface (Hurst 0.8, roll-off at a quarter of the box, no short cut-off),
scaled to an rms slope of 0.1 (x and y together), on a 64 µm box; E* 25 MPa, the
exponential law of w 0.025 J/m² and range 35 nm.
"""

from __future__ import annotations

import numpy as np

N, BOX, HURST, SLOPE_RMS, SEED = 256, 64e-6, 0.8, 0.1, 38
E_STAR, WORK, RANGE = 25e6, 0.025, 35e-9


def surface(amplitude: float = 1.0) -> np.ndarray:
    """Heights (m), N x N on pixels BOX / N, times ``amplitude``."""
    rng = np.random.default_rng(SEED)
    k = 2.0 * np.pi * np.fft.fftfreq(N, BOX / N)
    q = np.hypot(k[:, None], k[None, :])
    roll_off = 2.0 * np.pi / (BOX / 4.0)
    psd = np.where(q > 0.0, np.maximum(q, roll_off) ** (-2.0 - 2.0 * HURST), 0.0)
    z = np.real(np.fft.ifft2(np.sqrt(psd) * np.exp(2j * np.pi * rng.random((N, N)))))
    slope_x = np.real(np.fft.ifft2(1j * k[None, :] * np.fft.fft2(z)))
    return amplitude * z * SLOPE_RMS / np.sqrt(2.0 * np.mean(slope_x ** 2))
