"""The Dugdale (Maugis) law: a constant tension sigma0 up to the range h0 = w / sigma0, none
beyond (Maugis 1992, J. Colloid Interface Sci. 150:243); optionally with the step at h0
smoothed over a gap width on the grid's scale (:meth:`DugdaleLaw.on_grid`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from contact._errors import ContactInputError
from contact._validate import positive
from contact.adhesion.laws._base import InteractionLaw, maugis_parameter
from contact.adhesion.laws._registry import register_law

#: Smoothing width of the Dugdale step over sigma0 dx / E*, for :meth:`DugdaleLaw.on_grid`.
#: Measured at lambda = 1 (benchmarks/adhesion_maugis.py): 2 and 3 leave part of the
#: trapping (pull-off +1.4 % and +1.1 % on 192^2, cell 4), 5 gives +0.7 % on 144^2
#: (cell 6) and 8 about the same; the plain step +15.8 % on 48^2.
EDGE_SMOOTHING = 5.0


@register_law
@dataclass(frozen=True)
class DugdaleLaw(InteractionLaw):
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

    name: ClassVar[str] = "dugdale"
    summary: ClassVar[str] = ("tension w/h0 up to the gap h0 = --range, none beyond (Maugis "
                              "1992): the law with a closed form to check it by, and the "
                              "one the coarse-grid warning is measured on")
    grid_smoothed: ClassVar[bool] = True

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
    def from_parameters(cls, **values: float) -> DugdaleLaw:
        """The law of work ``work_of_adhesion`` (J/m^2) and range h0 = ``range_`` (m)."""
        return cls.from_range(values["work_of_adhesion"], values["range_"])

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

    def kernel_args(self, single: bool = False) -> tuple[int, float, float]:
        """The step (code DUGDALE, reach h0) or, smoothed, the ramp ending at its reach
        h0 + s/2 (DUGDALE_RAMP, width s); the same in either precision."""
        from contact.adhesion import kernels

        if self.smoothing > 0.0:
            return kernels.DUGDALE_RAMP, self.reach, self.smoothing
        return kernels.DUGDALE, self.range, 0.0

    def rigid_line_pull_off(self, radius: float) -> float:
        """2 sqrt(2 R w sigma0) (N/m): the width 2 sqrt(2 R h0) under sigma0."""
        return 2.0 * math.sqrt(2.0 * radius * self.work * self.sigma0)
