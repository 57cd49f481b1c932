"""How many pixels an adhesive interaction's cohesive zone must span: the coarse-grid
thresholds of every adhesive solve (:mod:`contact.adhesion.ball`, ``.line``, ``.flat``).

The cohesive (process) zone at the edge of an adhesive contact is about
l_pz = pi E* w / (4 sigma0^2) wide (the JKR-limit width of Maugis' 1992 equations); on a
grid too coarse for it the contact edge is pinned by the pixels and the pull-off comes out
too large. A module of its own, without NumPy, so that the command line's help can state
the thresholds without loading the solvers.
"""

from __future__ import annotations

__all__ = ["MIN_ZONE_PIXELS", "MIN_ZONE_PIXELS_PLAIN", "min_zone_pixels"]

#: The coarse-grid threshold: a cohesive zone narrower than this many pixels is warned
#: about. It is the threshold of the Dugdale step smoothed on the grid's scale
#: (:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`), the law ``surfmet adhesion`` and
#: ``flat-contact`` run by default, measured against Maugis-Dugdale's pull-off
#: (benchmarks/adhesion_zone_threshold.py, whose notes give the table): from 2 pixels up the
#: pull-off is within 2.1 % of Maugis' (lambda 1 to 5), between 1.5 and 2 up to +3.8 %,
#: below 1.1 pixels +2.6 % to +14 %.
MIN_ZONE_PIXELS = 2.0
#: The same for a law whose step is not smoothed (the plain Dugdale step of the line
#: contact, and the exponential law): the pixels pin the zone's end, an error first order
#: in the pixel over the zone (+11.8 % at 6.6 pixels, +5.3 % at 13, lambda = 1:
#: benchmarks/adhesion_convergence.py), so the warning starts at ten.
MIN_ZONE_PIXELS_PLAIN = 10.0


def min_zone_pixels(smoothed: bool) -> float:
    """The coarse-grid threshold in cohesive-zone pixels: :data:`MIN_ZONE_PIXELS` for a
    law whose step is smoothed on the grid, :data:`MIN_ZONE_PIXELS_PLAIN` otherwise."""
    return MIN_ZONE_PIXELS if smoothed else MIN_ZONE_PIXELS_PLAIN
