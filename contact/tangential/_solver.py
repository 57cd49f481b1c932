"""The tangential contact problem for a given pressure: Kalker's active-set iteration.

For a pressure p (and so a traction bound g = mu p), a rigid slip w and the fixed part
u0 of the tangential displacement difference, find tractions q on the contact elements
with Coulomb's law (Kalker 1990, sec. 2.1):

    |q| <= g;  s = 0 where |q| < g (adhesion);  q = -g s/|s| where s != 0 (slip),

s = w + L(A q + u0) the slip, L the upwind difference of steady rolling or the identity of
a shift (:mod:`contact.tangential._kinematics`) and A the Cerruti operator
(:mod:`contact.halfspace.pair`).

Algorithm (the active-set idea of Kalker's TANG, 1990 sec. 2.2): with the adhesion set H,
the slip set S and the slip directions e fixed, the problem is linear: q = g e on S and
s = 0 on H. That system is solved by GMRES (Saad & Schultz 1986) with the FFT products
of A, no matrix is formed. The sets and directions are then updated element by element
(:func:`contact.tangential._kernels.update_states`) until none changes and the directions
have settled.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from contact._errors import ConvergenceError
from contact.halfspace.pair import HalfSpacePair
from contact.tangential._cropped import BoxProducts
from contact.tangential._kernels import SLIP, STICK, update_states
from contact.tangential._kinematics import rolling_slip
from contact.tangential._newton import NewtonSystem, cross, diagonal

# relative tolerances of the inner (GMRES) solves of an inexact Newton iteration
# (Dembo, Eisenstat & Steihaug 1982, SIAM J. Numer. Anal. 19:400): loose while elements
# still change state, tighter while only the slip directions settle; the last steps take
# the caller's ``polish_rtol``
MOVING_RTOL = 1e-1
SETTLE_RTOL = 1e-2
# active-set iterations that may move elements into and out of slip in the same update
BOTH_MOVES_UNTIL = 10


@dataclass
class TangentialState:
    """Tractions, slip and element states of one solved tangential problem.

    Attributes
    ----------
    q : ndarray, shape (2, ny, nx)
        Tractions (q_x, q_y) on body 1 (Pa).
    s : ndarray, shape (2, ny, nx)
        Slip: a velocity over V in rolling (dimensionless), a distance in a shift (m).
    state : ndarray of int8, shape (ny, nx)
        0 exterior, 1 adhesion, 2 slip.
    e : ndarray, shape (2, ny, nx)
        Unit traction directions of the slip elements.
    outer, matvecs : int
        Active-set iterations and FFT operator products used.
    """

    q: np.ndarray
    s: np.ndarray
    state: np.ndarray
    e: np.ndarray
    outer: int = 0
    matvecs: int = 0
    dw: float = 0.0


def initial_state(g: np.ndarray) -> TangentialState:
    """Full adhesion on the loaded elements, zero tractions."""
    shape = g.shape
    return TangentialState(q=np.zeros((2, *shape)), s=np.zeros((2, *shape)),
                           state=np.where(g > 0, STICK, 0).astype(np.int8),
                           e=np.zeros((2, *shape)))


def slip_of(op: HalfSpacePair, q: np.ndarray, w: np.ndarray, u0: np.ndarray,
            rolling: bool, products: BoxProducts | None = None) -> np.ndarray:
    """s = w + L(A q + u0); with ``products`` (the box of the loaded elements, which
    holds q) exact on the loaded elements only."""
    u = (op if products is None else products).tangential(q[0], q[1]) + u0
    return w + (rolling_slip(u, op.dx) if rolling else u)


def solve_tangential(
    op: HalfSpacePair,
    g: np.ndarray,
    w: np.ndarray,
    u0: np.ndarray,
    *,
    rolling: bool,
    start: TangentialState | None = None,
    tol: float = 1e-6,
    max_outer: int = 200,
    force: float | None = None,
    area: float = 1.0,
    polish_rtol: float = 1e-7,
    recouple: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, float]] | None = None,
    start_only: bool = False,
) -> TangentialState:
    """Solve the tangential problem for the bound g = mu p (see the module docstring).

    Parameters
    ----------
    op : HalfSpacePair
        Influence operator of the grid.
    g : ndarray, shape (ny, nx)
        Traction bound mu p (Pa); elements with g = 0 carry no traction.
    w : ndarray, shape (2, ny, nx)
        Rigid slip (creepage, or rigid shift in metres).
    u0 : ndarray, shape (2, ny, nx)
        Fixed part of the tangential displacement difference (m): that of the pressure
        for dissimilar bodies, minus the previous displacement in a shift.
    rolling : bool
        Steady rolling (slip = velocity) or a shift (slip = distance).
    start : TangentialState, optional
        Warm start (its states are re-read against g).
    tol : float
        Tolerance on the slip directions and on the linear solves.
    max_outer : int
        Limit on active-set iterations.
    force : float, optional
        Prescribed total force along x (N): the rigid slip along x is then an unknown,
        added to ``w`` (its increment is returned in ``TangentialState.dw``). 3D only.
    area : float
        Element area (m^2), to turn tractions into the force.
    polish_rtol : float
        GMRES tolerance of the last Newton steps, once the sets stand (looser while an
        outer normal-tangential iteration is still moving the pressure).
    recouple : callable, optional
        ``q -> (g, u0, change)``: the normal problem solved again with the tractions q
        (dissimilar bodies), giving the new bound, the new fixed displacement and the
        relative change of the pressure. Called after every Newton step, so that the
        pressure converges with the tractions in one loop instead of an outer
        normal-tangential iteration that converges the tangential problem in full for
        each pressure; convergence then also needs the pressure to have settled.
    start_only : bool
        The answer is only the start of a finer solve (nested grids): return as soon as
        no element changes state, without settling the slip directions further.

    Raises
    ------
    ConvergenceError
        If the sets keep changing after ``max_outer`` iterations.
    """
    st = initial_state(g)
    if start is not None:
        keep = (g > 0) & (start.state > 0)
        st.state[keep] = start.state[keep]
        st.e[:, keep] = start.e[:, keep]
        st.q[:, g > 0] = start.q[:, g > 0]
    line_only_x = op.line and not np.any(w[1]) and not np.any(u0[1])
    ncomp = 1 if line_only_x else 2
    counter = [0]
    slack = 1e-9
    # the local (Gauss-Seidel) test suits the shift operator; the upwind rolling
    # operator is far from diagonally dominant and takes the plain test
    dxx, dyy = diagonal(op, rolling) if not rolling else (0.0, 0.0)
    w = w.copy()
    dw_total = 0.0
    d_shift = diagonal(op, rolling)[0]
    limit = float(g.sum()) * area
    polish = False
    moving = True
    box = BoxProducts(op, g > 0)
    change = 0.0
    same = False
    for it in range(1, max_outer + 1):
        H, S = st.state == STICK, st.state == SLIP
        if same:
            # nothing changed since the slip was formed (3D: no state change, the
            # directions only move in the Newton step): it is this step's residual
            q0, s0 = st.q.copy(), st.s
        else:
            q0 = np.zeros_like(st.q)
            q0[:, H] = st.q[:, H]
            q0[:, S] = g[S] * st.e[:, S]
            s0 = slip_of(op, q0, w, u0, rolling, box)
        residual = None if force is None else force / area - float(q0[0].sum())
        system = NewtonSystem(op, g, s0, q0, st.e, H, S, rolling, ncomp, d_shift, residual)
        step = system.solve(polish_rtol if polish else MOVING_RTOL if moving else SETTLE_RTOL)
        counter[0] += system.matvecs
        q, st.e, rot = step.q, step.e, step.rotation
        w[0] += step.dw
        dw_total += step.dw
        entered = 0
        if recouple is not None:
            g, u0, change = recouple(q)
            entered, new = _follow_bound(st, q, g)
            limit = float(g.sum()) * area
            box = BoxProducts(op, g > 0)
        s = slip_of(op, q, w, u0, rolling, box)
        if entered:
            _aim_new(st, q, s, g, new)
        st.q, st.s = q, s
        aim = 4 if ncomp == 1 else 0  # 3D directions come from the Newton step
        # both moves at once at first (half the steps where rim elements trade places);
        # later moves into slip first, which stops two groups of elements from trading
        # places for ever
        moves = 3 if it <= BOTH_MOVES_UNTIL else 1
        changes, de = update_states(q[0], q[1], s[0], s[1], g, st.state, st.e[0], st.e[1],
                                    dxx, dyy, slack, moves | aim)
        if changes == 0:
            changes, _ = update_states(q[0], q[1], s[0], s[1], g, st.state, st.e[0],
                                       st.e[1], dxx, dyy, slack, 2 | aim)
        changes += entered
        same = changes == 0 and ncomp == 2
        de = max(de, rot)
        moving = changes > 0 or change > 1e-3
        was_polished = polish
        polish = changes == 0 and de <= 1e-3 and change <= 1e-3
        settled = force is None or abs(float(q[0].sum()) * area - force) <= tol * 1e-2 * limit
        # done after a tight step that no longer turns the directions, or, in 3D, as
        # soon as the answer itself is good: every stick slip and every slip's
        # misalignment below tol of the slip the tractions cancel (plane strain is cheap
        # and keeps the stricter test: its full-stick cases dissipate exactly nothing)
        done = change <= tol and ((was_polished and de <= tol)
                                  or (ncomp == 2 and small_residual(
                                      s, st.state, st.e, w, u0, g, op.dx, rolling, tol)))
        if start_only:
            done = change <= 1e-3
        if changes == 0 and settled and done:
            st.outer, st.matvecs, st.dw = it, counter[0], dw_total
            if box.box is not None and not start_only:
                # the slip off the contact too, as the answer's slip field (a start only
                # passes on its tractions and states)
                st.s = slip_of(op, q, w, u0, rolling)
            st.q[:, st.state == SLIP] = g[st.state == SLIP] * st.e[:, st.state == SLIP]
            return st
    raise ConvergenceError(
        f"tangential solver: the stick/slip areas did not settle in {max_outer} iterations",
        float("nan"), max_outer)


def small_residual(s: np.ndarray, state: np.ndarray, e: np.ndarray, w: np.ndarray,
                   u0: np.ndarray, g: np.ndarray, dx: float, rolling: bool,
                   tol: float) -> bool:
    """Whether :func:`slip_residual` is below ``tol``."""
    return slip_residual(s, state, e, w, u0, g, dx, rolling) <= tol


def slip_residual(s: np.ndarray, state: np.ndarray, e: np.ndarray, w: np.ndarray,
                  u0: np.ndarray, g: np.ndarray, dx: float, rolling: bool) -> float:
    """The largest slip on the adhesion elements and slip across the traction on the
    slip elements, over the driving slip, the slip the tractions have to cancel (rigid
    slip plus the pressure's, the largest over the contact); inf when nothing drives."""
    drive = w + (rolling_slip(u0, dx) if rolling else u0)
    loaded = g > 0
    scale = float(np.hypot(drive[0], drive[1])[loaded].max()) if loaded.any() else 0.0
    if scale == 0.0:
        return math.inf
    stick, slip = state == STICK, state == SLIP
    worst = float(np.hypot(s[0, stick], s[1, stick]).max()) if stick.any() else 0.0
    if slip.any():
        worst = max(worst, float(np.abs(cross(e[:, slip], s[:, slip])).max()))
    return worst / scale


def _follow_bound(st: TangentialState, q: np.ndarray,
                  g: np.ndarray) -> tuple[int, np.ndarray]:
    """Bring the states and the slip tractions in line with a new bound g (in place):
    elements that left the contact carry nothing, slip tractions take the new bound.
    Returns the number of elements that entered or left, and the mask of those that
    entered (their slip directions come from the slip, :func:`_aim_new`)."""
    left = (g <= 0) & (st.state > 0)
    entered = (g > 0) & (st.state == 0)
    st.state[left] = 0
    q[:, left] = 0.0
    st.e[:, left] = 0.0
    slip = st.state == SLIP
    q[:, slip] = g[slip] * st.e[:, slip]
    return int(left.sum() + entered.sum()), entered


def _aim_new(st: TangentialState, q: np.ndarray, s: np.ndarray, g: np.ndarray,
             new: np.ndarray) -> None:
    """Elements that entered the contact start in slip against their slip: they enter at
    the rim, where the bound is near zero (in place)."""
    norm = np.hypot(s[0, new], s[1, new])
    ok = norm > 0
    e = np.zeros((2, int(new.sum())))
    e[0] = np.where(ok, -s[0, new] / np.where(ok, norm, 1.0), 1.0)
    e[1] = np.where(ok, -s[1, new] / np.where(ok, norm, 1.0), 0.0)
    st.state[new] = SLIP
    st.e[:, new] = e
    q[:, new] = g[new] * e
