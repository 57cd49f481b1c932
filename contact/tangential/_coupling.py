"""Inexact normal-tangential coupling of 3D steady rolling (dissimilar bodies, K != 0).

For dissimilar bodies the tangential tractions displace the surfaces normally, so the
pressure depends on the tractions and the two problems are coupled (Kalker 1990,
sec. 2.3). The 3D steady-rolling solver folds the coupling into its Newton loop: after
every Newton step of the tangential problem the pressure is solved again for the new
tractions, warm-started from the last pressure (:func:`contact.tangential._steady.
steady_rolling`). The coupling is weak (Kalker's constant K is -0.08 for steel on
aluminium), so each of these pressures moves by little (a few 1e-4 of the load at
first), and little of that movement is still wanted once the tractions move again.

This module solves those pressures inexactly, as an inexact Newton method solves its
linear systems (Dembo, Eisenstat & Steihaug 1982, SIAM J. Numer. Anal. 19:400): each
warm-started normal solve stops at a residual of ``FORCING`` times the relative change
of the pressure in the solve before it (no looser than ``LOOSEST``), and only the last
ones are solved to the final tolerance. Convergence of the loop is never declared on
a pressure solved loosely. The fixed point is the same as with every pressure solved
tight; only the work on the way changes (free rolling of the benchmark ball at 256^2,
nested from 32^2: 50 normal-solver iterations on the finest grid become 29, and 152 on
all four grids become 80).

Each of these solves is the normal solver's own iteration, started from the last
pressure of the loop and from that pressure's displacement, which the solve before
computed exactly (:func:`contact.bem._solver.resolve_pressure`): one float64 convolution
and the result record (contact radius, clusters, fields) are left out of every solve but
the first of a grid. The answer is the same to rounding (tractions within 1e-10 of their
largest value, the same stick/slip states, products and steps); measured at 256^2, one
warm solve to 1e-5 took 19 ms instead of 27 (min of 15), and the benchmark ball's
rolling solve makes 123 convolutions instead of 132 and one result record instead of 13.
"""

from __future__ import annotations

import numpy as np

from contact._errors import ConvergenceError
from contact.bem._solver import PressureField, WarmStart, resolve_pressure
from contact.halfspace.pair import HalfSpacePair

# residual tolerance of the normal solves that decide convergence (that of
# contact.tangential._normal.solve_pressure, so that the answer is the same)
PRESSURE_TOL = 1e-8
# the loosest residual a coupling solve stops at, and the forcing factor on the last
# relative change of the pressure (measured on the benchmark ball at 64^2-256^2:
# tractions within 1e-7 of their largest value of those with every pressure solved to
# PRESSURE_TOL)
LOOSEST = 1e-5
FORCING = 1e-2
# Newton steps of a solve from a coarse start before the first coupling solve: the first
# step moves tens of elements between stick and slip (80 of 220 slip elements at 256^2),
# its tractions are far from the answer and a pressure solved for them is soon solved
# again (measured on the benchmark ball at 64^2-256^2: the same Newton steps and GMRES
# products, one warm pressure solve fewer per grid; a lag of 2 moved the 64^2 tractions
# by 1.7e-6 of their largest value, against 7e-7 with 1)
LAG = 1
# a coupling solve asked for a residual within this factor of the final one is solved to
# the final one at once
TIGHT_ENOUGH = 100.0


def solve_pressure_to(op: HalfSpacePair, h: np.ndarray, load: float, tol: float,
                      extra: np.ndarray, start: np.ndarray,
                      displacement: np.ndarray | None) -> PressureField:
    """The 3D pressure for the load on the operator's grid, gap ``h + extra``, to residual
    ``tol``, warm-started from ``start`` (whose normal displacement, m, is
    ``displacement`` where known): the package's normal iteration without its result
    record (:func:`contact.bem._solver.resolve_pressure`); one error line if it does not
    converge."""
    r = resolve_pressure(h + extra, op.dx, op.dy, e_star=op.c.e_star, load=load,
                         start=WarmStart(start, displacement), tol=tol)
    if not r.converged:
        raise ConvergenceError(
            f"the coupled normal solve stopped after {r.iterations} iterations at residual "
            f"{r.residual:.3g} (tolerance {tol:.3g})", residual=r.residual,
            iterations=r.iterations)
    return r


class Recoupling:
    """The pressure solved again for the tractions of each Newton step (3D, K != 0):
    ``q -> (mu p, u0 of p, relative change of p)``, keeping the latest p and approach.

    Parameters
    ----------
    op : HalfSpacePair
        The grid's influence operator.
    h : ndarray
        Undeformed separation (m).
    load : float
        Normal force (N).
    mu : float
        Coefficient of friction.
    p, delta : ndarray, float
        The present pressure (Pa) and approach (m).
    tol : float
        The steady-rolling tolerance on the relative change of the pressure: a loosely
        solved pressure that changed by less is solved again to ``final`` before the
        change is reported, so that the loop cannot stop on a loose pressure.
    final : float
        Residual tolerance of the normal solves that may end the loop.
    lag : int
        Newton steps before the first coupling solve (``LAG`` after a coarse start,
        whose pressure already holds the coarse tractions; 0 from cold).
    displacement : ndarray, optional
        The normal displacement of ``p`` (m), where its solve gave it (the first coupling
        solve then starts without a convolution).
    """

    def __init__(self, op: HalfSpacePair, h: np.ndarray, load: float, mu: float,
                 p: np.ndarray, delta: float, tol: float, final: float = PRESSURE_TOL,
                 lag: int = 0, displacement: np.ndarray | None = None):
        self.op, self.h, self.load, self.mu = op, h, load, mu
        self.p, self.delta = p, delta
        self.tol, self.final = tol, final
        self.solves = 0
        self.last = np.inf
        self.calls = 0
        self.lag = lag
        self._u0: np.ndarray | None = None
        # the normal displacement of p, once a solve of the loop has computed it
        self._u = displacement

    def __call__(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
        self.calls += 1
        if self.calls <= self.lag:
            # the first steps still move the stick and slip areas: the pressure waits
            if self._u0 is None:
                self._u0 = self.op.tangential_from_normal(self.p)
            return self.mu * self.p, self._u0, 1.0
        rtol = max(self.final, min(LOOSEST, FORCING * self.last))
        if rtol <= TIGHT_ENOUGH * self.final:
            # nearly the final tolerance already: a loose solve would mostly be solved
            # again to the end (one warm normal solve's fixed cost saved)
            rtol = self.final
        extra = self.op.normal_from_tangential(q[0], q[1])
        r = solve_pressure_to(self.op, self.h, self.load, rtol, extra, self.p, self._u)
        change = _change(r.pressure, self.p)
        if rtol > self.final and change <= self.tol:
            # small enough to end the loop: only on a pressure solved to the end
            r = solve_pressure_to(self.op, self.h, self.load, self.final, extra, r.pressure,
                                  r.displacement)
            change = _change(r.pressure, self.p)
            self.solves += 1
        p_new, self.delta, self._u = r.pressure, r.approach, r.displacement
        self.p = p_new
        self.solves += 1
        self.last = change
        return self.mu * p_new, self.op.tangential_from_normal(p_new), change


def _change(p_new: np.ndarray, p: np.ndarray) -> float:
    """Relative (L1) change of the pressure."""
    return float(np.abs(p_new - p).sum() / p_new.sum())
