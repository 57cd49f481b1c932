"""Maugis-Dugdale sphere theory, solved here independently of the package (test truth).

Maugis (1992), J. Colloid Interface Sci. 150:243, in the notation of Johnson & Greenwood
(1997), J. Colloid Interface Sci. 192:326: A = a (K / (pi w R^2))^(1/3),
P = P / (pi w R), m = c / a, K = 4 E* / 3, lambda = 2 sigma0 (R / (pi w K^2))^(1/3).
For each m > 1 the cohesive-zone condition is a quadratic in A; the load follows.
"""

from __future__ import annotations

import numpy as np
from scipy import optimize


def md_curve(lam: float, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(A, P) of the Maugis-Dugdale solution at the ratios ``m`` = c / a > 1."""
    s = np.sqrt(m * m - 1.0)
    at = np.arctan(s)
    alpha = 0.5 * lam * (s + (m * m - 2.0) * at)
    beta = 4.0 * lam * lam / 3.0 * (s * at - m + 1.0)
    a = (-beta + np.sqrt(beta * beta + 4.0 * alpha)) / (2.0 * alpha)
    p = a ** 3 - lam * a * a * (s + m * m * at)
    return a, p


def md_pull_off(lam: float) -> float:
    """Largest tension of the Maugis-Dugdale curve, over pi w R (a positive number)."""
    m = 1.0 + np.logspace(-8, 4, 20001)
    _, p = md_curve(lam, m)
    k = int(np.argmin(p))
    if 0 < k < m.size - 1:  # polish the sampled minimum
        res = optimize.minimize_scalar(lambda x: md_curve(lam, np.array([x]))[1][0],
                                       bracket=(m[k - 1], m[k], m[k + 1]))
        return -float(res.fun)
    return -float(p[k])


def md_load_at_radius(lam: float, a: np.ndarray) -> np.ndarray:
    """Maugis-Dugdale load P / (pi w R) at the contact radii ``a`` (over the Maugis length).

    The radius A of the inner (compressive) contact decreases monotonically with m = c / a
    along the curve, so the load is single-valued in A and read by interpolation on a
    fine sampling of m.
    """
    m = 1.0 + np.logspace(-9, 3, 40001)
    big_a, p = md_curve(lam, m)
    return np.interp(np.asarray(a, dtype=float), big_a[::-1], p[::-1])


def md_curve_error(lam: float, a: np.ndarray, load: np.ndarray) -> np.ndarray:
    """|P - P_MD(a)| / max(|P_MD(a)|, P_c) at each (a, P) (over l_M and pi w R): the load's
    error relative to the load itself where it exceeds the pull-off P_c, and to P_c near
    zero load, where a relative error would blow up (the norm of the 2 % asked for)."""
    ref = md_load_at_radius(lam, a)
    return np.abs(np.asarray(load, dtype=float) - ref) / np.maximum(np.abs(ref), md_pull_off(lam))


def md_pull_off_approach(lam: float) -> float:
    """The approach at the pull-off (the largest tension), over (pi^2 w^2 R / K^2)^(1/3):
    Delta = A^2 - (4/3) lambda A sqrt(m^2 - 1) (Maugis 1992; Johnson & Greenwood 1997,
    eq. 6) at the m of the curve's least load."""
    m = 1.0 + np.logspace(-8, 4, 20001)
    _, p = md_curve(lam, m)
    k = int(np.argmin(p))
    best = m[k]
    if 0 < k < m.size - 1:
        best = optimize.minimize_scalar(lambda x: md_curve(lam, np.array([x]))[1][0],
                                        bracket=(m[k - 1], m[k], m[k + 1])).x
    a, _ = md_curve(lam, np.array([best]))
    return float(a[0] ** 2 - 4.0 / 3.0 * lam * a[0] * np.sqrt(best * best - 1.0))
