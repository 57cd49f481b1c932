"""Persson's theory of contact of a rough surface with a flat: area, mean gap, stiffness.

Area (Persson 2001, J. Chem. Phys. 115, 3840; Persson 2007, PRL 99, 125502): for full
contact of the whole spectrum,

    A/A0 = erf(1/(2√G)),   G = (π/4) (E*/p)² ∫ q³ C_P dq = (E* h'_rms / p)² / 8,

so ``A/A0 = erf(√2 p / (E* h'_rms))``, which tends to ``κ p / (E* h'_rms)`` with
``κ = √(8/π) ≈ 1.596`` at low pressure.

Mean gap (Yang & Persson 2008, PRL 100, 024303, Eqs. 3-4):

    ū(p) = √π ∫ dq q² C_P(q) w(q) ∫_p^∞ (dp'/p') [γ + 3(1-γ) P²(q, p')] exp(-(w(q) p'/E*)²),

with ``w(q) = (π ∫_{q0}^{q} q'³ C_P dq')^(-1/2) = √2 / h'_rms(q)`` (the rms slope of the
wavevectors up to q), ``P(q, p) = erf(w(q) p / E*)`` the area fraction seen at
magnification q, and ``γ ≈ 0.4`` (Yang & Persson's value; the fraction of the
non-contact elastic energy that the theory keeps). Substituting ``x = w p'/E*`` turns the
inner integral into a universal function ``F(x0) = ∫_{x0}^∞ (dx/x)[γ + 3(1-γ)erf²x]e^{-x²}``.

Stiffness per unit nominal area ``K = -dp/dū``: differentiating under the integral,

    K = p / (√π ∫ dq q² C_P w [γ + 3(1-γ) P²] exp(-(w p/E*)²)).

``C_P`` is Persson's PSD, ``C_P = C / (2π)²`` with C the convention of
:mod:`surfmet.psd` (Jacobs et al. 2017). All values SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.integrate import quad
from scipy.special import erf

from contact._errors import ContactInputError
from contact._validate import positive

#: Yang & Persson (2008) correction factor for the elastic energy of the non-contact area.
GAMMA = 0.4

#: Low-pressure slope of Persson's area: A/A0 -> κ p/(E* h'_rms).
KAPPA_PERSSON = math.sqrt(8.0 / math.pi)


@dataclass(frozen=True, eq=False)
class ModelCurve:
    """A rough-contact model evaluated at nominal pressures (SI).

    Attributes
    ----------
    model : str
    pressure : ndarray
        Nominal pressures p, Pa.
    area_fraction : ndarray
        A/A0.
    mean_gap : ndarray or None
        Mean gap ū between the flat and the surface's mean plane, m (None: the model
        gives none).
    stiffness : ndarray or None
        Normal contact stiffness per unit nominal area ``-dp/dū``, Pa/m.
    """

    model: str
    pressure: np.ndarray
    area_fraction: np.ndarray
    mean_gap: np.ndarray | None
    stiffness: np.ndarray | None


def kappa(area_fraction: np.ndarray, pressure: np.ndarray, e_star: float,
          slope_rms: float) -> np.ndarray:
    """The area-load proportionality ``κ = (A/A0) E* h'_rms / p``."""
    return np.asarray(area_fraction) * e_star * slope_rms / np.asarray(pressure)


def check_pressures(pressure: np.ndarray | float) -> np.ndarray:
    """Pressures as a 1D float array, all finite and positive."""
    p = np.atleast_1d(np.asarray(pressure, dtype=float))
    if p.ndim != 1 or p.size == 0 or not np.all(np.isfinite(p)) or np.any(p <= 0):
        raise ContactInputError("nominal pressures must be finite and positive")
    return p


def area_fraction(pressure: np.ndarray | float, e_star: float, slope_rms: float) -> np.ndarray:
    """Persson's ``A/A0 = erf(√2 p / (E* h'_rms))``."""
    p = check_pressures(pressure)
    positive(e_star, "e_star", "Pa")
    positive(slope_rms, "slope_rms")
    return erf(math.sqrt(2.0) * p / (e_star * slope_rms))


@lru_cache(maxsize=8)
def _inner_table(gamma: float) -> tuple[np.ndarray, np.ndarray]:
    """``F(x0)`` on a log grid of x0 (quad, once per γ)."""
    xs = np.geomspace(1e-8, 6.0, 1500)

    def f(x: float) -> float:
        return (gamma + 3.0 * (1.0 - gamma) * erf(x) ** 2) * math.exp(-x * x) / x

    vals = np.empty_like(xs)
    # integrate from the top down, piece by piece, so each quad sees a smooth interval
    acc = quad(f, xs[-1], np.inf)[0]
    vals[-1] = acc
    for k in range(xs.size - 2, -1, -1):
        acc += quad(f, xs[k], xs[k + 1])[0]
        vals[k] = acc
    return xs, vals


def _inner(x0: np.ndarray, gamma: float) -> np.ndarray:
    xs, vals = _inner_table(gamma)
    x0 = np.asarray(x0, dtype=float)
    out = np.interp(np.log(np.clip(x0, xs[0], xs[-1])), np.log(xs), vals)
    # below the table F ≈ F(x_min) + γ ln(x_min/x0) (the integrand is γ/x there)
    low = x0 < xs[0]
    out[low] = vals[0] + gamma * np.log(xs[0] / x0[low])
    out[x0 > xs[-1]] = 0.0
    return out


def persson(pressure: np.ndarray | float, e_star: float, q: np.ndarray, C: np.ndarray,
            weights: np.ndarray, dq: float, *, gamma: float = GAMMA) -> ModelCurve:
    """Persson's area, Yang-Persson mean gap and stiffness from an isotropic PSD.

    Parameters
    ----------
    pressure : array_like
        Nominal pressures, Pa.
    e_star : float
        Composite modulus, Pa.
    q, C, weights, dq :
        Radial PSD ``C^iso`` (m⁴, Jacobs et al. convention) with its DFT-cell weights and
        bin width, as in :class:`surfmet.psd.PSD` (so that ``Σ C w dq²/(2π)² = h_rms²``).
    gamma : float
        Yang & Persson's γ.
    """
    p = check_pressures(pressure)
    positive(e_star, "e_star", "Pa")
    positive(dq, "dq", "1/m")
    q = np.asarray(q, float)
    base = np.asarray(C, float) * np.asarray(weights, float) * dq**2 / (2.0 * math.pi) ** 2
    if q.shape != base.shape or q.ndim != 1 or not np.all(base >= 0):
        raise ContactInputError("q, C and weights must be 1D arrays of one length, C ≥ 0")
    if not np.any(base > 0):
        raise ContactInputError("the spectrum carries no power: a flat surface has no "
                                "roughness to press")
    order = np.argsort(q)
    q, base = q[order], base[order]
    slope2 = np.cumsum(q**2 * base)  # h'_rms² of the wavevectors up to q
    ok = slope2 > 0
    q, base, slope2 = q[ok], base[ok], slope2[ok]
    w = np.sqrt(2.0 / slope2)
    # √π ∫ dq q² C_P w (...)  with  ∫ dq q^k C_P = (1/2π) Σ q^(k-1) base
    pref = math.sqrt(math.pi) / (2.0 * math.pi) * q * base * w
    slope_rms = math.sqrt(float(slope2[-1]))
    area = erf(math.sqrt(2.0) * p / (e_star * slope_rms))
    gap = np.empty_like(p)
    stiff = np.empty_like(p)
    for k, pk in enumerate(p):
        x0 = w * pk / e_star
        gap[k] = float(np.sum(pref * _inner(x0, gamma)))
        dens = float(np.sum(pref * (gamma + 3.0 * (1.0 - gamma) * erf(x0) ** 2)
                            * np.exp(-x0**2)))
        stiff[k] = pk / dens if dens > 0 else math.inf
    return ModelCurve("persson", p, area, gap, stiff)
