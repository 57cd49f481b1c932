"""The reading-noise model of a column of frame indices and its maximum-likelihood estimate.

A row's time error has two parts: the frame grain and other timing scatter,
``sigma_t >= 1/(fps sqrt(12))``, and the scatter ``sigma_a`` (rad) in judging when a mark is at
the rod's axis, which costs ``sigma_a/omega`` in time and so weighs on the slow early rows
(on Table 3 the residuals are homoscedastic in angle, not in time). The first row is the time
origin (the launch) and has ``sigma_t`` only.

Quantisation convention: a mark crossing at true time ``t`` is read on the first frame that
shows it at or past the rod's axis, ``f = ceil(t fps)``; the half-frame bias this has against
rounding is common to all rows and absorbed by the start time. The error is uniform over one
frame: standard deviation ``1/(fps sqrt(12))`` = 2.4 ms at 120 fps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotor._forward import STALL
from rotor._paper import FPS

__all__ = ["Noise", "estimate_noise", "quantisation_sigma"]


def quantisation_sigma(fps: float = FPS) -> float:
    """Standard deviation of the frame-quantisation error, ``1/(fps sqrt(12))``, s."""
    return 1.0 / (fps * math.sqrt(12.0))


@dataclass(frozen=True)
class Noise:
    """Reading noise of one test: ``sigma_i^2 = sigma_t^2 + (sigma_a / omega_i)^2``.

    ``sigma_t`` (s, at least the quantisation sigma) is scatter in time; ``sigma_a`` (rad) is
    scatter in judging when a mark overlaps the rod's axis, which costs more time where the
    rotor turns slowly. ``omega_i`` is the model's angular speed at the row, kept above
    ``sqrt(2 eps0 sigma_a)`` (the speed after turning ``sigma_a`` from rest).
    """

    sigma_t: float
    sigma_a: float

    def sigma(self, omega: np.ndarray, eps0: float, origin: int | None = None) -> np.ndarray:
        """Per-row sigma (s); the row ``origin`` (the first mark, the time origin, read
        as the launch) gets the time scatter only."""
        w2 = np.asarray(omega, float) ** 2 + 2.0 * max(eps0, STALL) * self.sigma_a
        out = np.sqrt(self.sigma_t**2 + self.sigma_a**2 / np.maximum(w2, 1e-300))
        if origin is not None:
            out[origin] = self.sigma_t
        return out


_T_NU = 4.0
_T_CONSISTENCY = 1.2033643751050191
"""For Gaussian data the Student-t (nu = 4) maximum-likelihood scale is 0.831 sigma; this
factor makes the robust noise estimate consistent with the Gaussian one."""


def estimate_noise(r: np.ndarray, omega: np.ndarray, eps0: float, sigma_q: float,
                    start: Noise | None = None, robust: bool = False) -> Noise:
    """Maximum-likelihood ``(sigma_t >= sigma_q, sigma_a >= 0)`` for residuals ``r`` (s).

    ``robust``: Student-t likelihood (nu = 4), so that a few gross errors (misread rows) do
    not inflate the scale; the result is rescaled to be consistent with the Gaussian one.
    Two parameters only, so a coarse-to-fine grid (vectorised) is cheap and cannot stall.
    """
    r2 = np.asarray(r, float) ** 2
    if r2.size == 0:
        return Noise(sigma_q, 0.0)
    sa0 = start.sigma_a if start is not None else 0.0
    v = 1.0 / np.maximum(np.asarray(omega, float) ** 2
                         + 2.0 * max(eps0, STALL) * max(sa0, 0.01), 1e-300)
    q2 = sigma_q**2
    vs = float(np.mean(v))
    vn = v / vs
    c2 = _T_CONSISTENCY**2 if robust else 1.0

    def nll(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        var = (q2 * (1.0 + a[:, None, None]) + q2 * b[None, :, None] * vn) / c2
        if robust:
            terms = np.log(var) + (_T_NU + 1) * np.log1p(r2 / (_T_NU * var))
        else:
            terms = np.log(var) + r2 / var
        return terms.sum(axis=-1)

    top = math.log10(max(float(r2.max()) / q2, 1.0)) + 1.0
    a = np.concatenate(([0.0], np.logspace(-3, top, 31)))
    b = np.concatenate(([0.0], np.logspace(-3, top, 31)))
    for _ in range(3):
        grid = nll(a, b)
        i, j = np.unravel_index(int(np.argmin(grid)), grid.shape)
        a_best, b_best = float(a[i]), float(b[j])
        a = np.linspace(a[max(i - 1, 0)], a[min(i + 1, a.size - 1)], 15)
        b = np.linspace(b[max(j - 1, 0)], b[min(j + 1, b.size - 1)], 15)
    return Noise(float(math.sqrt(q2 * (1.0 + a_best))), float(math.sqrt(q2 * b_best / vs)))
