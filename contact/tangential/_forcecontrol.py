"""A prescribed total tangential force: the rigid slip that produces it.

The total force F_x is a non-increasing function of the rigid slip (creepage xi in
rolling, rigid shift in a shift): more slip of body 1 forward, more friction backward.
The slip for a target force is found by bracketing and the Illinois variant of regula
falsi (Dowell & Jarratt 1971, BIT 11:168), which keeps the force values it has (a solve
is not repeated at a bracket end) and every solve warm-started from the previous one
(CONTACT's outer Newton-Raphson on CKSI plays the same part).
"""

from __future__ import annotations

from collections.abc import Callable

from contact._errors import ContactInputError, ConvergenceError


def slip_for_force(
    force_of: Callable[[float], float],
    target: float,
    start: float,
    scale: float,
    bound: float,
    *,
    rtol: float = 1e-7,
    ftol: float = 1e-7,
) -> float:
    """The rigid slip x with ``force_of(x) == target``.

    Parameters
    ----------
    force_of : callable
        x -> total force (N); it solves the contact problem at x.
    target : float
        The prescribed force (N).
    start : float
        First guess of x.
    scale : float
        A typical size of x (first bracketing step).
    bound : float
        The largest force friction can carry, mu N: |target| must stay below it.
    rtol : float
        Tolerance on x relative to ``scale``.
    ftol : float
        Tolerance on the force relative to ``bound``.

    Raises
    ------
    ContactInputError
        If |target| >= bound (the bodies would slide as a whole).
    ConvergenceError
        If no bracket is found.
    """
    if abs(target) >= bound:
        raise ContactInputError(
            f"tangential force {abs(target):.4g} N is not below the friction limit "
            f"mu N = {bound:.4g} N: the bodies slide as a whole")
    f0 = force_of(start) - target
    if f0 == 0.0:
        return start
    direction = 1.0 if f0 > 0 else -1.0  # force falls as the slip grows
    lo, flo = start, f0
    step = scale
    for _ in range(60):
        hi = lo + direction * step
        fhi = force_of(hi) - target
        if fhi == 0.0:
            return hi
        if (fhi > 0) != (flo > 0):
            return _illinois(force_of, target, lo, flo, hi, fhi, rtol * scale,
                             ftol * bound)
        lo, flo = hi, fhi
        step *= 2.0
    raise ConvergenceError("no rigid slip found that gives the prescribed tangential force")


def _illinois(force_of, target, a, fa, b, fb, xtol, ftol):
    """Regula falsi with the Illinois halving on a bracket [a, b] of the force."""
    side = 0
    for _ in range(100):
        x = b - fb * (b - a) / (fb - fa)
        fx = force_of(x) - target
        if abs(fx) <= ftol or abs(b - a) <= xtol:
            return x
        if (fx > 0) == (fb > 0):
            b, fb = x, fx
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            a, fa = x, fx
            if side == 1:
                fb *= 0.5
            side = 1
    raise ConvergenceError("the rigid slip for the prescribed force did not converge")
