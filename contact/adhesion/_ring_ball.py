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

Where uniform rings would be more than :data:`GRADED_ABOVE` (Maugis' lambda above about
5.5: at lambda 10, 3,329 rings and ten minutes of CPU), they are graded
(:func:`ring_edges`): :data:`ZONE_RINGS` rings across the zone around the JKR contact
radius at pull-off, :data:`CYCLE_ZONE_RINGS` over the whole travel of the contact edge in
the cycle, widths growing by :data:`GROWTH` a ring away from both. The law's step is then
smoothed on the travel's rings (:func:`smoothing_width`), not the finest: on rings wider
than the width it is smoothed on, the zone's end is pinned (lattice trapping) and the
retraction holds the edge out, a pull-off 14 % high at lambda 10 (the step smoothed on
the fine rings); smoothed on the travel's rings, +0.3 % (benchmarks/adhesion_rings.md).
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
#: Uniform rings beyond this many are graded instead (:func:`ring_edges`): Maugis' lambda
#: above about 5.5 on any sphere (the count depends on lambda alone).
GRADED_ABOVE = 1000
#: The graded rings' fine band: the JKR contact radius at pull-off, 4^(-1/3) a0 = 0.63 a0,
#: plus or minus this share of a0 (and :data:`BAND_ZONES` cohesive zones); measured at
#: lambda 5 and 10, the retraction's least load lies at 0.62 a0 and the golden section
#: refines it between 0.59 a0 and 0.65 a0 (benchmarks/adhesion_rings.md).
BAND_HALF = 0.1
BAND_ZONES = 3.0
#: The contact edge's travel over a cycle, (least over a0, largest over max(a0, sqrt(2 R
#: h))): the JKR jump-out at a0 / 6^(2/3) = 0.30 a0 to past the deepest approach's 1.32 a0
#: (measured at lambda 5), with margins; there the rings are the cohesive zone over
#: this many wide, so that the edge is not trapped on a ring wider than the zone.
CYCLE_EDGES = (0.25, 1.5)
CYCLE_ZONE_RINGS = 2.0
#: Growth of the ring widths away from the fine band, and the widest ring over the
#: contact's scale max(a0, sqrt(2 R h)).
GROWTH = 1.1
WIDEST = 0.01


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
    graded : bool
        Whether the rings are graded (:func:`ring_edges`); ``dr`` is then the finest.
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
    graded: bool = False



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


def self_compliance(edges: np.ndarray) -> np.ndarray:
    """Each ring's displacement at its centre per unit pressure on itself, times E* (m),
    for rings of any widths between ``edges`` (m): the discs' difference
    (:func:`contact.halfspace.axisymmetric.disc_displacement`)."""
    edges = np.asarray(edges, dtype=float)
    r = 0.5 * (edges[1:] + edges[:-1])
    return np.array([float(disc_displacement(r[j:j + 1], edges[j + 1])[0]
                           - (disc_displacement(r[j:j + 1], edges[j])[0] if j else 0.0))
                     for j in range(r.size)])


def ring_law(law: InteractionLaw, e_star: float, edges: np.ndarray,
             smooth: float) -> InteractionLaw:
    """``law`` with its step (where it has one) smoothed on the rings between ``edges``
    (m), on the width ``smooth`` (m; :func:`smoothing_width`) or wider where a ring needs it.

    A grid's ramp, ``law.on_grid(dx, e_star)``, is :data:`EDGE_SMOOTHING` sigma0 dx / E*
    wide, several times the gap a pixel opens by letting go of sigma0. A ring's
    self-compliance grows as log(r / dr) along the radius (about 6 dr / E* on the outer
    rings, against a pixel's ~1 dx / E*), so that ramp can be narrower than the gap the
    ring opens, sigma0 K_ii: the ring then has two equilibria at one approach (holding the
    tension or not), and the approach and the retraction end on different ones. That is
    lattice trapping: a loss in a cycle that has no jump (measured 2.3e-14 J at Maugis
    lambda 0.0765, R 1 mm, E* 1 GPa, w 50 mJ/m^2, h0 200 nm, the ring beyond h0 by
    0.07 nm on the way in and within it on the way out). The ramp is therefore widened to
    :data:`RING_RAMP` times the largest sigma0 K_ii of the rings the contact edge travels
    over (those no wider than ``smooth``: all of them on uniform rings, the fine bands on
    graded ones) where that is wider, which leaves each such ring's release stable (its
    traction's slope sigma0 / s below its own stiffness 1 / K_ii); a law without a step
    is returned as ``on_grid`` returns it.
    """
    edges = np.asarray(edges, dtype=float)
    travel = np.diff(edges) <= smooth * (1.0 + 1e-9)
    stable = RING_RAMP * float(self_compliance(edges)[travel].max()) / EDGE_SMOOTHING
    return law.on_grid(max(smooth, stable), e_star)


def graded_edges(outer: float, bands: list[tuple[float, float, float]], widest: float, *,
                 growth: float = GROWTH) -> np.ndarray:
    """Ring edges (m) from 0 to ``outer``, graded: each band (lo, hi, width) asks rings of
    at most ``width`` between lo and hi (m); away from the bands the widths grow by
    ``growth`` a ring (a width w + (growth - 1) d at a distance d from a band of width w),
    up to ``widest``. A last ring narrower than half its neighbour is merged with it.

    Examples
    --------
    >>> e = graded_edges(100.0, [(40.0, 50.0, 1.0)], 5.0)
    >>> w = np.diff(e)
    >>> float(e[0]), float(e[-1]), float(w.min()), bool(np.all(w[1:] / w[:-1] < 1.11))
    (0.0, 100.0, 1.0, True)
    """
    def width(x: float) -> float:
        out = widest
        for lo, hi, w in bands:
            out = min(out, w + (growth - 1.0) * max(lo - x, x - hi, 0.0))
        return out

    edges = [0.0]
    while edges[-1] < outer:
        x = edges[-1]
        w = width(x)
        edges.append(x + min(w, width(x + w)))  # no wider than the width where it ends
    edges[-1] = outer
    if len(edges) > 2 and edges[-1] - edges[-2] < 0.5 * (edges[-2] - edges[-3]):
        del edges[-2]
    return np.array(edges)


def graded(outer: float, dr: float) -> bool:
    """Whether rings of width ``dr`` (m) to ``outer`` (m) are graded (:func:`ring_edges`)."""
    return max(16, math.ceil(outer / dr)) > GRADED_ABOVE


def smoothing_width(radius: float, e_star: float, law: InteractionLaw, dr: float,
                    outer: float) -> float:
    """The ring width (m) to smooth the law's step on (``law.on_grid``): ``dr``, or on
    graded rings the widest the contact edge travels over (module notes)."""
    if not graded(outer, dr):
        return dr
    return max(dr, process_zone(e_star, law.work, law.peak) / CYCLE_ZONE_RINGS)


def ring_edges(radius: float, e_star: float, law: InteractionLaw, dr: float,
               outer: float) -> np.ndarray:
    """The rings' edges (m): uniform of width ``dr`` to ``outer``, or graded
    (:func:`graded_edges`) where uniform rings would be more than :data:`GRADED_ABOVE`
    (module notes): ``dr`` around the JKR contact radius at pull-off, the cohesive zone
    over :data:`CYCLE_ZONE_RINGS` over the contact edge's whole travel."""
    n = max(16, math.ceil(outer / dr))
    if not graded(outer, dr):
        return np.arange(n + 1) * dr
    a0, reach, _ = scales(radius, e_star, law)
    ell = max(a0, reach)
    zone = process_zone(e_star, law.work, law.peak)
    half = BAND_HALF * a0 + BAND_ZONES * zone
    centre = 4.0 ** (-1.0 / 3.0) * a0
    bands = [(centre - half, centre + half, dr),
             (CYCLE_EDGES[0] * a0, CYCLE_EDGES[1] * ell, max(dr, zone / CYCLE_ZONE_RINGS))]
    return graded_edges(n * dr, bands, max(dr, WIDEST * ell))


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
        :func:`ring_law` first, on :func:`ring_edges` and :func:`smoothing_width` (its
        ``dr`` and ``outer`` from :func:`ring_width`).
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
    >>> from contact.adhesion._ring_ball import (adhesive_sphere, ring_edges, ring_law,
    ...                                          ring_width, smoothing_width)
    >>> law = DugdaleLaw.from_range(0.05, 1.530e-8)
    >>> dr, outer = ring_width(1e-3, 1e9, law)
    >>> edges = ring_edges(1e-3, 1e9, law, dr, outer)
    >>> law = ring_law(law, 1e9, edges, smoothing_width(1e-3, 1e9, law, dr, outer))
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
    edges = ring_edges(radius, e_star, law, dr, outer)
    n = edges.size - 1
    problem = ring_problem(radius, e_star, law, edges)
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
        outer_radius=float(edges[-1]), dr=dr, cycle=cycle,
        maugis_parameter=law.maugis(radius, e_star),
        tabor_parameter=tabor_parameter(law.work, radius, e_star, law.range),
        process_zone=zone, warnings=tuple(warnings), graded=graded(outer, dr))
