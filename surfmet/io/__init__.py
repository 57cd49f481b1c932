"""Scan readers and writers, one module per format, registered by name.

``surfmet.io.read(path)`` detects the format from magic bytes, then from the extension.
Loading a file imports only the data model, the error types and the format modules: never
analysis, plotting or numba.
"""

from __future__ import annotations

import importlib

from surfmet.io._registry import (
    FormatSpec,
    detect_format,
    formats,
    read,
    read_bytes,
    register_reader,
    register_writer,
)
from surfmet.io._writing import encode, write

# Every built-in format module; each registers itself on import. Order matters only for
# magic detection ties, which ``priority`` settles.
FORMAT_MODULES = (
    "x3p",
    "x3p_writer",
    "mitutoyo",
    "di",
    "ibw",
    "nid",
    "mi",
    "bcr",
    "tmd",
    "wsxm",
    "netcdf",
    "park",
    "smd",
    "mnt",
    "sur",
    "plu",
    "opd",
    "nms",
    "metropro",
    "al3d",
    "frt",
    "sdf",
    "asc",
    "gwy",
    "dektak",
    "opdx",
    "hfm",
    "xyz",
    "npy",
    "jpk",
    "h5",
    "zon",
    "container",
)

_LOADED: set[str] = set()


def load_format_modules() -> None:
    """Import every module ``FORMAT_MODULES`` names that is not imported yet.

    Called at import and before every lookup in the registry, so that a module added to the
    list is found without another step. A name with no module behind it is a mistake in the
    list, never a format to skip: it raises.

    Raises
    ------
    ModuleNotFoundError
        If ``FORMAT_MODULES`` names a module that ``surfmet/io/`` does not hold.

    Examples
    --------
    >>> from surfmet.io import FORMAT_MODULES, load_format_modules
    >>> load_format_modules()  # every module is imported already: nothing to do
    >>> "x3p" in FORMAT_MODULES
    True
    """
    # FORMAT_MODULES is read at call time (a test may add a line to it).
    for name in FORMAT_MODULES:
        if name in _LOADED:
            continue
        full = f"{__name__}.{name}"
        try:
            importlib.import_module(full)
        except ModuleNotFoundError as exc:
            if exc.name != full:
                raise  # the module exists; something it imports does not
            raise ModuleNotFoundError(
                f"surfmet.io.FORMAT_MODULES names {name!r}, but there is no module {full} "
                f"(surfmet/io/{name}.py): a misspelt or missing format module",
                name=full,
            ) from None
        _LOADED.add(name)


load_format_modules()


def read_container(path):
    """Every measurement of a contact.engineering container (see :mod:`surfmet.io.container`).

    Parameters
    ----------
    path : path-like
        A contact.engineering container (a zip holding ``meta.yml`` and the data files).

    Returns
    -------
    list of Topography or Profile
        One scan per measurement, in the container's order.

    Raises
    ------
    SurfmetFormatError
        Not a readable container, a data file that ``meta.yml`` names is missing, or a
        measurement that cannot be read.

    See Also
    --------
    surfmet.io.container : the format; read : one scan file.

    Examples
    --------
    An x3p file is a zip too, but without ``meta.yml`` it is no container:

    >>> from surfmet.io import read_container
    >>> from surfmet.data import path
    >>> read_container(path("paper_plate.x3p"))
    Traceback (most recent call last):
    ...
    surfmet._errors.SurfmetFormatError: ...: not a contact.engineering container ...)
    """
    from surfmet.io.container import read_container as _read

    return _read(path)


__all__ = [
    "FORMAT_MODULES",
    "FormatSpec",
    "detect_format",
    "encode",
    "formats",
    "load_format_modules",
    "read",
    "read_bytes",
    "read_container",
    "register_reader",
    "register_writer",
    "write",
]
