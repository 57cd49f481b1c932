"""Adhesion laws: the attractive traction between two surfaces at a local gap g.

Both laws are written as an interaction energy per unit area phi(g), with phi(0) = -w
(w the work of adhesion) and phi -> 0 far away; the attractive traction is
t(g) = phi'(g) >= 0 (a tension of magnitude t pulls the surfaces together).

- :class:`DugdaleLaw`: a constant tension sigma0 up to the range h0 = w / sigma0, none
  beyond (Maugis 1992, J. Colloid Interface Sci. 150:243).
- :class:`ExponentialLaw`: t(g) = (w / rho) exp(-g / rho), phi(g) = -w exp(-g / rho)
  (the exponential potential used for rough adhesive contact, e.g. Rey, Anciaux &
  Molinari 2017, Comput. Mech. 60:69).

Each law states its Maugis parameter for a sphere of radius R; the exponential law
uses the Dugdale law of the same work and peak tension (sigma0 = w / rho), the usual
matching of the two (Johnson & Greenwood 1997, J. Colloid Interface Sci. 192:326).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._validate import positive


def maugis_parameter(sigma0: float, work: float, radius: float, e_star: float) -> float:
    """Maugis' lambda = 2 sigma0 (R / (pi w K^2))^(1/3), K = 4 E* / 3 (Maugis 1992, eq. 6)."""
    k = 4.0 * e_star / 3.0
    return 2.0 * sigma0 * (radius / (math.pi * work * k * k)) ** (1.0 / 3.0)


def tabor_parameter(work: float, radius: float, e_star: float, length: float) -> float:
    """Tabor's mu = (R w^2 / (E*^2 z^3))^(1/3) with the interaction length z (Tabor 1977)."""
    return (radius * work * work / (e_star * e_star * length ** 3)) ** (1.0 / 3.0)


@dataclass(frozen=True)
class DugdaleLaw:
    """Dugdale (Maugis) cohesive zone: tension ``sigma0`` (Pa) for gaps below ``w / sigma0``.

    Attributes
    ----------
    work : float
        Work of adhesion w (J/m^2).
    sigma0 : float
        Cohesive tension (Pa).
    """

    work: float
    sigma0: float

    def __post_init__(self) -> None:
        positive(self.work, "the work of adhesion", "J/m^2")
        positive(self.sigma0, "the cohesive tension", "Pa")

    @classmethod
    def from_range(cls, work: float, range_: float) -> DugdaleLaw:
        """The law of work ``work`` and range h0 = ``range_`` (m): sigma0 = w / h0."""
        positive(range_, "the interaction range", "m")
        return cls(float(work), float(work) / float(range_))

    @property
    def range(self) -> float:
        """h0 = w / sigma0 (m), the gap at which the tension stops."""
        return self.work / self.sigma0

    @property
    def peak(self) -> float:
        """The largest tension (Pa)."""
        return self.sigma0

    @property
    def reach(self) -> float:
        """The gap beyond which the surfaces no longer attract (m): h0."""
        return self.range

    def potential(self, g: np.ndarray | float) -> np.ndarray:
        """phi(g) = -sigma0 (h0 - g)_+ (J/m^2)."""
        return -self.sigma0 * np.maximum(self.range - np.asarray(g, dtype=float), 0.0)

    def traction(self, g: np.ndarray | float) -> np.ndarray:
        """t(g) = sigma0 for g < h0, else 0 (Pa, attractive)."""
        return np.where(np.asarray(g, dtype=float) < self.range, self.sigma0, 0.0)

    def maugis(self, radius: float, e_star: float) -> float:
        """Maugis' lambda of a sphere of radius ``radius`` (m) with modulus ``e_star``."""
        return maugis_parameter(self.sigma0, self.work, radius, e_star)


@dataclass(frozen=True)
class ExponentialLaw:
    """Exponential interaction: t(g) = (w / rho) exp(-g / rho).

    Attributes
    ----------
    work : float
        Work of adhesion w (J/m^2).
    rho : float
        Range rho (m).
    """

    work: float
    rho: float

    def __post_init__(self) -> None:
        positive(self.work, "the work of adhesion", "J/m^2")
        positive(self.rho, "the interaction range", "m")

    @property
    def range(self) -> float:
        """rho (m)."""
        return self.rho

    @property
    def peak(self) -> float:
        """The largest tension w / rho (Pa), at contact."""
        return self.work / self.rho

    @property
    def reach(self) -> float:
        """The gap at which the tension has fallen to 5 % of its peak (m): rho ln 20."""
        return self.rho * math.log(20.0)

    def potential(self, g: np.ndarray | float) -> np.ndarray:
        """phi(g) = -w exp(-g / rho) (J/m^2)."""
        return -self.work * np.exp(-np.asarray(g, dtype=float) / self.rho)

    def traction(self, g: np.ndarray | float) -> np.ndarray:
        """t(g) = (w / rho) exp(-g / rho) (Pa, attractive)."""
        return self.peak * np.exp(-np.asarray(g, dtype=float) / self.rho)

    def maugis(self, radius: float, e_star: float) -> float:
        """Maugis' lambda of the Dugdale law of the same work and peak tension."""
        return maugis_parameter(self.peak, self.work, radius, e_star)


InteractionLaw = DugdaleLaw | ExponentialLaw
