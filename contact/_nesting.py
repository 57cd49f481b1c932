"""Coarse-to-fine nesting: the one grid-transfer stencil of every solver.

A solve without a warm start may first solve the problem on a grid of twice the pitch
over the same area (recursively) and start the fine solve from that answer,
interpolated: the nested iteration of multigrid practice (Brandt 1977, Math. Comp.
31:333). Only the start changes; the fine solve keeps its own convergence tests, so the
answer is that of the fine grid. The normal BEM (:mod:`contact.bem._solver`), the
viscoelastic rolling solve (:mod:`contact.viscoelastic._surface`) and steady rolling
(:mod:`contact.tangential._nested`) all use this stencil:

- :func:`coarsen`: the mean of each 2 x 2 block (a gap, a coarse cell's mean height);
- :func:`prolong`: bilinear interpolation from the coarse centres to the fine ones (two
  passes of :func:`prolong_axis`), wrapped round a periodic grid;
- :func:`can_nest` and :func:`coarse_grid`: whether a grid halves, and the halved grid
  (its pitch exactly doubled, its centres the means of the fine ones, its gap coarsened):
  the one coarsening of all three solvers, down to :data:`MIN_COARSE` cells a side
  (steady rolling: :data:`MIN_COARSE_ROLLING`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from contact._grid import Grid

#: The coarsest grid (cells a side) a nested solve descends to: below it the normal BEM
#: and the viscoelastic rolling solve start from cold (a conjugate-gradient iteration on
#: a 64^2 grid costs less than interpolating a start for it).
MIN_COARSE = 64
#: Steady rolling's coarsest grid: each of its Newton-GMRES products costs several
#: convolutions, so a start from a 32^2 grid still pays (measured in
#: :mod:`contact.tangential._nested`: 128^2 from 32^2 takes 43 products against 48 from
#: 64^2 and 32^2); passed as ``smallest`` by that family alone.
MIN_COARSE_ROLLING = 32


def coarsen(field: np.ndarray) -> np.ndarray:
    """The mean of each 2 x 2 block of cells over the last two axes (both even)."""
    *lead, ny, nx = field.shape
    return field.reshape(*lead, ny // 2, 2, nx // 2, 2).mean(axis=(-3, -1))


def prolong_axis(a: np.ndarray, axis: int, periodic: bool = False) -> np.ndarray:
    """Linear interpolation along ``axis`` to the grid twice as fine (one pass of
    :func:`prolong`); ``periodic``: the axis wraps round."""
    # Linear interpolation from coarse cell centres to the two fine centres of each cell:
    # fine 2I sits a quarter cell before coarse I, fine 2I+1 a quarter cell after it. On a
    # free grid the edge cells keep their own value outward; on a periodic one the cell
    # beyond the last is the first (a flat extension there would put a seam into the
    # start of a periodic solve, a kink the fine iteration must first remove).
    a = np.moveaxis(a, axis, 0)
    if periodic:
        prev, nxt = np.roll(a, 1, axis=0), np.roll(a, -1, axis=0)
    else:
        prev = np.concatenate((a[:1], a[:-1]))
        nxt = np.concatenate((a[1:], a[-1:]))
    out = np.empty((2 * a.shape[0], *a.shape[1:]), dtype=a.dtype)
    out[0::2] = 0.75 * a + 0.25 * prev
    out[1::2] = 0.75 * a + 0.25 * nxt
    return np.moveaxis(out, 0, axis)


def prolong(field: np.ndarray, periodic: bool = False) -> np.ndarray:
    """Bilinear interpolation of a cell field (last two axes) onto the grid twice as fine.

    ``periodic``: both axes wrap round (a periodic grid's field), instead of the edge cells
    keeping their value outward.

    Examples
    --------
    >>> import numpy as np
    >>> from contact._nesting import prolong
    >>> ring = np.array([[0.0, 4.0]])  # one period of two cells along x
    >>> prolong(ring, periodic=True)[0].tolist()
    [1.0, 1.0, 3.0, 3.0]
    >>> prolong(ring)[0].tolist()
    [0.0, 1.0, 3.0, 4.0]
    """
    return prolong_axis(prolong_axis(field, -2, periodic), -1, periodic)


def can_nest(ny: int, nx: int, smallest: int = MIN_COARSE) -> bool:
    """True if the grid halves evenly into one still at least ``smallest`` a side."""
    return ny % 2 == 0 and nx % 2 == 0 and min(ny, nx) >= 2 * smallest


def coarse_grid(grid: Grid, smallest: int = MIN_COARSE) -> Grid | None:
    """The grid of twice the pitch over the same area, its gap coarsened; None where the
    grid does not halve (:func:`can_nest`) or is a line contact."""
    if grid.line or not can_nest(grid.ny, grid.nx, smallest):
        return None
    # the pitch exactly doubled (not re-read from the averaged centres, which may round)
    return replace(grid, x=0.5 * (grid.x[0::2] + grid.x[1::2]),
                   y=0.5 * (grid.y[0::2] + grid.y[1::2]),
                   h=None if grid.h is None else coarsen(grid.h),
                   pitch=(2 * grid.dx, 2 * grid.dy))
