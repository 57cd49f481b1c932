"""Material ratio: Rmr(c), the Abbott-Firestone curve and the Rk family.

Definitions: ISO 4287:1997 (Rmr(c), material ratio curve, Rδc), ISO 21920-2:2021 (Rcm);
the ISO 13565 parameters that build on the curve are in :mod:`profiles._rk`. Ratios are
fractions in [0, 1] (not %), heights in metres. Computed from the measured points only
(NaN = not measured); for a uniformly sampled profile the fraction of points at or above a
level is the fraction of the evaluation length.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from profiles._arrays import as_heights, require_valid
from profiles._errors import ProfileError


def _heights(z: Any, minimum: int = 1) -> np.ndarray:
    z = as_heights(z)
    valid = require_valid(z, minimum, "the material ratio")
    return z[valid]


def material_ratio(z: Any, c: Any, *, reference: str = "mean") -> float | np.ndarray:
    """Rmr(c): fraction of the profile at or above the section level ``c``.

    Parameters
    ----------
    z : array_like
        Heights in metres from the mean line; NaN where not measured.
    c : float or array_like
        Section level(s) in metres.
    reference : {"mean", "peak"}
        ``"mean"``: ``c`` is a height above the mean line (z = 0).
        ``"peak"``: ``c`` is a depth below the highest point (ISO 4287 practice of
        measuring section levels from the top of the profile).

    Returns
    -------
    float or ndarray
        Material ratio(s) in [0, 1].

    See Also
    --------
    material_ratio_curve : the whole curve.
    height_at_ratio : the inverse.

    References
    ----------
    .. [1] ISO 21920-2:2021, Surface texture: Profile -- Part 2, material ratio Rmr(c).

    Examples
    --------
    Heights spread evenly from -1 µm to 1 µm: half the profile lies at or above the mean
    line, a quarter at or above +0.5 µm:

    >>> import numpy as np
    >>> from profiles import material_ratio
    >>> z = np.linspace(-1e-6, 1e-6, 1001)
    >>> print(f"{material_ratio(z, 0.0):.2f} {material_ratio(z, 0.5e-6):.2f}")
    0.50 0.25
    """
    zv = np.sort(_heights(z))
    levels = np.asarray(c, dtype=float)
    if reference == "peak":
        levels = zv[-1] - levels
    elif reference != "mean":
        raise ProfileError(f"reference must be 'mean' or 'peak', got {reference!r}")
    above = zv.size - np.searchsorted(zv, levels, side="left")
    out = above / zv.size
    return float(out) if np.ndim(out) == 0 else out


def material_ratio_curve(z: Any, n: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The Abbott-Firestone (material ratio) curve.

    Parameters
    ----------
    z : array_like
        Heights in metres; NaN where not measured.
    n : int, optional
        Number of evenly spaced ratios to interpolate the curve at.

    Returns
    -------
    (mr, height) : ndarrays
        ``height[i]`` is the level at which the material ratio is ``mr[i]``; heights
        decrease as ``mr`` goes from ``1/N`` to 1 (``N`` measured points). With ``n``
        given, the curve is interpolated at ``n`` evenly spaced ratios in [0, 1].

    Raises
    ------
    ProfileError
        If no point is measured.

    See Also
    --------
    material_ratio, height_at_ratio

    References
    ----------
    .. [1] E. J. Abbott, F. A. Firestone, "Specifying surface quality", Mechanical
       Engineering 55 (1933) 569-572.
    .. [2] ISO 21920-2:2021, material ratio curve.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import material_ratio_curve
    >>> mr, height = material_ratio_curve(np.linspace(-1e-6, 1e-6, 1001), n=5)
    >>> print(mr, (height * 1e6).round(2))
    [0.   0.25 0.5  0.75 1.  ] [ 1.   0.5  0.  -0.5 -1. ]
    """
    zv = np.sort(_heights(z))[::-1]
    mr = np.arange(1, zv.size + 1) / zv.size
    if n is None:
        return mr, zv
    grid = np.linspace(0.0, 1.0, int(n))
    return grid, np.asarray(height_at_ratio(z, grid), dtype=float)


def height_at_ratio(z: Any, mr: Any) -> float | np.ndarray:
    """Inverse material ratio curve: the level at which the ratio is ``mr`` (0..1).

    Parameters
    ----------
    z : array_like
        Heights in metres (from the mean line); NaN where not measured.
    mr : float or array_like
        Material ratio(s) as fractions in [0, 1].

    Returns
    -------
    float or ndarray
        The level(s) in metres, interpolated along the material ratio curve.

    See Also
    --------
    material_ratio : the forward curve.
    material_ratio_height : the ISO 21920-2 step version, from the top.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import height_at_ratio
    >>> z = np.linspace(-1e-6, 1e-6, 1001)
    >>> print(f"{height_at_ratio(z, 0.25) * 1e6:.2f} µm")
    0.50 µm
    """
    zv = np.sort(_heights(z))[::-1]
    m = np.asarray(mr, dtype=float)
    if np.any((m < 0) | (m > 1)):
        raise ProfileError("material ratios must lie between 0 and 1")
    # points (k/N, zv[k-1]) with the top at (0, max): a piecewise-linear inverse
    grid = np.concatenate(([0.0], np.arange(1, zv.size + 1) / zv.size))
    heights = np.concatenate(([zv[0]], zv))
    out = np.interp(m, grid, heights)
    return float(out) if np.ndim(out) == 0 else out


def material_ratio_height(z: Any, p: Any) -> float | np.ndarray:
    """Rcm(p): the section level at material ratio ``p``, measured from the highest point.

    ISO 21920-2:2021 (inverse material ratio, used to turn a material ratio into the
    height ``c`` of the "open c" / "closed c" significance rules of feature
    characterisation). On the N measured points sorted from the top, ``z(1) >= ... >=
    z(N)``, the level of ratio ``p`` is the highest level whose material ratio reaches
    ``p``: ``z(k)`` with ``k = ceil(p N)`` (``k >= 1``), so the value is ``z(k) - z(1)``,
    zero or negative (0 at ``p = 0``, ``-Rt`` at ``p = 1``). This is the construction of
    the RPTU / MTS reference implementation (Müller et al., Surf. Topogr.: Metrol. Prop.
    13 (2025) 015003). Unlike :func:`height_at_ratio` it does not interpolate between
    points: it is the step curve of :func:`material_ratio`.

    Parameters
    ----------
    z : array_like
        Heights in metres; NaN where not measured.
    p : float or array_like
        Material ratio(s) as fractions in [0, 1].

    Returns
    -------
    float or ndarray
        ``z(k) - z(1)`` in metres: zero or negative.

    See Also
    --------
    height_at_ratio : the interpolated level, from the mean line.

    References
    ----------
    .. [1] ISO 21920-2:2021, inverse material ratio Rcm(p).

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import material_ratio_height
    >>> z = np.linspace(-1e-6, 1e-6, 1001)
    >>> print(f"{material_ratio_height(z, 0.25) * 1e6:.2f} µm below the top")
    -0.50 µm below the top
    """
    zv = np.sort(_heights(z))[::-1]
    m = np.asarray(p, dtype=float)
    if np.any(~np.isfinite(m) | (m < 0) | (m > 1)):
        raise ProfileError("material ratios must lie between 0 and 1")
    # the tolerance keeps p = k/N (up to rounding) on point k, not k + 1
    k = np.clip(np.ceil(m * zv.size - 1e-9).astype(np.int64), 1, zv.size)
    out = zv[k - 1] - zv[0]
    return float(out) if np.ndim(out) == 0 else out


def section_height_difference(z: Any, mr1: float, mr2: float) -> float:
    """Rδc: height difference between the levels of material ratios ``mr1 < mr2``.

    Parameters
    ----------
    z : array_like
        Heights in metres.
    mr1, mr2 : float
        Material ratios as fractions, ``mr1 < mr2``.

    Returns
    -------
    float
        ``c(mr1) - c(mr2)`` in metres.

    See Also
    --------
    height_at_ratio

    References
    ----------
    .. [1] ISO 21920-2:2021, section height difference Rδc.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import section_height_difference
    >>> z = np.linspace(-1e-6, 1e-6, 1001)
    >>> print(f"Rδc(25 %, 75 %) = {section_height_difference(z, 0.25, 0.75) * 1e6:.2f} µm")
    Rδc(25 %, 75 %) = 1.00 µm
    """
    return float(height_at_ratio(z, mr1) - height_at_ratio(z, mr2))
