"""surfmet: rough-surface metrology and contact mechanics.

Reading scans::

    import surfmet
    from surfmet.data import path
    topo = surfmet.read(path("paper_plate.x3p"))  # Topography or Profile, heights in metres
    surfmet.write(topo, "copy.x3p")

Analysis lives in submodules (``surfmet.areal``, ``surfmet.areal.filters``...) and in the two
array-level engines ``profiles`` and ``contact``; they are imported on first use so that
``import surfmet`` stays fast: ``surfmet.areal`` or ``surfmet.mechanics.hertz_check`` works
after a bare ``import surfmet`` and loads only what it names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from surfmet._lazy import attach
from surfmet._version import __version__
from surfmet.errors import SurfmetError, SurfmetFormatError, SurfmetInputError
from surfmet.model import Profile, Topography

if TYPE_CHECKING:
    import os
    from pathlib import Path

    from surfmet.io.registry import Source


def read(source: Source, format: str | None = None, **options: Any) -> Topography | Profile:
    """Read a scan from a path, its bytes or a binary stream (see :func:`surfmet.io.read`)."""
    from surfmet.io import read as _read

    return _read(source, format=format, **options)


def write(scan: Topography | Profile, path: str | os.PathLike[str], format: str | None = None,
          **options: Any) -> Path:
    """Write a scan file (see :func:`surfmet.io.write`)."""
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
    "read",
    "write",
]
