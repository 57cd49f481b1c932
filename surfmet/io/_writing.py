"""Writing scans: :func:`encode` into a format's bytes, :func:`write` to a file (whole or
not at all), with the writers registered in :mod:`surfmet.io._registry`."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet.io._registry import _FORMATS, Scan, _load_all

__all__ = ["encode", "write"]


def encode(scan: Scan, format: str, **options: Any) -> bytes:
    """Encode a scan into the bytes of ``format`` (a format with a writer).

    Parameters
    ----------
    scan : Topography or Profile
        What to encode.
    format : str
        Registry name of a format with a writer.
    **options
        Passed to the writer.

    Returns
    -------
    bytes
        The file's content.

    Raises
    ------
    SurfmetInputError
        If the format has no writer.

    See Also
    --------
    write, read_bytes

    Examples
    --------
    >>> from surfmet.io import encode, read_bytes
    >>> from surfmet.data import path
    >>> ball = read_bytes(path("paper_ball.x3p").read_bytes())
    >>> buf = encode(ball, "npy")
    >>> read_bytes(buf, format="npy").shape
    (152, 147)
    >>> encode(ball, "plu")
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetInputError: no writer for format 'plu'; writable formats: [...]
    """
    _load_all()
    spec = _FORMATS.get(format)
    if spec is None or spec.encode is None:
        writable = sorted(n for n, s in _FORMATS.items() if s.encode is not None)
        raise SurfmetInputError(f"no writer for format {format!r}; writable formats: {writable}")
    return spec.encode(scan, **options)


def write(
    scan: Scan, path: str | os.PathLike[str], format: str | None = None, **options: Any
) -> Path:
    """Write a scan; the format comes from ``format=`` or the file extension.

    The file is written whole or not at all (:mod:`surfmet._atomic`).

    Parameters
    ----------
    scan : Topography or Profile
        What to write.
    path : path-like
        The output file.
    format : str, optional
        Registry name; by default the one the extension names.
    **options
        Passed to the writer.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    SurfmetInputError
        No writer for the format, or an extension that names none.
    SurfmetWriteError
        The operating system refused the file.

    See Also
    --------
    encode, read

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from surfmet.io import read, write
    >>> from surfmet.data import path
    >>> ball = read(path("paper_ball.x3p"))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     out = write(ball, pathlib.Path(tmp) / "ball.npy")
    ...     print(out.name, read(out).shape)
    ball.npy (152, 147)
    """
    _load_all()
    p = Path(path)
    if format is None:
        ext = p.suffix.lower().lstrip(".")
        candidates = [s.name for s in _FORMATS.values() if ext in s.extensions and s.encode]
        if not candidates:
            raise SurfmetInputError(
                f"{p}: cannot tell the output format from the extension {ext!r}"
            )
        format = candidates[0]
    from surfmet._atomic import write_bytes

    return write_bytes(p, encode(scan, format, **options))
