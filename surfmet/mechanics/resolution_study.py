"""Resolution studies on scans: ``--resolution-study`` of ``contact``, ``hertz-check`` and
``rolling``.

The scans are prepared as for the ordinary commands (spikes removed, plate levelled, the
ball's sphere removed, both paired on the finer pitch by
:func:`surfmet.mechanics.pairing.prepare_pair`),
then :mod:`contact._resolution` solves the contact on the composite roughness block-averaged
8x, 4x, 2x and at the native pixel, and fits the trend of each quantity against the pixel.
This module prints the study as a table (its JSON record is
:func:`surfmet.records._resolution.study_record`); the command line's
``--resolution-study`` is :mod:`surfmet.cli._resolution_study`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.scan_preparation import SPIKES

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from contact._material_pair import MaterialPair
    from contact._resolution import ResolutionStudy
    from surfmet.mechanics._types import Materials, ScanSource, Spikes
    from surfmet.mechanics.scan_preparation import PreparedScans

#: Each quantity of a study: label, JSON unit, scale to the text unit, text unit.
QUANTITIES = {
    "a_star": ("a*", "m", 1e6, "µm"),
    "approach": ("approach", "m", 1e6, "µm"),
    "area": ("real area", "m^2", 1e12, "µm²"),
    "corrected_area": ("corrected area", "m^2", 1e12, "µm²"),
    "yielded_fraction": ("yielded / πa0²", "1", 1.0, ""),
    "pmax": ("pmax", "Pa", 1e-6, "MPa"),
    "pmax_elastic": ("pmax elastic", "Pa", 1e-6, "MPa"),
    "sigma": ("σ", "m", 1e6, "µm"),
    "rms_slope": ("rms slope", "1", 1.0, ""),
    "profile_deviation": ("profile dev./p0", "1", 1.0, ""),
    "lambda_eff": ("λ_eff", "1", 1.0, ""),
}


def _study_inputs(plate: ScanSource | None, ball: ScanSource | None, materials: Materials,
                  spikes: Spikes, hardness: float | None = None
                  ) -> tuple[MaterialPair, PreparedScans]:
    """The resolved pair (:class:`contact._material_pair.MaterialPair`, ``hardness`` in place
    of the table's) and the prepared scans of a study."""
    from surfmet.mechanics.material_spec import material_pair, parse_materials
    from surfmet.mechanics.scan_preparation import prepare_scans

    mats = material_pair(materials, hardness=hardness)
    parse_materials(mats)  # both bodies are needed
    if plate is None and ball is None:
        raise SurfmetInputError("a resolution study needs a scan (--plate and/or --ball): a "
                                "smooth contact has nothing to refine")
    return mats, prepare_scans(plate, ball, spikes=spikes)


def contact_study(
    plate: ScanSource | None = None,
    ball: ScanSource | None = None,
    *,
    radius: float,
    load: float,
    materials: Materials = "steel,aluminium",
    hardness: float | None = None,
    plastic: bool = False,
    spikes: Spikes = SPIKES,
    factors: tuple[int, ...] = (8, 4, 2, 1),
    progress: Callable[[str], Any] | None = None,
) -> tuple[Any, Any]:
    """Resolution study of a ball on a plate from scans.

    Parameters
    ----------
    plate, ball : Topography or path
        The scans (at least one).
    radius, load : float
        R (m), W (N).
    materials : str, (Material, Material) or MaterialPair
        ``"BALL,PLATE"``, resolved here.
    hardness : float, optional
        Adds the elastic-plastic solve and the yielded fraction (Pa).
    plastic : bool
        Adds it at the pair's hardness (``hardness`` when given, else the softer body's).
    spikes : bool
        Remove spikes first.
    factors : tuple of int
        Coarsening factors, decreasing to 1.

    Returns
    -------
    (contact._resolution.ResolutionStudy, surfmet.mechanics.scan_preparation.PreparedScans)

    See Also
    --------
    contact._resolution : the engine's study.
    study_lines : the table in words.

    Examples
    --------
    A 0.64 mm patch of the bundled plate at its own 5 µm pixel and coarsened to 10 µm:
    the rough contact's radius still moves with the pixel, so it is not converged:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.resolution_study import contact_study
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> study, prep = contact_study(patch, radius=0.02, load=10.0, factors=(2, 1))
    >>> type(study).__name__, prep.spikes_removed
    ('ResolutionStudy', {'plate': 2})
    """
    from contact._resolution import sphere_study

    mats, prep = _study_inputs(plate, ball, materials, spikes, hardness)
    if plastic or hardness is not None:
        hardness = mats.hardness
    pair = prep.paired()
    study = sphere_study(radius, load, mats, pair.roughness, pair.dx, pair.dy,
                         hardness=hardness, sigma=prep.sigma, factors=factors,
                         progress=progress)
    return study, prep


def rolling_study(
    plate: ScanSource | None = None,
    ball: ScanSource | None = None,
    *,
    radius: float,
    loads: Sequence[float],
    materials: Materials = "steel,aluminium",
    hardness: float | None = None,
    lossy: str = "both",
    spikes: Spikes = SPIKES,
    factors: tuple[int, ...] = (8, 4, 2, 1),
    progress: Callable[[str], Any] | None = None,
    **sweep_kwargs: Any,
) -> tuple[Any, Any]:
    """Resolution study of lambda_eff (:func:`contact._resolution.rolling_study`) from scans;
    ``sweep_kwargs`` go to :func:`contact._rolling.sphere_sweep`.

    The materials are resolved here: ``lossy`` ("ball" or "plate") scales the hysteresis
    moment by that body's share of the displacement, and the plastic model takes the pair's
    hardness (``hardness`` when given, else the softer body's).

    See Also
    --------
    contact_study : the same for one contact.
    contact._resolution : the engine's study.

    Examples
    --------
    A 1.3 mm patch of the bundled plate: λ_eff changes with the pixel, so the scan's
    rolling exponent is not resolved at 5 µm:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.resolution_study import rolling_study, study_lines
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:256, :256], plate.dx, plate.dy)
    >>> study, prep = rolling_study(patch, radius=0.02, loads=[2.0, 5.0, 10.0], factors=(2, 1))
    >>> print(study_lines(study)[2])
    λ_eff                     3.287       1.2213   keeps moving (169 %)
    """
    from dataclasses import fields

    from contact import Dissipation
    from contact._resolution import rolling_study as engine

    mats, prep = _study_inputs(plate, ball, materials, spikes, hardness)
    if lossy not in ("both", "ball", "plate"):
        raise SurfmetInputError(f"lossy must be both, ball or plate, got {lossy!r}")
    if lossy != "both":  # the lossy body's share of the displacement scales M_r
        sweep_kwargs["share"] = mats.shares[0 if lossy == "ball" else 1]
    if sweep_kwargs.get("model") == "plastic":
        if mats.hardness is None:
            raise SurfmetInputError("the plastic model needs a hardness: give --hardness")
        sweep_kwargs["hardness"] = mats.hardness
    pair = prep.paired()
    # the flat keywords of the dissipation model travel as one contact.Dissipation
    named = {f.name for f in fields(Dissipation)}
    dissipation = Dissipation(**{k: sweep_kwargs.pop(k) for k in list(sweep_kwargs)
                                 if k in named})
    study = engine(radius, mats, loads, pair.roughness, pair.dx, pair.dy, factors=factors,
                   progress=progress, dissipation=dissipation, **sweep_kwargs)
    return study, prep


def study_lines(study: ResolutionStudy) -> list[str]:
    """A table (one row per quantity, one column per pixel) and the trend sentences.

    Parameters
    ----------
    study : ResolutionStudy
        A study.

    Returns
    -------
    list of str
        The table, then the trend sentences.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.resolution_study import contact_study, study_lines
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> study, _ = contact_study(patch, radius=0.02, load=10.0, factors=(2, 1))
    >>> print("\\n".join(study_lines(study)[:3]))
    resolution study: same 0.58 mm domain, pixel coarsened 2x, 1x
                              10 µm         5 µm   status
    a* (µm)                  254.73       293.76   keeps moving (13.3 %)
    """
    head = f"{'':18}" + "".join(f"{p * 1e6:>10.4g} µm" for p in study.pixels) + "   status"
    lines = [f"resolution study: same {study.side * 1e3:.4g} mm domain, pixel coarsened "
             + ", ".join(f"{lv.factor}x" for lv in study.levels), head]
    for name, t in study.trends.items():
        label, _, scale, unit = QUANTITIES.get(name, (name, "1", 1.0, ""))
        label = f"{label} ({unit})" if unit else label
        cells = "".join(f"{v * scale:>13.5g}" for v in t.values)
        pct = f"{100 * t.last_change:.3g} %" if math.isfinite(t.last_change) else "from 0"
        status = "unknown (no value)" if math.isnan(t.last_change) else f"{t.status} ({pct})"
        lines.append(f"{label:18}{cells}   {status}")
    lines.append("")
    lines += [f"- {t.sentence()}" for t in study.trends.values()]
    lines += [f"note: {n}" for n in study.notes]
    holds, reasons, left = study.verdict()
    if study.finest.comparison is not None:
        head = {True: "Hertz holds", False: "Hertz does not hold",
                None: "Undecided (a decisive criterion rests on a quantity that keeps "
                      "moving)"}[holds]
        lines.append("")
        lines.append(f"{head} at the native pixel, from converged quantities (and failures "
                     "that survive refinement) only:")
        lines += [f"  - {r}" for r in reasons]
        lines += [f"  (not used: {x})" for x in left]
    return lines

