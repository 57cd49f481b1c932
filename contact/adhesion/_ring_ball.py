"""The smooth adhesive sphere on a flat, solved on rings (:mod:`contact.adhesion._rings`).

The ring width resolves the cohesive zone l_pz = pi E* w / (4 sigma0^2) with
:data:`ZONE_RINGS` rings and the contact's scale (the larger of the JKR radius at zero
load and the zone's reach sqrt(2 R h)) with :data:`CONTACT_RINGS`; the rings reach
1.2 times the radius where the rigid sphere at the deepest approach would still feel the
law (sqrt(2 R (delta_max + reach))): the elastic surface outside a pressed contact moves
away from the flat, so the zone ends inside it. The cycle is the 3D command's
(:func:`contact.adhesion.cycle.approach_retraction`, the same approach range as
:func:`contact.adhesion.ball.adhesive_ball`), the approach measured from the distant
surface (Maugis' delta) since the half-space is not periodic.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._material_pair import MaterialPair, modulus
from contact._validate import positive
from contact._zone_resolution import MIN_ZONE_RINGS, ZONE_RINGS, process_zone
from contact.adhesion._rings import ring_problem
from contact.adhesion.ball import SpherePullOffs, scales
from contact.adhesion.cycle import Cycle, approach_retraction
from contact.adhesion.laws import EDGE_SMOOTHING, InteractionLaw, checked_law, tabor_parameter
from contact.halfspace.axisymmetric import disc_displacement

#: Rings across the contact's scale max(a0, sqrt(2 R h)), for the DMT end (a wide zone).
CONTACT_RINGS = 200.0
#: The rings' outer radius over the rigid sphere's reach at the deepest approach.
OUTER_MARGIN = 1.2
#: A stepped law's ramp on the rings is at least this many times the gap that the ring
#: most compliant to itself opens by letting go of the peak tension (:func:`ring_law`).
RING_RAMP = 2.0


@dataclass(frozen=True)
class RingBall(SpherePullOffs):
    """An approach-retraction cycle of a smooth adhesive sphere on rings (SI units).

    Attributes
    ----------
    radius, e_star : float
        Sphere radius R (m) and composite modulus E* (Pa).
    law : InteractionLaw
        The adhesion law (its step smoothed on the rings' width where it has one and the
        caller smoothed it).
    rings : int
        Number of rings.
    outer_radius, dr : float
        The rings' outer radius and width (m).
    cycle : Cycle
        The two legs (approach from the distant surface), pull-off, jumps and hysteresis.
    maugis_parameter, tabor_parameter : float
        Maugis' lambda and Tabor's mu with the law's range.
    process_zone : float
        The cohesive zone width l_pz = pi E* w / (4 sigma0^2) (m).
    warnings : tuple of str
        Resolution warnings (empty when none).
    """

    radius: float
    e_star: float
    law: InteractionLaw
    rings: int
    outer_radius: float
    dr: float
    cycle: Cycle
    maugis_parameter: float
    tabor_parameter: float
    process_zone: float
    warnings: tuple[str, ...]
    roughness_rms: float = 0.0



def approach_range(radius: float, e_star: float, law: InteractionLaw) -> tuple[float, float]:
    """(farthest, deepest) approach of the cycle (m): the 3D sphere's
    (:func:`contact.adhesion.ball.adhesive_ball`)."""
    a0, reach, d_scale = scales(radius, e_star, law)
    ell = max(a0, reach)
    return -(1.5 * d_scale + 1.2 * law.reach), ell * ell / radius


def ring_width(radius: float, e_star: float, law: InteractionLaw, *,
               zone_rings: float = ZONE_RINGS) -> tuple[float, float]:
    """(ring width, outer radius) in m for the sphere (module notes)."""
    a0, reach, _ = scales(radius, e_star, law)
    zone = process_zone(e_star, law.work, law.peak)
    dr = min(zone / zone_rings, max(a0, reach) / CONTACT_RINGS)
    deepest = approach_range(radius, e_star, law)[1]
    return dr, OUTER_MARGIN * math.sqrt(2.0 * radius * (deepest + law.reach))


def ring_count(dr: float, outer: float) -> int:
    """The rings of width ``dr`` (m) that reach ``outer`` (m), at least 16."""
    return max(16, math.ceil(outer / dr))


def self_compliance(dr: float, rings: int) -> np.ndarray:
    """Each ring's displacement at its centre per unit pressure on itself, times E* (m):
    the discs' difference (:func:`contact.halfspace.axisymmetric.disc_displacement`)."""
    edges = np.arange(rings + 1) * dr
    r = 0.5 * (edges[1:] + edges[:-1])
    return np.array([float(disc_displacement(r[j:j + 1], edges[j + 1])[0]
                           - (disc_displacement(r[j:j + 1], edges[j])[0] if j else 0.0))
                     for j in range(rings)])


def ring_law(law: InteractionLaw, e_star: float, dr: float, rings: int) -> InteractionLaw:
    """``law`` with its step (where it has one) smoothed for ``rings`` rings of width ``dr``.

    A grid's ramp, ``law.on_grid(dx, e_star)``, is :data:`EDGE_SMOOTHING` sigma0 dx / E*
    wide, several times the gap a pixel opens by letting go of sigma0. A ring's
    self-compliance grows as log(r / dr) along the radius (about 6 dr / E* on the outer
    rings, against a pixel's ~1 dx / E*), so that ramp can be narrower than the gap the
    ring opens, sigma0 K_ii: the ring then has two equilibria at one approach (holding the
    tension or not), and the approach and the retraction end on different ones. That is
    lattice trapping: a loss in a cycle that has no jump (measured 2.3e-14 J at Maugis
    lambda 0.0765, R 1 mm, E* 1 GPa, w 50 mJ/m^2, h0 200 nm, the ring beyond h0 by
    0.07 nm on the way in and within it on the way out). The ramp is therefore widened to
    :data:`RING_RAMP` times the largest sigma0 K_ii where that is wider, which leaves
    every ring's release stable (its traction's slope sigma0 / s below its own
    stiffness 1 / K_ii); a law without a step is returned as ``on_grid`` returns it.
    """
    stable = RING_RAMP * float(self_compliance(dr, rings).max()) / EDGE_SMOOTHING
    return law.on_grid(max(dr, stable), e_star)


def adhesive_sphere(radius: float, e_star: float | MaterialPair, law: InteractionLaw, *,
                    dr: float | None = None, steps: int = 40, tol: float = 1e-6,
                    progress: Callable[[int, int], None] | None = None) -> RingBall:
    """Approach a smooth sphere to a flat until its contact is about the JKR size, then
    retract it, on rings (module notes).

    Parameters
    ----------
    radius, e_star : float
        Sphere radius (m) and composite modulus (Pa), or a resolved
        :class:`contact._material_pair.MaterialPair`.
    law : InteractionLaw
        A registered law, as the solve should see it: smooth its step on the rings with
        :func:`ring_law` first (``dr`` from :func:`ring_width`).
    dr : float, optional
        Ring width (m); default :func:`ring_width`'s.
    steps : int
        Approach steps on each leg.
    tol : float
        Equilibrium tolerance of each solve, relative to the pressure scale.
    progress : callable, optional
        Called as ``progress(step, total)``.

    Examples
    --------
    Maugis' lambda 1 (R 1 mm, E* 1 GPa, w 0.05 J/m^2, h0 15.3 nm): the pull-off lies
    between JKR's 1.5 pi w R and DMT's 2 pi w R (Maugis' curve: 1.60 pi w R):

    >>> from contact.adhesion.laws import DugdaleLaw
    >>> from contact.adhesion._ring_ball import (adhesive_sphere, ring_count, ring_law,
    ...                                          ring_width)
    >>> law = DugdaleLaw.from_range(0.05, 1.530e-8)
    >>> dr, outer = ring_width(1e-3, 1e9, law)
    >>> law = ring_law(law, 1e9, dr, ring_count(dr, outer))
    >>> ball = adhesive_sphere(1e-3, 1e9, law, steps=12)
    >>> print(f"{ball.cycle.pull_off_force / (3.14159265 * 0.05 * 1e-3):.2f} pi w R")
    1.60 pi w R
    """
    positive(radius, "the radius", "m")
    e_star = modulus(e_star)
    positive(e_star, "E*", "Pa")
    checked_law(law)
    if int(steps) != steps or steps < 4:
        raise ContactInputError(f"the steps must be an integer of at least 4, got {steps!r}")
    width, outer = ring_width(radius, e_star, law)
    dr = width if dr is None else positive(dr, "the ring width", "m")
    n = ring_count(dr, outer)
    problem = ring_problem(radius, e_star, law, np.arange(n + 1) * dr)
    far, deep = approach_range(radius, e_star, law)
    cycle = approach_retraction(problem, np.linspace(far, deep, int(steps)), tol=tol,
                                progress=progress)
    zone = process_zone(e_star, law.work, law.peak)
    warnings = []
    if zone < MIN_ZONE_RINGS * dr:
        warnings.append(f"rings too coarse for the interaction: the cohesive zone ({zone:.3g} "
                        f"m) spans {zone / dr:.2g} rings, fewer than {MIN_ZONE_RINGS:g}")
    if cycle.retraction_leg.contact_area[-1] > 0.0:
        warnings.append("the retraction ended with the surfaces still touching: the pull-off "
                        "may lie beyond the last step")
    return RingBall(
        radius=float(radius), e_star=float(e_star), law=law, rings=n,
        outer_radius=n * dr, dr=dr, cycle=cycle,
        maugis_parameter=law.maugis(radius, e_star),
        tabor_parameter=tabor_parameter(law.work, radius, e_star, law.range),
        process_zone=zone, warnings=tuple(warnings))
