"""Scan readers and writers, one module per format, registered by name.

``surfmet.io.read(path)`` detects the format from magic bytes, then from the extension.
Loading a file imports only the data model, the error types and the format modules: never
analysis, plotting or numba.
"""

from __future__ import annotations

import importlib

from surfmet.io.registry import (
    FormatSpec,
    detect_format,
    formats,
    read,
    read_bytes,
    register_reader,
    register_writer,
)
from surfmet.io.writing import encode, write

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

for _mod in FORMAT_MODULES:
    try:
        importlib.import_module(f"surfmet.io.{_mod}")
    except ModuleNotFoundError as _exc:  # a format module not written yet
        if _exc.name != f"surfmet.io.{_mod}":
            raise

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
    surfmet.errors.SurfmetFormatError: ...: not a contact.engineering container ...)
    """
    from surfmet.io.container import read_container as _read

    return _read(path)


__all__ = [
    "FORMAT_MODULES",
    "FormatSpec",
    "detect_format",
    "encode",
    "formats",
    "read",
    "read_bytes",
    "read_container",
    "register_reader",
    "register_writer",
    "write",
]
