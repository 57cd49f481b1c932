"""Exception families raised by surfmet.

Every error a user can cause belongs to one family, and the CLI turns each of them into a
single line on stderr and exit status 1:

``SurfmetFormatError``
    A file that cannot be read: unknown format, truncated, corrupted, inconsistent header,
    zero points, all points non-measured.
``SurfmetInputError``
    A bad argument at the surfmet layer: unknown unit, malformed range, scan too short for a
    cut-off, all-NaN topography handed to an analysis.
``SurfmetWriteError``
    An output the operating system would not take: disk full, file size limit, no
    permission (nothing is half-written: :mod:`surfmet._atomic`).
``profiles.ProfileError``
    The same family inside the 1D engine (``profiles`` never imports ``surfmet``).
``contact.ContactInputError``, ``contact.ConvergenceError``, ``contact.EdgeContactError``
    Bad mechanics input (negative load, zero radius, NaN-only scan), a solver that did not
    converge (carries its residual), contact reaching the domain edge.

All input errors subclass :class:`ValueError`, so ``except ValueError`` catches every input
family; the engines' classes are re-exported here for convenience.
"""

from __future__ import annotations


class SurfmetError(Exception):
    """Base class of the errors surfmet raises on purpose.

    Catch it to handle any error surfmet raises on purpose.

    See Also
    --------
    SurfmetFormatError, SurfmetInputError

    Examples
    --------
    >>> import surfmet
    >>> try:
    ...     surfmet.read("no-such-file.x3p")
    ... except surfmet.SurfmetError as exc:
    ...     print(type(exc).__name__, "-", exc)
    SurfmetFormatError - no-such-file.x3p: no such file
    """


class SurfmetFormatError(SurfmetError, ValueError):
    """A scan file is unknown, truncated, corrupted or inconsistent.

    The message names the file and the problem.

    See Also
    --------
    surfmet.read : raises it for a file it cannot read.

    Examples
    --------
    >>> import surfmet.io
    >>> surfmet.io.read_bytes(b"not a scan", name="junk.dat")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetFormatError: junk.dat: ...
    >>> issubclass(surfmet.SurfmetFormatError, ValueError)
    True
    """


class SurfmetInputError(SurfmetError, ValueError):
    """An argument is unusable: wrong unit, malformed range, all-NaN data, too short a scan.

    Examples
    --------
    >>> import numpy as np
    >>> import surfmet
    >>> surfmet.Topography(np.zeros((2, 2)), dx=-1.0, dy=1.0)
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: dx must be a positive finite length in metres, got -1.0
    """


class SurfmetWriteError(SurfmetError, OSError):
    """An output file could not be written (disk full, size limit, permission); the
    message names the file. Nothing was half-written and an earlier file is kept."""


def user_error_types() -> tuple[type[BaseException], ...]:
    """All exception types that mean "the user's input is wrong" (CLI exit status 1).

    The engines are imported lazily so that loading a file never pulls them in.
    """
    types: list[type[BaseException]] = [SurfmetError]
    try:
        from profiles._errors import ProfileError

        types.append(ProfileError)
    except ImportError:  # pragma: no cover - engine missing in a partial install
        pass
    try:
        from contact._errors import ContactError

        types.append(ContactError)
    except ImportError:  # pragma: no cover
        pass
    return tuple(types)
