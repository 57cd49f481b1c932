"""Greenwood-Williamson (1966) contact of a nominally flat rough surface with a flat.

Summits of one radius R_s, density η and Gaussian heights (standard deviation σ_s about the
mean summit height y_s above the mean plane) each make a Hertz contact. With d the
separation of the flat from the mean summit plane and ``t = d/σ_s`` (Greenwood &
Williamson 1966, Proc. R. Soc. A 295, 300, Eqs. 6-8):

    n/A0 = η F_0(t),   A/A0 = π η R_s σ_s F_1(t),   p = (4/3) η E* √R_s σ_s^{3/2} F_{3/2}(t),

with ``F_n(t) = (2π)^{-1/2} ∫_t^∞ (s-t)^n e^{-s²/2} ds``. These are parabolic-cylinder
functions (Abramowitz & Stegun 19.5.3 / DLMF 12.5.1):

    F_n(t) = Γ(n+1) (2π)^{-1/2} e^{-t²/4} D_{-n-1}(t).

The mean gap is the separation from the surface's mean plane, ``ū = d + y_s`` (GW neglect
the bulk deformation), and the stiffness per unit area is
``K = -dp/dū = 2 η E* √R_s σ_s^{1/2} F_{1/2}(t)``. The summit parameters come from the
spectral moments (Nayak 1971; McCool 1986; :func:`contact.roughcontact.summit_parameters`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial.hermite_e import hermegauss
from scipy.optimize import brentq
from scipy.special import gamma as gamma_fn
from scipy.special import pbdv

from contact._errors import ContactInputError
from contact.roughcontact._persson import ModelCurve, check_pressures
from contact.roughcontact._summits import SummitParameters

#: Below this t the Gaussian mass under t is < 1e-15: F_n(t) is the Gaussian mean of
#: (s - t)^n, taken by Gauss-Hermite quadrature (the closed form's e^{-t²/4} D(t) is
#: 0 × inf past |t| ≈ 54).
_DEEP = -8.0
_NODES, _WEIGHTS = hermegauss(80)
#: The summits' mean plane more than this many σ_s into the surface: no rough contact left.
_FARTHEST = -1e6


def gw_integral(n: float, t: np.ndarray | float) -> np.ndarray:
    """``F_n(t) = (2π)^{-1/2} ∫_t^∞ (s-t)^n e^{-s²/2} ds``.

    Via the parabolic cylinder function, F_n(t) = Γ(n+1) (2π)^{-1/2} e^{-t²/4} D_{-n-1}(t)
    (Greenwood & Williamson 1966); deep in contact (t < -8) by 80-point Gauss-Hermite
    quadrature of the Gaussian mean of max(s - t, 0)^n, which agrees with it to 1e-14 there.
    """
    t = np.asarray(t, dtype=float)
    deep = t < _DEEP
    d, _ = pbdv(-n - 1.0, np.where(deep, 0.0, t))
    out = gamma_fn(n + 1.0) / math.sqrt(2.0 * math.pi) * np.exp(-t * t / 4.0) * d
    if np.any(deep):
        s = _NODES - t[deep][..., None]
        mean = np.maximum(s, 0.0) ** n @ _WEIGHTS / math.sqrt(2.0 * math.pi)
        out = np.where(deep, 0.0, out)
        out[deep] = mean
    return out


def gw_state(t: np.ndarray | float, e_star: float, s: SummitParameters
             ) -> dict[str, np.ndarray]:
    """Pressure, area fraction, contact-spot density, mean gap and stiffness at t = d/σ_s."""
    t = np.asarray(t, dtype=float)
    eta, R, sig = s.density, s.radius, s.sigma_s
    return {
        "pressure": 4.0 / 3.0 * eta * e_star * math.sqrt(R) * sig**1.5 * gw_integral(1.5, t),
        "area_fraction": math.pi * eta * R * sig * gw_integral(1.0, t),
        "spots": eta * gw_integral(0.0, t),
        "mean_gap": t * sig + s.mean_height,
        "stiffness": 2.0 * eta * e_star * math.sqrt(R * sig) * gw_integral(0.5, t),
    }


def greenwood_williamson(pressure: np.ndarray | float, e_star: float,
                         summits: SummitParameters) -> ModelCurve:
    """GW area fraction, mean gap and stiffness at the given nominal pressures.

    The separation is found by root-finding ``p(t)`` (monotonic) in ``log p``.
    """
    p = check_pressures(pressure)
    if not (summits.sigma_s > 0 and summits.radius > 0 and summits.density > 0):
        raise ContactInputError("GW needs a positive summit density, radius and σ_s")

    def logp(t: float) -> float:
        return math.log(float(gw_state(t, e_star, summits)["pressure"]))

    ts = np.empty_like(p)
    for k, pk in enumerate(p):
        lp = math.log(pk)
        lo, hi = -10.0, 10.0
        while logp(lo) < lp:  # pressures beyond full contact of every summit
            lo *= 2.0
            if lo < _FARTHEST:
                raise ContactInputError(
                    f"a nominal pressure of {pk:.4g} Pa is beyond the Greenwood-Williamson "
                    f"model for these summits (σ_s = {summits.sigma_s:.3g} m): the surface is "
                    "too smooth (or flat) for it")
        while logp(hi) > lp and hi < 60.0:
            hi += 5.0
        ts[k] = brentq(lambda t, lp=lp: logp(t) - lp, lo, hi, xtol=1e-12)
    st = gw_state(ts, e_star, summits)
    return ModelCurve("gw", p, np.minimum(st["area_fraction"], 1.0), st["mean_gap"],
                      st["stiffness"])
