"""The one iteration driver of the 3D normal solves: test, step, until converged or out of budget.

Every 3D normal solve runs through :func:`drive`; what differs between them is the
*method* plugged in, the object that knows the problem's terms (Tamaas' functional terms
are the model: Frérot, Anciaux, Rey & Molinari; Rey, Anciaux & Molinari 2017, Comput.
Mech. 60:69):

- :class:`contact.bem._iteration.PolonskyKeer`: the pressure under
  :class:`contact.bem._bounds.PressureBounds`, the elastic energy alone (0 <= p) or with
  a cap (0 <= p <= H, the plastic solve): the bounds pick the conjugate-gradient or the
  projected-gradient step of :mod:`contact.bem._steps`;
- :class:`contact.adhesion._descent.AcceleratedGradient`: the gap under g >= 0, the
  elastic energy plus the interaction law's plus the mean plane's (a spring at a
  prescribed approach, the load's potential under load control).

A method has two calls and two numbers:

- ``check()`` measures the residual of the current iterate and says what comes next
  (:class:`Check`): converged, step, test again (the method refreshed its iterate, e.g.
  the mixed-precision re-sync of the displacement), or stop (it diverged);
- ``step()`` takes one step and says what it did (:class:`contact.bem._steps.Outcome`);
- ``iteration``, the steps taken (the driver counts them), and ``residual``, the last
  measured residual (the callback's second argument).

The driver owns the budget (``budget`` steps), the callback (after every step that moved
the iterate) and the verdict (:class:`Verdict`); what the caller does with a verdict that
did not converge (raise, or return the iterate with ``converged=False``) is the caller's
strictness.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

from contact.bem._steps import Outcome


class Check(enum.Enum):
    """What the residual test of the iterate says comes next."""

    CONVERGED = "converged"
    STEP = "step"
    AGAIN = "again"  # the iterate was refreshed (a re-sync): test again, no step taken
    STOP = "stop"  # the method cannot go on (it diverged)


class Method(Protocol):
    """A normal-solve method as :func:`drive` runs it (module notes)."""

    iteration: int
    residual: float

    def check(self) -> Check:
        """Measure the residual of the current iterate; what comes next."""

    def step(self) -> Outcome:
        """One step from the current iterate."""


@dataclass(frozen=True)
class Verdict:
    """How a drive ended: ``converged``, or stopped by the method (``stopped``: a stall or
    a divergence) or by the budget (neither)."""

    converged: bool
    stopped: bool


def drive(method: Method, budget: int,
          callback: Callable[[int, float], Any] | None = None) -> Verdict:
    """Test and step ``method`` until it converges, stops, or has taken ``budget`` steps.

    ``method.iteration`` counts the steps (a warm method keeps its count: the budget is
    the total); ``callback(iteration, residual)`` is called after each step that moved
    the iterate.
    """
    while True:
        check = method.check()
        if check is Check.CONVERGED:
            return Verdict(converged=True, stopped=False)
        if check is Check.AGAIN:
            continue
        if check is Check.STOP:
            return Verdict(converged=False, stopped=True)
        if method.iteration >= budget:
            return Verdict(converged=False, stopped=False)
        method.iteration += 1
        outcome = method.step()
        if outcome is Outcome.STOP:
            return Verdict(converged=False, stopped=True)
        if outcome is Outcome.STEPPED and callback is not None:
            callback(method.iteration, method.residual)
