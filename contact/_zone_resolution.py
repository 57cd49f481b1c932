"""How many pixels an adhesive interaction's cohesive zone must span: the coarse-grid
thresholds of every adhesive solve (:mod:`contact.adhesion.ball`, ``.line``, ``.flat``).

The cohesive (process) zone at the edge of an adhesive contact is about
l_pz = pi E* w / (4 sigma0^2) wide (the JKR-limit width of Maugis' 1992 equations); on a
grid too coarse for it the contact edge is pinned by the pixels and the pull-off comes out
too large. A module of its own, without NumPy, so that the command line's help can state
the thresholds without loading the solvers.
"""

from __future__ import annotations

import itertools
import math

__all__ = ["MIN_ZONE_PIXELS", "MIN_ZONE_PIXELS_PLAIN", "ZONE_PULL_OFF_EXCESS",
           "min_zone_pixels", "process_zone", "pull_off_excess"]

#: The coarse-grid threshold: a cohesive zone narrower than this many pixels is warned
#: about. It is the threshold of the Dugdale step smoothed on the grid's scale
#: (:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`), the law ``surfmet adhesion`` and
#: ``flat-contact`` run by default, measured against Maugis-Dugdale's pull-off
#: (benchmarks/adhesion_zone_threshold.py, whose notes give the table): from 2 pixels up the
#: pull-off is within 2.1 % of Maugis' (lambda 1 to 5), between 1.5 and 2 up to +3.8 %,
#: below 1.1 pixels +2.6 % to +14 %.
MIN_ZONE_PIXELS = 2.0
#: Rings across the cohesive zone l_pz on the axisymmetric rings of a smooth sphere
#: (measured: docs/adhesion.md, "Axisymmetric rings"); kept here, light, for the CLI's help.
ZONE_RINGS = 8.0
#: Fewer zone rings than this are warned about.
MIN_ZONE_RINGS = 4.0
#: The same for a law whose step is not smoothed (the plain Dugdale step of the line
#: contact, and the exponential law): the pixels pin the zone's end, an error first order
#: in the pixel over the zone (+11.8 % at 6.6 pixels, +5.3 % at 13, lambda = 1:
#: benchmarks/adhesion_convergence.py), so the warning starts at ten.
MIN_ZONE_PIXELS_PLAIN = 10.0


def min_zone_pixels(smoothed: bool) -> float:
    """The coarse-grid threshold in cohesive-zone pixels: :data:`MIN_ZONE_PIXELS` for a
    law whose step is smoothed on the grid, :data:`MIN_ZONE_PIXELS_PLAIN` otherwise."""
    return MIN_ZONE_PIXELS if smoothed else MIN_ZONE_PIXELS_PLAIN


#: The measured convergence of the pull-off with the cohesive zone's pixels: the pull-off's
#: excess over Maugis-Dugdale's (%) of the command's sphere (Dugdale step smoothed on the
#: grid, cell 4 x the larger of a0 and the zone's reach, 40 steps a leg), read off the
#: runs of benchmarks/adhesion_zone_threshold.py whose JKR radius spans 16 pixels or more
#: (lambda 1.6 to 10; its table and docs/adhesion.md) as their upper envelope: at each
#: measured resolution the largest excess measured there or at any finer one, so that
#: what it states is not below what was seen. (zone pixels, excess %) by increasing
#: pixels; between them :func:`pull_off_excess` interpolates log-log.
ZONE_PULL_OFF_EXCESS = (
    (0.20, 149.55), (0.26, 99.87), (0.53, 26.55), (0.66, 14.49), (0.74, 13.61),
    (1.10, 4.57), (1.47, 2.28), (6.62, 1.54),
)


def process_zone(e_star: float, work: float, peak: float) -> float:
    """The cohesive zone's width l_pz = pi E* w / (4 sigma0^2) (m) of a law of work ``work``
    (J/m^2) and peak tension ``peak`` (Pa) between bodies of composite modulus ``e_star``."""
    return math.pi * e_star * work / (4.0 * peak * peak)


def pull_off_excess(zone_pixels: float) -> float | None:
    """The pull-off's measured excess (%) over Maugis-Dugdale's at a cohesive zone of
    ``zone_pixels`` pixels (smoothed Dugdale step): :data:`ZONE_PULL_OFF_EXCESS`
    interpolated log-log; None below the coarsest measured resolution (not measured),
    the floor's value above the finest."""
    table = ZONE_PULL_OFF_EXCESS
    if not zone_pixels >= table[0][0]:
        return None
    if zone_pixels >= table[-1][0]:
        return table[-1][1]
    for (p0, e0), (p1, e1) in itertools.pairwise(table):
        if zone_pixels <= p1:
            t = math.log(zone_pixels / p0) / math.log(p1 / p0)
            return math.exp(math.log(e0) + t * math.log(e1 / e0))
    return table[-1][1]  # pragma: no cover (the loop always returns)
