"""Adhesive contact of an elastic sphere on a flat, through an approach-retraction cycle.

The sphere is the paraboloid h = r^2 / (2 R) in the middle of a periodic square cell
(:mod:`contact.adhesion.solver`); the cell is made wide enough that the images of the
sphere neither touch nor reach the interaction zone of the middle one. The result states
the Maugis and Tabor parameters and warns when the grid cannot resolve the interaction.

Resolution criterion: the cohesive (process) zone at the edge of an adhesive contact is
about l_pz = pi E* w / (4 sigma0^2) wide in the JKR limit (the small-zone limit of
Maugis' 1992 equations; sigma0 the law's peak tension). On a coarser grid the contact
edge is pinned by the pixels and the pull-off comes out too large. Measured against
Maugis' curve (benchmarks/adhesion_maugis.py: cell 4 x the larger of the JKR radius and
the zone reach, 24 retraction steps, step halving of :mod:`contact.adhesion.cycle`):
lambda = 1 gives +11.8 % and +5.3 % at l_pz = 6.6 and 13 pixels (64^2, 128^2), an error
that halves with the pixel; lambda = 5 gives +81 % at 0.53 pixel (128^2). Below
:data:`contact._zone_resolution.MIN_ZONE_PIXELS_PLAIN` a warning is issued. The contact
itself must span several pixels too: the JKR radius at zero load should be eight pixels
or more. These figures are the plain Dugdale step's; the step smoothed on the grid's scale
(:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`) removes most of the pinning (lambda = 1:
+1.4 % on 48^2 of a cell 6 x a0; lambda = 5: +1.3 % at 1.6 pixels); its threshold
:data:`contact._zone_resolution.MIN_ZONE_PIXELS` is measured on the command's own sphere, and
:func:`edge_radius` reads the contact radius sub-pixel.

Rough surfaces: a composite roughness z sampled onto the grid (positive outward from
either body, so that it closes the gap: h = r^2 / (2 R) - z, the convention of
:mod:`contact.setups._ball_on_plate`) is subtracted from the paraboloid and the gap shifted
so that the first touch is at approach 0. The approach then runs 3 z_rms further than for
the smooth sphere, so that the contact reaches about the same size through the asperities.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._geometry import DomainSpec, domain_spec
from contact._grid import Grid
from contact._material_pair import MaterialPair, modulus
from contact._validate import positive
from contact._zone_resolution import (  # noqa: F401 (the thresholds, re-exported)
    MIN_ZONE_PIXELS,
    MIN_ZONE_PIXELS_PLAIN,
    min_zone_pixels,
    process_zone,
    pull_off_excess,
)
from contact.adhesion.cycle import Cycle, approach_retraction
from contact.adhesion.laws import InteractionLaw, checked_law, tabor_parameter
from contact.adhesion.memory import check_adhesion_memory
from contact.adhesion.solver import adhesive_problem

#: A JKR contact radius at zero load of fewer pixels than this is under-resolved.
MIN_CONTACT_PIXELS = 8.0


class SpherePullOffs:
    """The closed-form pull-offs of a sphere of ``radius`` under ``law``, shared by the
    grid's and the rings' results."""

    radius: float
    law: InteractionLaw

    @property
    def jkr_pull_off(self) -> float:
        """3 pi w R / 2 (N), Johnson, Kendall & Roberts (1971)."""
        return 1.5 * math.pi * self.law.work * self.radius

    @property
    def dmt_pull_off(self) -> float:
        """2 pi w R (N), Derjaguin, Muller & Toporov (1975)."""
        return 2.0 * math.pi * self.law.work * self.radius


@dataclass(frozen=True)
class AdhesiveBall(SpherePullOffs):
    """An approach-retraction cycle of an adhesive sphere on a flat (SI units).

    Attributes
    ----------
    radius, e_star : float
        Sphere radius R (m) and composite modulus E* (Pa).
    law : InteractionLaw
        The adhesion law.
    grid : int
        Cells per side.
    size, dx : float
        Side of the periodic cell and pixel (m).
    cycle : Cycle
        The two legs, pull-off, jumps and hysteresis.
    maugis_parameter, tabor_parameter : float
        Maugis' lambda (:meth:`DugdaleLaw.maugis`) and Tabor's mu with the law's range.
    process_zone : float
        The cohesive zone width l_pz = pi E* w / (4 sigma0^2) (m).
    warnings : tuple of str
        Resolution and separation warnings (empty when none).
    roughness_rms : float
        Rms of the roughness sampled onto the grid (m); 0 for smooth surfaces.
    """

    radius: float
    e_star: float
    law: InteractionLaw
    grid: int
    size: float
    dx: float
    cycle: Cycle
    maugis_parameter: float
    tabor_parameter: float
    process_zone: float
    warnings: tuple[str, ...]
    roughness_rms: float = 0.0



def scales(radius: float, e_star: float, law: InteractionLaw) -> tuple[float, float, float]:
    """(JKR radius at zero load, reach of the interaction zone, JKR approach scale), m.

    a0 = (9 pi w R^2 / (2 E*))^(1/3) (Johnson 1985, eq. 5.60 at P = 0); the zone reaches
    sqrt(2 R h) with h the law's reach (:attr:`DugdaleLaw.reach`); the
    approach scale is (pi^2 w^2 R / K^2)^(1/3), K = 4 E* / 3 (Maugis 1992).
    """
    w = law.work
    a0 = (4.5 * math.pi * w * radius * radius / e_star) ** (1.0 / 3.0)
    k = 4.0 * e_star / 3.0
    return (a0, math.sqrt(2.0 * radius * law.reach),
            (math.pi ** 2 * w * w * radius / k ** 2) ** (1.0 / 3.0))


def adhesive_ball(radius: float, e_star: float | MaterialPair, law: InteractionLaw, *,
                  domain: DomainSpec | None = None, steps: int = 40, tol: float = 1e-6,
                  roughness: np.ndarray | None = None,
                  progress: Callable[[int, int], None] | None = None) -> AdhesiveBall:
    """Approach a sphere to a flat until its contact is about the JKR size, then retract.

    Parameters
    ----------
    radius, e_star : float
        Sphere radius (m) and composite modulus (Pa),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    law : InteractionLaw
        A registered law (:mod:`contact.adhesion.laws`: e.g.
        :class:`~contact.adhesion.laws.DugdaleLaw`).
    domain : DomainSpec, optional
        Its ``grid``, cells per side (default 128), and ``size``, the side of the periodic
        cell (m; default 4 times the larger of the JKR radius at zero load and the reach
        of the interaction zone); the cell is periodic whatever the spec's other fields.
    steps : int
        Approach steps on each leg.
    tol : float
        Equilibrium tolerance of each solve, relative to the law's peak tension.
    roughness : ndarray, shape (grid, grid), optional
        Composite roughness z (m) on the solver's cells, positive where it closes the gap
        (see the module notes); default smooth surfaces.
    progress : callable, optional
        Called as ``progress(step, total)``.
    """
    positive(radius, "the radius", "m")
    spec = domain_spec(domain)
    grid = 128 if spec.grid is None else spec.grid
    size = spec.size
    e_star = modulus(e_star)
    positive(e_star, "E*", "Pa")
    checked_law(law)  # an unknown law is refused, never solved as another
    if int(grid) != grid or grid < 16:
        raise ContactInputError(f"the grid must be an integer of at least 16, got {grid!r}")
    if int(steps) != steps or steps < 4:
        raise ContactInputError(f"the steps must be an integer of at least 4, got {steps!r}")
    check_adhesion_memory(int(grid), steps=int(steps))  # before any grid is allocated
    a0, reach, d_scale = scales(radius, e_star, law)
    ell = max(a0, reach)
    size = default_size(radius, e_star, law) if size is None else \
        positive(size, "the domain size", "m")
    dx = size / grid
    x = (np.arange(grid) - grid / 2) * dx
    h = (x[:, None] ** 2 + x[None, :] ** 2) / (2.0 * radius)
    h, z_rms = rough_gap(h, roughness, f"a finite {grid} x {grid} array")
    problem = adhesive_problem(Grid(x=x, y=x, h=h, periodic=True, pitch=(dx, dx)),
                               e_star=e_star, law=law)
    deepest = ell * ell / radius + 3.0 * z_rms
    farthest = -(1.5 * d_scale + 1.2 * (reach * reach / (2.0 * radius)))
    cycle = approach_retraction(problem, np.linspace(farthest, deepest, int(steps)), tol=tol,
                                progress=progress)
    zone = process_zone(e_star, law.work, law.peak)
    return AdhesiveBall(
        radius=float(radius), e_star=float(e_star), law=law, grid=int(grid),
        size=float(size), dx=dx,
        cycle=cycle, maugis_parameter=law.maugis(radius, e_star),
        tabor_parameter=tabor_parameter(law.work, radius, e_star, law.range),
        process_zone=zone,
        warnings=_warnings(zone, a0, reach, dx, size, cycle,
                           law.smoothing > 0.0),
        roughness_rms=z_rms,
    )


def default_size(radius: float, e_star: float, law: InteractionLaw) -> float:
    """The default periodic cell (m): 4 times the larger of the JKR radius at zero load and
    the reach of the interaction zone (:func:`scales`)."""
    a0, reach, _ = scales(radius, e_star, law)
    return 4.0 * max(a0, reach)


def _warnings(zone: float, a0: float, reach: float, dx: float, size: float,
              cycle: Cycle, smoothed: bool = False) -> tuple[str, ...]:
    """The resolution and separation warnings of a cycle (see the module notes)."""
    out = []
    least = min_zone_pixels(smoothed)
    if zone < least * dx:
        out.append(
            f"grid too coarse for the interaction: the cohesive zone (pi E* w / (4 sigma0^2) "
            f"= {zone:.3g} m) spans {zone / dx:.2g} pixels, fewer than {least:g}; "
            f"{coarse_zone_effect(cycle, zone / dx if smoothed else None)}: raise the "
            "grid or shrink the domain")
    if a0 < MIN_CONTACT_PIXELS * dx:
        out.append(
            f"grid too coarse for the contact: the JKR radius at zero load ({a0:.3g} m) spans "
            f"{a0 / dx:.2g} pixels, fewer than {MIN_CONTACT_PIXELS:g}")
    if 2.0 * max(a0, reach) > 0.75 * size:
        out.append(f"the domain ({size:.3g} m) is small for the contact and its interaction "
                   f"zone (radius {max(a0, reach):.3g} m): the images of the periodic cell "
                   f"interact; enlarge it")
    if cycle.retraction_leg.contact_area[-1] > 0.0:
        out.append("the retraction ended with the surfaces still touching: the pull-off may "
                   "lie beyond the last step")
    return tuple(out)


def coarse_zone_effect(cycle: Cycle, zone_pixels: float | None = None) -> str:
    """What an unresolved cohesive zone does to this cycle's answer, in words: the
    pull-off comes out too large (the pixels pin the contact edge, see the module notes),
    by the measured excess at ``zone_pixels`` where given (smoothed Dugdale step:
    :func:`contact._zone_resolution.pull_off_excess`), or, where the retraction never
    pulled, there is no pull-off to overestimate and the adhesive tractions are what is
    not resolved."""
    if cycle.pull_off_force > 0.0:
        excess = None if zone_pixels is None else pull_off_excess(zone_pixels)
        if excess is not None:
            return (f"the pull-off is overestimated, by about +{excess:.2g} % at this "
                    "resolution (measured convergence, docs/adhesion.md)")
        return "the pull-off is overestimated"
    return "the adhesive tractions are not resolved (no pull-off was found at this grid)"


def rough_gap(h: np.ndarray, roughness: np.ndarray | None, shape_words: str
              ) -> tuple[np.ndarray, float]:
    """The smooth gap ``h`` less the composite ``roughness`` (same shape), moved to touch
    at zero, and the roughness's rms (m); ``h`` and 0 without roughness.

    Raises
    ------
    ContactInputError
        A roughness of another shape, or not finite (``shape_words`` says what was expected).
    """
    if roughness is None:
        return h, 0.0
    z = np.asarray(roughness, dtype=float)
    if z.shape != h.shape or not np.isfinite(z).all():
        raise ContactInputError(f"the roughness must be {shape_words}, got shape {z.shape}")
    h = h - z
    return h - h.min(), float(np.std(z))


def edge_radius(gap: np.ndarray, dx: float, band: float) -> float:
    """The radius of a sphere's touching zone read to a fraction of a pixel (m).

    Maugis' contact radius a is where the gap closes. The pressure there is finite (the
    cohesive tension), so the gap opens as (r - a)^(3/2), as at the edge of a Hertz
    contact, and g^(2/3) is linear in r near a. It is fitted by least squares over the
    open cells with gaps below ``band`` (m) within three pixels of the touching cells'
    disc radius, r measured from the sphere's axis at cell (ny // 2, nx // 2) as built
    by :func:`adhesive_ball`; the fit's zero is a. Counting the touching cells reads a
    only to about a pixel, which on the steep compressive part of a load-radius curve is
    a large error in the load. With fewer than eight cells in the band (or no contact)
    the disc radius of the touching cells is returned.
    """
    g = np.asarray(gap, dtype=float)
    ny, nx = g.shape
    y = (np.arange(ny) - ny // 2) * dx
    x = (np.arange(nx) - nx // 2) * dx
    r = np.hypot(y[:, None], x[None, :])
    disc = math.sqrt(float((g <= 0.0).sum()) * dx * dx / math.pi)
    near = (g > 0.0) & (g < band) & (r < disc + 3.0 * dx)
    if disc == 0.0 or near.sum() < 8:
        return disc
    slope, offset = np.polyfit(r[near], g[near] ** (2.0 / 3.0), 1)
    return float(-offset / slope)
