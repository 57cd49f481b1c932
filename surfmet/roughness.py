"""The roughness pipeline: read, spikes, F-operator, S/L filters, parameters — all recorded.

``roughness(scan)`` evaluates an areal scan (S-parameters, ISO 25178-2) or a profile
(R-parameters, ISO 21920-2 / ISO 4287 through :func:`profiles.analyze_profile`), and
returns a :class:`RoughnessResult` whose ``settings`` say exactly what was done: the form
removed, the filters and nesting indices, the edge treatment, the window, the spikes
removed and the Sq/Sa (or Rq/Ra) spike diagnosis.

Order of operations for an areal scan (ISO 25178-2, 3.1.4): optional window →
optional spike removal (:mod:`surfmet._spikes`, on the raw scan, because spikes would bias
the least-squares form) → F-operator (:mod:`surfmet.areal._form`) → optional S-filter (λs) →
optional L-filter (λc) (:mod:`surfmet.areal._filters`) → parameters (:mod:`surfmet.areal`).
Without ``ls``/``lc`` the parameters are those of the S-F surface after the F-operator,
which is what surfalize and SurfaceTopography report after their plane levelling.

``roughness_many`` runs several files one after the other and records a failed file in
its own entry instead of stopping; the per-file work is the top-level, picklable
:func:`roughness_file`, so that a process pool or Dask can map it.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._measurements import DETREND_LEVELS, Measurement, read_measurement
from surfmet._model import Profile, Topography, require_measurement
from surfmet._profile_evaluation import _profile_level, evaluate_profile  # noqa: F401  (show uses it)
from surfmet._roughness_result import RoughnessResult, consistent_diagnosis, unit_caveats
from surfmet.units import parse_length, parse_length_range

AREAL_LEVELS = ("none", "mean", "plane", "poly:N", "sphere", "cylinder")
AREAL_STANDARD = "ISO 25178-2:2012 (areal; --standard applies to profiles)"


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


def _read(scan: Any) -> tuple[Topography | Profile, str | None]:
    if isinstance(scan, Measurement):
        return require_measurement(read_measurement(scan)), str(scan)
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
    element_start: str | None = None,
) -> RoughnessResult:
    """Roughness parameters of a scan with every processing step recorded.

    Parameters
    ----------
    scan : Topography, Profile, path or surfmet._measurements.Measurement
        A file holding several measurements (a container) gives its first here;
        :func:`roughness_many` and the command evaluate each.
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
        Remove spikes (:func:`surfmet._spikes.remove_spikes`) before levelling; the report
        goes into the result.
    edge : {"discard", "moment", "renormalise"}
        Edge treatment of the areal Gaussian filters (:mod:`surfmet.areal._filters`).
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
        (:mod:`profiles._rk`); ``"levels"`` reproduces a Mitutoyo SurfTest printout.
        Default: what the file states (``evaluation_conditions["rk_line"]``), else
        ``"secant"``.
    valley_suppression : bool
        Profiles: ISO 13565-1 two-stage λc filter (stratified surfaces).
    element_start : {"peak", "first-crossing"}, optional
        Profiles: how the profile elements of RSm and Rc are paired in each stretch
        (:mod:`profiles._elements`): peak first, or from the stretch's first mean-line
        crossing, as a Mitutoyo SurfTest does per sampling length. Default: what the file
        states (``evaluation_conditions["element_start"]``) while the standard in force is
        the file's, else ``"peak"``.

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
    level, why_level = _stated_level(data, level)
    if isinstance(data, Profile) or profile is not None:
        from surfmet._profile_roughness import resolve_conditions

        cond = resolve_conditions(dict(data.metadata), standard=standard, lc=lc, ls=ls,
                                  n_sampling=n_sampling, rk_line=rk_line,
                                  element_start=element_start)
        res = evaluate_profile(data, source, level=level, cond=cond, window=win,
                               profile=profile, spikes=spikes,
                               valley_suppression=bool(valley_suppression))
    else:
        ls_v = _length_or_none(ls, "ls")
        lc_v = _length_or_none(lc, "lc")
        if ls_v is not None and lc_v is not None and not ls_v < lc_v:
            raise SurfmetInputError(f"ls ({ls_v:.3g} m) must be shorter than lc "
                                    f"({lc_v:.3g} m)")
        res = _areal_roughness(data, source, level=level or "plane", ls=ls_v, lc=lc_v,
                               window=win, spikes=spikes, edge=edge, which=which)
    if why_level:
        res.settings.setdefault("notes", []).insert(
            0, f"levelling {res.settings.get('level')}: {why_level}")
    if isinstance(scan, (str, os.PathLike)) and data.metadata.get("container"):
        res.settings.setdefault("notes", []).insert(
            0, f"measurement {data.metadata.get('measurement', 0)} "
            f"({data.metadata.get('member')}) of the container, as surfmet.read gives it: "
            "`surfmet roughness` and roughness_many evaluate every measurement")
    return res


def _areal_roughness(topo: Topography, source: str | None, *, level: str, ls, lc, window,
                     spikes: bool, edge: str, which: Any) -> RoughnessResult:
    from profiles._form import is_flat
    from surfmet._flat_scan import flat_diagnosis, flat_parameters
    from surfmet._spikes import remove_spikes, spike_diagnosis
    from surfmet.areal import PARAMETER_UNITS, areal_parameters
    from surfmet.areal._filters import l_filter, s_filter
    from surfmet.areal._form import dominant_form, remove_form
    from surfmet.records._form import form_record
    from surfmet.records._roughness import (
        areal_settings_record,
        cutoff_record,
        filter_record,
        spike_report_record,
    )

    settings = areal_settings_record("areal", AREAL_STANDARD, topo, window)
    if window is not None:
        topo = _crop_areal(topo, window)
    if not np.isfinite(topo.heights).any():
        raise SurfmetInputError("the scan has no measured point")
    settings["non_measured_fraction"] = topo.nan_fraction
    report = None
    before = None
    if spikes:
        levelled_raw, _ = remove_form(topo, level)
        before = spike_diagnosis(levelled_raw)
        topo, report = remove_spikes(topo)
        settings["spikes"] = spike_report_record(report)
    else:
        settings["spikes"] = {"removed": False}
    surface, form = remove_form(topo, level)
    settings["form"] = form_record(form)
    settings["level"] = form.method
    filters = []
    settings["ls"] = cutoff_record(ls)
    settings["lc"] = cutoff_record(lc)
    if ls is not None:
        surface, info = s_filter(surface, ls, edge=edge)
        filters.append(filter_record(info))
    if lc is not None:
        surface, info = l_filter(surface, lc, edge=edge)
        filters.append(filter_record(info))
    settings["filters"] = filters
    if filters:
        from surfmet.areal._filters import EDGE_MEANING

        settings["edge"] = {"value": edge, "meaning": EDGE_MEANING.get(edge, "")}
    settings["surface"] = ("S-L surface" if lc is not None else "S-F surface")
    caveats = unit_caveats(topo) + [c for c in [dominant_form(topo, form)] if c]
    if caveats:
        settings["caveats"] = caveats
    params = areal_parameters(surface, which)
    values = params.as_dict()
    parameters = {k: (v, PARAMETER_UNITS[k]) for k, v in values.items()}
    settings["n_valid_points"] = params.n_valid
    notes = list(params.notes)
    flat = is_flat(topo.heights, surface.heights)
    if flat:
        parameters, note = flat_parameters(parameters, "areal")
        notes = [note]
    if notes:
        settings["notes"] = notes
    diag = consistent_diagnosis(spike_diagnosis(surface), values, "S",
                                report.count if report is not None else None)
    if flat:
        diag = flat_diagnosis(diag)
    dd = diag.as_dict()
    if before is not None:
        dd["before_spike_removal"] = before.as_dict()
    settings["spike_diagnosis"] = dd
    return RoughnessResult(
        kind="areal",
        parameters=parameters,
        settings=settings, spike_report=report, spike_diagnosis=diag, file=source,
        surface=surface,
    )


def _stated_level(data: Topography | Profile, level: str | None) -> tuple[str | None, str]:
    """The level to use and a note: a container's ``detrend_mode`` when none is given."""
    mode = data.metadata.get("detrend_mode")
    if level is not None or mode not in DETREND_LEVELS:
        return level, ""
    return DETREND_LEVELS[mode], f"the container's detrend_mode ({mode}) for this measurement"


def roughness_file(path: str | os.PathLike[str] | Measurement,
                   read_options: dict[str, Any] | None = None, **options: Any) -> dict[str, Any]:
    """Roughness of one file (or container measurement) as a JSON-ready dict; errors are
    returned, not raised.

    Returns ``{"file", "status": "ok", "parameters", "settings"}`` or
    ``{"file", "status": "error", "error": message}``. Top-level and picklable, for
    process pools and Dask. ``read_options`` go to :func:`surfmet.read` (``height_unit=``,
    ``dx=``, ``dy=``, ``channel=``).
    """
    from surfmet._errors import user_error_types

    name = str(path)
    try:
        scan: Any = path
        if read_options:  # the units and channel the user states (--height-unit, ...)
            if isinstance(path, Measurement):
                scan = read_measurement(path, **read_options)
            else:
                from surfmet.io import read

                scan = read(path, **read_options)
        res = roughness(scan, **options)
    except user_error_types() as exc:
        return {"file": name, "status": "error", "error": str(exc)}
    except Exception as exc:  # a bug must not stop a batch; it is reported as such
        return {"file": name, "status": "error",
                "error": f"internal error: {type(exc).__name__}: {exc}"}
    from surfmet.records._roughness import roughness_record

    return {"file": name, "status": "ok", **roughness_record(res)}


def roughness_many(
    paths: Iterable[str | os.PathLike],
    *,
    workers: int | None = 1,
    scheduler: str | None = None,
    progress: bool | None = False,
    **options: Any,
) -> list[dict[str, Any]]:
    """:func:`roughness_file` on each path; one entry per file (per measurement of a
    container, :func:`surfmet._measurements.expand_measurements`), in order, failures
    included.

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

    from surfmet._batch import batch_map
    from surfmet._measurements import expand_measurements

    return batch_map(partial(roughness_file, **options), expand_measurements(paths),
                     workers=workers, scheduler=scheduler, progress=progress,
                     desc="roughness")


__all__ = ["AREAL_STANDARD", "Measurement", "RoughnessResult", "consistent_diagnosis",
           "evaluate_profile", "roughness", "roughness_file", "roughness_many", "unit_caveats"]
