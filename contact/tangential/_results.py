"""The result of a tangential contact solve and the quantities read off it.

Signs follow :mod:`contact.tangential._kinematics`: forces are those on body 1, creepage
is the rigid slip of body 1 relative to body 2 over the rolling speed, the leading edge
is at the largest x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._record import SolveRecord, edge_contact, edge_warning
from contact.halfspace.constants import PairConstants
from contact.tangential._grid import Grid
from contact.tangential._kernels import SLIP, STICK
from contact.tangential._kinematics import Creepage, rigid_slip

# above this share of the dissipation in the contact's edge elements, the slip zone is
# not resolved by the grid (see TangentialResult.edge_dissipation_share)
EDGE_SHARE_LIMIT = 0.5


def edge_note(share: float) -> str | None:
    """One line saying the dissipation is not resolved by the grid, or None."""
    if share <= EDGE_SHARE_LIMIT:
        return None
    return (f"{100 * share:.0f} % of the frictional dissipation lies in the edge elements of "
            "the contact: the slip zone is not resolved by this grid and the dissipation "
            "depends on it; refine the grid (--grid) and compare")


@dataclass(frozen=True)
class TangentialResult:
    """Pressure, tractions and slip of a rolling or shift solve.

    Attributes
    ----------
    grid : Grid
        The grid and undeformed separation.
    constants : PairConstants
        Combined elastic constants (G, nu, K).
    mu : float
        Coefficient of friction.
    p : ndarray, shape (ny, nx)
        Pressure (Pa).
    q : ndarray, shape (2, ny, nx)
        Tractions on body 1 (Pa).
    s : ndarray, shape (2, ny, nx)
        Slip: velocity over V in rolling (dimensionless), distance in a shift (m).
    state : ndarray of int8
        0 exterior, 1 adhesion, 2 slip.
    creepage : Creepage
        Creepages in rolling; in a shift, xi and eta hold the rigid shift (m).
    approach : float
        Rigid approach delta (m) against the datum of h (plane strain: only relative).
    rolling : bool
        Steady rolling (else a shift).
    iterations : int
        Normal-tangential (Panagiotopoulos) iterations; in 3D steady rolling of
        dissimilar bodies, the pressure solves done inside the Newton loop.
    outer, matvecs : int
        Active-set iterations of the last tangential solve and the FFT operator products
        it used (0 where not recorded).
    tol : float
        The tolerance it was solved to (NaN where not recorded).
    solve : SolveRecord
        The solve record (:mod:`contact._record`), formed from the answer when the solver
        gives none: iterations the active-set iterations (``outer``), outer iterations
        the normal-tangential ones (``iterations``), the residual the slip residual of
        :func:`contact.tangential._solver.slip_residual` formed afresh, converged True (the
        solvers raise :class:`~contact._errors.ConvergenceError` otherwise), edge contact
        pressure on the grid's edge (:func:`contact._record.edge_contact`, with its warning).
    """

    grid: Grid
    constants: PairConstants
    mu: float
    p: np.ndarray
    q: np.ndarray
    s: np.ndarray
    state: np.ndarray
    creepage: Creepage
    approach: float
    rolling: bool
    iterations: int
    outer: int = 0
    matvecs: int = 0
    tol: float = float("nan")
    solve: SolveRecord | None = None

    def __post_init__(self) -> None:
        if self.solve is None:
            object.__setattr__(self, "solve", self._record())
            edge_warning(self.solve.edge_contact, stacklevel=4)

    def _record(self) -> SolveRecord:
        """The solve record formed from the answer with the elastic pair's operator."""
        from contact.halfspace.pair import HalfSpacePair
        from contact.tangential._solver import slip_residual

        g = self.grid
        op = HalfSpacePair(len(g.y), len(g.x), g.dx, g.dy, self.constants, line=g.line)
        u0 = op.tangential_from_normal(self.p)
        if self.rolling:
            w = rigid_slip(self.grid.x, self.grid.y, self.creepage)
        else:  # a rigid shift along x, held in creepage.xi (m)
            w = np.zeros_like(self.q)
            w[0] = self.creepage.xi
        res = slip_residual(self.s, self.state, self.directions, w, u0, self.mu * self.p,
                            self.grid.dx, self.rolling)
        return tangential_record(res, rolling=self.rolling, iterations=self.iterations,
                                 outer=self.outer, tol=self.tol, p=self.p, s=self.s)

    @property
    def directions(self) -> np.ndarray:
        """Unit directions of the tractions (0 where there is none), shape (2, ny, nx)."""
        norm = np.hypot(self.q[0], self.q[1])
        return np.divide(self.q, norm, out=np.zeros_like(self.q), where=norm > 0)

    @property
    def fn(self) -> float:
        """Normal force (N; N/m in plane strain)."""
        return float(self.p.sum() * self.grid.area)

    @property
    def fx(self) -> float:
        """Tangential force on body 1 along x (N; N/m in plane strain)."""
        return float(self.q[0].sum() * self.grid.area)

    @property
    def fy(self) -> float:
        """Tangential force on body 1 along y (N; N/m in plane strain)."""
        return float(self.q[1].sum() * self.grid.area)

    @property
    def pmax(self) -> float:
        """Peak pressure (Pa)."""
        return float(self.p.max())

    @property
    def contact_area(self) -> float:
        """Loaded area (m^2; contact width in m in plane strain)."""
        return float(np.count_nonzero(self.p > 0) * self.grid.area)

    @property
    def stick_area(self) -> float:
        """Adhesion area (m^2; m in plane strain)."""
        return float(np.count_nonzero(self.state == STICK) * self.grid.area)

    @property
    def slip_area(self) -> float:
        """Slip area (m^2; m in plane strain)."""
        return float(np.count_nonzero(self.state == SLIP) * self.grid.area)

    @property
    def n_stick(self) -> int:
        """Number of adhesion elements."""
        return int(np.count_nonzero(self.state == STICK))

    @property
    def n_slip(self) -> int:
        """Number of slip elements."""
        return int(np.count_nonzero(self.state == SLIP))

    def _dissipation(self) -> np.ndarray:
        """Frictional dissipation per element over dA, -q . s on the slip elements (Pa).

        Only slip elements dissipate: there the traction opposes the slip, so each term
        is mu p |s| >= 0. On adhesion elements the slip is zero up to the solver's
        tolerance, and -q . s of that remainder (of either sign, and large when mu is)
        is not dissipation."""
        w = -(self.q * self.s).sum(axis=0)
        return np.where(self.state == SLIP, w, 0.0)

    @property
    def frictional_power(self) -> float:
        """Frictional dissipation per unit rolling speed, -sum(q . s) dA over the slip
        elements (N = J/m rolled; N/m = J/m^2 in plane strain); never negative. In a
        shift, the frictional work of the step (J)."""
        return float(self._dissipation().sum() * self.grid.area)

    @property
    def edge_dissipation_share(self) -> float:
        """Share of the frictional dissipation on the elements at the edge of the contact
        area (loaded elements with an unloaded neighbour along x or y); 0 when nothing
        dissipates. Near 1, the slip lies in a band one element wide at the rim, where
        the traction bound mu p falls to zero: the grid does not resolve the slip zone
        and the dissipation depends on it (for free rolling of a smooth dissimilar pair it
        falls about threefold per halving of the element; on rough contacts it grows as
        more asperity rims are resolved), so refine the grid before trusting it."""
        inside = self.p > 0
        core = inside.copy()
        core[:, 1:] &= inside[:, :-1]
        core[:, :-1] &= inside[:, 1:]
        if inside.shape[0] > 1:
            core[1:, :] &= inside[:-1, :]
            core[:-1, :] &= inside[1:, :]
        core[:, [0, -1]] = False
        if inside.shape[0] > 1:
            core[[0, -1], :] = False
        w = self._dissipation()
        total = float(w.sum())
        return float(w[inside & ~core].sum() / total) if total > 0 else 0.0

    def pressure_moment(self) -> float:
        """Moment of the pressure about the contact centre, sum(p x) dA (N m; N in plane
        strain): positive when the pressure leans to the leading edge and resists rolling."""
        return float((self.p * self.grid.x[None, :]).sum() * self.grid.area)

    def pressure_moment_coefficient(self, radius: float) -> float:
        """The pressure's moment about the centre over N R (dimensionless): the
        asymmetry of this pressure. For elastic bodies it is not a dissipation (a rough
        contact's pressure leans either way with the asperities under it, a smooth
        one's by a rounding of the grid): see :meth:`rolling_resistance_coefficient`."""
        return self.pressure_moment() / (self.fn * radius)

    @property
    def rolling_resistance_coefficient(self) -> float:
        """The frictional dissipation per metre rolled over the normal load, F_r / N
        (dimensionless): the micro-slip rolling resistance M_r / (N R) of
        :mod:`contact.tangential._microslip` (Johnson 1985, sec. 8.2)."""
        return self.frictional_power / self.fn


def tangential_record(residual: float, *, rolling: bool, iterations: int, outer: int,
                      tol: float, p: np.ndarray, s: np.ndarray) -> SolveRecord:
    """The solve record of a tangential answer (pressure ``p``, slip ``s``) with its slip
    ``residual``; with nothing slipping and nothing to drive a slip (inf) it is 0."""
    if math.isinf(residual) and not np.any(s):
        residual = 0.0
    return SolveRecord(
        method="steady rolling" if rolling else "shift",
        iterations=int(outer) if outer else int(iterations),
        outer_iterations=int(iterations) if outer else None,
        residual=float(residual), tolerance=float(tol), converged=True,
        edge_contact=edge_contact(p),
        residual_definition="largest slip left on the adhesion elements or across the "
                            "traction on the slip elements, over the driving slip")
