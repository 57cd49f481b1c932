"""The default grid of an adhesive sphere: the coarsest that resolves the cohesive zone,
within the memory guard.

On a grid whose pixels are wider than the cohesive zone l_pz = pi E* w / (4 sigma0^2) the
contact edge is pinned and the pull-off comes out too large (:mod:`contact._zone_resolution`:
+27 % at half a pixel, lambda 5). The zone narrows as 0.75 l_M / lambda^2 (l_M = (pi w R^2
/ K)^(1/3) Maugis' length) while the periodic cell is about 7.3 l_M (4 a0), so a fixed
grid cannot serve every lambda: the default is the grid that gives the zone
:data:`contact._zone_resolution.MIN_ZONE_PIXELS` pixels (never fewer cells than
:data:`LEAST_GRID`, the default before), rounded up to a multiple of
:data:`GRID_MULTIPLE` (fast FFT lengths), and at most the largest grid that fits in
memory (:func:`contact.adhesion.memory.largest_adhesion_grid`); where memory caps it, the
choice says so and by how much the pull-off is then off
(:func:`contact._zone_resolution.pull_off_excess`, measured). A grid beyond the largest
default run measured (:data:`LARGEST_MEASURED`) is still chosen (extrapolation over
coarser grids does not replace it: benchmarks/adhesion_richardson.py), and its reason
says so and what half of it would be off by.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact._zone_resolution import min_zone_pixels, pull_off_excess
from contact.adhesion.memory import largest_adhesion_grid

#: The least default grid (cells per side): the command's fixed default before the grid
#: followed the zone, ample for the contact itself (a0 spans 32 pixels on it).
LEAST_GRID = 128
#: Default grids are multiples of this (FFT lengths with small factors).
GRID_MULTIPLE = 16
#: The largest default grid whose run was measured, and its CPU time (s): lambda 5 on 496^2
#: in 4.5 min on 2 shared cores (tests/test_adhesion_default_grid.py, +0.94 % from
#: Maugis). Beyond it the choice says so and what half the grid would cost in accuracy:
#: extrapolating from coarser grids does not replace it (benchmarks/adhesion_richardson.py:
#: Richardson pairs from grids below 1.5 zone pixels come out 2 to 22 % low).
LARGEST_MEASURED = (496, 270.0)


@dataclass(frozen=True)
class GridChoice:
    """The default grid and why.

    Attributes
    ----------
    grid : int
        Cells per side to use.
    wanted : int
        Cells per side that resolve the zone (``grid`` unless memory caps it).
    why : str
        How it was chosen, in words (for the output).
    capped_excess : float or None
        Where memory caps the grid: the pull-off's measured excess (%) at the grid's
        resolution (None when not capped or not measured that coarse).
    """

    grid: int
    wanted: int
    why: str
    capped_excess: float | None = None

    @property
    def capped(self) -> bool:
        """Whether the memory guard kept the grid below the one resolving the zone."""
        return self.grid < self.wanted


def resolving_grid(size: float, zone: float, *, steps: int, smoothed: bool = True,
                   available: int | None = None) -> GridChoice:
    """The default grid of a periodic cell of side ``size`` (m) for a cohesive zone of
    width ``zone`` (m) (module notes).

    Parameters
    ----------
    size, zone : float
        Side of the periodic cell and the cohesive zone's width l_pz (m).
    steps : int
        Approach steps on each leg (they enter the memory estimate).
    smoothed : bool
        Whether the law's step is smoothed on the grid (the threshold and the measured
        excess are those of the smoothed Dugdale step).
    available : int, optional
        Available memory (bytes); default the machine's.
    """
    least = min_zone_pixels(smoothed)
    need = math.ceil(size * least / zone * (1.0 - 1e-12))
    wanted = max(LEAST_GRID, GRID_MULTIPLE * math.ceil(need / GRID_MULTIPLE))
    largest = largest_adhesion_grid(steps=steps, available=available)
    if largest is None or wanted <= largest or largest < LEAST_GRID:
        # below the least grid the memory guard refuses with its own message
        return GridChoice(wanted, wanted, f"default: the cohesive zone {least:g} pixels wide "
                          f"or more (at least {LEAST_GRID} cells){_cost(wanted, size, zone)}")
    grid = largest - largest % GRID_MULTIPLE
    pixels = zone * grid / size
    excess = pull_off_excess(pixels) if smoothed else None
    off = (f"the pull-off then comes out about +{excess:.2g} % too large (measured "
           "convergence, docs/adhesion.md)" if excess is not None else
           "the pull-off then comes out too large by more than measured (docs/adhesion.md)")
    return GridChoice(grid, wanted,
                      f"default, capped by memory: {grid} cells (the cohesive zone "
                      f"{pixels:.2g} pixels wide) where {wanted} would give it {least:g}; "
                      f"{off}", excess)


def _cost(grid: int, size: float, zone: float) -> str:
    """What a default ``grid`` beyond :data:`LARGEST_MEASURED` costs and what half of it
    would be off by (the measured :func:`contact._zone_resolution.pull_off_excess`), in
    words; empty up to it."""
    top, seconds = LARGEST_MEASURED
    if grid <= top:
        return ""
    half = GRID_MULTIPLE * math.ceil(grid / 2 / GRID_MULTIPLE)
    pixels = zone * half / size
    excess = pull_off_excess(pixels)
    off = (f"about +{excess:.2g} % too large" if excess is not None else
           "too large by more than measured")
    return (f"; {grid} cells is beyond the largest default run measured ({top} cells, "
            f"{seconds / 60:.2g} min of CPU on 2 cores; the time grows faster than the "
            f"cells), and --grid {half} (the zone {pixels:.1f} pixels) would give the "
            f"pull-off {off} (measured convergence, docs/adhesion.md)")
