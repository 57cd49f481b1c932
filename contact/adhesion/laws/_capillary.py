"""The capillary law: a liquid meniscus of constant Laplace pressure bridging the gap.

A meniscus condensed (or wetting) between two surfaces fills the gap where it is thinner
than h_c = 2 r_K cos(theta) and pulls them together with its Laplace pressure
dp = gamma / r_K (Kelvin radius r_K, surface tension gamma, contact angle theta; the
meniscus' other principal radius, of the order of the contact's, is taken as infinite,
r_K << R). As an interaction law this is a Dugdale step of tension dp and range h_c, so
its work of adhesion is w = dp h_c = 2 gamma cos(theta), and the rigid sphere's pull-off
is F = 2 pi R w = 4 pi R gamma cos(theta), independent of r_K (Israelachvili,
*Intermolecular and Surface Forces*, 3rd ed. 2011, section 17.9; Orowan 1970); between the
rigid and the soft sphere, Maugis-Dugdale with w = 2 gamma cos(theta) and sigma0 = dp
(Maugis 1992; Maugis & Gauthier-Manuel 1994, J. Adhesion Sci. Technol. 8:1311). On a grid
the step is smoothed as the Dugdale law's (:meth:`CapillaryLaw.on_grid`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from contact._errors import ContactInputError
from contact._validate import positive
from contact.adhesion.laws._base import InteractionLaw, LawParameter
from contact.adhesion.laws._dugdale import DugdaleLaw
from contact.adhesion.laws._registry import register_law


@register_law
@dataclass(frozen=True)
class CapillaryLaw(InteractionLaw):
    """Capillary meniscus: tension gamma / r_K (Pa) for gaps below 2 r_K cos(theta).

    Attributes
    ----------
    surface_tension : float
        The liquid's surface tension gamma (N/m).
    contact_angle : float
        Its contact angle theta on the surfaces (rad), 0 <= theta < pi / 2.
    kelvin_radius : float
        The meniscus' Kelvin radius r_K (m).
    smoothing : float
        Width of the ramp replacing the step at h_c (m, as
        :class:`~contact.adhesion.laws.DugdaleLaw`'s); 0 (default) keeps the step.
    """

    name: ClassVar[str] = "capillary"
    summary: ClassVar[str] = ("a liquid meniscus, Laplace pressure gamma/r_K where the gap "
                              "is below 2 r_K cos(theta) (w = 2 gamma cos(theta))")
    parameters: ClassVar[tuple[LawParameter, ...]] = (
        LawParameter("surface_tension", "N/m", "the meniscus' surface tension gamma, e.g. "
                     "72mN/m"),
        LawParameter("contact_angle", "rad", "the liquid's contact angle theta, below 90 "
                     "degrees, e.g. 30deg"),
        LawParameter("kelvin_radius", "m", "the meniscus' Kelvin radius r_K, e.g. 0.5nm"),
    )
    grid_smoothed: ClassVar[bool] = True

    surface_tension: float
    contact_angle: float
    kelvin_radius: float
    smoothing: float = 0.0

    def __post_init__(self) -> None:
        positive(self.surface_tension, "the surface tension", "N/m")
        positive(self.kelvin_radius, "the Kelvin radius", "m")
        theta = float(self.contact_angle)
        if not (math.isfinite(theta) and 0.0 <= theta < 0.5 * math.pi):
            raise ContactInputError(
                f"the contact angle must be at least 0 and below 90 degrees (a meniscus "
                f"that does not wet does not pull), got {self.contact_angle!r} rad")
        _ = self.step  # the step's own checks (the smoothing within the range)

    @property
    def step(self) -> DugdaleLaw:
        """The Dugdale step of the same tension, range and smoothing."""
        return DugdaleLaw(self.work, self.peak, self.smoothing)

    @property
    def work(self) -> float:
        """w = 2 gamma cos(theta) (J/m^2)."""
        return 2.0 * self.surface_tension * math.cos(self.contact_angle)

    @property
    def peak(self) -> float:
        """The Laplace pressure gamma / r_K (Pa)."""
        return self.surface_tension / self.kelvin_radius

    @property
    def range(self) -> float:
        """h_c = w / (gamma / r_K) = 2 r_K cos(theta) (m)."""
        return self.work / self.peak

    @property
    def reach(self) -> float:
        """h_c + smoothing / 2 (m)."""
        return self.step.reach

    def potential(self, g: np.ndarray | float) -> np.ndarray:
        """phi(g) = -(gamma / r_K) (h_c - g)_+ (J/m^2), the step's."""
        return self.step.potential(g)

    def traction(self, g: np.ndarray | float) -> np.ndarray:
        """t(g) = gamma / r_K for g < h_c, else 0 (Pa, attractive), the step's."""
        return self.step.traction(g)

    def kernel_args(self, single: bool = False) -> tuple[int, float, float]:
        """The kernels' Dugdale step (or ramp) of tension gamma / r_K."""
        return self.step.kernel_args(single)

    def on_grid(self, dx: float, e_star: float) -> CapillaryLaw:
        """This law with its step smoothed as :meth:`DugdaleLaw.on_grid` smooths it."""
        return replace(self, smoothing=self.step.on_grid(dx, e_star).smoothing)

    def rigid_line_pull_off(self, radius: float) -> float:
        """2 sqrt(2 R w gamma / r_K) (N/m), the step's."""
        return self.step.rigid_line_pull_off(radius)
