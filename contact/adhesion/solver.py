"""One adhesive normal solve on a periodic grid, at a prescribed approach or under a load.

The unknown is the gap g >= 0 between the deformed surfaces, as in the primal
formulation of Rey, Anciaux & Molinari (2017), Comput. Mech. 60:69. With the surface
displacement u = g - h + delta (h the initial gap, delta the rigid-body approach) the
total energy per cell area is

    Pi(g) = 1/2 <u, S u> + sum_i phi(g_i),

S the periodic half-space stiffness (the exact inverse of the spectrum of the core's
periodic Love operator, :class:`contact.halfspace.convolution.Convolution`, about
E* |q| / 2, applied with that operator's transforms) and phi the adhesion law's energy
(:mod:`contact.adhesion.laws`). Its stationary points under g >= 0 are the equilibria:
the pressure p = S u equals the attractive traction -t(g) where the surfaces are apart
and p >= -t(0) where they touch, so the tensile tractions come out of the solve
instead of being assumed. Pi is not convex (phi is concave), so a warm-started local
minimiser follows one equilibrium branch under displacement control, and a branch that
ends makes the next solve jump to another one: that is the jump-in and jump-out.

The mean displacement (the q = 0 mode, free in a periodic body) is held by a spring as
stiff as the stiffest Fourier mode, so that the conditioning is that of the elastic
operator; the spring's stretch P / (k A) is removed from the reported approach, which is
measured from the mean plane of the deformed surface. Pi is minimised by a projected
gradient with Nesterov momentum (FISTA, Beck & Teboulle 2009, SIAM J. Imaging Sci. 2:183),
the momentum restarted whenever it points uphill (O'Donoghue & Candes 2015, Found. Comput.
Math. 15:715), with the step 1 / (the largest stiffness), and 1.3 times that under
load control (:data:`LOAD_STEP`). Both controls are one method
(:class:`contact.adhesion._descent.AcceleratedGradient`: load control is approach control
with the mean-plane spring off and the load's pressure on) run by the one driver of the
normal solves (:func:`contact.bem._loop.drive`), as the non-adhesive and plastic solves
of :mod:`contact.bem` are.

Discretisation: a cell either touches (zero gap) or not and carries a uniform pressure,
so the contact edge is pinned by the pixels; on retraction the contact stays too large
and the tension too high, by an error first order in the pixel over the cohesive zone
l = pi E* w / (4 sigma0^2): about 0.7 dx / l on the pull-off of a sphere and of a wavy
surface alike (benchmarks/adhesion_convergence.py; tests/test_adhesion_validation.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError, ConvergenceError
from contact._grid import Grid, scan_grid
from contact._record import SolveRecord, edge_contact
from contact._validate import positive
from contact.adhesion._descent import descend, elastic_offset
from contact.adhesion.laws import InteractionLaw, kernel_arguments
from contact.bem._state import SolverStats
from contact.halfspace.convolution import Convolution, convolution

#: Step of the load-controlled solve (:func:`solve_adhesive_at_pressure`) in units of
#: 1 / (the largest stiffness). The momentum iteration y = x + beta (x - x'), x+ = y - s
#: grad(y) on a mode of curvature lambda is stable while s lambda < 2 (1 + beta) /
#: (1 + 2 beta), which is 4/3 or more for every beta < 1 (FISTA's beta stays below 1),
#: and the law's concave energy only lowers lambda. On the benchmark's surface (128^2 to
#: 512^2) 1.3 took 12 to 14 % fewer iterations than 1 and found the same contact cells;
#: 1.4 diverged.
LOAD_STEP = 1.3
#: A load-controlled solve whose violation exceeds this many times the first iterate's
#: pressure scale has diverged, and is solved again at the step 1 / (largest stiffness).
DIVERGED = 1e3
#: The accelerated load-controlled solve (the step LOAD_STEP and the free cells' shift,
#: both chosen on the benchmark's surface, not derived for every one) gets this share of
#: the iteration budget; a solve that has not converged within it has stalled, and is
#: solved again from its start with the classical step and no shift, which has the rest.
ACCELERATED_SHARE = 0.25
#: Under load control the mean gap has no elastic stiffness (the q = 0 mode is free), and
#: the gradient step moves it slowly: after each step the cells apart are moved by
#: FREE_SHIFT more times the step's mean over them, times their share of the cells (where
#: the contact is large the free cells are pockets between contacts, stiff to a uniform
#: shift: unweighted, 4 left a 64^2 solve at 55 % contact unconverged). On the
#: benchmark's surface 4 took 26 % (512^2) and 37 % (128^2) fewer iterations than without
#: it (at the step 1.3), the same contact cells.
FREE_SHIFT = 4.0


@dataclass(frozen=True)
class AdhesiveState:
    """One equilibrium of an adhesive contact (SI units).

    Attributes
    ----------
    gap, pressure : ndarray, shape (ny, nx)
        Gap g >= 0 (m) and pressure p (Pa, compression positive, tension negative).
    approach : float
        Approach of the rigid bodies (m), from the mean plane of the deformed surface.
    load : float
        Total normal load (N; negative: the surfaces pull on each other).
    contact_area : float
        Area where the gap is zero (m^2).
    energy : float
        Elastic plus interaction energy (J), the potential whose derivative in the
        approach is the load.
    residual : float
        Largest violation of equilibrium, relative to the larger of the law's peak
        tension and the largest compressive pressure.
    iterations : int
        Projected-gradient iterations.
    solve : SolveRecord
        The solve record (:mod:`contact._record`; the domain is periodic: no edge).
    """

    gap: np.ndarray
    pressure: np.ndarray
    approach: float
    load: float
    contact_area: float
    energy: float
    residual: float
    iterations: int
    solve: SolveRecord


@dataclass(frozen=True, eq=False)
class AdhesiveProblem:
    """The fixed data of a series of adhesive solves on one periodic grid.

    Build with :func:`adhesive_problem` (a 3D grid) or
    :func:`contact.adhesion.line.line_problem` (a line contact).
    """

    gap0: np.ndarray
    dx: float
    e_star: float
    law: InteractionLaw
    stiffness: np.ndarray  # E* |q| / 2 on the rfft grid, the q = 0 entry the mean spring
    grid: Grid | None = None  # the grid the problem was built on (coordinates, boundary)

    @property
    def cell_area(self) -> float:
        """Area of one cell (m^2)."""
        return self.dx * self.dx

    @property
    def operator(self) -> Convolution:
        """The periodic half-space operator of the grid (E* = 1; cached by the factory)."""
        ny, nx = self.gap0.shape
        return convolution(ny, nx, self.dx, self.dx, True)

    def elastic_stiffness(self, spring: bool, single: bool = False) -> np.ndarray:
        """The stiffness the elastic term applies: with the mean-plane spring (approach
        control) or without it (q = 0 free: load control), in float32 where ``single``."""
        if spring and not single:
            return self.stiffness
        stiff = self.stiffness.astype(np.float32 if single else np.float64)  # a copy
        if not spring:
            stiff[0, 0] = 0.0
        return stiff

    @property
    def spring(self) -> float:
        """Stiffness per area of the mean-displacement spring (Pa/m)."""
        return float(self.stiffness[0, 0])

    def equilibrium(self, approach: float, initial: np.ndarray | None = None, *,
                    tol: float = 1e-7) -> AdhesiveState:
        """:func:`solve_adhesive` at ``approach`` from the gap ``initial`` (the call of
        :mod:`contact.adhesion.cycle`, which the ring problem answers too)."""
        return solve_adhesive(self, approach, initial, tol=tol)


def adhesive_problem(gap0: np.ndarray | Grid, dx: float | None = None,
                     e_star: float | None = None,
                     law: InteractionLaw | None = None) -> AdhesiveProblem:
    """Check the input and precompute the periodic stiffness of a square-pitch grid.

    Parameters
    ----------
    gap0 : ndarray, shape (ny, nx), or Grid
        The undeformed gap h (m) on square cells of pitch ``dx``, or a periodic 3D
        :class:`contact._grid.Grid` carrying it (then ``dx`` is not given: the grid holds
        its pitch and origin, as for :func:`contact.bem.solve_normal`).
    dx : float
        Pixel (m), with an array gap.
    e_star : float
        Composite modulus E* (Pa).
    law : InteractionLaw
        The adhesion law.
    """
    grid = _periodic_grid(gap0, dx)
    if e_star is None or law is None:
        raise ContactInputError("give the composite modulus e_star (Pa) and the law")
    h = np.ascontiguousarray(grid.h, dtype=float)
    if not (grid.dx > 0 and e_star > 0):
        raise ContactInputError("the pitch and E* must be positive")
    ny, nx = h.shape
    # the inverse of the core's periodic Love operator (uniform pressure on each cell),
    # the same operator as the periodic normal BEM's
    with np.errstate(divide="ignore"):
        s = e_star / convolution(ny, nx, grid.dx, grid.dx, True).spec64
    s[0, 0] = 0.0
    s[0, 0] = s.max()
    return AdhesiveProblem(h, grid.dx, float(e_star), law, s, grid)


def _periodic_grid(gap0: np.ndarray | Grid, dx: float | None) -> Grid:
    """The periodic, square-pitch 3D grid of an adhesive problem, with its gap: the Grid
    given, checked, or one laid like a scan's pixels around an array gap."""
    if isinstance(gap0, Grid):
        if dx is not None:
            raise ContactInputError("a Grid carries its pitch: do not give dx with it")
        if gap0.h is None or gap0.line:
            raise ContactInputError(
                "the adhesive solve needs a 3D Grid with its gap h (a line contact is "
                "contact.adhesion.line.line_problem's)")
        if not gap0.periodic:
            raise ContactInputError("the adhesive solve is periodic: give a periodic Grid")
        if gap0.dx != gap0.dy:
            raise ContactInputError(
                f"the adhesive solve needs square cells, the grid's are {gap0.dx:g} x "
                f"{gap0.dy:g} m")
        h = np.asarray(gap0.h, dtype=float)
    else:
        if dx is None:
            raise ContactInputError("give the pixel dx (m), or the gap as a contact._grid.Grid")
        h = np.asarray(gap0, dtype=float)
    if h.ndim != 2 or min(h.shape) < 4 or not np.isfinite(h).all():
        raise ContactInputError("the gap must be a finite 2D array of at least 4x4")
    if isinstance(gap0, Grid):
        return gap0
    pitch = positive(dx, "the pixel dx", "m")
    return scan_grid(h.shape, pitch, periodic=True, h=np.ascontiguousarray(h))


def solve_adhesive(problem: AdhesiveProblem, approach: float,
                   initial: np.ndarray | None = None, *, tol: float = 1e-7,
                   max_iter: int = 20000) -> AdhesiveState:
    """The equilibrium nearest ``initial`` (a gap field) at rigid approach ``approach``.

    Parameters
    ----------
    problem : AdhesiveProblem
        Grid, stiffness and law (:func:`adhesive_problem`).
    approach : float
        Rigid-body approach delta (m) imposed on the spring-held mean plane.
    initial : ndarray, optional
        Warm start: a gap field (e.g. the previous step's); default the rigid gap.
    tol : float
        Largest violation of equilibrium (projected gradient), relative to the larger of
        the law's peak tension and the largest compressive pressure.
    max_iter : int
        Iteration limit of the projected gradient.

    Raises
    ------
    ConvergenceError
        When the iteration limit is reached before the tolerance.
    """
    h, law = problem.gap0, problem.law
    if initial is not None and np.shape(initial) != h.shape:
        raise ContactInputError(
            f"the warm-start gap has shape {np.shape(initial)}, the grid {h.shape}")
    g = np.maximum(h - approach if initial is None else np.asarray(initial, dtype=float), 0.0)
    # 1 / the largest stiffness: the quadratic's Lipschitz constant
    y, nit = descend(problem, g, law_code(law), max_iter, approach=approach,
                     step=1.0 / problem.spring, tol=tol)
    return _state(problem, y, approach, nit, tol, counts=_counters(problem, nit, False))


def solve_adhesive_at_pressure(problem: AdhesiveProblem, pressure: float,
                               initial: np.ndarray, *, tol: float = 1e-7,
                               max_iter: int = 20000, single: bool = False) -> AdhesiveState:
    """The equilibrium nearest ``initial`` (a gap field) under the mean pressure ``pressure``.

    Load control: the mean-plane spring is dropped (the q = 0 stiffness set to zero) and
    the load's potential P A mean(g) added to Pi (with the mean displacement zero, the
    approach is mean(h) - mean(g), so its work -P A delta is P A mean(g) up to a
    constant). The gradient is then p' + P + t(g), p' the elastic pressure of zero mean,
    and one minimisation gives the equilibrium that carries P, whose pressure field is
    p' + P. For P > 0, Pi is bounded below (g >= 0, phi >= -w), so a minimum exists; under
    a tension, surfaces apart are unstable under load control (t falls with the gap), and
    :func:`solve_adhesive` under a prescribed approach is the tool.

    Parameters
    ----------
    problem, tol, max_iter
        As for :func:`solve_adhesive`.
    pressure : float
        The mean pressure imposed (Pa, compression positive).
    initial : ndarray
        Warm start, required: a gap field (e.g. the rigid gap touching at its highest
        point, or the previous load's equilibrium).
    single : bool
        Run the two FFTs of each iteration in float32 (about four times cheaper), and
        the exponential law's exponential to float32 accuracy (:mod:`contact.adhesion.kernels`), for
        loose tolerances only: their rounding, about 1e-7 of the largest modal pressure,
        must stay well below ``tol`` times the pressure scale. The iteration then stops at
        half ``tol``, and the final residual is checked in float64.

    Returns
    -------
    AdhesiveState
        The approach is measured from the mean plane of the deformed surface, as in
        :func:`solve_adhesive`.
    """
    h = problem.gap0
    if np.shape(initial) != h.shape:
        raise ContactInputError(
            f"the warm-start gap has shape {np.shape(initial)}, the grid {h.shape}")
    g = np.ascontiguousarray(np.maximum(np.asarray(initial, dtype=float), 0.0))
    budget = max(1, int(ACCELERATED_SHARE * max_iter))
    code = law_code(problem.law, single)
    y, nit = descend(problem, g, code, budget, pressure=pressure,
                     step=LOAD_STEP / problem.spring, tol=tol, single=single,
                     shift=FREE_SHIFT, diverged=DIVERGED)
    if y is None:  # diverged or stalled: again with the classical step and no shift
        y, more = descend(problem, g, code, max_iter - nit, pressure=pressure,
                          step=1.0 / problem.spring, tol=tol, single=single)
        nit += more
    return _state(problem, y, float(np.mean(h) - np.mean(y)), nit, tol,
                  mean_pressure=pressure, counts=_counters(problem, nit, single))


def law_code(law: InteractionLaw, single: bool = False) -> tuple[int, float, float]:
    """The law as the kernels take it (:mod:`contact.adhesion.kernels`): (code, reach,
    ramp width), as the law states it; an unregistered law is refused
    (:func:`contact.adhesion.laws.kernel_arguments`)."""
    return kernel_arguments(law, single)


def _counters(problem: AdhesiveProblem, evaluations: int, single: bool) -> SolverStats:
    """The work of one adhesive solve, counted as the normal BEM counts its own
    (:class:`contact.bem._state.SolverStats`, copied into ``SolveRecord.counters``): each
    gradient evaluation of the descent applies the stiffness once with the operator's
    transforms (:meth:`contact.halfspace.convolution.Convolution.spectral`, a forward and
    an inverse FFT), in float32 where ``single``; the record's pressure (:func:`_state`)
    applies it once more in float64. The forward transforms of the undeformed gap
    (:func:`contact.adhesion._descent.elastic_offset`, one per descent and one for the
    record) are no convolution and are not counted."""
    n = int(evaluations)
    return SolverStats(iterations=n, fft_single=n if single else 0,
                       fft_double=(0 if single else n) + 1,
                       levels=[(*problem.gap0.shape, n)])


def _violation(g: np.ndarray, grad: np.ndarray) -> np.ndarray:
    """Violation of equilibrium per cell (Pa): |p + t| apart, max(-(p + t), 0) touching."""
    return np.where(g <= 0.0, np.maximum(-grad, 0.0), np.abs(grad))


def _state(problem: AdhesiveProblem, g: np.ndarray, approach: float, nit: int,
           tol: float, mean_pressure: float | None = None,
           counts: SolverStats | None = None) -> AdhesiveState:
    """The equilibrium record of the gap ``g``, after checking its residual; with
    ``mean_pressure`` (load control) the mean displacement is zero and the mean pressure
    that."""
    h, law = problem.gap0, problem.law
    # the pressure as the iteration formed it (the same rounding as its own test)
    stiffness = problem.elastic_stiffness(mean_pressure is None)
    p = problem.operator.spectral(
        g, stiffness, False, 1,
        elastic_offset(problem, stiffness, None if mean_pressure is not None else approach))
    if mean_pressure is not None:
        p += mean_pressure
    u = g - h + approach
    t = law.traction(g)
    touching = g <= 0.0
    residual = float(_violation(g, p + t).max()) / max(law.peak, float(p.max()))
    if residual > tol:
        raise ConvergenceError(
            f"the adhesive solve stopped at residual {residual:.3g} of the pressure scale "
            f"(approach {approach:.4g} m); refine the approach steps or the grid",
            residual=residual, iterations=nit)
    area = problem.cell_area
    pressure = np.where(touching, p, -t)
    load = float(p.sum() * area)
    if mean_pressure is None:
        mean_u = load / (problem.spring * h.size * area)
        elastic = 0.5 * float(np.vdot(u, p)) - 0.5 * problem.spring * mean_u ** 2 * h.size
    else:  # u has zero mean, so the mean pressure does no elastic work
        mean_u = 0.0
        elastic = 0.5 * float(np.vdot(u, p - mean_pressure))
    return AdhesiveState(
        gap=g, pressure=pressure, approach=approach - mean_u, load=load,
        contact_area=float(touching.sum() * area),
        energy=(elastic + float(law.potential(g).sum())) * area,
        residual=residual, iterations=int(nit),
        solve=SolveRecord(method="adhesive (accelerated projected gradient)",
                          iterations=int(nit), residual=residual, tolerance=tol,
                          converged=True, edge_contact=edge_contact(touching, periodic=True),
                          periodic=True,
                          residual_definition="largest violation of equilibrium over the "
                                              "pressure scale",
                          counters=None if counts is None else counts.snapshot()),
    )
