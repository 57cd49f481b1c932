"""Post-processing of contact fields on the grid: radial averages, the effective (second
moment) radius, the profile deviation from a reference, the perimeter-corrected real area
and block averages of a height map.

Arrays in, floats or small frozen dataclasses out. The metrics are those the verdicts
(:mod:`contact._hertzcheck`, :mod:`contact._resolution`) and the model hierarchy
(:mod:`contact.roughcontact._hierarchy`) measure a solution with.

The perimeter correction follows Yastrebov, Anciaux & Molinari (2015), "From infinitesimal
to full contact between rough surfaces: evolution of the contact area", Int. J. Solids
Struct. 52:83-102: counting the cells in contact over-estimates the area of a digitised
contact by a term proportional to its perimeter, A_c = A - (pi - 1 + ln 2)/24 * P dx, with
P the number of contact / no-contact switches between neighbouring cells times dx.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from contact._errors import ContactInputError
from contact._validate import positive

#: The profile deviation from Hertz is measured within this many Hertz radii.
PROFILE_EXTENT = 1.5
#: Yastrebov et al. (2015) perimeter coefficient (pi - 1 + ln 2) / 24.
PERIMETER_COEFFICIENT = (math.pi - 1.0 + math.log(2.0)) / 24.0


@dataclass(frozen=True, eq=False)
class RadialProfile:
    """Azimuthal average of a pressure field.

    Attributes
    ----------
    r : ndarray
        Bin centres (m): 0, w, 2w, ... (bin k holds the cells with (k - 1/2) w <= r <
        (k + 1/2) w; bin 0 those with r < w/2).
    p : ndarray
        Mean pressure of the cells of each bin (Pa).
    p_hertz : ndarray or None
        Mean Hertz pressure over the same cells (Pa), when a Hertz solution was given.
    count : ndarray
        Cells per bin.
    width : float
        Bin width w (m).
    centre : (float, float)
        Centre of the average (m).

    Examples
    --------
    >>> import numpy as np
    >>> from contact import radial_average
    >>> x = np.linspace(-1e-4, 1e-4, 41)
    >>> prof = radial_average(np.ones((41, 41)), x, x)
    >>> prof.r.size, float(prof.p[0]), prof.p_hertz is None
    (29, 1.0, True)
    """

    r: np.ndarray
    p: np.ndarray
    p_hertz: np.ndarray | None
    count: np.ndarray
    width: float
    centre: tuple[float, float]


def radial_average(
    pressure: np.ndarray,
    x: np.ndarray,
    y: np.ndarray,
    *,
    centre: tuple[float, float] = (0.0, 0.0),
    width: float | None = None,
    r_max: float | None = None,
    hertz: Any = None,
) -> RadialProfile:
    """Azimuthally averaged pressure about ``centre``.

    Parameters
    ----------
    pressure : ndarray, shape (ny, nx)
        Pressure field (Pa) on cells centred at ``x`` (columns) and ``y`` (rows).
    x, y : ndarray
        Cell-centre coordinates (m).
    centre : (float, float)
        (x, y) of the centre (m); default the origin (the ball's apex in
        :mod:`contact.setups._ball_on_plate`).
    width : float, optional
        Bin width (m); default the larger of the cell pitch and r_max / 60.
    r_max : float, optional
        Largest bin centre (m); default the farthest cell that carries pressure.
    hertz : HertzSphere or any object with ``pressure(r)``, optional
        Also average its pressure (a Hertz or other radial model) over the same cells.

    Returns
    -------
    RadialProfile
        Bins that hold no cell are dropped.

    Raises
    ------
    ContactInputError
        A pressure field whose shape is not ``(y.size, x.size)``, or a width or r_max
        that is not positive.

    Examples
    --------
    The Hertz pressure of the paper's ball, averaged about its centre, is its own average:

    >>> import numpy as np
    >>> from contact import composite_modulus, hertz_sphere, material, radial_average
    >>> h = hertz_sphere(0.02, 10.0, composite_modulus(material("steel"),
    ...                                                material("aluminium")))
    >>> x = np.linspace(-2 * h.a, 2 * h.a, 81)
    >>> p = h.pressure(np.hypot(x[None, :], x[:, None]))
    >>> rad = radial_average(p, x, x, hertz=h)
    >>> print(f"{rad.p[0] / h.p0:.3f}", bool(np.allclose(rad.p, rad.p_hertz)))
    1.000 True
    """
    p = np.asarray(pressure, dtype=float)
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if p.ndim != 2 or p.shape != (y.size, x.size):
        raise ContactInputError(
            f"pressure of shape {p.shape} does not match x ({x.size}) and y ({y.size})"
        )
    rr = np.hypot(x[None, :] - centre[0], y[:, None] - centre[1])
    dx = float(np.min(np.diff(x))) if x.size > 1 else 1.0
    dy = float(np.min(np.diff(y))) if y.size > 1 else dx
    if r_max is None:
        r_max = float(rr[p > 0].max()) if (p > 0).any() else float(rr.max())
    r_max = positive(r_max, "r_max", "m")
    width = positive(max(dx, dy, r_max / 60.0) if width is None else width,
                     "the bin width", "m")
    k = np.floor(rr / width + 0.5).astype(np.int64).ravel()
    nb = math.floor(r_max / width + 0.5) + 1
    keep = k < nb
    k = k[keep]
    count = np.bincount(k, minlength=nb)
    sums = np.bincount(k, weights=p.ravel()[keep], minlength=nb)
    ok = count > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = sums / count
    ph = None
    if hertz is not None:
        hp = hertz.pressure(rr).ravel()[keep]
        ph = (np.bincount(k, weights=hp, minlength=nb) / np.maximum(count, 1))[ok]
    return RadialProfile(r=np.arange(nb)[ok] * width, p=mean[ok], p_hertz=ph,
                         count=count[ok], width=float(width),
                         centre=(float(centre[0]), float(centre[1])))


def effective_radius(pressure: np.ndarray, x: np.ndarray, y: np.ndarray,
                     centre: tuple[float, float] | None = None) -> float:
    """Radius a* of the Hertz distribution with the same second moment of pressure.

    a* = sqrt(5/2 <r^2>_p), <r^2>_p = sum p r^2 / sum p about ``centre`` (default: the
    pressure centroid). Hertz has <r^2>_p = 2 a^2 / 5, so a* = a for a smooth contact.
    """
    p = np.asarray(pressure, dtype=float)
    total = p.sum()
    if not total > 0:
        return 0.0
    xx = np.asarray(x, dtype=float)[None, :]
    yy = np.asarray(y, dtype=float)[:, None]
    if centre is None:
        centre = (float((p * xx).sum() / total), float((p * yy).sum() / total))
    m2 = float((p * ((xx - centre[0]) ** 2 + (yy - centre[1]) ** 2)).sum() / total)
    return math.sqrt(2.5 * m2)


def profile_deviation(profile: RadialProfile, p0: float, r_limit: float) -> float:
    """Area-weighted rms of (p - p_hertz) over the bins within ``r_limit``, divided by p0."""
    if profile.p_hertz is None:
        raise ContactInputError("the profile carries no Hertz pressure to compare with")
    sel = profile.r <= r_limit
    if not sel.any():
        return math.nan
    w = profile.count[sel].astype(float)
    d = profile.p[sel] - profile.p_hertz[sel]
    return math.sqrt(float((w * d**2).sum() / w.sum())) / p0


def block_average(z: np.ndarray, factor: int) -> np.ndarray:
    """Mean of each ``factor x factor`` block (rows and columns past a whole block dropped).

    Parameters
    ----------
    z : ndarray (ny, nx)
        Heights (finite).
    factor : int
        Block side in pixels (1 returns a copy).

    Returns
    -------
    ndarray (ny // factor, nx // factor)
    """
    z = np.asarray(z, dtype=float)
    k = int(factor)
    if k < 1 or k != factor:
        raise ContactInputError(f"the coarsening factor must be a positive integer, got {factor!r}")
    if z.ndim != 2:
        raise ContactInputError(f"the heights must be a 2D map, got shape {z.shape}")
    ny, nx = z.shape[0] // k, z.shape[1] // k
    if ny < 1 or nx < 1:
        raise ContactInputError(f"a {z.shape} map is smaller than one {k} x {k} block")
    return z[:ny * k, :nx * k].reshape(ny, k, nx, k).mean(axis=(1, 3))


def centred_blocks(z: np.ndarray, factor: int, centre: tuple[int, int]
                   ) -> tuple[np.ndarray, tuple[int, int]]:
    """Block-average ``z`` with one block on the native pixel ``centre`` (row, column) and as
    many whole blocks on either side as fit symmetrically.

    Returns the coarse map and the (row, column) of the centre block in it. For an even
    factor the centre block's middle lies half a native pixel before ``centre``.
    """
    k = int(factor)
    out_slices = []
    index = []
    for c, n in zip(centre, z.shape):
        start = c - k // 2
        m = min(start // k, (n - start - k) // k)
        if start < 0 or m < 0:
            raise ContactInputError("the scan is too small around its centre for a "
                                    f"{k} x {k} block")
        out_slices.append(slice(start - m * k, start + (m + 1) * k))
        index.append(m)
    return block_average(z[tuple(out_slices)], k), (index[0], index[1])


def corrected_area(contact: np.ndarray, dx: float, dy: float | None = None) -> float:
    """Real contact area with the Yastrebov-Anciaux-Molinari (2015) perimeter correction.

    A_c = n_contact dx dy - (pi - 1 + ln 2)/24 * (switches along x + switches along y) dx dy,
    where a switch is a pair of neighbouring cells of which one is in contact.
    """
    c = np.asarray(contact, dtype=bool)
    dy = dx if dy is None else dy
    switches = int(np.count_nonzero(c[:, 1:] != c[:, :-1])
                   + np.count_nonzero(c[1:, :] != c[:-1, :]))
    return float((np.count_nonzero(c) - PERIMETER_COEFFICIENT * switches) * dx * dy)
