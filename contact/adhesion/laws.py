"""Adhesion laws: the attractive traction between two surfaces at a local gap g.

Both laws are written as an interaction energy per unit area phi(g), with phi(0) = -w
(w the work of adhesion) and phi -> 0 far away; the attractive traction is
t(g) = phi'(g) >= 0 (a tension of magnitude t pulls the surfaces together).

- :class:`DugdaleLaw`: a constant tension sigma0 up to the range h0 = w / sigma0, none
  beyond (Maugis 1992, J. Colloid Interface Sci. 150:243); optionally with the step at h0
  smoothed over a gap width on the grid's scale (:meth:`DugdaleLaw.on_grid`).
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
from contact.errors import ContactInputError

#: Smoothing width of the Dugdale step over sigma0 dx / E*, for :meth:`DugdaleLaw.on_grid`.
#: Measured at lambda = 1 (benchmarks/adhesion_maugis.py): 2 and 3 leave part of the
#: trapping (pull-off +1.4 % and +1.1 % on 192^2, cell 4), 5 gives +0.7 % on 144^2
#: (cell 6) and 8 about the same; the plain step +15.8 % on 48^2.
EDGE_SMOOTHING = 5.0


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

    With ``smoothing`` s > 0 the step at h0 becomes a linear ramp from sigma0 at
    h0 - s / 2 to 0 at h0 + s / 2: the same work w and peak sigma0 (so the same Maugis
    parameter). On a grid the step pins the end of the cohesive zone to the pixels (a
    lattice trapping: a cell releases all of its tension at once, so the zone's end jumps
    from cell to cell and a retraction holds too much tension), an error first order in
    the pixel over the zone's width. A ramp as wide as the change of the gap across a
    cell at the zone's end, which is of order sigma0 dx / E*, spreads the release over
    about one cell, as a cell straddling h0 would have it if its tension were the share of
    its area inside the zone; :meth:`on_grid` sets it. The ramp changes the law by an
    antisymmetric traction of zero net work, so its own effect on the load is second order
    in its width.

    Attributes
    ----------
    work : float
        Work of adhesion w (J/m^2).
    sigma0 : float
        Cohesive tension (Pa).
    smoothing : float
        Width of the ramp replacing the step at h0 (m); 0 (default) keeps the step.
    """

    work: float
    sigma0: float
    smoothing: float = 0.0

    def __post_init__(self) -> None:
        positive(self.work, "the work of adhesion", "J/m^2")
        positive(self.sigma0, "the cohesive tension", "Pa")
        s = float(self.smoothing)
        if not (math.isfinite(s) and 0.0 <= s <= self.range):
            raise ContactInputError(
                f"the Dugdale smoothing must be between 0 and the range h0 = "
                f"{self.range:.3g} m, got {self.smoothing!r}")

    @classmethod
    def from_range(cls, work: float, range_: float) -> DugdaleLaw:
        """The law of work ``work`` and range h0 = ``range_`` (m): sigma0 = w / h0."""
        positive(range_, "the interaction range", "m")
        return cls(float(work), float(work) / float(range_))

    def on_grid(self, dx: float, e_star: float,
                factor: float = EDGE_SMOOTHING) -> DugdaleLaw:
        """This law with its step smoothed for a grid of pitch ``dx`` (m) and modulus
        ``e_star`` (Pa): width ``factor`` sigma0 dx / E*, at most h0 (see the class
        notes)."""
        width = factor * self.sigma0 * positive(dx, "the pitch", "m") / positive(
            e_star, "E*", "Pa")
        return DugdaleLaw(self.work, self.sigma0, min(width, self.range))

    @property
    def range(self) -> float:
        """h0 = w / sigma0 (m), the gap at which the tension stops (the ramp's middle)."""
        return self.work / self.sigma0

    @property
    def peak(self) -> float:
        """The largest tension (Pa)."""
        return self.sigma0

    @property
    def reach(self) -> float:
        """The gap beyond which the surfaces no longer attract (m): h0 + smoothing / 2."""
        if self.smoothing == 0.0:
            return self.range
        return self.range + 0.5 * self.smoothing

    def potential(self, g: np.ndarray | float) -> np.ndarray:
        """phi(g) = -sigma0 (h0 - g)_+ (J/m^2); with the ramp, -sigma0 (h0 + s/2 - g)^2 / (2 s)
        on it."""
        g = np.asarray(g, dtype=float)
        if self.smoothing == 0.0:
            return -self.sigma0 * np.maximum(self.range - g, 0.0)
        s, far = self.smoothing, self.range + 0.5 * self.smoothing
        ramp = -self.sigma0 * np.maximum(far - g, 0.0) ** 2 / (2.0 * s)
        return np.where(g <= far - s, -self.sigma0 * (self.range - g), ramp)

    def traction(self, g: np.ndarray | float) -> np.ndarray:
        """t(g) = sigma0 for g < h0, else 0 (Pa, attractive); with the ramp, sigma0 (h0 +
        s/2 - g) / s on it."""
        g = np.asarray(g, dtype=float)
        if self.smoothing == 0.0:
            return np.where(g < self.range, self.sigma0, 0.0)
        far = self.range + 0.5 * self.smoothing
        return self.sigma0 * np.clip((far - g) / self.smoothing, 0.0, 1.0)

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
