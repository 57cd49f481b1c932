"""The exponential law: t(g) = (w / rho) exp(-g / rho), phi(g) = -w exp(-g / rho) (the
exponential potential used for rough adhesive contact, e.g. Rey, Anciaux & Molinari 2017,
Comput. Mech. 60:69).

Its Maugis parameter is that of the Dugdale law of the same work and peak tension
(sigma0 = w / rho), the usual matching of the two (Johnson & Greenwood 1997, J. Colloid
Interface Sci. 192:326).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from contact._validate import positive
from contact.adhesion.laws._base import InteractionLaw
from contact.adhesion.laws._registry import register_law


@register_law
@dataclass(frozen=True)
class ExponentialLaw(InteractionLaw):
    """Exponential interaction: t(g) = (w / rho) exp(-g / rho).

    Attributes
    ----------
    work : float
        Work of adhesion w (J/m^2).
    rho : float
        Range rho (m).
    """

    name: ClassVar[str] = "exponential"
    summary: ClassVar[str] = "the smooth t(g) = (w/rho) exp(-g/rho), rho = --range"

    work: float
    rho: float

    def __post_init__(self) -> None:
        positive(self.work, "the work of adhesion", "J/m^2")
        positive(self.rho, "the interaction range", "m")

    @classmethod
    def from_parameters(cls, **values: float) -> ExponentialLaw:
        """The law of work ``work_of_adhesion`` (J/m^2) and range rho = ``range_`` (m)."""
        return cls(values["work_of_adhesion"], values["range_"])

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

    def kernel_args(self, single: bool = False) -> tuple[int, float, float]:
        """EXPONENTIAL (EXPONENTIAL_SINGLE in float32 solves) with the reach rho."""
        from contact.adhesion import kernels

        return (kernels.EXPONENTIAL_SINGLE if single else kernels.EXPONENTIAL), self.rho, 0.0

    def rigid_line_pull_off(self, radius: float) -> float:
        """w sqrt(2 pi R / rho) (N/m): the Gaussian integral of t(x^2 / (2 R))."""
        return self.work * math.sqrt(2.0 * math.pi * radius / self.rho)
