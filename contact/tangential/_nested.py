"""Nested grids for steady rolling: a coarse solve as the start of a fine one.

Most of a cold steady-rolling solve goes into finding the stick and slip areas, the slip
directions, the creepage of a prescribed force and the coupled pressure; all of these are
already close on a grid of half the resolution. The fine solve therefore starts from the
coarse answer: each coarse element's state copied to the 2 x 2 fine elements it covers,
the traction and pressure interpolated with the stencil of :mod:`contact._nesting` (the
nested iteration of multigrid practice; Brandt 1977, Math. Comp. 31:333). Only the start
changes: the fine solve keeps its own convergence tests, so the answer is that of the
fine grid.

The grid just above the coarsest is started from the coarsest directly (four times its
pitch, the answer prolonged twice): most of a fine solve's Newton steps go into the one-
or two-element slip band at the rim, which the coarsest grids do not resolve, so the
intermediate grid saves the next solve less than it costs (measured on the benchmark
ball, free rolling: 128^2 from 32^2 takes 43 GMRES products against 48 from 64^2 and
32^2; with fx = 0.2 mu N, 100 against 109; the 256^2 solves on top take the same
products as before). Higher up every grid halves the pitch: skipping 128^2 under 256^2
helped free rolling but cost driven rolling a quarter more products on the finest grid.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact import _nesting as nesting
from contact._grid import Grid
from contact.tangential._kernels import SLIP, STICK
from contact.tangential._solver import TangentialState

# below this many elements a side a grid is solved from cold (the reason for steady
# rolling's smaller coarsest grid is given with the constant)
SMALLEST = nesting.MIN_COARSE_ROLLING


@dataclass(frozen=True)
class CoarseStart:
    """What a fine solve takes from the coarse one."""

    p: np.ndarray
    state: TangentialState
    xi: float


def coarse_grid(grid: Grid) -> tuple[Grid, int] | None:
    """The start grid and how many times its pitch halves to ``grid``'s: twice the pitch
    (3D, even sides; :func:`contact._nesting.coarse_grid`), or four times where that grid
    is the coarsest one (SMALLEST elements a side, solved cold); None where nesting does
    not pay."""
    half = nesting.coarse_grid(grid, SMALLEST)
    if half is None:
        return None
    quarter = nesting.coarse_grid(half, SMALLEST)
    if quarter is not None and nesting.coarse_grid(quarter, SMALLEST) is None:
        return quarter, 2
    return half, 1


def _fine(a: np.ndarray) -> np.ndarray:
    """Each element to the 2 x 2 it covers (piecewise constant)."""
    return np.repeat(np.repeat(a, 2, axis=-1), 2, axis=-2)


def prolong(p: np.ndarray, q: np.ndarray, state: np.ndarray, xi: float,
            levels: int = 1) -> CoarseStart:
    """A coarse answer on the grid ``levels`` halvings of the pitch finer: states to the
    2 x 2 elements each covers, the traction and pressure interpolated bilinearly
    (:mod:`contact._nesting`), once per level."""
    qf, st, pf = q, state, p
    for _ in range(levels):
        qf, st = nesting.prolong(qf), _fine(st)
        pf = np.clip(nesting.prolong(pf), 0.0, None)
    st = st.astype(np.int8)
    norm = np.hypot(qf[0], qf[1])
    slip = (st == SLIP) & (norm > 0)
    e = np.zeros_like(qf)
    e[:, slip] = qf[:, slip] / norm[slip]
    st[(st == SLIP) & ~slip] = 1
    start = TangentialState(q=qf, s=np.zeros_like(qf), state=st, e=e)
    return CoarseStart(p=pf, state=start, xi=xi)


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
