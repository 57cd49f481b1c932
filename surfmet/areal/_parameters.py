"""All areal parameters of a scan in one call, with their units and families.

Every parameter uses the measured (non-NaN) points only. Families, each in its module:
:mod:`surfmet.areal._height`, :mod:`surfmet.areal._hybrid`, :mod:`surfmet.areal._spatial`,
:mod:`surfmet.areal._features`, :mod:`surfmet.areal._material_ratio` (the "functional" family).
Definitions: ISO 25178-2:2012, with the discrete forms of its 2021 revision where the 2012
text gives only integrals.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography
from surfmet.areal._features import WOLF_PRUNING, feature_parameters
from surfmet.areal._height import height_parameters
from surfmet.areal._hybrid import gradient_parameters
from surfmet.areal._material_ratio import functional_parameters
from surfmet.areal._points import heights_of
from surfmet.areal._spatial import ACF_THRESHOLD, spatial_parameters, texture_direction

PARAMETER_UNITS: dict[str, str] = {
    "Sa": "m",
    "Sq": "m",
    "Sp": "m",
    "Sv": "m",
    "Sz": "m",
    "Ssk": "",
    "Sku": "",
    "Sdq": "",
    "Sdr": "%",
    "Sal": "m",
    "Str": "",
    "Std": "°",
    "Spd": "1/m^2",
    "Spc": "1/m",
    "Sk": "m",
    "Spk": "m",
    "Svk": "m",
    "Smr1": "%",
    "Smr2": "%",
}
"""Unit of each parameter as returned (SI lengths; ratios in %, angles in degrees)."""

GROUPS: dict[str, tuple[str, ...]] = {
    "height": ("Sa", "Sq", "Sp", "Sv", "Sz", "Ssk", "Sku"),
    "hybrid": ("Sdq", "Sdr"),
    "spatial": ("Sal", "Str", "Std"),
    "feature": ("Spd", "Spc"),
    "functional": ("Sk", "Spk", "Svk", "Smr1", "Smr2"),
}


@dataclass(frozen=True)
class ArealParameters:
    """Areal parameters of one surface; ``None`` for parameters not requested.

    Units are in :data:`PARAMETER_UNITS`. ``notes`` explains values that are bounds or
    undefined (e.g. Str of a surface with a lay).
    """

    Sa: float | None = None
    Sq: float | None = None
    Sp: float | None = None
    Sv: float | None = None
    Sz: float | None = None
    Ssk: float | None = None
    Sku: float | None = None
    Sdq: float | None = None
    Sdr: float | None = None
    Sal: float | None = None
    Str: float | None = None
    Std: float | None = None
    Spd: float | None = None
    Spc: float | None = None
    Sk: float | None = None
    Spk: float | None = None
    Svk: float | None = None
    Smr1: float | None = None
    Smr2: float | None = None
    n_valid: int = 0
    notes: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` of the computed parameters, in the order of PARAMETER_UNITS."""
        return {f.name: getattr(self, f.name) for f in fields(self)
                if f.name in PARAMETER_UNITS and getattr(self, f.name) is not None}


def _resolve(which: Iterable[str] | str | None) -> list[str]:
    if which is None:
        return list(PARAMETER_UNITS)
    if isinstance(which, str):
        which = [w.strip() for w in which.split(",") if w.strip()]
    out: list[str] = []
    for w in which:
        if w in GROUPS:
            out.extend(GROUPS[w])
        elif w in PARAMETER_UNITS:
            out.append(w)
        else:
            raise SurfmetInputError(
                f"unknown areal parameter {w!r}; known: {', '.join(PARAMETER_UNITS)} or a "
                f"group ({', '.join(GROUPS)})"
            )
    return out


def areal_parameters(
    topo: Topography,
    which: Iterable[str] | str | None = None,
    *,
    acf_threshold: float = ACF_THRESHOLD,
    pruning: float = WOLF_PRUNING,
    exclude_edge: bool = True,
) -> ArealParameters:
    """Compute ISO 25178-2 areal parameters of a (levelled, filtered) topography.

    Parameters
    ----------
    topo : Topography
        The scale-limited surface; NaN points are ignored everywhere.
    which : iterable of str or comma-separated str, optional
        Symbols (``"Sa"``) or group names (``"height"``, ``"hybrid"``, ``"spatial"``,
        ``"feature"``, ``"functional"``); default all.
    acf_threshold : float
        s for Sal and Str (ISO 25178-3 default 0.2).
    pruning : float
        Wolf pruning height as a fraction of Sz (default 0.05).
    exclude_edge : bool
        Do not count hills that touch the border or a non-measured area (Spd, Spc).

    Returns
    -------
    ArealParameters

    Raises
    ------
    SurfmetInputError
        Not a Topography, no measured point, an unknown symbol.
    """
    wanted = _resolve(which)
    z = heights_of(topo)
    n_valid = int(np.count_nonzero(~np.isnan(z)))
    if n_valid == 0:
        raise SurfmetInputError("the scan has no measured point")
    values: dict[str, Any] = {}
    notes: list[str] = []
    groups = {g for g, syms in GROUPS.items() if any(s in wanted for s in syms)}
    if "height" in groups:
        values.update(height_parameters(topo))
    if "hybrid" in groups:
        values.update(gradient_parameters(topo))
    if "spatial" in groups:
        if {"Sal", "Str"} & set(wanted):
            sp, nt = spatial_parameters(topo, acf_threshold)
            values.update(sp)
            notes.extend(nt)
        else:
            values["Std"] = texture_direction(topo)
    if "feature" in groups:
        values.update(feature_parameters(topo, pruning, exclude_edge))
    if "functional" in groups:
        values.update(functional_parameters(topo))
    kept = {k: float(values[k]) for k in wanted}
    return ArealParameters(**kept, n_valid=n_valid, notes=tuple(notes))
