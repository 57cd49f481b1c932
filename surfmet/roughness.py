"""The roughness pipeline: read, spikes, F-operator, S/L filters, parameters — all recorded.

``roughness(scan)`` evaluates an areal scan (S-parameters, ISO 25178-2) or a profile
(R-parameters, ISO 21920-2 / ISO 4287 through :func:`profiles.analyze_profile`), and
returns a :class:`RoughnessResult` whose ``settings`` say exactly what was done: the form
removed, the filters and nesting indices, the edge treatment, the window, the spikes
removed and the Sq/Sa (or Rq/Ra) spike diagnosis.

Order of operations for an areal scan (ISO 25178-2, 3.1.4): optional window →
optional spike removal (:mod:`surfmet.spikes`, on the raw scan, because spikes would bias
the least-squares form) → F-operator (:mod:`surfmet.areal.form`) → optional S-filter (λs) →
optional L-filter (λc) (:mod:`surfmet.areal.filters`) → parameters (:mod:`surfmet.areal`).
Without ``ls``/``lc`` the parameters are those of the S-F surface after the F-operator,
which is what surfalize and SurfaceTopography report after their plane levelling.

``roughness_many`` runs several files one after the other and records a failed file in
its own entry instead of stopping; the per-file work is the top-level, picklable
:func:`roughness_file`, so that a process pool or Dask can map it.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from surfmet.errors import SurfmetInputError
from surfmet.model import Profile, Topography, require_measurement
from surfmet.units import jsonable, parse_length, parse_length_range

AREAL_LEVELS = ("none", "mean", "plane", "poly:N", "sphere", "cylinder")
AREAL_STANDARD = "ISO 25178-2:2012 (areal; --standard applies to profiles)"


@dataclass(frozen=True, eq=False)
class RoughnessResult:
    """Outcome of :func:`roughness`.

    Attributes
    ----------
    kind : {"areal", "profile"}
    parameters : dict
        ``{symbol: (value, unit)}``; SI lengths, ratios in %, angles in degrees.
    settings : dict
        What was done (form, filters, cut-offs, edge treatment, window, spikes, diagnosis).
    spike_report : SpikeReport or None
        Present when spike removal ran.
    spike_diagnosis : SpikeDiagnosis or None
        Sq/Sa (Rq/Ra) diagnosis of the evaluated surface.
    file : str or None
        Source path when known.
    surface : Topography or None
        The evaluated areal surface (after window, spikes, F-operator and filters) that
        the S-parameters describe, for figures; not part of the JSON.
    analysis : profiles.ProfileAnalysis or None
        The profile engine's analysis behind R-parameters (primary, waviness, roughness),
        for figures; not part of the JSON.
    """

    kind: str
    parameters: dict[str, tuple[float, str]]
    settings: dict[str, Any] = field(default_factory=dict)
    spike_report: Any = None
    spike_diagnosis: Any = None
    file: str | None = None
    surface: Any = field(default=None, repr=False)
    analysis: Any = field(default=None, repr=False)

    def value(self, symbol: str) -> float:
        """The value of one parameter (SI)."""
        try:
            return self.parameters[symbol][0]
        except KeyError:
            raise SurfmetInputError(
                f"{symbol!r} was not computed; have {', '.join(self.parameters)}"
            ) from None

    def to_json(self) -> dict[str, Any]:
        """``{"parameters": {sym: {"value", "unit"}}, "settings": {...}}`` (JSON types).

        Lengths in a profile's settings (SI floats in :attr:`settings`) become
        ``{"value", "unit"}`` here, at the edge.
        """
        settings = self.settings
        if self.kind == "profile":
            from surfmet.profile_roughness import with_units

            settings = with_units(settings)
        return {
            "parameters": {k: {"value": jsonable(v), "unit": u}
                           for k, (v, u) in self.parameters.items()},
            "settings": jsonable(settings),
        }


def _length_or_none(value: Any, what: str) -> float | None:
    if value is None:
        return None
    if isinstance(value, str) and value.strip().lower() in ("none", "off", ""):
        return None
    if isinstance(value, str) and value.strip().lower() == "auto":
        raise SurfmetInputError(f"{what} auto (the ISO 4288 rule) applies to profiles; an "
                                f"areal scan needs a length or none")
    v = parse_length(value)
    if not v > 0:
        raise SurfmetInputError(f"{what} must be a positive length, got {value!r}")
    return v


def _window(window: Any) -> tuple[float, float] | None:
    if window is None:
        return None
    if isinstance(window, str):
        return parse_length_range(window)
    try:
        lo, hi = (float(v) for v in window)
    except (TypeError, ValueError):
        raise SurfmetInputError(f"window must be X0:X1 or (x0, x1), got {window!r}") from None
    if not hi > lo:
        raise SurfmetInputError(f"window {window!r} is empty: X1 must exceed X0")
    return lo, hi


def _crop_areal(topo: Topography, win: tuple[float, float]) -> Topography:
    x = topo.x
    cols = np.flatnonzero((x >= win[0] - 1e-12 * topo.dx) & (x <= win[1] + 1e-12 * topo.dx))
    if cols.size < 2:
        raise SurfmetInputError(
            f"window {win[0]:.6g}..{win[1]:.6g} m holds fewer than 2 columns of the "
            f"{topo.size_x:.6g} m wide scan"
        )
    md = dict(topo.metadata)
    md["window_x0"] = float(x[cols[0]])
    return topo.replace(heights=topo.heights[:, cols[0]: cols[-1] + 1], metadata=md)


def unit_caveats(scan: Any) -> list[str]:
    """What the file does not state about its units, to carry into every result: each unit
    assumed, or stated by the user (:meth:`surfmet.model.Calibration.caveats`).

    ``scan`` is a Topography or Profile (its pixel is named), or its metadata.
    """
    from surfmet.model import Calibration

    cal = getattr(scan, "calibration", None)
    return (cal if cal is not None else Calibration.of(scan or {})).caveats()


def consistent_diagnosis(diag: Any, values: dict[str, float], prefix: str,
                         spikes_removed: int | None) -> Any:
    """The spike diagnosis restated with the result's own q/a ratio and kurtosis.

    The diagnosis recomputes them about the sample mean; the profile parameters are taken
    about the mean line (ISO), so the two could print different Rku for one result. Here
    the table's values are used, and after a spike removal the advice is not "remove
    spikes" again but what the extreme heights left must be.
    """
    import dataclasses

    from surfmet.spikes import OUTLIER_SIGMAS, SUSPECT_SQ_OVER_SA

    q, a, k = values.get(f"{prefix}q"), values.get(f"{prefix}a"), values.get(f"{prefix}ku")
    if not (q and a and k is not None and np.isfinite(k)):
        return diag
    ratio = q / a
    if spikes_removed is None and (f"{ratio:.3g}", f"{k:.3g}") == (
            f"{diag.sq_over_sa:.3g}", f"{diag.kurtosis:.3g}"):
        return diag  # already says what the table says
    suspected = ratio > SUSPECT_SQ_OVER_SA or diag.n_outliers > 0
    names = f"{prefix}q, {prefix}z, {prefix}sk and {prefix}ku"
    head = (f"{prefix}q/{prefix}a = {ratio:.3g} (Gaussian surface: {diag.gaussian_ratio:.3g}; "
            f"real textures at most ~1.4); {prefix}ku = {k:.3g}; {diag.n_outliers} point(s) "
            f"lie beyond {OUTLIER_SIGMAS:g} robust sigma of the height distribution.")
    if not suspected:
        msg = (f"{prefix}q/{prefix}a = {ratio:.3g} (Gaussian surface: "
               f"{diag.gaussian_ratio:.3g}); no sign of spikes.")
    elif spikes_removed is None:
        msg = (f"{head} A few extreme heights (spikes, outliers, dust) dominate {names}: "
               "remove spikes (roughness(..., spikes=True) / --spikes) or check the scan "
               "before trusting them.")
    else:
        msg = (f"{head} This is after removing {spikes_removed} spike(s): the extreme "
               "heights left are not isolated spikes (wide dust, pits, scratches, steps or "
               f"non-measured edges read as heights), which spike removal does not touch; "
               f"inspect the scan before trusting {names}.")
    return dataclasses.replace(diag, sq_over_sa=ratio, kurtosis=float(k),
                               suspected=bool(suspected), message=msg)


def _read(scan: Any) -> tuple[Topography | Profile, str | None]:
    if isinstance(scan, (Topography, Profile)):
        return require_measurement(scan), scan.metadata.get("source")
    if isinstance(scan, (str, os.PathLike)):
        from surfmet.io import read

        return require_measurement(read(scan)), str(scan)
    raise SurfmetInputError(
        f"roughness needs a Topography, a Profile or a file path, got {type(scan).__name__}"
    )


def roughness(
    scan: Topography | Profile | str | os.PathLike,
    *,
    level: str | None = None,
    ls: Any = None,
    lc: Any = None,
    window: Any = None,
    profile: str | None = None,
    spikes: bool = False,
    edge: str = "discard",
    which: Any = None,
    standard: str | None = None,
    n_sampling: int | None = None,
    rk_line: str | None = None,
    valley_suppression: bool = False,
) -> RoughnessResult:
    """Roughness parameters of a scan with every processing step recorded.

    Parameters
    ----------
    scan : Topography, Profile or path
    level : str, optional
        F-operator: ``"none"``, ``"mean"``, ``"plane"``, ``"poly:N"``, ``"sphere"``,
        ``"cylinder"`` (areal); on a profile ``"plane"`` means a least-squares line.
        Default ``"plane"``, except ``"none"`` for a file holding an instrument's
        R-profile (already referred to its mean line by the instrument's filter).
    ls, lc : float or str, optional
        Nesting indices of the S- and L-filters (metres, or text with a unit such as
        ``"2.5um"``; ``"none"`` for no filter). Areal default: none (the S-F surface).
        Profile default: the λc the file states (an instrument's export), else the ISO 4288
        rule (``"auto"``); ``lc="none"`` evaluates an already filtered profile as it is.
    window : "X0:X1" or (x0, x1), optional
        Restrict the evaluation to this x-range (metres from the scan origin).
    profile : "row:K" or "col:K", optional
        Evaluate a profile extracted from an areal scan (R-parameters).
    spikes : bool
        Remove spikes (:func:`surfmet.spikes.remove_spikes`) before levelling; the report
        goes into the result.
    edge : {"discard", "moment", "renormalise"}
        Edge treatment of the areal Gaussian filters (:mod:`surfmet.areal.filters`).
        Default ``"discard"``: the Gaussian filter of ISO 16610-61 is the full weighting
        function only where it lies inside the scan; within half a nesting index of a
        border it is cut (the end effects of ISO 16610-21, 4.3, whose corrections ISO
        16610-28 lists, and which ISO 4288 leaves out of a profile's evaluation as run-up
        and run-out), so that band is left out and the parameters come from the inner
        area, where the filter is the standard's. The moment correction keeps the band and
        is exact for a plane, but attenuates wavelengths near λc there (Sq of a surface
        with wavelengths at λc/2-λc/6 about 2 % low on a 2.5 λc scan); use it, or
        ``"renormalise"``, for a scan too small to lose the band.
    which : optional
        Areal parameters to compute (symbols or groups, see
        :func:`surfmet.areal.areal_parameters`); default all.
    standard : {"iso21920", "iso4287"}, optional
        Profiles: ISO 21920-2 (over the evaluation length) or ISO 4287:1997 (per sampling
        length, averaged, as most instruments print). Default: what the file states, else
        ``"iso21920"``.
    n_sampling : int, optional
        Profiles: number of sampling lengths. Default: what the file states, else 5.
    rk_line : {"secant", "least-squares", "levels"}, optional
        Profiles: construction of the ISO 13565-2 equivalent straight line
        (:mod:`profiles.rk`); ``"levels"`` reproduces a Mitutoyo SurfTest printout.
        Default: what the file states (``evaluation_conditions["rk_line"]``), else
        ``"secant"``.
    valley_suppression : bool
        Profiles: ISO 13565-1 two-stage λc filter (stratified surfaces).

    Returns
    -------
    RoughnessResult

    Raises
    ------
    SurfmetInputError, SurfmetFormatError, profiles.ProfileError
        Unreadable file, bad option, scan too small for a cut-off, all-NaN data.
    """
    data, source = _read(scan)
    win = _window(window)
    if isinstance(data, Profile) or profile is not None:
        from surfmet.profile_roughness import resolve_conditions

        cond = resolve_conditions(dict(data.metadata), standard=standard, lc=lc, ls=ls,
                                  n_sampling=n_sampling, rk_line=rk_line)
        return _profile_roughness(data, source, level=level, cond=cond, window=win,
                                  profile=profile, spikes=spikes,
                                  extra={"rk_line": cond.rk_line,
                                         "valley_suppression": bool(valley_suppression)})
    ls_v = _length_or_none(ls, "ls")
    lc_v = _length_or_none(lc, "lc")
    if ls_v is not None and lc_v is not None and not ls_v < lc_v:
        raise SurfmetInputError(f"ls ({ls_v:.3g} m) must be shorter than lc ({lc_v:.3g} m)")
    return _areal_roughness(data, source, level=level or "plane", ls=ls_v, lc=lc_v, window=win,
                            spikes=spikes, edge=edge, which=which)


def _areal_roughness(topo: Topography, source: str | None, *, level: str, ls, lc, window,
                     spikes: bool, edge: str, which: Any) -> RoughnessResult:
    from surfmet.areal import PARAMETER_UNITS, areal_parameters
    from surfmet.areal.filters import l_filter, s_filter
    from surfmet.areal.form import dominant_form, remove_form
    from surfmet.spikes import remove_spikes, spike_diagnosis

    settings: dict[str, Any] = {"kind": "areal", "standard": AREAL_STANDARD,
                                "grid": {"nx": topo.nx, "ny": topo.ny},
                                "dx": {"value": topo.dx, "unit": "m"},
                                "dy": {"value": topo.dy, "unit": "m"}}
    if window is not None:
        topo = _crop_areal(topo, window)
        settings["window"] = {"value": list(window), "unit": "m"}
    else:
        settings["window"] = None
    if not np.isfinite(topo.heights).any():
        raise SurfmetInputError("the scan has no measured point")
    settings["non_measured_fraction"] = topo.nan_fraction
    report = None
    before = None
    if spikes:
        levelled_raw, _ = remove_form(topo, level)
        before = spike_diagnosis(levelled_raw)
        topo, report = remove_spikes(topo)
        settings["spikes"] = report.as_dict()
    else:
        settings["spikes"] = {"removed": False}
    surface, form = remove_form(topo, level)
    settings["form"] = form.as_dict()
    settings["level"] = form.method
    filters = []
    settings["ls"] = None if ls is None else {"value": ls, "unit": "m"}
    settings["lc"] = None if lc is None else {"value": lc, "unit": "m"}
    if ls is not None:
        surface, info = s_filter(surface, ls, edge=edge)
        filters.append(info.as_dict())
    if lc is not None:
        surface, info = l_filter(surface, lc, edge=edge)
        filters.append(info.as_dict())
    settings["filters"] = filters
    if filters:
        from surfmet.areal.filters import EDGE_MEANING

        settings["edge"] = {"value": edge, "meaning": EDGE_MEANING.get(edge, "")}
    settings["surface"] = ("S-L surface" if lc is not None else "S-F surface")
    caveats = unit_caveats(topo) + [c for c in [dominant_form(topo, form)] if c]
    if caveats:
        settings["caveats"] = caveats
    params = areal_parameters(surface, which)
    values = params.as_dict()
    settings["n_valid_points"] = params.n_valid
    if params.notes:
        settings["notes"] = list(params.notes)
    diag = consistent_diagnosis(spike_diagnosis(surface), values, "S",
                                report.count if report is not None else None)
    dd = diag.as_dict()
    if before is not None:
        dd["before_spike_removal"] = before.as_dict()
    settings["spike_diagnosis"] = dd
    return RoughnessResult(
        kind="areal",
        parameters={k: (v, PARAMETER_UNITS[k]) for k, v in values.items()},
        settings=settings, spike_report=report, spike_diagnosis=diag, file=source,
        surface=surface,
    )


def _profile_level(level: str) -> str:
    text = str(level).strip().lower()
    if text in ("sphere", "cylinder") or text.startswith("cylinder:"):
        raise SurfmetInputError(
            f"level {level!r} is an areal form; for a profile use none, mean, plane (a "
            "least-squares line) or poly:N"
        )
    return "line" if text == "plane" else text


def _profile_roughness(data, source, *, level, cond, window, profile, spikes, extra
                       ) -> RoughnessResult:
    import profiles
    from surfmet.extract import extract_profile
    from surfmet.profile_roughness import (
        conditions_record,
        engine_cutoffs,
        feature_values,
        stratified_parameters,
    )
    from surfmet.spikes import remove_spikes, spike_diagnosis

    settings: dict[str, Any] = {"kind": "profile"}
    report = None
    lvl = _profile_level(level or ("none" if cond.prefiltered else "plane"))
    if isinstance(data, Topography):
        if profile is None:  # pragma: no cover - guarded by the caller
            raise SurfmetInputError("an areal scan needs profile='row:K' or 'col:K'")
        if spikes:
            data, report = remove_spikes(data)
            settings["spikes"] = report.as_dict()
        prof = extract_profile(data, profile)
        settings["profile"] = prof.metadata.get("profile")
    else:
        if profile is not None:
            raise SurfmetInputError("--profile applies to areal scans; this file is a profile")
        prof = data
        if spikes:
            as_topo = Topography(prof.z[None, :], prof.dx, prof.dx, metadata=prof.metadata)
            cleaned, report = remove_spikes(as_topo)
            prof = prof.replace(z=cleaned.heights[0])
            settings["spikes"] = report.as_dict()
    if not spikes:
        settings["spikes"] = {"removed": False}
    lc_arg, ls_arg = engine_cutoffs(cond)
    ap = profiles.analyze_profile(prof.z, prof.dx, x=prof.x, window=window, level=lvl,
                                  ls=ls_arg, lc=lc_arg, n_sampling=cond.n_sampling,
                                  standard=cond.standard,
                                  valley_suppression=extra["valley_suppression"])
    stated = dict(prof.metadata.get("evaluation_conditions") or {})
    settings["conditions"] = conditions_record(cond, ap.settings, stated)
    settings.update(ap.settings)
    settings["level"] = lvl
    units = type(ap.parameters).UNITS
    values = ap.parameters.as_dict()
    rough = ap.roughness[ap.evaluated] if ap.evaluated is not None else ap.roughness
    parameters = {k: (v, units.get(k, "")) for k, v in values.items()}
    more, notes = stratified_parameters(rough, extra["rk_line"])
    parameters.update(more)
    feats, feature_notes = feature_values(rough, ap.settings["dx"], ap.parameters.Rz)
    parameters.update(feats)
    notes += feature_notes
    settings["rk_line"] = {"value": cond.rk_line, "why": cond.why["rk_line"]}
    caveats = unit_caveats(prof)
    if caveats:
        settings["caveats"] = caveats
    if notes:
        settings["notes"] = notes
    diag = consistent_diagnosis(spike_diagnosis(rough, prefix="R"), values, "R",
                                report.count if report is not None else None)
    settings["spike_diagnosis"] = diag.as_dict()
    return RoughnessResult(
        kind="profile",
        parameters=parameters,
        settings=settings, spike_report=report, spike_diagnosis=diag, file=source,
        analysis=ap,
    )


def roughness_file(path: str | os.PathLike, read_options: dict[str, Any] | None = None,
                   **options: Any) -> dict[str, Any]:
    """Roughness of one file as a JSON-ready dict; errors are returned, not raised.

    Returns ``{"file", "status": "ok", "parameters", "settings"}`` or
    ``{"file", "status": "error", "error": message}``. Top-level and picklable, for
    process pools and Dask. ``read_options`` go to :func:`surfmet.read` (``height_unit=``,
    ``dx=``, ``dy=``, ``channel=``).
    """
    from surfmet.errors import user_error_types

    name = str(path)
    try:
        scan: Any = path
        if read_options:  # the units and channel the user states (--height-unit, ...)
            from surfmet.io import read

            scan = read(path, **read_options)
        res = roughness(scan, **options)
    except user_error_types() as exc:
        return {"file": name, "status": "error", "error": str(exc)}
    except Exception as exc:  # a bug must not stop a batch; it is reported as such
        return {"file": name, "status": "error",
                "error": f"internal error: {type(exc).__name__}: {exc}"}
    return {"file": name, "status": "ok", **res.to_json()}


def roughness_many(
    paths: Iterable[str | os.PathLike],
    *,
    workers: int | None = 1,
    scheduler: str | None = None,
    progress: bool | None = False,
    **options: Any,
) -> list[dict[str, Any]]:
    """:func:`roughness_file` on each path; one entry per file, in order, failures included.

    Parameters
    ----------
    paths : iterable of path-like
    workers : int or None
        Local processes (1 = serial, the default here; None = one per core).
    scheduler : str, optional
        Address of a Dask distributed scheduler; the files are processed there instead.
    progress : bool or None
        Show a progress bar on stderr (None: only on a terminal).
    **options
        Passed to :func:`roughness` (level, ls, lc, window, profile, spikes...).
    """
    from functools import partial

    from surfmet.batch import batch_map

    return batch_map(partial(roughness_file, **options), [str(p) for p in paths],
                     workers=workers, scheduler=scheduler, progress=progress,
                     desc="roughness")
