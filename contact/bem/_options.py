"""The settings of a normal solve: one frozen :class:`SolveOptions` beside the bounds.

The same ten settings (tolerance, iteration budget, precision, threads, progress callback,
strictness, nesting, preconditioning, edge report, kernel) used to be declared again at
every level of the ball-on-plate path (the facade, :meth:`SphereContact.solve`,
:func:`contact.bem.solve_normal`). They travel as one object instead: a caller builds it
once, every level hands it on, and a level that needs another setting for an inner solve
(a looser tolerance for a coarse start, no edge report for a domain it enlarges itself)
derives it with :meth:`SolveOptions.but`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from contact._errors import ContactInputError
from contact.halfspace.operator import KERNELS

if TYPE_CHECKING:  # the counters are the iteration's; only the annotation refers to them
    from contact.bem._state import SolverStats

#: The precisions of the search-direction convolution (see the notes of :mod:`contact.bem`).
PRECISIONS = ("mixed", "double")
#: What a free-boundary solve does with pressure on its outermost cells.
EDGE_POLICIES = ("warn", "ignore")


@dataclass(frozen=True)
class SolveOptions:
    """How a normal contact is solved (not what is solved: that is the grid, the load or
    approach and the :class:`~contact.bem._bounds.PressureBounds`).

    Attributes
    ----------
    tol : float
        Target residual (see :class:`~contact.bem._result.ContactResult`); 1e-6 gives the
        Hertz maximum pressure to about 1e-6 of discretisation-free accuracy.
    max_iter : int
        Iteration limit of the finest grid.
    precision : {"mixed", "double"}
        "mixed" runs the search-direction FFT in float32 (see the notes of :mod:`contact.bem`).
    workers : int, optional
        Threads for scipy.fft (default: all cores).
    callback : callable, optional
        Called as ``callback(iteration, residual)`` after each iteration of the finest grid.
    strict : bool
        Raise :class:`~contact._errors.ConvergenceError` if the tolerance is not reached;
        with ``strict=False`` the result is returned with ``converged=False``.
    nested : bool
        Start from the solution of a twice coarser grid when no warm start is given
        (:func:`contact._nesting.coarse_grid`).
    precondition : bool
        Precondition the conjugate gradient with the periodic stiffness ``|q|/2``
        (Vollebregt 2014, J. Comput. Phys. 257:333).
    edge : {"warn", "ignore"}
        A free-boundary solution with pressure on the outermost cells: "warn" issues the
        one edge warning of :func:`contact._record.edge_warning` and adds it as a note;
        callers that enlarge the domain themselves pass "ignore".
    kernel : {"love", "spectral"}
        The half-space operator (:func:`contact.halfspace.convolution.convolution`): Love's
        uniform pressure on each cell (every domain), or the spectral ``2 / |q|`` of Tamaas and
        ContactMechanics (periodic only). ``result.extra["kernel"]`` says which was used,
        and a spectral solve's method says so.
    stats : SolverStats, optional
        Live counters (iterations, FFTs, grid levels) for a benchmark that reads them while
        the solve runs; the same counts end in ``result.solve.counters`` either way. Not
        part of the options' equality.

    Examples
    --------
    >>> from contact import SolveOptions
    >>> loose = SolveOptions(tol=1e-4, strict=False)
    >>> loose.but(edge="ignore").edge
    'ignore'
    """

    tol: float = 1e-6
    max_iter: int = 2000
    precision: str = "mixed"
    workers: int | None = None
    callback: Callable[[int, float], Any] | None = None
    strict: bool = True
    nested: bool = True
    precondition: bool = True
    edge: str = "warn"
    kernel: str = "love"
    stats: SolverStats | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not (self.tol > 0.0):
            raise ContactInputError(f"the tolerance must be positive, got {self.tol!r}")
        if int(self.max_iter) != self.max_iter or self.max_iter < 1:
            raise ContactInputError(
                f"the iteration budget must be a positive integer, got {self.max_iter!r}")
        for name, value, allowed in (("precision", self.precision, PRECISIONS),
                                     ("edge", self.edge, EDGE_POLICIES),
                                     ("kernel", self.kernel, KERNELS)):
            if value not in allowed:
                raise ContactInputError(
                    f"{name} must be one of {', '.join(map(repr, allowed))}, got {value!r}")

    def but(self, **changes: Any) -> SolveOptions:
        """These options with ``changes`` (the keyword names of the attributes)."""
        return dataclasses.replace(self, **changes)


def options_of(options: SolveOptions | None) -> SolveOptions:
    """``options``, or the defaults where None; anything else is refused in one line."""
    if options is None:
        return SolveOptions()
    if not isinstance(options, SolveOptions):
        raise ContactInputError(
            f"options must be a contact.SolveOptions, got {type(options).__name__}")
    return options
