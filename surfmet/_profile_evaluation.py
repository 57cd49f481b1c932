"""One profile's roughness in the facade: extraction, spikes, the engine, and the names.

:func:`evaluate_profile` is what :func:`surfmet.roughness.roughness` does with a profile
(or a row/column of an areal scan): spike removal, the profile engine
(:func:`profiles.analyze_profile`) under the resolved evaluation conditions
(:mod:`surfmet._profile_roughness`), the ISO 13565 and feature parameters, and the record.

Names. ISO 21920-2 (as ISO 4287 before it) names a parameter by the profile it is taken
on: P for the primary profile, R for the roughness profile (Pa, Pq, Pz... against Ra, Rq,
Rz...). When no λc filter separates roughness from waviness (the automatic cut-off found
the profile too short for ISO 4288, or the evaluation was given no λc on a profile not
stated to be filtered), the values are the primary profile's and carry P names, in the
text, the JSON and the CSV alike; ``settings["profile_kind"]`` says which. A file holding
an instrument's R-profile, and ``lc="none"`` (documented as "already filtered, evaluate as
it is"), keep R.
"""

from __future__ import annotations

from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography


def _profile_level(level: str) -> str:
    text = str(level).strip().lower()
    if text in ("sphere", "cylinder") or text.startswith("cylinder:"):
        raise SurfmetInputError(
            f"level {level!r} is an areal form; for a profile use none, mean, plane (a "
            "least-squares line) or poly:N"
        )
    return "line" if text == "plane" else text


def primary_profile(cond: Any, settings: dict[str, Any]) -> bool:
    """Whether the evaluated profile is the primary profile (P names, ISO 21920-2).

    True when no λc filter was applied and nothing states the profile filtered already:
    not an instrument's R-profile, and λc not set to none by the user (which
    :func:`surfmet.roughness.roughness` documents as "an already filtered profile").
    """
    from surfmet._profile_roughness import FROM_USER

    return (settings.get("lc") is None and not cond.prefiltered
            and cond.why.get("lc") != FROM_USER)


def primary_names(parameters: dict[str, Any]) -> dict[str, Any]:
    """The same parameters with the R of each name made the primary profile's P."""
    return {("P" + k[1:] if k.startswith("R") else k): v for k, v in parameters.items()}


def _extract(data: Any, profile: str | None, spikes: bool, settings: dict[str, Any]
             ) -> tuple[Any, Any]:
    """The profile to evaluate, spikes removed when asked: (profile, spike report)."""
    from surfmet._extract import extract_profile
    from surfmet._spikes import remove_spikes
    from surfmet.records._roughness import spike_report_record

    report = None
    if isinstance(data, Topography):
        if profile is None:  # pragma: no cover - guarded by the caller
            raise SurfmetInputError("an areal scan needs profile='row:K' or 'col:K'")
        if spikes:
            data, report = remove_spikes(data)
            settings["spikes"] = spike_report_record(report)
        prof = extract_profile(data, profile)
        settings["profile"] = prof.metadata.get("profile")
        return prof, report
    if profile is not None:
        raise SurfmetInputError("--profile applies to areal scans; this file is a profile")
    prof = data
    if spikes:
        as_topo = Topography(prof.z[None, :], prof.dx, prof.dx, metadata=prof.metadata)
        cleaned, report = remove_spikes(as_topo)
        prof = prof.replace(z=cleaned.heights[0])
        settings["spikes"] = spike_report_record(report)
    return prof, report


def evaluate_profile(data: Any, source: str | None, *, level: str | None, cond: Any,
                     window: Any, profile: str | None, spikes: bool,
                     valley_suppression: bool) -> Any:
    """R- (or P-) parameters of a profile with every step recorded (a RoughnessResult)."""
    import profiles
    from profiles._form import is_flat
    from surfmet._flat_scan import flat_diagnosis, flat_parameters
    from surfmet._profile_roughness import engine_cutoffs, feature_values, stratified_parameters
    from surfmet._roughness_result import RoughnessResult, consistent_diagnosis, unit_caveats
    from surfmet._spikes import spike_diagnosis
    from surfmet.records._roughness import conditions_record

    settings: dict[str, Any] = {"kind": "profile"}
    lvl = _profile_level(level or ("none" if cond.prefiltered else "plane"))
    prof, report = _extract(data, profile, spikes, settings)
    if not spikes:
        settings["spikes"] = {"removed": False}
    lc_arg, ls_arg = engine_cutoffs(cond)
    ap = profiles.analyze_profile(prof.z, prof.dx, x=prof.x, window=window, level=lvl,
                                  ls=ls_arg, lc=lc_arg, n_sampling=cond.n_sampling,
                                  standard=cond.standard,
                                  valley_suppression=valley_suppression,
                                  element_start=cond.element_start)
    stated = dict(prof.metadata.get("evaluation_conditions") or {})
    settings["conditions"] = conditions_record(cond, ap.settings, stated)
    settings.update(ap.settings)
    settings["level"] = lvl
    units = type(ap.parameters).UNITS
    values = ap.parameters.as_dict()
    rough = ap.roughness[ap.evaluated] if ap.evaluated is not None else ap.roughness
    parameters = {k: (v, units.get(k, "")) for k, v in values.items()}
    notes: list[str] = []
    flat = is_flat(ap.form + ap.primary, rough)
    if not flat:
        more, notes = stratified_parameters(rough, cond.rk_line)
        parameters.update(more)
        feats, feature_notes = feature_values(rough, ap.settings["dx"], ap.parameters.Rz)
        parameters.update(feats)
        notes += feature_notes
    letter = "R"
    if primary_profile(cond, ap.settings):
        letter = "P"
        parameters = primary_names(parameters)
        values = primary_names(values)
    ap.settings["parameter_letter"] = letter  # for the profile figure's legend
    settings["parameter_letter"] = letter
    settings["profile_kind"] = ("primary profile: P-parameters, no λc filter (ISO 21920-2)"
                                if letter == "P" else "roughness profile: R-parameters")
    if flat:
        parameters, note = flat_parameters(parameters, "profile")
        notes.insert(0, note)
    settings["rk_line"] = {"value": cond.rk_line, "why": cond.why["rk_line"]}
    settings["element_start"] = {"value": cond.element_start,
                                 "why": cond.why["element_start"]}
    caveats = unit_caveats(prof)
    if caveats:
        settings["caveats"] = caveats
    if notes:
        settings["notes"] = notes
    diag = consistent_diagnosis(spike_diagnosis(rough, prefix=letter), values, letter,
                                report.count if report is not None else None)
    if flat:
        diag = flat_diagnosis(diag)
    settings["spike_diagnosis"] = diag.as_dict()
    return RoughnessResult(kind="profile", parameters=parameters, settings=settings,
                           spike_report=report, spike_diagnosis=diag, file=source,
                           analysis=ap)
