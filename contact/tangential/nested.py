"""Nested grids for steady rolling: a coarse solve as the start of a fine one.

Most of a cold steady-rolling solve goes into finding the stick and slip areas, the slip
directions, the creepage of a prescribed force and the coupled pressure; all of these are
already close on a grid of half the resolution. The fine solve therefore starts from the
coarse answer: each coarse element's state copied to the 2 x 2 fine elements it covers,
the traction and pressure interpolated with the stencil of :mod:`contact.nesting` (the
nested iteration of multigrid practice; Brandt 1977, Math. Comp. 31:333). Only the start
changes: the fine solve keeps its own convergence tests, so the answer is that of the
fine grid.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact import nesting
from contact.grid import Grid
from contact.tangential.kernels import SLIP, STICK
from contact.tangential.solver import TangentialState

# below this many elements a side a grid is solved from cold
SMALLEST = 32


@dataclass(frozen=True)
class CoarseStart:
    """What a fine solve takes from the coarse one."""

    p: np.ndarray
    state: TangentialState
    xi: float


def coarse_grid(grid: Grid) -> Grid | None:
    """The grid of twice the pitch over the same area (3D, even sides of at least
    2 SMALLEST), or None where nesting does not pay (:func:`contact.nesting.coarse_grid`)."""
    return nesting.coarse_grid(grid, SMALLEST)


def _fine(a: np.ndarray) -> np.ndarray:
    """Each element to the 2 x 2 it covers (piecewise constant)."""
    return np.repeat(np.repeat(a, 2, axis=-1), 2, axis=-2)


def _smooth(a: np.ndarray) -> np.ndarray:
    """Bilinear interpolation of a coarse field to the fine grid; the passes run along x
    first (the reverse of :func:`contact.nesting.prolong`), which keeps the rounding, and
    so the answers, of steady rolling as they were."""
    return nesting.prolong_axis(nesting.prolong_axis(a, -1), -2)


def prolong(p: np.ndarray, q: np.ndarray, state: np.ndarray, xi: float) -> CoarseStart:
    """A coarse answer on the fine grid: states to the 2 x 2 elements each covers, the
    traction and pressure interpolated bilinearly (:mod:`contact.nesting`)."""
    qf = _smooth(q)
    st = _fine(state).astype(np.int8)
    norm = np.hypot(qf[0], qf[1])
    slip = (st == SLIP) & (norm > 0)
    e = np.zeros_like(qf)
    e[:, slip] = qf[:, slip] / norm[slip]
    st[(st == SLIP) & ~slip] = 1
    start = TangentialState(q=qf, s=np.zeros_like(qf), state=st, e=e)
    return CoarseStart(p=np.clip(_smooth(p), 0.0, None), state=start, xi=xi)


# a prolonged traction within this fraction of the fine bound starts in slip
REACHES_BOUND = 0.99


def restate(state: TangentialState, g: np.ndarray) -> None:
    """The fine states of a prolonged start, read off its tractions against the fine
    grid's own bound g = mu p (in place): slip, along the traction, where the traction
    reaches the bound, adhesion on the other loaded elements. The coarse states copied
    to 2 x 2 fine elements make the slip band at the rim twice too wide; read this way the
    fine solve settles in one Newton step fewer (256^2 free rolling: 6 instead of 7)."""
    q = state.q
    size = np.hypot(q[0], q[1])
    loaded = g > 0
    slip = loaded & (size > 0) & (size >= REACHES_BOUND * g)
    state.state[:] = np.where(loaded, STICK, 0)
    state.state[slip] = SLIP
    state.e[:] = 0.0
    state.e[:, slip] = q[:, slip] / size[slip]
