"""Roughness statistics the contact verdicts use: the combined rms of independent
surfaces, their rms slope, and the Greenwood-Johnson-Matsubara roughness parameter.

Greenwood, Johnson & Matsubara (1984), Wear 100:47; Johnson (1985), *Contact Mechanics*,
sec. 13.4.
"""

from __future__ import annotations

import math

import numpy as np

from contact._errors import ContactInputError


def gjm_alpha(sigma: float, radius: float, a0: float) -> float:
    """The Greenwood-Johnson-Matsubara roughness parameter alpha = sigma R / a0^2.

    Parameters
    ----------
    sigma : float
        Combined rms roughness of the two surfaces (m), sqrt(sigma1^2 + sigma2^2).
    radius : float
        Ball radius R (m).
    a0 : float
        Hertz contact radius of the smooth surfaces at the same load (m).

    Returns
    -------
    float
        α; below about 0.05 roughness hardly changes the Hertz pressure.

    See Also
    --------
    contact.check_sphere : the verdict that uses it.

    References
    ----------
    .. [1] J. A. Greenwood, K. L. Johnson, E. Matsubara, "A surface roughness parameter in
       Hertz contact", Wear 100 (1984) 47-57.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 13.

    Examples
    --------
    1 µm of roughness under the paper's ball at 10 N (a0 = 137 µm):

    >>> from contact import gjm_alpha
    >>> print(f"alpha = {gjm_alpha(1e-6, 0.02, 136.8e-6):.2f}")
    alpha = 1.07
    """
    for name, v in (("sigma", sigma), ("radius", radius), ("a0", a0)):
        if not math.isfinite(v) or v < 0 or (name != "sigma" and v == 0):
            raise ContactInputError(f"{name} must be a finite positive length, got {v!r}")
    return float(sigma) * float(radius) / float(a0) ** 2


def combined_rms(*surfaces: np.ndarray | None) -> float:
    """Combined rms of independent surfaces, sqrt(sum sigma_i^2), each from its finite points
    about its own mean (NaN = not measured is ignored; None entries are skipped)."""
    total = 0.0
    for z in surfaces:
        if z is None:
            continue
        a = np.asarray(z, dtype=float)
        v = a[np.isfinite(a)]
        if v.size == 0:
            raise ContactInputError("a roughness map has no measured point")
        total += float(np.mean((v - v.mean()) ** 2))
    return math.sqrt(total)


def rms_slope(z: np.ndarray, dx: float, dy: float | None = None) -> float:
    """Rms gradient sqrt(<(dz/dx)^2 + (dz/dy)^2>) by forward differences (dimensionless)."""
    z = np.asarray(z, dtype=float)
    dy = dx if dy is None else dy
    gx = np.diff(z, axis=1) / dx
    gy = np.diff(z, axis=0) / dy
    return float(math.sqrt(np.mean(gx**2) + np.mean(gy**2)))
