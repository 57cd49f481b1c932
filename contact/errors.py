"""Errors and warnings of the contact-mechanics engine (free of any ``surfmet`` import)."""

from __future__ import annotations


class ContactError(Exception):
    """Base class of the contact engine's deliberate errors."""


class ContactInputError(ContactError, ValueError):
    """Unusable mechanics input: negative load, zero radius, NaN-only scan, unknown material."""


class ConvergenceError(ContactError, RuntimeError):
    """The solver stopped before reaching its tolerance.

    Attributes
    ----------
    residual : float
        The relative residual reached.
    iterations : int
        The number of iterations done.
    """

    def __init__(self, message: str, residual: float = float("nan"), iterations: int = -1):
        super().__init__(message)
        self.residual = residual
        self.iterations = iterations


class EdgeContactError(ContactError, RuntimeError):
    """Contact pressure reaches the edge of the computational domain and cannot be enlarged."""


class EdgeContactWarning(UserWarning):
    """Contact pressure reached the domain edge; the domain was enlarged (or the result is
    truncated, when enlarging was switched off)."""


class ContactMemoryError(ContactInputError):
    """The grid asked for would not fit in the available memory (see :mod:`contact.bem.memory`)."""
