"""Gaussian profile filter (ISO 16610-21) with explicit end-effect handling (ISO 16610-28).

Weighting function (ISO 16610-21)::

    s(x) = exp(-pi * (x / (alpha * lc))**2) / (alpha * lc),   alpha = sqrt(ln 2 / pi)

whose mean-line transmission is ``exp(-pi * (alpha * lc / lambda)**2)``: exactly 50 % at
``lambda = lc``. The weighting function is truncated at ``+-truncation * lc`` (default
1.0, which drops 1e-7 of the weight; a truncation at ±0.5 λc would drop 0.76 % of it and
shift the transmission measurably) and normalised on the discrete grid.

End effects. Near the profile ends (and next to non-measured points) part of the weighting
function has no data under it. This module never pads the profile with invented data
(mirror reflection, as some tools do, bends a tilted profile at its ends: its mean line
curls towards the mirror image). Three treatments, each recorded by the caller:

``"moment"`` (default)
    The moment criterion of ISO 16610-28 to first order: at every point the weights are
    corrected so that the zeroth and first moments of the (truncated, hole-masked)
    weighting function are those of the full one. This is the same as fitting a straight
    line under the Gaussian weights (a Gaussian regression filter of order 1, cf.
    ISO 16610-31). In the interior, with no holes, it is exactly the ISO 16610-21 filter;
    at the ends it reproduces any straight line exactly, so a tilt creates no false
    roughness, and the whole profile is kept.
``"renormalise"``
    Zeroth-order moment criterion: the truncated weights are divided by their sum. Keeps
    the whole profile but follows a tilted line only approximately at the ends.
``"discard"``
    Plain (zeroth-order) filter, then half a cut-off is dropped at each end (the run-up
    and run-out of ISO 4288 / ISO 3274); the ends come back as NaN.

Non-measured points (NaN) are excluded by giving them zero weight: the filter is
renormalised over the measured points only, so holes do not spread; outputs are NaN where
the input is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy import fft as sp_fft

from profiles._arrays import as_heights, as_step, require_valid
from profiles._errors import ProfileError
from profiles._resolution import nesting_index_problem

#: ISO 16610-21 constant: the Gaussian transmits 50 % at the cut-off.
ALPHA = math.sqrt(math.log(2.0) / math.pi)

END_TREATMENTS = ("moment", "renormalise", "discard")
_ALIASES = {"renormalize": "renormalise", "moment-criterion": "moment", "regression": "moment"}


def parse_end_treatment(value: Any) -> str:
    """Validate an end-treatment name (see module docstring)."""
    text = str(value).strip().lower()
    text = _ALIASES.get(text, text)
    if text not in END_TREATMENTS:
        raise ProfileError(
            f"unknown end treatment {value!r}: use one of {', '.join(END_TREATMENTS)}"
        )
    return text


def gaussian_transmission(wavelength: Any, cutoff: float) -> np.ndarray:
    """Theoretical mean-line (low-pass) amplitude transmission (ISO 16610-21).

    Parameters
    ----------
    wavelength : float or array_like
        Wavelength(s) in metres.
    cutoff : float
        The cut-off λc in metres.

    Returns
    -------
    ndarray
        ``exp(-π (α λc / λ)²)`` with ``α = sqrt(ln 2 / π)``: 50 % at the cut-off.

    See Also
    --------
    gaussian_mean_line : the filter itself.

    References
    ----------
    .. [1] ISO 16610-21:2011, Filtration -- Part 21: Linear profile filters: Gaussian
       filters, Eq. (2).

    Examples
    --------
    >>> from profiles import gaussian_transmission
    >>> print(gaussian_transmission([0.8e-3, 2.5e-3], 0.8e-3).round(3))
    [0.5   0.931]
    """
    lam = np.asarray(wavelength, dtype=float)
    return np.exp(-np.pi * (ALPHA * cutoff / lam) ** 2)


def _correlate_all(
    data: list[np.ndarray], kernels: list[np.ndarray], pairs: list[tuple[int, int]]
) -> list[np.ndarray]:
    """Centred correlations ``out[i] = sum_j k[j] a[i + j - h]`` (zero outside the profile).

    Long kernels go through one FFT per array and per kernel, shared by all the pairs.
    The kernel may be longer than the profile (a cut-off longer than a short profile):
    the centred ``n`` values of the full correlation are taken, not numpy's ``"same"``,
    which returns ``max(n, m)`` values.
    """
    n = data[0].size
    m = kernels[0].size
    h = m // 2
    if m <= 129 or n <= 129:
        return [np.convolve(data[a], kernels[k][::-1])[h : h + n] for a, k in pairs]
    size = sp_fft.next_fast_len(n + m - 1, real=True)
    fd = {a: sp_fft.rfft(data[a], size) for a in {a for a, _ in pairs}}
    fk = {k: sp_fft.rfft(kernels[k][::-1], size) for k in {k for _, k in pairs}}
    return [sp_fft.irfft(fd[a] * fk[k], size)[h : h + n] for a, k in pairs]


def gaussian_mean_line(
    z: Any,
    dx: float,
    cutoff: float,
    *,
    end_treatment: str = "moment",
    truncation: float = 1.0,
) -> np.ndarray:
    """Gaussian low-pass (mean line) of a uniformly sampled profile.

    Parameters
    ----------
    z : array_like
        Heights, NaN where not measured.
    dx : float
        Sampling step in metres.
    cutoff : float
        Cut-off wavelength in metres (λc for the mean line, λs for the short-wave filter).
    end_treatment : {"moment", "renormalise", "discard"}
        See the module docstring. ``"discard"`` returns NaN within ``cutoff/2`` of the
        ends.
    truncation : float
        Half-width of the weighting function in cut-offs.

    Returns
    -------
    ndarray
        The filtered profile, NaN where ``z`` is NaN (and at discarded ends).

    See Also
    --------
    split_profile : primary, waviness and roughness at once.
    gaussian_transmission : its amplitude transmission.

    References
    ----------
    .. [1] ISO 16610-21:2011, Filtration -- Part 21: Linear profile filters: Gaussian
       filters.

    Examples
    --------
    The mean line of a 100 µm ripple with λc = 0.8 mm is flat (the Gaussian passes 0 % of
    it):

    >>> import numpy as np
    >>> from profiles import gaussian_mean_line
    >>> x = np.arange(4000) * 1e-6
    >>> line = gaussian_mean_line(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6, 0.8e-3)
    >>> print(f"{np.abs(line[1000:3000]).max() * 1e9:.1f} nm")
    0.0 nm
    """
    z = as_heights(z)
    dx = as_step(dx)
    cutoff = as_step(cutoff, "cutoff")
    end_treatment = parse_end_treatment(end_treatment)
    if not (math.isfinite(truncation) and truncation > 0):
        raise ProfileError(f"truncation must be positive, got {truncation!r}")
    problem = nesting_index_problem(cutoff, dx, "cut-off")
    if problem:
        raise ProfileError(problem)
    valid = require_valid(z, 1, "Gaussian filtering")
    n = z.size
    h = max(1, math.ceil(truncation * cutoff / dx))
    h = min(h, n - 1) if n > 1 else 1
    # offsets in samples (well scaled for the moment sums)
    d = np.arange(-h, h + 1, dtype=np.float64)
    g = np.exp(-np.pi * (d * dx / (ALPHA * cutoff)) ** 2)
    v = valid.astype(np.float64)
    zf = np.where(valid, z, 0.0)
    if end_treatment == "moment":
        # zeroth, first and second moments of the masked weights, and the weighted data
        s0, t0, s1, s2, t1 = _correlate_all(
            [v, zf], [g, g * d, g * d * d], [(0, 0), (1, 0), (0, 1), (0, 2), (1, 1)]
        )
    else:
        s0, t0 = _correlate_all([v, zf], [g], [(0, 0), (1, 0)])
    with np.errstate(invalid="ignore", divide="ignore"):
        order0 = t0 / s0
        if end_treatment == "moment":
            den = s0 * s2 - s1 * s1
            order1 = (s2 * t0 - s1 * t1) / den
            # too few points under the window to fix a slope: fall back to order 0
            weak = ~(den > 1e-9 * s0 * s2) | ~np.isfinite(order1)
            out = np.where(weak, order0, order1)
        else:
            out = order0
    out[~valid] = np.nan
    if end_treatment == "discard":
        cut = math.ceil(0.5 * cutoff / dx - 1e-9)
        if 2 * cut >= n:
            raise ProfileError(
                f"profile is {n * dx * 1e3:.4g} mm long: discarding half a cut-off "
                f"({0.5 * cutoff * 1e3:.4g} mm) at each end leaves nothing; use "
                f"end_treatment='moment' or a shorter cut-off"
            )
        out[:cut] = np.nan
        out[n - cut :] = np.nan
    return out


@dataclass(frozen=True, eq=False)
class ProfileSplit:
    """Primary / waviness / roughness decomposition of a profile.

    Attributes
    ----------
    primary : ndarray
        Input after the λs (short-wave) filter, or the input itself if ``ls`` is None.
    waviness : ndarray
        Mean line of ``primary`` (λc Gaussian low-pass).
    roughness : ndarray
        ``primary - waviness``; NaN at non-measured points and at discarded ends.
    settings : dict
        ``lc``, ``ls``, ``end_treatment``, ``truncation``, ``discarded_each_end`` (m),
        ``filter``.

    See Also
    --------
    split_profile : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import split_profile
    >>> x = np.arange(4000) * 1e-6
    >>> parts = split_profile(1e-6 * np.sin(2 * np.pi * x / 100e-6), 1e-6, lc=0.8e-3)
    >>> parts.primary.shape == parts.roughness.shape == parts.waviness.shape
    True
    """

    primary: np.ndarray
    waviness: np.ndarray
    roughness: np.ndarray
    settings: dict[str, Any] = field(default_factory=dict)


def split_profile(
    z: Any,
    dx: float,
    *,
    lc: float,
    ls: float | None = None,
    end_treatment: str = "moment",
    truncation: float = 1.0,
    valley_suppression: bool = False,
) -> ProfileSplit:
    """Split a levelled, uniformly sampled profile into primary, waviness and roughness.

    Parameters
    ----------
    z : array_like
        Heights in metres with the form removed, NaN where not measured.
    dx : float
        Sampling step in metres.
    lc : float
        Long-wave cut-off λc in metres (roughness/waviness boundary).
    ls : float, optional
        Short-wave cut-off λs in metres (ISO 3274); None = no λs filter.
    end_treatment, truncation
        See :func:`gaussian_mean_line`.
    valley_suppression : bool
        ISO 13565-1:1996 two-stage mean line for stratified (plateau) surfaces: the deep
        valleys below the first Gaussian mean line are replaced by that line, and the
        profile so truncated is filtered again; its mean line is the waviness. The
        plateau's roughness is then no longer pulled down by the valleys.

    Raises
    ------
    ProfileError
        If the profile is shorter than one cut-off (two with ``"discard"``), or ``ls``
        is not shorter than ``lc``.

    See Also
    --------
    gaussian_mean_line : the waviness alone.
    analyze_profile : levelling, filtering and parameters in one call.

    References
    ----------
    .. [1] ISO 16610-21:2011, Geometrical product specifications (GPS) -- Filtration --
       Part 21: Linear profile filters: Gaussian filters.

    Examples
    --------
    A 100 µm ripple on a 4 mm wave: with λc = 0.8 mm the ripple is roughness and the wave
    waviness, but for the 2.7 % of the wave the Gaussian lets through at λ = 5 λc
    (``1 - exp(-π (α λc / λ)²)`` of 5 µm, 0.14 µm), away from the ends:

    >>> import numpy as np
    >>> from profiles import split_profile
    >>> x = np.arange(8000) * 1e-6
    >>> ripple = 1e-6 * np.sin(2 * np.pi * x / 100e-6)
    >>> wave = 5e-6 * np.sin(2 * np.pi * x / 4e-3)
    >>> parts = split_profile(ripple + wave, 1e-6, lc=0.8e-3)
    >>> mid = slice(2000, 6000)
    >>> print(f"{np.abs(parts.roughness - ripple)[mid].max() * 1e6:.2f} µm")
    0.14 µm
    """
    z = as_heights(z)
    dx = as_step(dx)
    lc = as_step(lc, "lc")
    end_treatment = parse_end_treatment(end_treatment)
    length = z.size * dx
    need = (2.0 if end_treatment == "discard" else 1.0) * lc
    if length < need * (1 - 1e-9) - dx:
        extra = " plus half a cut-off run-up and run-out" if end_treatment == "discard" else ""
        raise ProfileError(
            f"profile is {length * 1e3:.4g} mm long, too short for the cut-off "
            f"λc = {lc * 1e3:.4g} mm (needs at least {need * 1e3:.4g} mm: one cut-off{extra}); "
            f"use a shorter λc, a longer profile, or no λc filter"
        )
    problem = nesting_index_problem(lc, dx, "cut-off λc")
    if problem:
        raise ProfileError(problem)
    if ls is not None:
        ls = as_step(ls, "ls")
        problem = nesting_index_problem(ls, dx, "cut-off λs")
        if problem:
            raise ProfileError(problem)
        if ls >= lc:
            raise ProfileError(f"λs ({ls:.4g} m) must be shorter than λc ({lc:.4g} m)")
        # λs is applied with the same end treatment except discarding (its run-out is
        # negligible next to λc's)
        primary = gaussian_mean_line(
            z,
            dx,
            ls,
            end_treatment="renormalise" if end_treatment == "renormalise" else "moment",
            truncation=truncation,
        )
    else:
        primary = z.copy()
    waviness = gaussian_mean_line(
        primary, dx, lc, end_treatment=end_treatment, truncation=truncation
    )
    if valley_suppression:
        truncated = np.where(primary < waviness, waviness, primary)
        waviness = gaussian_mean_line(
            truncated, dx, lc, end_treatment=end_treatment, truncation=truncation
        )
    roughness = primary - waviness
    discarded = math.ceil(0.5 * lc / dx - 1e-9) * dx if end_treatment == "discard" else 0.0
    settings = {
        "filter": ("ISO 13565-1 valley suppression (two Gaussian stages)"
                   if valley_suppression else "Gaussian, ISO 16610-21"),
        "lc": lc,
        "ls": ls,
        "end_treatment": end_treatment,
        "truncation": truncation,
        "discarded_each_end": discarded,
    }
    return ProfileSplit(primary, waviness, roughness, settings)

