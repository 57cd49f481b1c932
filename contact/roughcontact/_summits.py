"""Spectral moments and the Greenwood-Williamson summit parameters they imply.

For an isotropic Gaussian surface with areal PSD ``C^iso(q)`` (m⁴, the convention of
Jacobs, Junge & Pastewka 2017: ``h_rms² = (1/2π) ∫ q C^iso dq``), the moments of any
straight profile through it are (Nayak 1971, Eq. 2; Longuet-Higgins 1957)

    m0 = h_rms²,   m2 = <h_x²> = ½ <|∇h|²>,   m4 = <h_xx²> = ⅜ <(∇²h)²>,

with ``<|∇h|^2> = (1/2π) ∫ q³ C dq`` and ``<(∇²h)²> = (1/2π) ∫ q⁵ C dq``. From them:

- Nayak's bandwidth parameter ``α = m0 m4 / m2²`` (≥ 1.5 for a Gaussian surface);
- the summit density ``η = m4 / (6π√3 m2)`` (Nayak 1971, Eq. 62);
- the mean summit radius of curvature ``R_s = (3/8) √(π/m4)`` (McCool 1986, Eq. 11);
- the summit-height standard deviation ``σ_s = √(1 − 0.8968/α) √m0`` and the mean
  summit height above the mean plane ``y_s = 4 √m0 / √(πα)`` (McCool 1986, Eqs. 9-10).

All these depend on the highest wavevector kept, so on the scan's lateral resolution
(m2 and m4 grow without bound for a self-affine surface as the pixel shrinks).

References
----------
Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol. 93, 398.
McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37.
Greenwood, J. A. & Williamson, J. B. P. (1966). Contact of nominally flat surfaces.
Proc. R. Soc. A 295, 300.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import trapezoid

from contact._errors import ContactInputError
from contact._validate import positive

#: McCool's (1986) constant in σ_s² = (1 − 0.8968/α) m0.
_MCCOOL = 0.8968


@dataclass(frozen=True)
class SummitParameters:
    """Profile spectral moments and the summit statistics derived from them (SI).

    Attributes
    ----------
    m0, m2, m4 : float
        Profile moments: m², (dimensionless), 1/m².
    alpha : float
        Nayak bandwidth parameter ``m0 m4 / m2²``.
    density : float
        Summit density η, 1/m².
    radius : float
        Mean summit radius of curvature R_s, m.
    sigma_s : float
        Standard deviation of summit heights, m.
    mean_height : float
        Mean summit height above the mean plane y_s, m.
    """

    m0: float
    m2: float
    m4: float
    alpha: float
    density: float
    radius: float
    sigma_s: float
    mean_height: float

    @property
    def h_rms(self) -> float:
        """rms height ``√m0``, m."""
        return math.sqrt(self.m0)

    @property
    def slope_rms(self) -> float:
        """Areal rms slope ``h'_rms = √(2 m2)``."""
        return math.sqrt(2.0 * self.m2)

    @property
    def curvature_rms(self) -> float:
        """Areal rms Laplacian ``√<(∇²h)²> = √(8 m4 / 3)``, 1/m."""
        return math.sqrt(8.0 * self.m4 / 3.0)

    @property
    def gw_product(self) -> float:
        """The Greenwood-Williamson roughness product ``η R_s σ_s`` (dimensionless)."""
        return self.density * self.radius * self.sigma_s


def summit_parameters(m0: float, m2: float, m4: float) -> SummitParameters:
    """Summit statistics from the profile moments (Nayak 1971; McCool 1986).

    Raises
    ------
    ContactInputError
        A non-positive or non-finite moment, or ``α < 1.5`` (no Gaussian surface has it:
        the moments are inconsistent, e.g. taken from different bands).
    """
    if m0 == 0 and m2 == 0 and m4 == 0:
        raise ContactInputError("all spectral moments are 0: a flat surface has no summits")
    for name, v in (("m0", m0), ("m2", m2), ("m4", m4)):
        positive(v, f"spectral moment {name}")
    alpha = m0 * m4 / m2**2
    if alpha < 1.5 * (1.0 - 1e-9):
        raise ContactInputError(
            f"Nayak's bandwidth parameter m0·m4/m2² = {alpha:.4g} is below 1.5, which no "
            "Gaussian surface has: take m0, m2 and m4 from the same band of the spectrum"
        )
    density = m4 / (6.0 * math.pi * math.sqrt(3.0) * m2)
    radius = 0.375 * math.sqrt(math.pi / m4)
    sigma_s = math.sqrt(max(0.0, 1.0 - _MCCOOL / alpha) * m0)
    mean_height = 4.0 * math.sqrt(m0) / math.sqrt(math.pi * alpha)
    return SummitParameters(m0=float(m0), m2=float(m2), m4=float(m4), alpha=float(alpha),
                            density=density, radius=radius, sigma_s=sigma_s,
                            mean_height=mean_height)


def isotropic_moments(q: np.ndarray, C: np.ndarray, weights: np.ndarray | None = None,
                      dq: float | None = None) -> tuple[float, float, float]:
    """Profile moments (m0, m2, m4) of an isotropic surface from its radial PSD.

    Parameters
    ----------
    q : ndarray
        Radial wavevectors, rad/m (increasing, positive).
    C : ndarray
        Isotropic PSD ``C^iso(q)``, m⁴.
    weights, dq : optional
        Discrete quadrature: ``Σ f(q) C w dq² / (2π)²`` reproduces the 2D Parseval sum when
        ``w`` counts the DFT cells in each radial bin (``surfmet.psd.PSD`` carries both).
        Without them the trapezoid rule on ``(1/2π) ∫ q f(q) C dq`` is used.
    """
    q = np.asarray(q, dtype=float)
    C = np.asarray(C, dtype=float)
    if q.shape != C.shape or q.ndim != 1 or q.size < 2:
        raise ContactInputError("q and C must be 1D arrays of the same length (≥ 2)")
    if weights is not None and dq is not None:
        base = C * np.asarray(weights, dtype=float) * dq**2 / (2.0 * math.pi) ** 2
        m0 = float(np.sum(base))
        m2 = 0.5 * float(np.sum(base * q**2))
        m4 = 0.375 * float(np.sum(base * q**4))
    else:
        def integ(f: np.ndarray) -> float:
            return float(trapezoid(q * f * C, q) / (2.0 * math.pi))

        m0 = integ(np.ones_like(q))
        m2 = 0.5 * integ(q**2)
        m4 = 0.375 * integ(q**4)
    return m0, m2, m4


def plasticity_index(e_star: float, hardness: float, summits: SummitParameters) -> float:
    """Greenwood-Williamson plasticity index ``ψ = (E*/H) √(σ_s / R_s)``.

    ψ < 0.6: asperities deform elastically at any practical load; ψ > 1: most yield
    (Greenwood & Williamson 1966).
    """
    positive(e_star, "E*", "Pa")
    positive(hardness, "the hardness", "Pa")
    return float(e_star / hardness * math.sqrt(summits.sigma_s / summits.radius))
