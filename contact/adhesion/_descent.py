"""The adhesive solve's method: the accelerated projected gradient on the gap, both controls.

The energy per cell area of the gap g >= 0 (:mod:`contact.adhesion.solver`) is a sum of
terms, as in Tamaas' functional terms (Rey, Anciaux & Molinari 2017, Comput. Mech.
60:69):

- the elastic term 1/2 <u, S u>, u = g - h + delta, S the problem's stiffness (by default
  the exact inverse of the periodised Love kernel's spectrum, about E* |q| / 2) applied
  with the half-space operator's transforms
  (:meth:`contact.halfspace.convolution.Convolution.spectral`);
- the interaction law's sum phi(g) (the kernels' law code,
  :func:`contact.adhesion.solver.law_code`);
- the mean plane's term, which is the one difference between the two controls: at a
  prescribed approach delta the mean displacement is held by a spring as stiff as the
  stiffest Fourier mode; under load control the spring is off and the load's potential
  P A mean(g) adds the mean pressure P to the gradient. One control is the other with the
  spring switched: :class:`AcceleratedGradient` takes ``approach`` (spring on) or
  ``pressure`` (spring off).

The method is a projected gradient with Nesterov momentum (FISTA, Beck & Teboulle 2009,
SIAM J. Imaging Sci. 2:183), the momentum restarted whenever it points uphill
(O'Donoghue & Candes 2015, Found. Comput. Math. 15:715); the load-controlled solve adds
its free-cell shift and its divergence guard (:data:`contact.adhesion.solver.FREE_SHIFT`,
:data:`contact.adhesion.solver.DIVERGED`). The one driver of the normal solves
(:func:`contact.bem._loop.drive`) runs it: :func:`descend`.
"""

from __future__ import annotations

import math
from typing import Protocol

import numpy as np

from contact.adhesion import kernels
from contact.bem import _loop as loop
from contact.bem._loop import Check
from contact.bem._steps import Outcome
from contact.halfspace.convolution import Convolution


class GapProblem(Protocol):
    """What the method reads of :class:`contact.adhesion.solver.AdhesiveProblem`."""

    gap0: np.ndarray
    law: object  # an interaction law (contact.adhesion.laws), its kernel code given apart

    @property
    def operator(self) -> Convolution: ...

    @property
    def spring(self) -> float: ...

    def elastic_stiffness(self, spring: bool, single: bool = False) -> np.ndarray: ...


class AcceleratedGradient:
    """The gap solve as :func:`contact.bem._loop.drive` runs it (module notes).

    ``problem`` is a :class:`contact.adhesion.solver.AdhesiveProblem`; ``gap`` the start
    (left as it is); ``code`` the law's kernel code (``law_code``); ``approach`` (m: the
    spring on) or ``pressure`` (Pa: load control). ``step`` is the gradient step (m/Pa);
    ``single`` runs the transforms in float32 and stops at half ``tol``, for a float64
    check to pass. ``shift``: move the free cells' mean by that many times the step's
    (None: no shift); ``diverged``: stop where the violation exceeds that many times the
    first iterate's pressure scale (None: no guard).
    """

    def __init__(self, problem: GapProblem, gap: np.ndarray, code: tuple[int, float, float], *,
                 approach: float | None = None, pressure: float = 0.0, step: float,
                 tol: float, single: bool = False, shift: float | None = None,
                 diverged: float | None = None):
        self.operator, self.law = problem.operator, problem.law
        self.real = np.float32 if single else np.float64
        # the mean plane's term: the spring at the approach, or the load's mean pressure
        self.stiffness = problem.elastic_stiffness(approach is not None, single)
        self.pressure = self.real(pressure)
        self.single, self.step_length, self.code = single, step, code
        self.shift, self.diverged = shift, diverged
        self.stop = 0.5 * tol if single else tol  # float32: room for the float64 check
        self.minus = elastic_offset(problem, self.stiffness, approach, single)
        self.y = np.array(gap, dtype=float, order="C")
        self.flat_y = self.y.ravel()
        self.flat_g = self.flat_y.copy()
        self.flat_new = np.empty(self.y.size)
        # the transforms' input: y itself, or its float32 copy written by the momentum
        self.y_fft = self.y.astype(np.float32) if single else self.y
        self.flat_fft = self.y_fft.ravel()
        self.theta, self.uphill, self.limit = 1.0, False, math.inf
        self.iteration, self.evaluations, self.residual = 0, 0, math.inf

    def check(self) -> Check:
        """The gradient at y, its projected step (kept for :meth:`step`) and the test."""
        self.evaluations += 1
        p = self.operator.spectral(self.y_fft, self.stiffness, self.single, 1, self.minus)
        if self.pressure:
            p += self.pressure
        kind, reach, width = self.code
        viol, pmax, dot = kernels.gradient_step(self.flat_y, self.flat_g, p.ravel(), kind,
                                                self.law.peak, reach, width,
                                                self.step_length, self.flat_new)
        scale = max(self.law.peak, pmax)
        self.residual = viol / scale
        if viol <= self.stop * scale:
            return Check.CONVERGED
        if self.diverged is not None:
            if self.evaluations == 1:
                self.limit = self.diverged * scale
            elif not viol < self.limit:  # also NaN
                return Check.STOP
        self.uphill = dot > 0.0
        return Check.STEP

    def step(self) -> Outcome:
        """The momentum step from the projected step (restarted where it pointed uphill)."""
        if self.uphill:
            self.theta = 1.0
        theta = self.theta
        theta_new = 0.5 * (1.0 + math.sqrt(1.0 + 4.0 * theta * theta))
        c = (theta - 1.0) / theta_new
        y, g, new = self.flat_y, self.flat_g, self.flat_new
        if self.shift is not None:  # the free cells' mean moved 1 + shift times as far
            shift = self.shift * kernels.free_mean_step(y, new)
            kernels.momentum_shift_into(new, g, c, shift, y, self.flat_fft)
        else:
            kernels.momentum_into(new, g, c, y, self.flat_fft)
        self.flat_g, self.flat_new = new, g  # the new iterate is the next one's old
        self.theta = theta_new
        return Outcome.STEPPED


def elastic_offset(problem: GapProblem, stiffness: np.ndarray, approach: float | None,
                   single: bool = False) -> np.ndarray:
    """S h^, or S (h - delta)^ at an approach: the elastic pressure's spectrum is
    S g^ minus it (g the gap)."""
    h = problem.gap0 if approach is None else problem.gap0 - approach
    real = np.float32 if single else np.float64
    return stiffness * problem.operator.spectrum(h.astype(real), single, 1)


def descend(problem: GapProblem, gap: np.ndarray, code: tuple[int, float, float],
            max_iter: int, **terms) -> tuple[np.ndarray | None, int]:
    """Run :class:`AcceleratedGradient` (``terms``: its keywords) through the one driver,
    at most ``max_iter`` gradient evaluations: (the last iterate, or None where guarded
    (``diverged``) and it diverged or ran out; the evaluations done)."""
    method = AcceleratedGradient(problem, gap, code, **terms)
    try:
        verdict = loop.drive(method, max_iter - 1)
    finally:
        problem.operator.release()
    if not verdict.converged:
        if method.diverged is not None:
            return None, method.evaluations
        if not verdict.stopped:
            # out of budget: the last gradient's step is the iterate handed back (the
            # caller checks its residual exactly)
            method.step()
    return method.y, method.evaluations
