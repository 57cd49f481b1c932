"""The files shipped with surfmet, found wherever surfmet is installed.

``surfmet/data`` holds the paper stand-in scans (``paper_plate.x3p``, ``paper_ball.x3p``;
see ``examples/paper_2022/make_surfaces.py``) and the rotor frame table of Alaci, Ciornei &
Romanu (2022), Table 3 (``table3_frames.tsv``)::

    import surfmet
    from surfmet.data import path

    plate = surfmet.read(path("paper_plate.x3p"))
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from surfmet._errors import SurfmetInputError


def names() -> tuple[str, ...]:
    """Names of the shipped data files, sorted.

    Returns
    -------
    tuple of str
        File names accepted by :func:`path`.
    """
    folder = resources.files(__name__)
    return tuple(sorted(f.name for f in folder.iterdir()
                        if f.is_file() and not f.name.endswith((".py", ".pyc"))))


def path(name: str) -> Path:
    """Path of a file shipped in ``surfmet/data``.

    Parameters
    ----------
    name : str
        File name, e.g. ``"paper_plate.x3p"`` (see :func:`names`).

    Returns
    -------
    pathlib.Path
        The file on disk (surfmet is installed unzipped, so the path is a real file).

    Raises
    ------
    SurfmetInputError
        If no shipped file has that name.
    """
    found = Path(str(resources.files(__name__).joinpath(name)))
    if "/" in name or "\\" in name or not found.is_file():
        raise SurfmetInputError(f"surfmet ships no data file {name!r}; "
                                f"the shipped files are {', '.join(names())}")
    return found


__all__ = ["names", "path"]
