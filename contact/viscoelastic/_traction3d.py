"""Tangential tractions of steady rolling on a viscoelastic half-space in 3D.

The 3D counterpart of :mod:`contact.viscoelastic._traction` (plane strain): Coulomb
friction, stick and slip areas, prescribed creepage xi or prescribed total force F_x
(free rolling: 0), for the pressure of :mod:`contact.viscoelastic._surface`. The active-set
Newton machinery of :mod:`contact.tangential._solver` is reused unchanged; only the
influence operator differs.

Operator. Poisson's ratio is constant in time (CONTACT's convention, see
:mod:`contact.viscoelastic._rheology`), so every Cerruti kernel of
:mod:`contact.halfspace.cerruti` (Johnson 1985, *Contact Mechanics*, eqs. 3.86-3.87)
carries the time dependence of 1/G(t), i.e. of the pair's creep compliance
C(t) = C_g + sum dC_m (1 - exp(-t/theta_m)). This is exact for one viscoelastic body
against a rigid one, or for two bodies with the same nu (quasi-identical: no
normal-tangential coupling, K = 0). With w = A_g q the glassy elastic displacement
(G_g = (1 - nu)/C_g) the steady-state hereditary integral along the rolling direction
is the one :mod:`contact.viscoelastic._surface` applies to the normal kernel
(Carbone & Putignano 2013, J. Mech. Phys. Solids 61:1822, eq. 10):

    u = w + sum (dC_m / C_g) F_m(w),
    F_m(x, y) = (1/l_m) int_0^inf exp(-xi/l_m) w(x + xi, y) dxi,   l_m = V theta_m,

the material at x having passed x + xi a time xi/V before (the contact moves towards +x,
the sign convention of :mod:`contact.tangential._kinematics`). F_m is the exact recursive
filter :func:`contact.viscoelastic._kernels.creep_filter_rows`. w is needed ahead of the
grid: it is computed on the grid extended ahead by ``ahead`` grid lengths (tractions zero
there) and continued beyond by the 1/r decay of a point force at the grid centre
(Gauss-Laguerre quadrature), which keeps the operator linear in q.

Limits: l -> 0 gives F = w and u = (C_r/C_g) w, the relaxed elastic body; l -> inf
gives F -> 0 and the glassy one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._record import LEADING_EDGE, edge_contact, edge_warning, raise_edge
from contact.halfspace.constants import PairConstants
from contact.halfspace.pair import HalfSpacePair
from contact.tangential._grid import Grid
from contact.tangential._kinematics import Creepage, rigid_slip
from contact.tangential._results import TangentialResult, tangential_record
from contact.tangential._solver import slip_residual, solve_tangential
from contact.tangential._steady import check_friction
from contact.viscoelastic._kernels import creep_filter_rows
from contact.viscoelastic._rheology import CreepSeries, pair_creep
from contact.viscoelastic._surface import monopole_tail


def constants_at(compliance: float, nu: float) -> PairConstants:
    """Elastic pair constants of the surface compliance C = 1/E* (1/Pa) and nu (K = 0)."""
    if not (math.isfinite(nu) and -1.0 < nu < 0.5 + 1e-12):
        raise ContactInputError(f"Poisson's ratio must lie in (-1, 0.5], got {nu!r}")
    return PairConstants(G=(1.0 - nu) / compliance, nu=float(nu), K=0.0)


def pair_poisson(body1: object, body2: object) -> float:
    """The pair's combined Poisson ratio nu (Kalker 1990, sec. 1.5), the bodies weighted by
    their mean surface compliances C_i = (C_g + C_r)/2 (None: rigid):

        nu/(1 - nu) = sum nu_i C_i/(1 - nu_i) / sum C_i,

    from 1/G_i = 2 C_i/(1 - nu_i). Exact for one deforming body or equal ratios.
    """
    num = den = 0.0
    for body in (body1, body2):
        if body is None:
            continue
        cs = pair_creep(body, None)
        c = 0.5 * (cs.glassy + cs.relaxed)
        nu = float(body.nu)
        num += nu * c / (1.0 - nu)
        den += c
    if den == 0.0:
        raise ContactInputError("at least one body must deform (both were rigid)")
    r = num / den
    return r / (1.0 + r)


class ViscoHalfSpacePair(HalfSpacePair):
    """The steady-rolling tangential operator of a viscoelastic pair (see module notes).

    Its elastic attributes (``c``, ``real``, ``spec``, the preconditioner) are those of
    the mean compliance (C_g + C_r)/2; :meth:`tangential` is the viscoelastic product.

    Parameters
    ----------
    ny, nx : int
        Grid shape.
    dx, dy : float
        Element size (m).
    creep : CreepSeries
        The pair's creep series.
    nu : float
        The combined Poisson ratio (constant in time).
    speed : float
        Rolling speed V (m/s).
    ahead : float
        Extension of the evaluation grid ahead, in grid lengths.
    """

    def __init__(self, ny: int, nx: int, dx: float, dy: float, creep: CreepSeries,
                 nu: float, speed: float, ahead: float = 0.5):
        if not (math.isfinite(speed) and speed > 0):
            raise ContactInputError(f"the rolling speed must be positive in m/s, got {speed!r}")
        super().__init__(ny, nx, dx, dy, constants_at(0.5 * (creep.glassy + creep.relaxed), nu))
        self.creep, self.speed = creep, float(speed)
        self.m = math.ceil(ahead * nx) if creep.amplitudes else 0
        # the glassy pair on the grid extended ahead (the tractions are zero there)
        self._ext = HalfSpacePair(ny, nx, dx, dy, constants_at(creep.glassy, nu),
                                  ahead=self.m)
        # the tail from a point force at the grid centre (not the tractions' centroid),
        # which keeps the operator linear in q
        yc = (np.arange(ny) - 0.5 * (ny - 1)) * dy
        xe = (nx + self.m - 1 - 0.5 * (nx - 1)) * dx
        self._tails = [monopole_tail(xe, 0.0, yc, self.speed * th) for th in creep.times]

    def tangential(self, qx: np.ndarray, qy: np.ndarray | None = None,
                   single: bool = False) -> np.ndarray:
        """(u_x, u_y), shape (2, ny, nx), of the tractions in steady rolling (m);
        ``single``: float32 transforms of the elastic part (for loose inner solves)."""
        w = self._ext.tangential(qx, qy if qy is not None and np.any(qy) else None, single)
        u = w.copy()
        cg = self.creep.glassy
        for dc, th, tail in zip(self.creep.amplitudes, self.creep.times, self._tails):
            for k in range(2):
                wk = np.ascontiguousarray(w[k])
                u[k] += (dc / cg) * creep_filter_rows(wk, wk[:, -1] * tail, self.dx,
                                                      self.speed * th)
        return u[..., : self.nx]


def pressure_tangential(op: ViscoHalfSpacePair, p: np.ndarray, body1: object,
                        body2: object) -> np.ndarray:
    """(u_x, u_y), shape (2, ny, nx), of the pressure in steady rolling of dissimilar
    bodies (m): Kalker's coupling term (u_x from p = -K x/(pi G rho^2),
    :mod:`contact.halfspace.cerruti`) with its own time dependence.

    With constant Poisson ratios K/G = (b1 C1(t) - b2 C2(t))/2, b_i = (1 - 2 nu_i)/(1 - nu_i)
    and C_i(t) the surface creep compliance of body i (1/G_i = 2 C_i/(1 - nu_i)), so each
    body's part is its glassy value times the unit-K/G displacement w of p plus its delayed
    amplitudes times the creep filters F_m(w) of its own times (as in
    :class:`ViscoHalfSpacePair`). A rigid body (None) contributes nothing. The relaxed
    limit (V theta -> 0) is the elastic coupling of the relaxed moduli, the glassy one
    (V theta -> inf) that of the glassy moduli.
    """
    from contact.halfspace.constants import PairConstants

    unit = HalfSpacePair(op.ny, op.nx, op.dx, op.dy, PairConstants(G=1.0, nu=0.0, K=1.0),
                         ahead=op.m)
    w = unit.tangential_from_normal(np.asarray(p, dtype=float))
    u = np.zeros_like(w)
    yc = (np.arange(op.ny) - 0.5 * (op.ny - 1)) * op.dy
    xe = (op.nx + op.m - 1 - 0.5 * (op.nx - 1)) * op.dx
    for sign, body in ((1.0, body1), (-1.0, body2)):
        if body is None:
            continue
        nu = float(body.nu)  # type: ignore[attr-defined]
        coef = 0.5 * sign * (1.0 - 2.0 * nu) / (1.0 - nu)
        cs = pair_creep(body, None)
        u += coef * cs.glassy * w
        for dc, th in zip(cs.amplitudes, cs.times):
            ell = op.speed * th
            tail = monopole_tail(xe, 0.0, yc, ell)
            for k in range(2):
                wk = np.ascontiguousarray(w[k])
                u[k] += coef * dc * creep_filter_rows(wk, wk[:, -1] * tail, op.dx, ell)
    return u[..., : op.nx]


@dataclass(frozen=True)
class ViscoRolling:
    """A viscoelastic pair rolling at a speed: what its operator
    (:class:`ViscoHalfSpacePair`) needs besides the grid.

    Attributes
    ----------
    creep : CreepSeries
        The pair's creep series.
    nu : float
        The combined Poisson ratio.
    speed : float
        Rolling speed V (m/s).
    ahead : float
        Extension of the operator's evaluation grid ahead, in grid lengths.
    """

    creep: CreepSeries
    nu: float
    speed: float
    ahead: float = 0.5


def visco_steady_tractions(grid: Grid, pressure: np.ndarray, rolling: ViscoRolling, mu: float,
                           *, creepage: float | None = None, fx: float | None = None,
                           tol: float = 1e-6, coupling: tuple | None = None
                           ) -> TangentialResult:
    """Steady rolling tractions on a viscoelastic pair for a given pressure (3D).

    Parameters
    ----------
    grid : Grid
        The grid (:func:`contact.tangential._grid.sphere_grid` or the pressure's own).
    pressure : ndarray, shape (ny, nx)
        Pressure (Pa), e.g. from :func:`contact.viscoelastic._surface.solve_surface`.
    rolling : ViscoRolling
        The pair's creep series, combined Poisson ratio and rolling speed
        (:class:`ViscoRolling`).
    mu : float
        Coefficient of friction (> 0).
    creepage : float, optional
        Prescribed longitudinal creepage xi; otherwise the force ``fx`` is prescribed.
    fx : float, optional
        Prescribed F_x on body 1 (N), |F_x| < mu N (default 0: free rolling).
    tol : float
        Tolerance of the slip directions and linear solves.
    coupling : (body1, body2), optional
        The two bodies (None: rigid) of a dissimilar pair: the tangential displacement of
        the pressure (:func:`pressure_tangential`) joins the slip, one-way coupling (the
        pressure is given; the tractions' normal displacement does not change it).
        Without it the bodies are quasi-identical (K = 0).
    """
    mu = check_friction(mu)
    if grid.line:
        raise ContactInputError("plane strain: use contact.viscoelastic._traction")
    if creepage is not None and fx is not None:
        raise ContactInputError("prescribe the tangential force or the creepage, not both")
    if creepage is not None and not math.isfinite(creepage):
        raise ContactInputError(f"the creepage must be a finite number, got {creepage!r}")
    p = np.asarray(pressure, dtype=float)
    if p.shape != grid.h.shape:
        raise ContactInputError(f"the pressure must have the grid's shape {grid.h.shape}")
    if edge_contact(p, leading_only=True):
        raise_edge(LEADING_EDGE, "the grid")
    op = ViscoHalfSpacePair(len(grid.y), len(grid.x), grid.dx, grid.dy, rolling.creep,
                            rolling.nu, rolling.speed, rolling.ahead)
    g = mu * p
    u0 = (np.zeros((2, *p.shape)) if coupling is None
          else pressure_tangential(op, p, *coupling))
    xi = 0.0 if creepage is None else float(creepage)
    force = None
    if creepage is None:
        force = 0.0 if fx is None else float(fx)
        fn = float(p.sum()) * grid.area
        if abs(force) >= mu * fn:
            raise ContactInputError(
                f"tangential force {abs(force):.4g} N is not below the friction limit "
                f"mu N = {mu * fn:.4g} N: the bodies slide as a whole")
    w = rigid_slip(grid.x, grid.y, Creepage(xi))
    st = solve_tangential(op, g, w, u0, rolling=True, tol=tol, force=force, area=grid.area)
    xi += st.dw
    # the residual with this viscoelastic operator (the result's default uses the elastic one)
    res = slip_residual(st.s, st.state, st.e, rigid_slip(grid.x, grid.y, Creepage(xi)), u0, g,
                        grid.dx, True)
    record = tangential_record(res, rolling=True, iterations=1, outer=st.outer, tol=tol,
                               p=p, s=st.s)
    edge_warning(record.edge_contact)
    return TangentialResult(grid=grid, constants=op.c, mu=mu, p=p, q=st.q, s=st.s,
                            state=st.state, creepage=Creepage(xi), approach=float("nan"),
                            rolling=True, iterations=1, outer=st.outer, matvecs=st.matvecs,
                            tol=tol, solve=record)


def rolling_sphere_tractions(radius: float, load: float, creep: CreepSeries, nu: float,
                             speed: float, mu: float, *, n: int = 64,
                             creepage: float | None = None, fx: float | None = None,
                             tol: float = 1e-6, **normal_kw) -> tuple:
    """A ball rolling on a viscoelastic pair: the normal solve of
    :func:`contact.viscoelastic._surface.rolling_sphere`, then the tractions on its grid.

    Returns (RollingResult, TangentialResult).
    """
    from contact.viscoelastic._surface import rolling_sphere

    res = rolling_sphere(radius, load, creep, speed, n=n, **normal_kw)
    x, y = np.asarray(res.x), np.asarray(res.y)
    h = (x[None, :] ** 2 + y[:, None] ** 2) / (2.0 * radius)
    grid = Grid(x=x, y=y, h=h)
    tr = visco_steady_tractions(grid, np.asarray(res.pressure), ViscoRolling(creep, nu, speed),
                                mu, creepage=creepage, fx=fx, tol=tol)
    return res, tr
