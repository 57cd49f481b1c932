"""surfmet: rough-surface metrology and contact mechanics.

Reading scans::

    import surfmet
    from surfmet.data import path
    topo = surfmet.read(path("paper_plate.x3p"))  # Topography or Profile, heights in metres
    surfmet.write(topo, "copy.x3p")
    row = surfmet.extract_profile(topo, "row:256")  # a Profile: one row of the scan

Analysis lives in submodules (``surfmet.areal``, ``surfmet.areal._filters``...) and in the two
array-level engines ``profiles`` and ``contact``; they are imported on first use so that
``import surfmet`` stays fast: ``surfmet.areal`` or ``surfmet.mechanics.hertz_check`` works
after a bare ``import surfmet`` and loads only what it names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetError, SurfmetFormatError, SurfmetInputError
from surfmet._extract import extract_profile
from surfmet._lazy import attach
from surfmet._model import Profile, Topography
from surfmet._version import __version__

if TYPE_CHECKING:
    import os
    from pathlib import Path

    from surfmet.io._registry import Source


def read(source: Source, format: str | None = None, **options: Any) -> Topography | Profile:
    """Read a scan file (see :func:`surfmet.io.read`).

    Parameters
    ----------
    path : path-like
        The scan file.
    format : str, optional
        Registry name (``"x3p"``, ``"plu"``...); by default detected from the magic bytes,
        then from the extension (see :func:`surfmet.io.formats`).
    **options
        Passed to the format's reader (``channel=``, ``height_unit=``, ``dx=``...).

    Returns
    -------
    Topography or Profile
        Heights in metres, NaN where not measured.

    Raises
    ------
    SurfmetFormatError
        Unknown format, unreadable, truncated or inconsistent file.

    See Also
    --------
    surfmet.io.read : the reader this calls, with every option.
    write : the other direction.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> plate.shape, plate.dx
    ((512, 1024), 5e-06)
    >>> print(f"{plate.size_x * 1e3:.2f} mm x {plate.size_y * 1e3:.2f} mm")
    5.12 mm x 2.56 mm
    """
    from surfmet.io import read as _read

    return _read(source, format=format, **options)


def write(scan: Topography | Profile, path: str | os.PathLike[str], format: str | None = None,
          **options: Any) -> Path:
    """Write a scan file (see :func:`surfmet.io.write`).

    Parameters
    ----------
    scan : Topography or Profile
        What to write.
    path : path-like
        The output file; its extension names the format unless ``format=`` does.
    format : str, optional
        Registry name of a format with a writer (``"x3p"``, ``"npy"``, ``"npz"``).
    **options
        Passed to the format's writer.

    Returns
    -------
    pathlib.Path
        The file written (whole or not at all).

    Raises
    ------
    SurfmetInputError
        No writer for the format, or an extension that names none.
    SurfmetWriteError
        The operating system refused the file (disk full, no permission).

    See Also
    --------
    surfmet.io.write, read

    Examples
    --------
    >>> import tempfile, pathlib
    >>> import surfmet
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     out = surfmet.write(plate, pathlib.Path(tmp) / "copy.x3p")
    ...     back = surfmet.read(out)
    >>> bool((back.heights == plate.heights).all())
    True
    """
    from surfmet.io import write as _write

    return _write(scan, path, format=format, **options)


#: Rooms reachable as ``surfmet.<room>`` after ``import surfmet``, each imported on first use
#: (not in ``__all__``: a star import names the API, it does not load every room).
SUBMODULES = (
    "areal",
    "data",
    "demo",
    "file_info",
    "fitting",
    "io",
    "mechanics",
    "plots",
    "psd",
    "records",
    "report",
    "roughness",
    "scale_dependent",
    "sweep",
    "synth",
    "units",
    "value_lists",
)

__getattr__, __dir__ = attach(__name__, SUBMODULES)

__all__ = [
    "Profile",
    "SurfmetError",
    "SurfmetFormatError",
    "SurfmetInputError",
    "Topography",
    "__version__",
    "extract_profile",
    "read",
    "write",
]
