"""Errors and warnings of the contact-mechanics engine (free of any ``surfmet`` import)."""

from __future__ import annotations


class ContactError(Exception):
    """Base class of the contact engine's deliberate errors.

    Catch it to handle any error the engine raises on purpose.

    See Also
    --------
    ContactInputError, ConvergenceError, EdgeContactError

    Examples
    --------
    >>> import contact
    >>> try:
    ...     contact.material("unobtainium")
    ... except contact.ContactError as exc:
    ...     print(type(exc).__name__)
    ContactInputError
    """


class ContactInputError(ContactError, ValueError):
    """Unusable mechanics input: negative load, zero radius, NaN-only scan, unknown material.

    A :class:`ValueError`, so ``except ValueError`` catches it.

    Examples
    --------
    >>> from contact import hertz_sphere
    >>> hertz_sphere(0.02, -1.0, 5.9e10)
    Traceback (most recent call last):
    ...
    contact._errors.ContactInputError: load must be positive and finite in N, got -1.0
    """


class ConvergenceError(ContactError, RuntimeError):
    """The solver stopped before reaching its tolerance.

    Attributes
    ----------
    residual : float
        The relative residual reached.
    iterations : int
        The number of iterations done.

    See Also
    --------
    contact.solve_normal : raises it (``SolveOptions.max_iter``, ``SolveOptions.tol``).

    Examples
    --------
    >>> from contact import ConvergenceError, SolveOptions, solve_normal, sphere_gap
    >>> from contact._grid import gap_grid
    >>> grid = gap_grid(sphere_gap(32, 1e-5, 0.02), 1e-5)
    >>> try:
    ...     solve_normal(grid, e_star=5.9e10, load=10.0, options=SolveOptions(max_iter=2))
    ... except ConvergenceError as exc:
    ...     print(exc.iterations, exc.residual > 1e-6)
    2 True
    """

    def __init__(self, message: str, residual: float = float("nan"), iterations: int = -1):
        super().__init__(message)
        self.residual = residual
        self.iterations = iterations


class EdgeContactError(ContactError, RuntimeError):
    """Contact pressure reaches the edge of the computational domain and cannot be enlarged.

    See Also
    --------
    EdgeContactWarning : what ``on_edge="enlarge"`` (the default) gives instead.

    Examples
    --------
    >>> from contact import DomainSpec, solve_sphere
    >>> solve_sphere(0.02, 10.0, 5.9e10, domain=DomainSpec(grid=32, size=1e-4), on_edge="raise")
    Traceback (most recent call last):
    ...
    contact._errors.EdgeContactError: contact reaches the edge of the 0.1 mm domain: ...
    """


class EdgeContactWarning(UserWarning):
    """Contact pressure reached the domain edge; the domain was enlarged (or the result is
    truncated, when enlarging was switched off).

    Examples
    --------
    A 0.1 mm domain is too small for a 137 µm Hertz radius; the solver enlarges it and
    says so:

    >>> import warnings
    >>> from contact import DomainSpec, EdgeContactWarning, solve_sphere
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     res = solve_sphere(0.02, 10.0, 5.9e10, domain=DomainSpec(grid=32, size=1e-4))
    >>> caught[0].category is EdgeContactWarning, res.solve.edge_contact
    (True, False)
    """


class ContactMemoryError(ContactInputError):
    """The grid asked for would not fit in the available memory (see :mod:`contact.bem._memory`).

    Examples
    --------
    >>> from contact import DomainSpec, solve_sphere
    >>> solve_sphere(0.02, 10.0, 5.9e10, domain=DomainSpec(grid=100000, max_grid=None))
    Traceback (most recent call last):
    ...
    contact._errors.ContactMemoryError: a 100000 x 100000 contact grid needs about ...
    """
