"""An elastic-perfectly-plastic reference for the tests: a plastic-displacement fixed point
built on elastic solves only.

The engine solves elastic-plastic contact with the capped Polonsky-Keer iteration of
:func:`contact.bem.solve_normal` (``hardness=``). This is a second, independent algorithm
for the same conditions (p <= H everywhere, p = H wherever the permanent indentation
u_pl > 0, elastic complementarity elsewhere, load balance): solve the *elastic* contact of
the gap h + u_pl, take the pressure above H on the yielded set and deepen u_pl there by the
displacement that excess makes (a plain linear convolution, scipy.signal, with Love's
closed-form influence coefficients written out here: not the solver's kernels or its
DC-FFT); where u_pl > 0 and p < H the indentation shrinks back. The load constraint
pushes part of the removed load back onto the yielded cells, a slow mode of the plain
iteration that Anderson mixing over the last few steps removes (Walker & Ni 2011, SIAM J.
Numer. Anal. 49:1715).

It shares nothing with the capped iteration but the elastic solver.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from scipy.signal import fftconvolve

from contact import SolveOptions
from contact._grid import gap_grid
from contact.bem import solve_normal


@dataclass(frozen=True, eq=False)
class PlasticReference:
    """The fixed point's answer: pressure (Pa), permanent indentation (m), approach (m)."""

    pressure: np.ndarray
    plastic_displacement: np.ndarray
    approach: float
    outer_iterations: int
    yield_excess: float


def _love(x: np.ndarray, y: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """Displacement at (x, y) per unit pressure on the cell [-dx/2, dx/2] x [-dy/2, dy/2],
    E* = 1: Love (1929) in Johnson's (1985, eq. 3.25) logarithmic form, written here apart
    from the engine's influence coefficients. On a grid of cell offsets no corner
    coordinate is 0, so every logarithm is finite."""
    def corner(cx: np.ndarray, cy: np.ndarray) -> np.ndarray:
        r = np.hypot(cx, cy)
        return cx * np.log(cy + r) + cy * np.log(cx + r)

    a, b = 0.5 * dx, 0.5 * dy
    return (corner(x + a, y + b) - corner(x + a, y - b) - corner(x - a, y + b)
            + corner(x - a, y - b)) / math.pi


def _displacement(p: np.ndarray, dx: float, e_star: float) -> np.ndarray:
    """Surface displacement of the pressure ``p`` on a free (non-periodic) square grid."""
    n = p.shape[0]
    off = np.arange(-(n - 1), n) * dx
    kernel = _love(off[None, :], off[:, None], dx, dx)
    full = fftconvolve(p, kernel, mode="full")
    return full[n - 1:2 * n - 1, n - 1:2 * n - 1] / e_star


def fixed_point_plastic(
    problem,
    load: float,
    hardness: float,
    elastic,
    *,
    tol: float = 1e-6,
    yield_tol: float = 1e-3,
    relax: float = 0.7,
    anderson: int = 6,
    max_outer: int = 300,
) -> PlasticReference:
    """Elastic-perfectly-plastic contact of ``problem`` (an elastic
    :class:`contact.setups._ball_on_plate.SphereContact`) at ``load``, warm-started from its
    elastic solution ``elastic``; stops when no yielded cell carries more than
    H (1 + yield_tol). Raises AssertionError when it does not converge."""
    n, dx = problem.domain.n, problem.domain.dx
    e_star = problem.e_star
    origin = (-(n // 2) * dx, -(n // 2) * dx)
    h = problem.gap0
    p = np.asarray(elastic.pressure)
    upl = np.zeros_like(h)
    hist_u: list[np.ndarray] = []
    hist_g: list[np.ndarray] = []
    best = worst = math.inf
    res = None
    for outer in range(1, max_outer + 1):
        res = solve_normal(gap_grid(h + upl, dx, origin=origin), e_star=e_star, load=load,
                           initial=p, options=SolveOptions(tol=tol, edge="ignore"))
        p = np.asarray(res.pressure)
        active = (p > hardness) | (upl > 0)
        step = np.where(active, p - hardness, 0.0)
        worst = float(np.abs(step).max()) / hardness
        if worst <= yield_tol:
            pressure = np.where(upl > 0, hardness, np.minimum(p, hardness))
            return PlasticReference(pressure=pressure, plastic_displacement=upl,
                                    approach=float(res.approach), outer_iterations=outer,
                                    yield_excess=worst)
        g = np.where(active, _displacement(step, dx, e_star), 0.0).ravel()
        if worst > 4.0 * best:  # a bad extrapolation: start the history again
            hist_u.clear()
            hist_g.clear()
        best = min(best, worst)
        hist_u.append(upl.ravel().copy())
        hist_g.append(g)
        if len(hist_u) > anderson + 1:
            hist_u.pop(0)
            hist_g.pop(0)
        new = hist_u[-1] + relax * hist_g[-1]
        if len(hist_u) >= 2:
            d_g = np.stack([b - a for a, b in itertools.pairwise(hist_g)], axis=1)
            d_u = np.stack([b - a for a, b in itertools.pairwise(hist_u)], axis=1)
            gamma, *_ = np.linalg.lstsq(d_g, hist_g[-1], rcond=None)
            new = new - (d_u + relax * d_g) @ gamma
        upl = np.maximum(new.reshape(h.shape), 0.0)
    raise AssertionError(f"the fixed point did not converge: {100 * worst:.3g} % above H")
