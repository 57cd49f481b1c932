"""The measurements a file holds: one for a scan file, several for a container.

A contact.engineering container (a zip with ``meta.yml``) holds several measurements of
one surface; ``surfmet scales`` reads all of them (:func:`surfmet.io.read_container`), and
so does ``surfmet roughness``: each measurement is evaluated on its own, as if it were a
file, and gets its own record, named ``CONTAINER:MEMBER`` (the name the container reader
gives a measurement in its messages). A measurement travels (to a process pool, to Dask)
as a small :class:`Measurement` reference and is read where it is evaluated.

A container also states how each measurement is levelled (``detrend_mode``), which
``scales`` applies (:func:`surfmet.scale_dependent.level_as_stated`): it is the default
F-operator of that measurement's roughness too (:data:`DETREND_LEVELS`).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

DETREND_LEVELS = {"center": "mean", "height": "plane", "curvature": "poly:2"}
"""The F-operator of each ``detrend_mode`` a container states (that of
:func:`surfmet.scale_dependent.level_as_stated`): the default level of its measurements."""


@dataclass(frozen=True)
class Measurement:
    """One measurement of a container file: its path, index in ``meta.yml`` and member."""

    path: str
    index: int
    member: str

    def __str__(self) -> str:
        return f"{self.path}:{self.member}"


def _is_container_file(path: str) -> bool:
    from surfmet.io.container import _is_container

    p = Path(path)
    try:
        with p.open("rb") as fh:
            if fh.read(4) != b"PK\x03\x04":
                return False
        return _is_container(p.read_bytes())
    except OSError:
        return False  # unreadable: the reader's own error names it


def expand_measurements(paths: Iterable[str | os.PathLike]) -> list[str | Measurement]:
    """The paths, each container replaced by its measurements (in ``meta.yml`` order).

    A container that cannot be read stays a path: evaluating it gives the reader's error.
    """
    from surfmet._errors import SurfmetFormatError
    from surfmet.io import read_container

    out: list[str | Measurement] = []
    for path in paths:
        name = str(path)
        if not _is_container_file(name):
            out.append(name)
            continue
        try:
            scans = read_container(name)
        except SurfmetFormatError:
            out.append(name)
            continue
        out.extend(Measurement(name, k, str(s.metadata.get("member", k)))
                   for k, s in enumerate(scans))
    return out


def read_measurement(item: Measurement, **read_options: Any) -> Any:
    """The scan of one container measurement, its ``source`` the measurement's name;
    ``read_options`` (``height_unit=``, ``dx=``, ``dy=``) go to :func:`surfmet.read`."""
    from surfmet.io import read

    return read(item.path, measurement=item.index, **read_options).with_metadata(
        source=str(item))
