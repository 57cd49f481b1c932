"""The profile roughness pipeline: window, positions, levelling, λs/λc filters, parameters.

Order of operations (ISO 3274 / ISO 4288 / ISO 21920-3)::

    window (x0, x1)  ->  uniform positions  ->  form removal (level)  ->  λs filter
        ->  λc filter (mean line)  ->  evaluation length  ->  parameters

Every choice is written into :attr:`ProfileAnalysis.settings` so that a result can be
reproduced and audited (lengths in metres).

Window. ``window=(x0, x1)`` keeps the points from the sample nearest to ``x0`` to the
sample nearest to ``x1``, inclusive, as a profilometer's cursors do.

Positions. Non-uniform positions are handled by :func:`profiles._positions.regularize`:
a uniform grid printed with rounded positions (Dektak CSV exports) is recognised and used
as is; genuinely irregular sampling is resampled linearly onto a uniform grid (median step),
recorded in ``settings["positions"]``.

Cut-off. ``lc`` is a length, ``None`` (no λc filter: the parameters are those of the
levelled primary profile, what ISO 4287 calls P-parameters), or ``"auto"`` (ISO 4288,
see :mod:`profiles._cutoff`). With ``"auto"``, if the profile is shorter than the
evaluation length ISO 4288 requires for the chosen cut-off (five cut-offs, plus a run-up
and run-out of half a cut-off each with ``end_treatment="discard"``), no λc filter is
applied rather than filtering a profile too short to support it: the parameters are those
of the levelled primary profile over ``n_sampling`` equal parts, as a profilometer reports
them between its cursors, and ``settings["lc"]`` is None with ``settings["lc_note"]``
saying why and which cut-off ISO 4288 would have used. An explicit length that the profile
cannot support raises :class:`ProfileError`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from profiles._arrays import as_heights, as_positions, as_step, length_text, require_valid
from profiles._cutoff import LS_FOR_LC, iso4288_cutoff
from profiles._errors import ProfileError, ProfileTooShortError
from profiles._filters import ALPHA, gaussian_mean_line, parse_end_treatment, split_profile
from profiles._form import level_profile, parse_level
from profiles._parameters import (
    ProfileParameters,
    evaluation_slice,
    parse_standard,
    profile_parameters,
)
from profiles._positions import regularize

_DEFINITIONS = {
    "iso21920": "ISO 21920-2:2021: Ra, Rq, Rsk, Rku, RΔq, RSm, Rc over the evaluation "
    "length; Rp, Rv, Rz averaged over the sampling lengths (see profiles._parameters)",
    "iso4287": "ISO 4287:1997: every parameter defined per sampling length (Ra, Rq, Rsk, "
    "Rku, RΔq, Rp, Rv, Rz, Rc, RSm) averaged over the sampling lengths; Rt over the "
    "evaluation length (see profiles._parameters)",
}


@dataclass(frozen=True, eq=False)
class ProfileAnalysis:
    """Outcome of :func:`analyze_profile`.

    Attributes
    ----------
    parameters : ProfileParameters
        The ISO parameters over the evaluation length.
    settings : dict
        Exactly what was done (window, positions, levelling, ls, lc and how it was chosen,
        end treatment, sampling lengths, points used...). Lengths in metres.
    x : ndarray
        Uniform positions (metres) of the analysed points (after window/regularisation).
    form : ndarray
        The removed form (least-squares line / polynomial), at ``x``.
    primary : ndarray
        Levelled profile after the λs filter (NaN = not measured).
    waviness : ndarray or None
        λc mean line; None without λc filter.
    roughness : ndarray
        ``primary - waviness`` (or ``primary`` without λc filter): the profile the
        parameters were computed from; NaN where not measured or discarded.
    evaluated : ndarray of bool
        True for the points inside the evaluation length.

    See Also
    --------
    analyze_profile : makes it.

    Examples
    --------
    >>> import surfmet, profiles
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> res = profiles.analyze_profile(plate.heights[256], plate.dx)
    >>> res.settings["lc"], res.settings["parameters_of"]
    (0.0008, 'roughness profile')
    >>> res.roughness.shape == res.primary.shape
    True
    """

    parameters: ProfileParameters
    settings: dict[str, Any]
    x: np.ndarray
    form: np.ndarray
    primary: np.ndarray
    waviness: np.ndarray | None
    roughness: np.ndarray
    evaluated: np.ndarray = field(repr=False)


def _window(x: np.ndarray, window: Any) -> tuple[slice, tuple[float, float]]:
    try:
        a, b = (float(w) for w in window)
    except (TypeError, ValueError):
        raise ProfileError(f"window must be (x0, x1) in metres, got {window!r}") from None
    if not (math.isfinite(a) and math.isfinite(b)) or b <= a:
        raise ProfileError(f"window must satisfy x0 < x1, got ({a!r}, {b!r})")
    if b < x[0] or a > x[-1]:
        raise ProfileError(
            f"window {a * 1e6:.6g}-{b * 1e6:.6g} µm lies outside the profile "
            f"({x[0] * 1e6:.6g}-{x[-1] * 1e6:.6g} µm)"
        )

    def nearest(v: float, inner: int) -> int:
        # the sample nearest to v; on an exact tie, the one inside the window
        k = int(np.searchsorted(x, v))
        if k <= 0:
            return 0
        if k >= x.size:
            return x.size - 1
        dl, dr = v - x[k - 1], x[k] - v
        if dl < dr:
            return k - 1
        if dr < dl:
            return k
        return k if inner > 0 else k - 1

    i0, i1 = nearest(a, +1), nearest(b, -1)
    if i1 - i0 + 1 < 2:
        raise ProfileError(
            f"window {a * 1e6:.6g}-{b * 1e6:.6g} µm holds fewer than 2 points of the profile"
        )
    return slice(i0, i1 + 1), (a, b)


def _parse_cutoff(value: Any, name: str) -> float | str | None:
    """A cutoff option ``name`` (``lc`` or ``ls``): a length in metres, ``"auto"`` or None."""
    if value is None:
        return None
    if isinstance(value, str):
        text = value.strip().lower()
        if text == "auto":
            return "auto"
        if text in ("none", "off", "no"):
            return None
        raise ProfileError(f"{name} must be a length in metres, 'auto' or None, got {value!r}")
    return as_step(value, name)


def _uniform_window(
    z: np.ndarray, dx: Any, x: Any, window: Any, settings: dict[str, Any]
) -> tuple[np.ndarray, np.ndarray, float]:
    """Positions, window and uniform resampling: (z, positions, step); records settings."""
    if x is None:
        dx = as_step(dx)
        pos = np.arange(z.size) * dx
    else:
        pos = as_positions(x, z.size)

    # window (on the positions as given, i.e. as the instrument displays them)
    if window is not None:
        sl, (a, b) = _window(pos, window)
        z, pos = z[sl], pos[sl]
        settings["window"] = [a, b]
        settings["window_points"] = [int(sl.start), int(sl.stop - 1)]
        settings["window_extent"] = [float(pos[0]), float(pos[-1])]
    else:
        settings["window"] = None

    # uniform sampling
    if x is not None and z.size >= 3:
        reg = regularize(z, pos)
        z, pos, dx = reg.z, reg.x, reg.dx
        settings["positions"] = {"method": reg.method, **reg.info}
    else:
        if x is not None:  # 1-2 points: nothing to regularise
            dx = float(pos[-1] - pos[0]) if z.size == 2 else as_step(dx)
        settings["positions"] = {"method": "uniform"}
    settings["dx"] = float(dx)
    return z, pos, float(dx)


def _choose_lc(
    primary: np.ndarray,
    dx: float,
    lc_req: float | str | None,
    n_sampling: int | None,
    end_treatment: str,
    periodic: bool | None,
    settings: dict[str, Any],
) -> float | None:
    """The λc to apply (None: no λc filter); records how it was chosen."""
    length = primary.size * dx
    if lc_req == "auto":
        settings["lc_mode"] = "auto (ISO 4288)"
        try:
            choice = iso4288_cutoff(primary, dx, periodic=periodic)
        except ProfileTooShortError as exc:
            settings["lc_note"] = (
                f"{exc}; no λc filter applied: the parameters are those of the levelled "
                f"primary profile (P-parameters) over {5 if n_sampling is None else n_sampling} "
                f"equal parts; give a cut-off to filter it (not ISO 4288 conformant)"
            )
            return None
        settings["lc_iso4288"] = choice.as_dict()
        nsec = 5 if n_sampling is None else int(n_sampling)
        need = nsec * choice.lc + (choice.lc if end_treatment == "discard" else 0.0)
        if length < need * (1 - 1e-9) - dx:
            settings["lc_note"] = (
                f"ISO 4288 gives λc = {length_text(choice.lc)} "
                f"({choice.parameter} = {length_text(choice.value)}), whose evaluation length "
                f"({length_text(need)}) is longer than the profile ({length_text(length)}): "
                f"no λc filter applied; parameters are of the levelled primary profile "
                f"(P-parameters) over {nsec} equal parts (as a profilometer reports between "
                f"its cursors)"
            )
            return None
        return choice.lc
    if lc_req is None:
        settings["lc_mode"] = "none"
        return None
    settings["lc_mode"] = "given"
    return float(lc_req)


def _choose_ls(
    ls_req: float | str | None, lc_value: float | None, dx: float, settings: dict[str, Any]
) -> float | None:
    """The λs to apply (None: no λs filter); ``"auto"`` follows ISO 3274's pairing."""
    if ls_req == "auto":
        if lc_value is None:
            settings["ls_note"] = "an automatic λs needs a λc; no λs filter applied"
            return None
        nearest = min(LS_FOR_LC, key=lambda c: abs(math.log(c / lc_value)))
        cand = LS_FOR_LC[nearest]
        if dx <= cand / 5 * (1 + 1e-9):
            return cand
        settings["ls_note"] = (
            f"ISO 3274 pairs λc = {lc_value * 1e3:.4g} mm with λs = {cand * 1e6:.4g} µm,"
            f" but the step ({dx * 1e6:.4g} µm) is coarser than λs/5: no λs filter"
        )
        return None
    if ls_req is not None:
        return float(ls_req)
    return None


def _filter_with_lc(
    primary: np.ndarray,
    dx: float,
    lc_value: float,
    ls_value: float | None,
    n_sampling: int | None,
    end_treatment: str,
    truncation: float,
    windowed: bool,
    settings: dict[str, Any],
    valley_suppression: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, slice, int, float]:
    """λs/λc split and evaluation length: (primary, waviness, roughness, slice, n, lc)."""
    n = primary.size
    length = n * dx
    nsec = 5 if n_sampling is None else int(n_sampling)
    need = nsec * lc_value + (lc_value if end_treatment == "discard" else 0.0)
    if n_sampling is not None and length < need * (1 - 1e-9) - dx:
        extra = " plus half a cut-off run-up and run-out" if end_treatment == "discard" else ""
        raise ProfileError(
            f"profile{' window' if windowed else ''} is {length * 1e3:.4g} mm "
            f"long, too short for λc = {lc_value * 1e3:.4g} mm: {nsec} sampling lengths"
            f"{extra} need {need * 1e3:.4g} mm. Use a shorter cut-off, fewer sampling "
            f"lengths (n_sampling), a longer profile, or no λc filter (lc=None)"
        )
    split = split_profile(
        primary, dx, lc=lc_value, ls=ls_value, end_treatment=end_treatment,
        truncation=truncation, valley_suppression=valley_suppression,
    )
    if valley_suppression:
        settings["filter"] = split.settings["filter"] + "; " + settings["filter"]
    settings["discarded_each_end"] = split.settings["discarded_each_end"]
    # evaluation length: central whole sampling lengths among the kept points
    if end_treatment == "discard":
        cut = round(split.settings["discarded_each_end"] / dx)
        lo, hi = cut, n - cut
    else:
        lo, hi = 0, n
    sl, nsec = evaluation_slice(hi - lo, dx, lc_value, n_sampling)
    sl = slice(lo + sl.start, lo + sl.stop)
    settings["parameters_of"] = "roughness profile"
    return split.primary, split.waviness, split.roughness, sl, nsec, lc_value


def analyze_profile(
    z: Any,
    dx: float,
    *,
    x: Any = None,
    window: Any = None,
    level: Any = "line",
    ls: Any = None,
    lc: Any = "auto",
    n_sampling: int | None = 5,
    end_treatment: str = "moment",
    truncation: float = 1.0,
    periodic: bool | None = None,
    standard: str = "iso21920",
    valley_suppression: bool = False,
    element_start: str = "peak",
) -> ProfileAnalysis:
    """Roughness analysis of a line profile.

    Parameters
    ----------
    z : array_like
        Heights in metres, NaN where not measured.
    dx : float
        Sampling step in metres (ignored when ``x`` is given, except as a fallback).
    x : array_like, optional
        Positions in metres for non-uniformly sampled profiles (see module docstring).
    window : (x0, x1), optional
        Restrict the analysis to this x-range (metres), before levelling.
    level : {"line", "none", "mean", "poly:N"}
        Form removal by least squares (``"plane"`` is accepted as ``"line"``).
    ls : float, "auto" or None
        Short-wave cut-off λs in metres; ``"auto"``: the ISO 3274 value for λc, applied
        only if the sampling step is at most λs/5 (else skipped, noted). Default: none.
    lc : float, "auto" or None
        Long-wave cut-off λc in metres; ``"auto"``: ISO 4288 (see module docstring);
        None: no λc filter.
    n_sampling : int or None
        Number of sampling lengths (default 5). With a λc filter the sampling length is
        λc and the central ``n_sampling`` of them are evaluated (None: all that fit);
        without, the profile is divided into ``n_sampling`` equal parts (for Rz).
    end_treatment : {"moment", "renormalise", "discard"}
        Filter end-effect handling (:mod:`profiles._filters`).
    truncation : float
        Gaussian weighting function half-width, in cut-offs.
    periodic : bool, optional
        For ``lc="auto"``: force the ISO 4288 periodic / non-periodic rule.
    standard : {"iso21920", "iso4287"}
        ISO 21920-2 (over the evaluation length) or ISO 4287:1997 (per sampling length,
        averaged); see :mod:`profiles._parameters`.
    valley_suppression : bool
        Use the ISO 13565-1 two-stage λc filter (stratified surfaces) instead of the
        plain Gaussian (:func:`profiles._filters.split_profile`).
    element_start : {"peak", "first-crossing"}
        Pairing of the profile elements for RSm and Rc (:mod:`profiles._elements`).

    Returns
    -------
    ProfileAnalysis

    Raises
    ------
    ProfileError
        All-NaN profile, empty window, a profile too short for the requested cut-off and
        sampling lengths, bad arguments.

    See Also
    --------
    profile_parameters : the parameters of a profile already filtered.
    split_profile : the filtering alone.
    iso4288_cutoff : the automatic cut-off.

    References
    ----------
    .. [1] ISO 21920-2:2021, Geometrical product specifications (GPS) -- Surface texture:
       Profile -- Part 2: Terms, definitions and surface texture parameters.
    .. [2] ISO 16610-21:2011, Filtration -- Part 21: Linear profile filters: Gaussian filters.
    .. [3] ISO 4288:1996, Rules and procedures for the assessment of surface texture.

    Examples
    --------
    A row of the bundled plate scan, with the cut-off chosen by ISO 4288:

    >>> import surfmet, profiles
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> res = profiles.analyze_profile(plate.heights[256], plate.dx)
    >>> print(f"lc = {res.settings['lc'] * 1e3} mm, Ra = {res.parameters.Ra * 1e6:.2f} µm")
    lc = 0.8 mm, Ra = 1.71 µm
    """
    z = as_heights(z)
    standard = parse_standard(standard)
    end_treatment = parse_end_treatment(end_treatment)
    level_name, _ = parse_level(level)
    lc_req = _parse_cutoff(lc, "lc")
    ls_req = _parse_cutoff(ls, "ls")
    if n_sampling is not None and int(n_sampling) < 1:
        raise ProfileError(f"n_sampling must be >= 1, got {n_sampling}")
    settings: dict[str, Any] = {"points_input": int(z.size)}

    z, pos, dx = _uniform_window(z, dx, x, window, settings)
    require_valid(z, 3, "roughness analysis")

    # form removal
    fit = level_profile(z, dx, x=pos, level=level)
    settings["level"] = level_name
    settings["level_coefficients"] = list(fit.coefficients)
    primary = fit.residuals
    settings["profile_length"] = z.size * dx

    lc_value = _choose_lc(primary, dx, lc_req, n_sampling, end_treatment, periodic, settings)
    ls_value = _choose_ls(ls_req, lc_value, dx, settings)
    settings["ls"] = ls_value
    settings["lc"] = lc_value
    settings["end_treatment"] = end_treatment if (lc_value or ls_value) else None
    if lc_value is not None or ls_value is not None:
        settings["filter"] = (
            f"Gaussian (ISO 16610-21, alpha = {ALPHA:.6f}), weights truncated at "
            f"±{truncation:g} cut-off"
        )
        settings["truncation"] = truncation

    waviness: np.ndarray | None = None
    if lc_value is not None:
        primary, waviness, rough, sl, nsec, sampling_length = _filter_with_lc(
            primary, dx, lc_value, ls_value, n_sampling, end_treatment, truncation,
            window is not None, settings, valley_suppression,
        )
    else:
        if ls_value is not None:
            primary = gaussian_mean_line(
                primary, dx, ls_value,
                end_treatment="renormalise" if end_treatment == "renormalise" else "moment",
                truncation=truncation,
            )
        rough = primary
        nsec = 5 if n_sampling is None else int(n_sampling)
        sl = slice(0, z.size)
        sampling_length = (sl.stop - sl.start) * dx / nsec
        settings["parameters_of"] = "levelled primary profile (no λc filter)"

    ev = rough[sl]
    params = profile_parameters(ev, dx, n_sampling=nsec, standard=standard,
                                element_start=element_start)
    evaluated = np.zeros(z.size, dtype=bool)
    evaluated[sl] = True
    settings["n_sampling"] = nsec
    settings["sampling_length"] = float(sampling_length)
    settings["evaluation_length"] = float((sl.stop - sl.start) * dx)
    settings["evaluation_range"] = [float(pos[sl.start]), float(pos[sl.stop - 1])]
    settings["points_used"] = int(np.count_nonzero(np.isfinite(ev)))
    settings["points_not_measured"] = int(np.count_nonzero(~np.isfinite(ev)))
    settings["standard"] = standard
    settings["definitions"] = _DEFINITIONS[standard]

    def frozen(a: np.ndarray) -> np.ndarray:
        a = np.array(a, dtype=float)
        a.setflags(write=False)
        return a

    evaluated.setflags(write=False)
    return ProfileAnalysis(
        parameters=params,
        settings=settings,
        x=frozen(pos),
        form=frozen(fit.form),
        primary=frozen(primary),
        waviness=None if waviness is None else frozen(waviness),
        roughness=frozen(rough),
        evaluated=evaluated,
    )
