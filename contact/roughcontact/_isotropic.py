"""The isotropic 2D PSD that Persson's theory needs, from a profile (1D) PSD.

For an isotropic surface the PSD of its line scans is the projection of the areal PSD
(Jacobs, Junge & Pastewka 2017, Surf. Topogr.: Metrol. Prop. 5, 013001, sec. 2.2, in
their convention ``h_rms² = (1/π) ∫₀^∞ C¹ᴰ dq = (1/2π) ∫₀^∞ q C^iso dq``):

    C¹ᴰ(q) = (1/π) ∫₀^∞ C^iso(√(q² + q_y²)) dq_y,

an Abel transform, whose inverse is

    C^iso(q) = -2 ∫_q^∞ (dC¹ᴰ/dy) dy / √(y² - q²).

:func:`iso_from_profile_psd` evaluates the inverse exactly for the spectrum that is linear
in log-log between the given points (a power law on each interval): on an interval where
``C¹ᴰ ∝ y^s`` it is a smooth integral in ``t`` (substitute ``y = q cosh t``), summed by
Gauss-Legendre, and above the last point an incomplete beta function.
For a self-affine spectrum ``C¹ᴰ = A q^(-1-2H)`` it returns the closed form
``C^iso = C¹ᴰ(q)/q · 2√π Γ(1+H)/Γ(1/2+H)`` (:func:`self_affine_factor`).

The inverse at q needs the 1D PSD at every y > q: above the last point the spectrum is
continued by the power law of its last interval, its exponent made no shallower than -1
(H = 0), so that a flattening at the end of the data (noise) does not feed an unbounded
tail. Without a continuation the profile power measured at the last point would have to
come from areal wavevectors below it and would pile up there.

:func:`log_quadrature` gives wavevectors and weights with which
:func:`contact.roughcontact.persson` and :func:`contact.roughcontact.isotropic_moments`
integrate such a spectrum over a band.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import beta, betainc, gammaln

from contact._errors import ContactInputError

#: Shallowest exponent of the 1D PSD's continuation above the data (H = 0).
TAIL_SLOPE_MAX = -1.0


def self_affine_factor(hurst: float) -> float:
    """``C^iso(q) q / C¹ᴰ(q) = 2√π Γ(1+H)/Γ(1/2+H)`` for ``C¹ᴰ ∝ q^(-1-2H)``."""
    if not -0.5 < hurst:
        raise ContactInputError(f"the Hurst exponent must exceed -1/2, got {hurst!r}")
    return 2.0 * math.sqrt(math.pi) * math.exp(gammaln(1.0 + hurst) - gammaln(0.5 + hurst))


#: Gauss-Legendre nodes on [-1, 1] for the finite intervals (their integrand is smooth in t).
_GL_T, _GL_W = np.polynomial.legendre.leggauss(24)


def _segment(q: np.ndarray, y0: float, y1: float, c0: float, s: float) -> np.ndarray:
    """``-2 ∫_{max(q,y0)}^{y1} dC/dy dy/√(y²-q²)`` for ``C = c0 (y/y0)^s``.

    With ``dC/dy = s C / y`` and ``y = q cosh t`` the integral is
    ``-2 s c0 (q/y0)^s ∫ cosh(t)^(s-1) dt / q``, smooth in t (Gauss-Legendre).
    """
    out = np.zeros(q.size)
    live = q < y1
    if s == 0.0 or not live.any():
        return out
    qq = q[live]
    t0 = np.arccosh(np.maximum(1.0, y0 / qq))
    t1 = np.arccosh(y1 / qq)
    half = 0.5 * (t1 - t0)
    t = (t0 + t1)[:, None] * 0.5 + half[:, None] * _GL_T[None, :]
    integral = half * np.sum(_GL_W[None, :] * np.cosh(t) ** (s - 1.0), axis=1)
    out[live] = -2.0 * s * c0 * (qq / y0) ** s / qq * integral
    return out


def _tail(q: np.ndarray, y0: float, c0: float, s: float) -> np.ndarray:
    """The continuation ``C = c0 (y/y0)^s`` above ``y0`` (s ≤ -1): with ``u = (q/y)²`` an
    incomplete beta function, ``-s c0 (q/y0)^s / q · B(a, ½) I_x(a, ½)``, ``a = (1-s)/2``."""
    a = 0.5 * (1.0 - s)
    x = np.minimum(1.0, (q / y0) ** 2)
    return -s * c0 * (q / y0) ** s / q * beta(a, 0.5) * betainc(a, 0.5, x)


def iso_from_profile_psd(q_1d: np.ndarray, c_1d: np.ndarray, q: np.ndarray | None = None
                         ) -> np.ndarray:
    """The isotropic (radial) PSD ``C^iso(q)`` (m⁴) of the surface whose profiles have
    the PSD ``c_1d`` (m³) at ``q_1d`` (rad/m).

    Parameters
    ----------
    q_1d, c_1d : ndarray
        Profile PSD, at least two points with positive wavevectors and values (any order).
    q : ndarray, optional
        Where to evaluate ``C^iso`` (rad/m, positive); default ``q_1d`` sorted.

    Raises
    ------
    ContactInputError
        Mismatched or too short arrays, non-positive values.

    Notes
    -----
    Where the profile PSD rises with q (noise, a step where measurements of different
    levels meet in an average) the inverse takes negative values: no isotropic surface
    has such profiles. They are returned as they are; the caller decides.
    """
    y = np.asarray(q_1d, dtype=float)
    c = np.asarray(c_1d, dtype=float)
    if y.shape != c.shape or y.ndim != 1 or y.size < 2:
        raise ContactInputError("q and C¹ᴰ must be 1D arrays of one length, at least 2")
    if not (np.all(np.isfinite(y)) and np.all(y > 0) and np.all(np.isfinite(c))
            and np.all(c > 0)):
        raise ContactInputError("a profile PSD needs finite positive wavevectors and values")
    order = np.argsort(y)
    y, c = y[order], c[order]
    if np.any(np.diff(y) <= 0):
        raise ContactInputError("the profile PSD's wavevectors repeat")
    qo = y if q is None else np.atleast_1d(np.asarray(q, dtype=float))
    if not (np.all(np.isfinite(qo)) and np.all(qo > 0)):
        raise ContactInputError("C^iso is evaluated at positive wavevectors only")
    slopes = np.diff(np.log(c)) / np.diff(np.log(y))
    out = np.zeros(qo.size)
    for k, s in enumerate(slopes):
        out += _segment(qo, y[k], y[k + 1], c[k], float(s))
    return out + _tail(qo, y[-1], c[-1], min(float(slopes[-1]), TAIL_SLOPE_MAX))


def log_quadrature(q_min: float, q_max: float, per_decade: int = 40
                   ) -> tuple[np.ndarray, np.ndarray, float]:
    """Midpoint rule in ``log q`` over ``[q_min, q_max]`` for an isotropic spectrum.

    Returns ``(q, weights, dq)`` such that ``Σ f(q) C w dq²/(2π)²`` approximates
    ``(1/2π) ∫ q f(q) C^iso(q) dq``: the convention of the radial DFT bins that
    :func:`contact.roughcontact.persson` and :func:`~contact.roughcontact.isotropic_moments`
    take (``dq`` is ``q_min``; ``w = 2π q Δq / dq²``).
    """
    if not (0 < q_min < q_max and math.isfinite(q_max)):
        raise ContactInputError(f"need 0 < q_min < q_max, got {q_min!r}, {q_max!r}")
    n = max(2, math.ceil(per_decade * math.log10(q_max / q_min)))
    edges = np.geomspace(q_min, q_max, n + 1)
    qm = np.sqrt(edges[:-1] * edges[1:])
    w = 2.0 * math.pi * qm * np.diff(edges) / q_min**2
    return qm, w, float(q_min)
