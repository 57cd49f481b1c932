"""Tangential tractions of steady rolling on viscoelastic bodies, plane strain (Carter's
problem with creep), for quasi-identical bodies (no normal-tangential coupling).

Kinematics (Kalker 1990, *Three-dimensional elastic bodies in rolling contact*, ch. 1;
Johnson 1985, sec. 8.2). In the contact frame the material flows towards -x at V. With
q the traction on body 1 and u = u_1 - u_2 the relative tangential surface displacement,
the slip of body 1 over body 2 per unit rolling speed is

    s(x) = xi - du/dx,

xi the creepage. Coulomb friction: stick s = 0 with |q| <= mu p; slip
q = -mu p sign(s). In plane strain u_x from q_x has the same kernel as u_z from p
(Johnson 1985, eqs. 2.24b, 2.25b), so the viscoelastic influence matrix of
:func:`contact.viscoelastic._line.influence_matrix` serves both. As in CONTACT's steady
state (its user guide, "Multiple cases, sequences": the previous instance is the present
solution shifted by one element), du/dx is the upwind difference
(u_{i+1} - u_i)/dx, the material at cell i having come from cell i + 1.

Solution: active set over stick and slip cells with the total force
dx sum q = F (or the creepage) prescribed, until no stick cell exceeds mu p and no slip
cell slips against its traction.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._record import SolveRecord, edge_contact


@dataclass(frozen=True, eq=False)
class TractionResult:
    """Steady rolling tractions (SI, per unit length).

    Attributes
    ----------
    traction : ndarray
        q on body 1 (Pa), 0 outside the contact.
    creepage : float
        xi (-): (velocity of body 1 - velocity of body 2) / V at rigid-body level.
    force : float
        dx sum q (N/m).
    stick, slip : ndarray of bool
        Adhesion and slip cells.
    iterations : int
        Active-set iterations.
    solve : SolveRecord
        The record (:mod:`contact._record`): the residual is the largest excess of a
        sticking traction over its bound mu p, over the largest bound.
    """

    traction: np.ndarray
    creepage: float
    force: float
    stick: np.ndarray
    slip: np.ndarray
    iterations: int
    solve: SolveRecord


def _solve(A: np.ndarray, dx: float, on: np.ndarray, state: np.ndarray, bound: np.ndarray,
           force: float | None, creepage: float | None) -> tuple[np.ndarray, float]:
    """Linear solve for q (stick cells) and xi (unless given), with slip cells at
    q = state * bound."""
    n = A.shape[0]
    stick = np.flatnonzero(on & (state == 0))
    slipq = np.where(on & (state != 0), state * bound, 0.0)
    nxt = np.minimum(np.arange(n) + 1, n - 1)
    G = (A[nxt] - A) / dx  # du/dx rows (upwind)
    m = stick.size
    q = slipq.copy()
    if creepage is not None:  # stick: G q = xi
        if m:
            q[stick] = np.linalg.solve(G[np.ix_(stick, stick)],
                                       creepage - G[stick] @ slipq)
        return q, float(creepage)
    M = np.zeros((m + 1, m + 1))
    M[:m, :m] = -G[np.ix_(stick, stick)]
    M[:m, m] = 1.0
    M[m, :m] = dx
    rhs = np.concatenate((G[stick] @ slipq, [force - dx * slipq.sum()]))
    sol = np.linalg.solve(M, rhs)
    q[stick] = sol[:m]
    return q, float(sol[m])


def steady_traction(A: np.ndarray, pressure: np.ndarray, dx: float, mu: float,
                    force: float | None = None, *, creepage: float | None = None,
                    max_iter: int = 200) -> TractionResult:
    """Steady rolling tractions for a prescribed total tangential force or creepage.

    Parameters
    ----------
    A : (n, n) ndarray
        The pair's tangential influence matrix (m/Pa), e.g. ``influence_matrix`` of the
        pair's creep series (quasi-identical bodies).
    pressure : (n,) ndarray
        Normal pressure (Pa); the contact is where it is positive.
    dx : float
        Cell pitch (m).
    mu : float
        Coefficient of friction, > 0.
    force : float, optional
        F_x on body 1 (N/m), |F| < mu N (default 0, free rolling, unless ``creepage``).
    creepage : float, optional
        xi instead of the force.
    """
    p = np.asarray(pressure, dtype=float)
    if not (np.isfinite(mu) and mu > 0):
        raise ContactInputError(f"the coefficient of friction must be positive, got {mu!r}")
    if force is not None and creepage is not None:
        raise ContactInputError("prescribe the tangential force or the creepage, not both")
    if creepage is not None and not np.isfinite(creepage):
        raise ContactInputError(f"the creepage must be a finite number, got {creepage!r}")
    force = 0.0 if force is None and creepage is None else force
    on = p > 0
    bound = mu * p
    # "reaches": a force equal to mu N up to the rounding of the pressure's quadrature
    if force is not None and abs(force) >= bound.sum() * dx * (1.0 - 1e-12):
        raise ContactInputError("the tangential force reaches mu N: the roller slides")
    state = np.zeros(p.size)  # 0 stick, +-1 slip with q = state * mu p
    nxt = np.minimum(np.arange(p.size) + 1, p.size - 1)
    for it in range(1, max_iter + 1):
        q, xi = _solve(A, dx, on, state, bound, force, creepage)
        u = A @ q
        s = xi - (u[nxt] - u) / dx
        over = on & (state == 0) & (np.abs(q) > bound * (1 + 1e-12))
        wrong = on & (state != 0) & (s * state > 0)  # slipping along its own traction
        if not over.any() and not wrong.any():
            stick = on & (state == 0)
            excess = np.where(stick, np.abs(q) - bound, 0.0).max(initial=0.0)
            record = SolveRecord(
                method="plane-strain traction active set", iterations=it,
                residual=max(float(excess), 0.0) / max(float(bound.max()), 1e-300),
                tolerance=1e-12, converged=True, edge_contact=edge_contact(p),
                residual_definition="largest excess of a sticking traction over mu p, "
                                    "over the largest mu p")
            return TractionResult(q, xi, float(q.sum() * dx), stick, on & ~stick, it, record)
        state[over] = np.sign(q[over])
        state[wrong] = 0.0
    raise ConvergenceError("steady rolling tractions: stick/slip areas not settled",
                           iterations=max_iter)
