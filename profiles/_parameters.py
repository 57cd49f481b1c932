"""Profile (R-) parameters per ISO 4287:1997 / ISO 21920-2:2021.

The heights passed in are measured from the mean line (a roughness profile, or a levelled
primary profile); nothing is re-centred here. All values are SI (metres; slopes and shape
factors dimensionless) and come from measured points only (NaN = not measured).

Definitions used (``ln`` evaluation length, ``lr`` sampling length, ``z`` heights):

Two standards, chosen with ``standard``:

``"iso21920"`` (default, ISO 21920-2:2021)
    Ra, Rq, Rsk, Rku, Rdq, Rsm and Rc are evaluated once over the evaluation length ``ln``;
    Rp, Rv, Rz are means over the sampling lengths.
``"iso4287"`` (ISO 4287:1997, what most instruments print by default)
    Every parameter the standard defines per sampling length (Ra, Rq, Rsk, Rku, Rdq, Rp,
    Rv, Rz, Rc, Rsm) is evaluated in each sampling length and the values are averaged
    (ISO 4288:1996, 4.1); the height discrimination of Rsm and Rc is 10 % of the Rz of
    that sampling length. Rt stays an evaluation-length parameter.

``Ra``   arithmetic mean of ``|z|``.
``Rq``   root mean square of ``z``.
``Rsk``  ``mean(z**3) / Rq**3``.  ``Rku``  ``mean(z**4) / Rq**4``.
``Rp``   mean over the sampling lengths of the highest peak ``max(z)`` in each.
``Rv``   mean over the sampling lengths of the deepest valley ``-min(z)`` in each
         (a positive number).
``Rz``   mean over the sampling lengths of ``max(z) - min(z)`` in each (= Rp + Rv); with
         five sampling lengths this is the classical DIN "RzDin".
``Rt``   ``max(z) - min(z)`` over ``ln``.
``Rsm``  mean width of the profile elements (ISO 4287): an element is a peak (part
         above the mean line) with the adjacent valley; peaks and valleys lower than the
         height discrimination (10 % of Rz) or narrower than the width discrimination
         (1 % of ``lr``) are not counted as such but merged into their neighbours
         (ISO 4287 height/spacing discrimination). Widths are measured between
         successive up-crossings of the mean line, located by linear interpolation
         (:mod:`profiles._elements`).
``Rc``   mean height of the same profile elements (peak height plus valley depth).
``Rdq``  root mean square of the local slope ``dz/dx``, with the seven-point derivative of
         ISO 4287:1997 (note to the local slope), ``(z[i+3] - 9 z[i+2] + 45 z[i+1] - 45 z[i-1]
         + 9 z[i-2] - z[i-3]) / (60 dx)``, evaluated where all seven points are measured.
         For non-uniform positions the central difference is used instead.

Sampling lengths: with ``sampling_length=None`` the evaluation length is divided into
``n_sampling`` equal parts (what a profilometer does on a cursor window); otherwise
``n_sampling`` sampling lengths of the given size are taken from the centre of the profile
(``n_sampling=None``: as many whole ones as fit) and every parameter is evaluated on that
central evaluation length.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from types import MappingProxyType
from typing import Any, ClassVar

import numpy as np

from profiles._arrays import as_heights, as_positions, as_step, cell_widths, require_valid
from profiles._elements import profile_elements
from profiles._errors import ProfileError
from profiles._resolution import sampling_length_problem

#: The two ways of evaluating per-sampling-length parameters (see module docstring).
STANDARDS = ("iso21920", "iso4287")

# ISO 4287:1997, note to the local slope dZ/dX: seven-point first derivative.
_SLOPE7 = np.array([-1.0, 9.0, -45.0, 0.0, 45.0, -9.0, 1.0]) / 60.0


@dataclass(frozen=True)
class ProfileParameters:
    """ISO 4287 / ISO 21920-2 profile parameters, SI units (see :attr:`UNITS`).

    NaN means "not defined for this profile" (e.g. ``Rsm`` when no complete profile
    element exists, ``Rsk`` of a perfectly flat profile).

    See Also
    --------
    profile_parameters : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import profile_parameters
    >>> x = np.arange(4000) * 1e-6
    >>> p = profile_parameters(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6)
    >>> print(f"Ra = {p.Ra * 1e6:.3f} µm, Rq = {p.Rq * 1e6:.3f} µm, RSm = {p.Rsm * 1e6:.0f} µm")
    Ra = 0.636 µm, Rq = 0.707 µm, RSm = 100 µm
    """

    Ra: float
    Rq: float
    Rp: float
    Rv: float
    Rz: float
    Rt: float
    Rsk: float
    Rku: float
    Rsm: float
    Rdq: float
    Rc: float = math.nan

    UNITS: ClassVar[Mapping[str, str]] = MappingProxyType(
        {
            "Ra": "m",
            "Rq": "m",
            "Rp": "m",
            "Rv": "m",
            "Rz": "m",
            "Rt": "m",
            "Rsk": "",
            "Rku": "",
            "Rsm": "m",
            "Rdq": "",
            "Rc": "m",
        }
    )

    def as_dict(self) -> dict[str, float]:
        """``{symbol: value}`` in SI, in the order of :attr:`UNITS`."""
        return {k: float(v) for k, v in asdict(self).items()}


def evaluation_slice(
    n_points: int, dx: float, sampling_length: float, n_sampling: int | None
) -> tuple[slice, int]:
    """Central run of whole sampling lengths within ``n_points`` uniform points.

    Returns
    -------
    (slice, n_sections)
        The points of the evaluation length and the number of sampling lengths in it.

    Raises
    ------
    ProfileError
        If the profile holds fewer than ``n_sampling`` sampling lengths.
    """
    length = n_points * dx
    per = sampling_length / dx  # points per sampling length (may be fractional)
    # one sample of slack: a 4 mm trace may be stored as 8000 or as 8001 points
    fits = math.floor((n_points + 1) / per + 1e-9)
    wanted = fits if n_sampling is None else int(n_sampling)
    if wanted < 1 or fits < wanted:
        need = (wanted if wanted >= 1 else 1) * sampling_length
        raise ProfileError(
            f"profile is {length * 1e3:.4g} mm long but {max(wanted, 1)} sampling length(s) "
            f"of {sampling_length * 1e3:.4g} mm need {need * 1e3:.4g} mm: measure a longer "
            f"profile, use fewer sampling lengths or a shorter cut-off"
        )
    m = min(round(wanted * per), n_points)
    start = (n_points - m) // 2
    return slice(start, start + m), wanted


def _sections(pos: np.ndarray, widths: np.ndarray, n_sections: int) -> np.ndarray:
    """Index of the sampling length each point falls in (by the start of its cell)."""
    start = pos[0] - 0.5 * widths[0]
    total = float(np.sum(widths))
    lr = total / n_sections
    left = pos - 0.5 * widths - start
    k = np.floor(left / lr + 1e-9).astype(np.int64)
    return np.clip(k, 0, n_sections - 1)


def _local_slope(z: np.ndarray, pos: np.ndarray, uniform: bool, dx: float) -> np.ndarray:
    """Local slopes at the points where the derivative stencil is fully measured."""
    if uniform:
        if z.size < 7:
            return np.empty(0)
        windows = np.lib.stride_tricks.sliding_window_view(z, 7)
        slope = windows @ _SLOPE7 / dx
    else:
        if z.size < 3:
            return np.empty(0)
        slope = (z[2:] - z[:-2]) / (pos[2:] - pos[:-2])
    return slope[np.isfinite(slope)]


def profile_parameters(
    z: Any,
    dx: float,
    *,
    x: Any = None,
    sampling_length: float | None = None,
    n_sampling: int | None = 5,
    standard: str = "iso21920",
    height_discrimination: float = 0.10,
    width_discrimination: float = 0.01,
    element_start: str = "peak",
) -> ProfileParameters:
    """Compute the ISO profile parameters of a profile measured from its mean line.

    Parameters
    ----------
    z : array_like, shape (n,)
        Heights in metres from the mean line (roughness profile or levelled primary
        profile); NaN where not measured.
    dx : float
        Sampling step in metres (for non-uniform ``x``: only used if ``x`` is None).
    x : array_like, optional
        Point positions in metres when the sampling is not uniform. Each point then counts
        with the length of profile it stands for (half-way to its neighbours).
    sampling_length : float, optional
        Sampling length ``lr`` in metres (normally ``lr = λc``). ``None``: the profile is
        the evaluation length and is divided into ``n_sampling`` equal sampling lengths.
    n_sampling : int or None
        Number of sampling lengths (default 5, ISO 4288). With ``sampling_length`` given,
        ``None`` takes all whole sampling lengths that fit.
    standard : {"iso21920", "iso4287"}
        Evaluate over the evaluation length (ISO 21920-2) or per sampling length and
        average (ISO 4287:1997); see the module docstring.
    height_discrimination, width_discrimination : float
        For ``Rsm`` and ``Rc``: fraction of ``Rz`` and of ``lr`` below which peaks/valleys
        are not counted (ISO 4287 defaults 10 % and 1 %).
    element_start : {"peak", "first-crossing"}
        How the profile elements of each stretch are paired (:mod:`profiles._elements`):
        peak first (ISO 4287 reading), or from the first mean-line crossing, as a
        Mitutoyo SurfTest does.

    Returns
    -------
    ProfileParameters

    Raises
    ------
    ProfileError
        All-NaN profile, bad step/positions, a profile shorter than the requested
        sampling lengths, or sampling lengths under three sampling distances
        (:mod:`profiles._resolution`).

    See Also
    --------
    analyze_profile : levelling and filtering first, then these.
    rk_parameters, feature_parameters : the other parameter families.

    References
    ----------
    .. [1] ISO 21920-2:2021, Geometrical product specifications (GPS) -- Surface texture:
       Profile -- Part 2: Terms, definitions and surface texture parameters.
    .. [2] ISO 4287:1997, Surface texture: Profile method -- Terms, definitions and surface
       texture parameters.

    Examples
    --------
    A sine of amplitude A has Ra = 2A/π, Rq = A/√2, Rz = 2A, RSm its wavelength:

    >>> import numpy as np
    >>> from profiles import profile_parameters
    >>> x = np.arange(4000) * 1e-6
    >>> p = profile_parameters(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6)
    >>> print(f"Ra = {p.Ra * 1e6:.3f} µm (2/π = {2 / np.pi:.3f}), Rq = {p.Rq * 1e6:.3f} µm")
    Ra = 0.636 µm (2/π = 0.637), Rq = 0.707 µm
    >>> print(f"Rz = {p.Rz * 1e6:.2f} µm, RSm = {p.Rsm * 1e6:.0f} µm")
    Rz = 2.00 µm, RSm = 100 µm
    """
    z = as_heights(z)
    standard = parse_standard(standard)
    uniform = x is None
    if uniform:
        dx = as_step(dx)
        pos = np.arange(z.size) * dx
    else:
        pos = as_positions(x, z.size)
        dx = float(np.median(np.diff(pos))) if z.size > 1 else as_step(dx)
    if n_sampling is not None and int(n_sampling) < 1:
        raise ProfileError(f"n_sampling must be >= 1, got {n_sampling}")
    require_valid(z, 1, "profile parameters")

    if sampling_length is not None:
        lr = as_step(sampling_length, "sampling_length")
        if uniform:
            sl, n_sections = evaluation_slice(z.size, dx, lr, n_sampling)
        else:
            total = float(np.sum(cell_widths(pos)))
            fits = math.floor(total / lr * (1 + 1e-9))
            n_sections = fits if n_sampling is None else int(n_sampling)
            if n_sections < 1 or fits < n_sections:
                raise ProfileError(
                    f"profile is {total * 1e3:.4g} mm long, shorter than "
                    f"{max(n_sections, 1)} sampling length(s) of {lr * 1e3:.4g} mm"
                )
            centre = 0.5 * (pos[0] + pos[-1])
            half = 0.5 * n_sections * lr
            keep = np.flatnonzero((pos >= centre - half) & (pos <= centre + half))
            sl = slice(int(keep[0]), int(keep[-1]) + 1)
        z = z[sl]
        pos = pos[sl]
    else:
        n_sections = 5 if n_sampling is None else int(n_sampling)

    widths = np.full(z.size, dx) if uniform else cell_widths(pos)
    problem = sampling_length_problem(float(np.sum(widths)), n_sections, dx)
    if problem:
        raise ProfileError(problem)
    lr = float(np.sum(widths)) / n_sections
    valid = require_valid(z, 1, "profile parameters")
    zv = z[valid]
    Rt = float(zv.max() - zv.min())

    # sections are contiguous runs of points: reduce each with reduceat
    sec = _sections(pos, widths, n_sections)
    first = np.concatenate(([0], np.flatnonzero(np.diff(sec[valid])) + 1))
    top = np.maximum.reduceat(zv, first)
    bottom = np.minimum.reduceat(zv, first)
    Rp = float(np.mean(top))
    Rv = float(np.mean(-bottom))
    Rz = float(np.mean(top - bottom))

    if standard == "iso21920":
        values = _stretch_values(z, pos, widths, uniform, dx,
                                 height_discrimination * Rz, width_discrimination * lr,
                                 element_start)
    else:
        bounds = np.searchsorted(sec, np.arange(n_sections + 1))
        per = []
        for a, b in itertools.pairwise(bounds):
            zs = z[a:b]
            if not np.isfinite(zs).any():
                continue
            rz = float(np.nanmax(zs) - np.nanmin(zs))
            per.append(_stretch_values(zs, pos[a:b], widths[a:b], uniform, dx,
                                       height_discrimination * rz, width_discrimination * lr,
                                       element_start))
        values = {k: _mean_defined([p[k] for p in per]) for k in per[0]}
    return ProfileParameters(Rp=Rp, Rv=Rv, Rz=Rz, Rt=Rt, **values)


def parse_standard(standard: Any) -> str:
    """Validate a standard name: ``"iso21920"`` or ``"iso4287"`` (spellings tolerated)."""
    text = str(standard).strip().lower().replace(" ", "").replace("-", "").replace("_", "")
    text = {"iso219202": "iso21920", "21920": "iso21920", "4287": "iso4287",
            "iso4287:1997": "iso4287", "iso42871997": "iso4287"}.get(text, text)
    if text not in STANDARDS:
        raise ProfileError(f"unknown standard {standard!r}: use iso21920 or iso4287")
    return text


def _mean_defined(values: list[float]) -> float:
    """Mean of the finite values (a sampling length without elements has no Rsm)."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    return float(v.mean()) if v.size else math.nan


def _stretch_values(z: np.ndarray, pos: np.ndarray, widths: np.ndarray, uniform: bool,
                    dx: float, height: float, width: float, element_start: str = "peak"
                    ) -> dict[str, float]:
    """Ra, Rq, Rsk, Rku, Rsm, Rdq, Rc of one stretch (evaluation or sampling length)."""
    valid = np.isfinite(z)
    zv, wv = z[valid], widths[valid]
    wsum = float(np.sum(wv))
    Ra = float(np.sum(wv * np.abs(zv)) / wsum)
    Rq = float(math.sqrt(np.sum(wv * zv * zv) / wsum))
    if Rq > 0:
        Rsk = float(np.sum(wv * zv**3) / wsum / Rq**3)
        Rku = float(np.sum(wv * zv**4) / wsum / Rq**4)
    else:
        Rsk = Rku = math.nan
    elements = profile_elements(z, pos, height, width, start=element_start)
    Rsm = float(np.mean(elements.widths)) if elements.widths.size else math.nan
    Rc = float(np.mean(elements.heights)) if elements.heights.size else math.nan
    slope = _local_slope(z, pos, uniform, dx)
    Rdq = float(math.sqrt(np.mean(slope * slope))) if slope.size else math.nan
    return {"Ra": Ra, "Rq": Rq, "Rsk": Rsk, "Rku": Rku, "Rsm": Rsm, "Rdq": Rdq, "Rc": Rc}
