"""Grid transfer for nested solves: a twice coarser gap, a twice finer pressure.

Without a warm start, :func:`contact.bem.solve_normal` first solves the problem on a grid
twice as coarse (recursively) and starts the fine solve from that pressure, interpolated.
"""

from __future__ import annotations

import numpy as np

#: Grids smaller than this (in either direction) are solved directly, not nested.
MIN_COARSE = 64


def coarsen(field: np.ndarray) -> np.ndarray:
    """The mean of each 2 x 2 block of cells (both sides of ``field`` even)."""
    ny, nx = field.shape
    return field.reshape(ny // 2, 2, nx // 2, 2).mean(axis=(1, 3))


def _prolong_axis(a: np.ndarray, axis: int) -> np.ndarray:
    # Bilinear interpolation from coarse cell centres to the two fine centres of each cell:
    # fine 2I sits a quarter cell before coarse I, fine 2I+1 a quarter cell after it.
    a = np.moveaxis(a, axis, 0)
    prev = np.concatenate((a[:1], a[:-1]))
    nxt = np.concatenate((a[1:], a[-1:]))
    out = np.empty((2 * a.shape[0], *a.shape[1:]), dtype=a.dtype)
    out[0::2] = 0.75 * a + 0.25 * prev
    out[1::2] = 0.75 * a + 0.25 * nxt
    return np.moveaxis(out, 0, axis)


def prolong(field: np.ndarray) -> np.ndarray:
    """Bilinear interpolation of a cell field onto the grid twice as fine."""
    return _prolong_axis(_prolong_axis(field, 0), 1)


def can_nest(ny: int, nx: int) -> bool:
    """True if the grid halves evenly into one still at least :data:`MIN_COARSE` a side."""
    return ny % 2 == 0 and nx % 2 == 0 and min(ny, nx) >= 2 * MIN_COARSE
