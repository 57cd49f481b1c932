"""The adhesive sphere on a flat as an axisymmetric problem: rings instead of a 2D grid.

A smooth sphere on a flat is axisymmetric, so the pressure is a function of the radius
alone. It is carried by uniform pressures on rings, whose surface displacement
(:class:`contact.halfspace.axisymmetric.RingOperator`: Johnson 1985, eq. 3.39) is exact
for the rings, on a free (not periodic) half-space: the approach is Maugis' delta,
measured from the distant surface. The cohesive zone, 0.75 l_M / lambda^2 wide at the
JKR end (l_M Maugis' length), then costs rings along one radius, not pixels over an
area: at lambda 10 a 2D grid needed 1952^2 cells for two zone pixels, a radius needs a
few thousand rings for eight.

One equilibrium at a rigid approach delta (:func:`solve_rings`): the touching rings are a
disc, rings 0 ... k-1 (the gap zero, so the displacement there is delta - h), the others
carry the law's traction at their gap, p = -t(g), g = h - delta + K p. For a given k
this is solved by Newton's method, the law's slope t'(g) (by a central difference of the
law's own traction, so any registered law serves) kept on the rings where it couples most
(the cohesive zone's end: :data:`NEWTON_RINGS` at most) and the traction of the others
updated in place; the disc K_kk is solved with the leading block of one LU factorisation
of K (its partial pivoting is the identity, checked at build: the diagonal dominates each
column), so each iteration costs O(n^2). Then k moves, as a primal-dual active set does:
a touching ring holding more tension than t(0) lets go, an open ring with a negative gap
touches. The iterate is converged when the set no longer changes and equilibrium holds
to ``tol`` of the pressure scale (the touching rings' gap recomputed from the pressures
included: a damped step or a set change leaves it off zero), the 3D solve's residual
(:func:`contact.adhesion.solver.solve_adhesive`).

The displacement-controlled cycle is the 3D one's (:mod:`contact.adhesion.cycle`): the
ring problem states :meth:`RingProblem.equilibrium` as the periodic one does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from scipy import linalg

from contact._errors import ContactInputError, ConvergenceError
from contact._record import SolveRecord
from contact.adhesion.laws import InteractionLaw
from contact.adhesion.solver import AdhesiveState
from contact.halfspace.axisymmetric import RingOperator

#: Rings whose traction slope is kept in the Newton step (the largest |t'(g)| first); the
#: others' tractions are updated from their gaps (their coupling is weaker by the ratio).
NEWTON_RINGS = 48
#: A ring's slope below this share of the largest is not kept in the Newton step.
SLOPE_SHARE = 1e-3
#: The widest band of rings next to the disc solved through its Schur complement
#: (:func:`_band_step`).
BLOCK_RINGS = 48
#: Iterations of one equilibrium (Newton steps and set changes together).
MAX_ITERATIONS = 400
#: Newton iterations tried from the warm start before the descent takes over.
NEWTON_TRIES = 20
#: Newton iterations that must halve the open rings' residual, else the descent takes over
#: (Newton converges quadratically where it converges at all).
STALL = 6
#: Halvings of a Newton step that does not lower the residual.
HALVINGS = 8
#: A residual (over the pressure scale) past which Newton has left its branch.
DIVERGED = 1e3
#: The descent's tolerance before Newton finishes, and its iteration budget.
DESCENT_TOL = 1e-3
DESCENT_ITERATIONS = 20000
#: Rings whose gap (or the rigid sphere's) is within this many times the law's reach are
#: the descent's (with a margin); the outer ones carry no traction.
OUTER_REACH = 4.0


@dataclass(frozen=True, eq=False)
class RingProblem:
    """The fixed data of a series of axisymmetric adhesive solves (SI units).

    Build with :func:`ring_problem`. ``gap0`` is the undeformed gap r^2 / (2 R) at the
    ring centres ``r``, ``area`` the rings' areas, ``matrix`` the displacement (m) per
    unit pressure (Pa) of each ring at each centre (E* included), ``lu`` its LU factors.
    """

    edges: np.ndarray
    r: np.ndarray
    gap0: np.ndarray
    area: np.ndarray
    e_star: float
    law: InteractionLaw
    matrix: np.ndarray = field(repr=False)
    lu: np.ndarray = field(repr=False)

    @cached_property
    def descent_step(self) -> np.ndarray:
        """The descent's step per ring (m/Pa): each ring's self-compliance K_ii over the
        largest eigenvalue of D^1/2 S D^1/2 (S = K^-1, D = diag K_ii), by power iteration
        on it (a solve with K each), with a 5 % margin. On uniform rings K_ii is about one
        value and this is the plain step 1 / max eig S; on graded ones a ring of ten times
        the width takes a step ten times as long, not the finest ring's."""
        d = np.sqrt(self.diagonal)
        x = np.ones_like(self.r)
        piv = np.arange(x.size)
        value = 0.0
        for _ in range(60):
            y = d * linalg.lu_solve((self.lu, piv), d * x, check_finite=False)
            new = float(np.linalg.norm(y) / np.linalg.norm(x))
            x = y / np.linalg.norm(y)
            if abs(new - value) <= 1e-4 * new:
                break
            value = new
        return self.diagonal / (1.05 * new)

    @cached_property
    def diagonal(self) -> np.ndarray:
        """Each ring's displacement per unit pressure on itself (m/Pa)."""
        return np.diag(self.matrix).copy()

    @property
    def dx(self) -> float:
        """The narrowest ring's width (m): the width of uniform rings, the fine band's of
        graded ones."""
        return float(np.min(np.diff(self.edges)))

    def equilibrium(self, approach: float, initial: np.ndarray | None = None, *,
                    tol: float = 1e-7) -> AdhesiveState:
        """:func:`solve_rings` at ``approach`` from the gap ``initial`` (the cycle's call)."""
        return solve_rings(self, approach, initial, tol=tol)


def ring_problem(radius: float, e_star: float, law: InteractionLaw,
                 edges: np.ndarray) -> RingProblem:
    """The sphere of ``radius`` (m) and modulus ``e_star`` (Pa) with ``law`` on the rings
    between ``edges`` (m, from 0, increasing; uniform or graded, as
    :func:`contact.adhesion._ring_ball.graded_edges` makes them: each ring's influence is
    exact for any widths, :mod:`contact.halfspace.axisymmetric`).

    Raises
    ------
    ContactInputError
        Edges that do not start at 0 and increase, or (never met on uniform rings, nor on
        graded ones whose widths grow by 10 % a ring) a ring matrix whose LU needs
        pivoting, so that its leading blocks would not be the discs'.
    """
    op = RingOperator(np.asarray(edges, dtype=float))
    matrix = op.matrix / e_star
    lu, piv = linalg.lu_factor(matrix, check_finite=False)
    if np.any(piv != np.arange(piv.size)):
        raise ContactInputError("the ring matrix needs pivoting: its discs cannot share "
                                "one factorisation")
    area = math.pi * (op.edges[1:] ** 2 - op.edges[:-1] ** 2)
    return RingProblem(op.edges, op.r, op.r ** 2 / (2.0 * radius), area, float(e_star), law,
                       matrix, lu)


def _disc_solve(problem: RingProblem, k: int, b: np.ndarray) -> np.ndarray:
    """K_kk^{-1} b for the disc of the first ``k`` rings (b of k rows, one or more columns):
    the leading block of the LU factors is the disc's own factorisation."""
    lu = problem.lu[:k, :k]
    y = linalg.solve_triangular(lu, b, lower=True, unit_diagonal=True, check_finite=False)
    return linalg.solve_triangular(lu, y, lower=False, check_finite=False)


def _slope(law: InteractionLaw, g: np.ndarray) -> np.ndarray:
    """t'(g) (Pa/m) by a central difference of the law's traction, on a gap step small
    against its range; one-sided at g = 0 (the law is not defined below, and a Newton
    iterate's overlap there is taken at contact: the exponential's exp(-g / rho) of a deep
    overlap overflows)."""
    eps = 1e-6 * law.range
    g = np.maximum(g, 0.0)
    lo = np.maximum(g - eps, 0.0)
    step = (g + eps) - lo
    # a gap so wide that eps is lost in it (a diverging Newton iterate, which the caller
    # rejects) lies far beyond the law's reach: no slope there, not 0 / 0
    slope = np.zeros_like(g)
    ok = step > 0.0
    slope[ok] = (law.traction(g[ok] + eps) - law.traction(lo[ok])) / step[ok]
    return slope


def _newton_step(problem: RingProblem, delta: float, k: int, p: np.ndarray,
                 g: np.ndarray) -> np.ndarray:
    """The pressures after one Newton step at the disc ``k`` from ``p`` (gaps ``g``): the
    strongly coupled open rings (the largest |t'(g)| K_ii) and the disc solved together,
    the other open rings given their traction at their gap."""
    law, kmat, h = problem.law, problem.matrix, problem.gap0
    g = np.maximum(g, 0.0)  # an open ring's overlap is taken at contact, as in _merit
    slope = _slope(law, g[k:])
    coupling = np.abs(slope) * problem.diagonal[k:]
    strong = np.flatnonzero(coupling > SLOPE_SHARE * max(float(coupling.max(initial=0.0)),
                                                        1e-300))
    if strong.size and k and int(strong[-1]) < BLOCK_RINGS:
        # the strong rings lie next to the disc: take the whole band k ... k + m - 1,
        # whose Schur complement is a block of the LU factors already held
        ring = np.arange(k, k + int(strong[-1]) + 1)
        return _band_step(problem, delta, k, p, g, ring, slope[: ring.size])
    if strong.size > NEWTON_RINGS:
        strong = strong[np.argsort(-coupling[strong])[:NEWTON_RINGS]]
    ring = np.sort(strong) + k
    new = p.copy()
    new[k:] = -law.traction(g[k:])  # the weakly coupled rings: their traction at their gap
    fixed = new.copy()
    fixed[:k] = 0.0
    fixed[ring] = 0.0
    u_fixed = kmat @ fixed  # the displacement of the rings whose pressure is now known
    if ring.size == 0:
        if k:
            new[:k] = _disc_solve(problem, k, delta - h[:k] - u_fixed[:k])
        return new
    d = slope[ring - k]
    # Newton at the strong rings: p + t(g) + t'(g) (u_new - u) = 0 with u = K p
    right = -law.traction(g[ring]) + d * (kmat[ring] @ p - u_fixed[ring])
    block = kmat[np.ix_(ring, ring)]
    if k:
        y = _disc_solve(problem, k, delta - h[:k] - u_fixed[:k])
        x = _disc_solve(problem, k, kmat[:k, ring])
        left = np.eye(ring.size) + d[:, None] * (block - kmat[ring, :k] @ x)
        new[ring] = np.linalg.solve(left, right - d * (kmat[ring, :k] @ y))
        new[:k] = y - x @ new[ring]
    else:
        new[ring] = np.linalg.solve(np.eye(ring.size) + d[:, None] * block, right)
    return new


def _band_step(problem: RingProblem, delta: float, k: int, p: np.ndarray, g: np.ndarray,
               ring: np.ndarray, d: np.ndarray) -> np.ndarray:
    """:func:`_newton_step` where its rings are the band k ... k + m - 1 next to the disc.

    With K = L U unpivoted, the Schur complement K_bb - K_bk K_kk^-1 K_kb of the band is
    L_bb U_bb (the band's diagonal blocks of the factors), so the step costs two disc
    solves of one vector and an m x m product instead of m disc solves."""
    law, kmat, h, lu = problem.law, problem.matrix, problem.gap0, problem.lu
    lo, hi = k, k + ring.size
    new = p.copy()
    new[hi:] = -law.traction(g[hi:])
    fixed = new.copy()
    fixed[:hi] = 0.0
    u_fixed = kmat @ fixed
    band = lu[lo:hi, lo:hi]
    schur = np.tril(band, -1) @ np.triu(band) + np.triu(band)  # L_bb U_bb, L unit
    right = -law.traction(g[lo:hi]) + d * (kmat[lo:hi] @ p - u_fixed[lo:hi])
    y = _disc_solve(problem, k, delta - h[:k] - u_fixed[:k])
    left = np.eye(ring.size) + d[:, None] * schur
    new[lo:hi] = np.linalg.solve(left, right - d * (kmat[lo:hi, :k] @ y))
    new[:k] = _disc_solve(problem, k, delta - h[:k] - u_fixed[:k] - kmat[:k, lo:hi] @ new[lo:hi])
    return new


def _gaps(problem: RingProblem, delta: float, k: int, u: np.ndarray) -> np.ndarray:
    """The gap of the displacement ``u`` (= K p) with the disc ``k`` touching (zero there)."""
    g = problem.gap0 - delta + u
    g[:k] = 0.0
    return g


def _violation(problem: RingProblem, k: int, p: np.ndarray, g: np.ndarray,
               u: np.ndarray, approach: float) -> np.ndarray:
    """Violation of equilibrium per ring (Pa): the touching rings' tension beyond t(0) and
    their gap (from ``u`` = K p, which a damped step or a set change leaves off zero: the
    disc's own equation) as the pressure it would take to close it, the open rings'
    |p + t(g)|, and a negative gap as the pressure it would take to lift it (its gap over
    the ring's self-compliance)."""
    law = problem.law
    out = np.zeros_like(p)
    disc = np.abs(problem.gap0[:k] - approach + u[:k]) / problem.diagonal[:k]
    out[:k] = np.maximum(np.maximum(-(p[:k] + law.traction(0.0)), 0.0), disc)
    out[k:] = np.abs(p[k:] + law.traction(np.maximum(g[k:], 0.0)))
    neg = g[k:] < 0.0
    out[k:][neg] = np.maximum(out[k:][neg],
                              -g[k:][neg] / problem.diagonal[k:][neg])
    return out


def _next_disc(problem: RingProblem, k: int, p: np.ndarray, g: np.ndarray,
               tol_pa: float) -> int:
    """The disc after a set change: grown to the last open ring with a negative gap, else
    shrunk to the first touching ring holding more tension than t(0) (by ``tol_pa``)."""
    sunk = np.flatnonzero(g[k:] < -tol_pa * problem.diagonal[k:])
    if sunk.size:
        return k + int(sunk[-1]) + 1
    pulled = np.flatnonzero(p[:k] + problem.law.traction(0.0) < -tol_pa)
    if pulled.size:
        return int(pulled[0])
    return k


def solve_rings(problem: RingProblem, approach: float, initial: np.ndarray | None = None,
                *, tol: float = 1e-7, max_iter: int = MAX_ITERATIONS) -> AdhesiveState:
    """The equilibrium nearest ``initial`` (a gap on the rings) at the rigid approach
    ``approach`` (m, from the distant surface); module notes.

    Newton's method on the disc's active set first; where it does not settle (near a jump,
    where the branch it started on ends), the accelerated projected gradient on the total
    energy (:func:`_descend`, the 3D solve's method) finds the minimum the warm start
    descends to, and Newton finishes from there.

    Raises
    ------
    ConvergenceError
        When neither reaches ``tol``.
    """
    h = problem.gap0
    g = np.maximum(h - approach if initial is None else np.asarray(initial, dtype=float), 0.0)
    if g.shape != h.shape:
        raise ContactInputError(f"the warm-start gap has shape {g.shape}, the rings {h.shape}")
    found = _newton(problem, approach, g, tol, NEWTON_TRIES)
    spent = NEWTON_TRIES
    if found is None:
        g, used = _descend(problem, approach, g, max(tol, DESCENT_TOL), DESCENT_ITERATIONS)
        spent += used
        found = _newton(problem, approach, g, tol, max_iter)
        spent += max_iter
        if found is None:
            g, used = _descend(problem, approach, g, tol, DESCENT_ITERATIONS)
            spent += used
            found = _newton(problem, approach, g, tol, NEWTON_TRIES)
    if found is None:
        raise ConvergenceError(
            f"the axisymmetric adhesive solve did not reach the residual {tol:.3g} of the "
            f"pressure scale (approach {approach:.4g} m); refine the approach steps",
            residual=math.inf, iterations=spent)
    k, p, g, nit, residual = found
    return _ring_state(problem, approach, k, p, g, nit, residual, tol)


def _newton(problem: RingProblem, approach: float, g: np.ndarray, tol: float,
            max_iter: int) -> tuple[int, np.ndarray, np.ndarray, int, float] | None:
    """Newton's method on the disc's active set from the gap ``g``: (disc, pressures,
    gaps, iterations, residual), or None where it has not converged in ``max_iter``."""
    h, law, kmat = problem.gap0, problem.law, problem.matrix
    k = int(np.argmax(g > 0.0)) if np.any(g > 0.0) else h.size
    p = -law.traction(np.maximum(g, 0.0))  # the disc's rings are set just below
    if k:
        p[:k] = _disc_solve(problem, k, approach - h[:k] - kmat[:k, k:] @ p[k:])
    u = kmat @ p
    seen: dict[int, int] = {}
    trail: list[float] = []  # the open rings' residual at each iteration
    for it in range(1, max_iter + 1):
        g = _gaps(problem, approach, k, u)
        scale = max(law.peak, float(p.max()))
        residual = float(_violation(problem, k, p, g, u, approach).max()) / scale
        if residual <= tol:
            return k, p, g, it, residual
        if not math.isfinite(residual) or residual > DIVERGED:
            return None
        newton = float(np.abs(p[k:] + law.traction(np.maximum(g[k:], 0.0))).max(initial=0.0))
        trail.append(newton / scale)
        if len(trail) > STALL and trail[-1] > 0.5 * trail[-1 - STALL]:
            return None  # not converging (rings cycling across the law's step): descend
        if newton <= tol * scale:  # equilibrium for this disc: move the disc
            k_new = _next_disc(problem, k, p, g, tol * scale)
            seen[k_new] = seen.get(k_new, 0) + 1
            if seen[k_new] > 3:  # a cycle of discs: no settled set from here
                return None
            k = k_new
            g = _gaps(problem, approach, k, u)
            trail.clear()
        p, u = _damped(problem, approach, k, p, u, g)
    return None


def _merit(problem: RingProblem, approach: float, k: int, p: np.ndarray,
           u: np.ndarray) -> float:
    """The open rings' equilibrium residual sum (p + t(g))^2 (Pa^2) at the disc ``k``
    (``u`` = K p)."""
    g = problem.gap0[k:] - approach + u[k:]
    return float(np.sum((p[k:] + problem.law.traction(np.maximum(g, 0.0))) ** 2))


def _damped(problem: RingProblem, approach: float, k: int, p: np.ndarray, u: np.ndarray,
            g: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One Newton step from ``p`` (``u`` = K p, gaps ``g``) at the disc ``k``, halved while
    it does not lower the residual (:func:`_merit`): near the zone's end a full step can
    carry rings across the law's step and back, a cycle of two that never converges.
    The displacement is linear in the step, so a halving costs no product with K."""
    full = _newton_step(problem, approach, k, p, g)
    u_full = problem.matrix @ full
    start = _merit(problem, approach, k, p, u)
    alpha = 1.0
    for _ in range(HALVINGS):
        trial, u_trial = p + alpha * (full - p), u + alpha * (u_full - u)
        if _merit(problem, approach, k, trial, u_trial) < (1.0 - 1e-4 * alpha) * start:
            return trial, u_trial
        alpha *= 0.5
    return full, u_full


def _descend(problem: RingProblem, approach: float, g: np.ndarray, tol: float,
             max_iter: int) -> tuple[np.ndarray, int]:
    """:func:`_descend_rings` on the leading rings only, where the outer ones are far from
    the law's reach: they carry no traction, so their pressure is zero and the inner
    rings' problem is closed (its stiffness the leading block of the LU factors), at a
    cost of the inner rings squared per iteration. Checked after: an outer ring found
    within reach has the descent rerun on all rings."""
    h, reach, n = problem.gap0, problem.law.reach, problem.gap0.size
    near = np.flatnonzero(np.minimum(g, h - approach) < OUTER_REACH * reach)
    m = n if near.size == 0 else min(n, int(near[-1]) + 1 + max(16, n // 20))
    if m < n:
        inner, used = _descend_rings(problem, approach, g[:m], tol, max_iter)
        p = linalg.lu_solve((problem.lu[:m, :m], np.arange(m)), inner - h[:m] + approach,
                            check_finite=False)
        outer = h[m:] - approach + problem.matrix[m:, :m] @ p
        if float(outer.min()) > reach:
            return np.concatenate([inner, outer]), used
    return _descend_rings(problem, approach, g, tol, max_iter)


def _descend_rings(problem: RingProblem, approach: float, g: np.ndarray, tol: float,
                   max_iter: int) -> tuple[np.ndarray, int]:
    """The accelerated projected gradient (FISTA with restart, as
    :mod:`contact.adhesion._descent` runs it on a grid) on the total energy
    1/2 u.A S u + sum A phi(g), S = K^-1, of the leading ``g.size`` rings (the others
    without pressure), from the gap ``g``: the gap reached and the iterations. Every step
    descends, so it ends at a minimum (a stable equilibrium)."""
    law, m = problem.law, g.size
    h = problem.gap0[:m]
    lu = (problem.lu[:m, :m], np.arange(m))
    step = problem.descent_step[:m]
    x = g.copy()
    y = g.copy()
    theta = 1.0
    for it in range(1, max_iter + 1):
        p = linalg.lu_solve(lu, y - h + approach, check_finite=False)
        grad = p + law.traction(y)
        viol = np.where(y <= 0.0, np.maximum(-grad, 0.0), np.abs(grad))
        if float(viol.max()) <= tol * max(law.peak, float(p.max())):
            return y, it
        x_new = np.maximum(y - step * grad, 0.0)
        if float(np.dot(grad, x_new - x)) > 0.0:  # uphill momentum: restart
            theta = 1.0
        theta_new = 0.5 * (1.0 + math.sqrt(1.0 + 4.0 * theta * theta))
        y = np.maximum(x_new + (theta - 1.0) / theta_new * (x_new - x), 0.0)
        x, theta = x_new, theta_new
    return x, max_iter


def _ring_state(problem: RingProblem, approach: float, k: int, p: np.ndarray,
                g: np.ndarray, nit: int, residual: float, tol: float) -> AdhesiveState:
    """The equilibrium record of the rings (energy: elastic plus interaction, J)."""
    law, area = problem.law, problem.area
    g = np.maximum(g, 0.0)
    u = problem.matrix @ p
    energy = 0.5 * float(np.sum(area * p * u)) + float(np.sum(area * law.potential(g)))
    pressure = p.copy()
    return AdhesiveState(
        gap=g, pressure=pressure, approach=float(approach), load=float(np.sum(area * p)),
        contact_area=float(math.pi * problem.edges[k] ** 2), energy=energy,
        residual=residual, iterations=int(nit),
        solve=SolveRecord(method="adhesive, axisymmetric rings (Newton, disc active set)",
                          iterations=int(nit), residual=residual, tolerance=tol,
                          converged=True, edge_contact=bool(k >= h_size(problem)),
                          residual_definition="largest violation of equilibrium over the "
                                              "pressure scale"),
    )


def h_size(problem: RingProblem) -> int:
    """The number of rings."""
    return int(problem.gap0.size)
