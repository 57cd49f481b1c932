"""The types of the facades' inputs, named once (imported under ``TYPE_CHECKING`` only, so
that the facades' imports stay lazy: nothing here is loaded when a facade runs).

- :data:`ScanSource`: a scan, as a :class:`~surfmet._model.Topography` or a file to read
  with :func:`surfmet.read`;
- :data:`Materials`: ``"BALL,PLATE"`` text, a pair of :class:`contact._materials.Material`
  or a resolved :class:`contact._material_pair.MaterialPair`;
- :data:`Spikes`: ``"remove"`` / ``"keep"``, or True (remove) / False (keep);
- :data:`Loads`: the loads of a sweep (N, or N/m for a line);
- :data:`Progress`: wraps an iterable to show progress (``tqdm``'s calling form);
- :data:`PathLike`: an output file (as :func:`surfmet.plots._style.finish` takes it);
- :data:`AdhesionLaw`: an adhesion law of :mod:`contact.adhesion.laws`;
- :data:`RoughnessMap`: a composite roughness map and its pitch, ``(z, dx, dy)`` (m).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any, TypeAlias

import numpy as np

from contact._material_pair import MaterialPair
from contact._materials import Material
from contact.adhesion.laws import InteractionLaw
from surfmet._model import Topography

ScanSource: TypeAlias = Topography | str | os.PathLike[str]
Materials: TypeAlias = str | MaterialPair | tuple[Material, Material] | list[Material]
Spikes: TypeAlias = bool | str
Loads: TypeAlias = Sequence[float] | np.ndarray
Progress: TypeAlias = Callable[[Iterable[Any]], Iterable[Any]]
PathLike: TypeAlias = str | Path
AdhesionLaw: TypeAlias = InteractionLaw  # any law of the table (contact.adhesion.laws)
RoughnessMap: TypeAlias = tuple[np.ndarray, float, float]

__all__ = ["AdhesionLaw", "Loads", "Materials", "PathLike", "Progress", "RoughnessMap",
           "ScanSource", "Spikes"]
