"""Johnson's (1995) JKR solution for a wavy surface, a test truth independent of the package.

K.L. Johnson (1995), "The adhesion of two elastic bodies with slightly wavy surfaces",
Int. J. Solids Struct. 32:423. A surface h(x) = Delta (1 - cos(2 pi x / L)) (plane
strain, composite modulus E*) touches a flat on strips of half-width a, one per period L.
Re-derived here: the adhesive solution is the non-adhesive one of Westergaard (mean
pressure p* sin^2(pi a / L), p* = pi E* Delta / L, zero stress intensity at the edges;
Johnson 1985, Contact Mechanics, section 13.2) plus a periodic array of flat punches of
half-width a, whose pressure p_f cos(pi x / L) / sqrt(sin^2(pi a / L) - sin^2(pi x / L))
has mean p_f and stress intensity K = -p_f sqrt(L cot(pi a / L)) at the edges. Griffith's
condition K^2 / (2 E*) = w then gives

    p / p* = sin^2(pi a / L) - alpha sqrt(tan(pi a / L)),
    alpha = sqrt(2 w L / (pi^2 E* Delta^2)),

Johnson's result, as also written in ContactEngineering's Adhesion reference solutions
(sinewave/JKR.py: ``P = sin^2(pi a) - alpha sqrt(tan(pi a))`` in units of L and p*).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize


def mean_pressure(a: np.ndarray | float, alpha: float) -> np.ndarray:
    """p / p* at contact half-width ``a`` (in wavelengths, 0 < a < 1/2)."""
    t = math.pi * np.asarray(a, dtype=float)
    return np.sin(t) ** 2 - alpha * np.sqrt(np.tan(t))


def alpha_of(work: float, e_star: float, amplitude: float, wavelength: float) -> float:
    """Johnson's alpha = sqrt(2 w L / (pi^2 E* Delta^2))."""
    return math.sqrt(2.0 * work * wavelength / (math.pi ** 2 * e_star * amplitude ** 2))


def pull_off(alpha: float) -> tuple[float, float]:
    """(largest tension / p* as a positive number, half-width a / L where it is reached)."""
    res = optimize.minimize_scalar(lambda a: float(mean_pressure(a, alpha)),
                                   bounds=(1e-9, 0.49), method="bounded",
                                   options={"xatol": 1e-12})
    return -float(res.fun), float(res.x)


def mean_gap(a: np.ndarray | float, alpha: float, amplitude: float) -> np.ndarray:
    """Mean gap (over the whole period, the contact's zeros included) at half-width ``a``
    (in wavelengths), in units of ``amplitude`` times ``amplitude``: Delta [1 - U + U ln U
    - alpha sqrt(tan(pi a)) ln U], U = sin^2(pi a).

    Derived here from the same superposition. A periodic array of strip punches of
    half-width a under the mean pressure p_f moves the mean gap by -c p_f, with
    c = (2 L / (pi E*)) ln(1 / sin(pi a / L)) (the array's compliance; Johnson 1985, 13.2).
    At fixed contact the Westergaard solution stiffens like the punch array (Barber's
    theorem), so from u(0) = Delta (touching at a point, the mean of h) its mean gap is
    Delta - int c dp_W = Delta [1 - U (1 - ln U)] with dp_W = p* dU; the punch of
    p_f = -alpha p* sqrt(tan(pi a)) adds -c p_f, the alpha term. Checked: the plane-strain
    adhesive solve of tests/test_flat_adhesion.py's case (alpha 0.3, zone 0.005 L, 512 x 4,
    each pressure solved from the last) meets it within 0.32 % from 0.2 p* to -0.08 p*.
    """
    t = math.pi * np.asarray(a, dtype=float)
    u = np.sin(t) ** 2
    return amplitude * (1.0 - u + u * np.log(u) - alpha * np.sqrt(np.tan(t)) * np.log(u))


def half_width(p: float, alpha: float) -> float:
    """Half-width a / L on the load-controlled (stable) branch at p / p* = ``p``."""
    _, a_po = pull_off(alpha)
    top = optimize.minimize_scalar(lambda a: -float(mean_pressure(a, alpha)),
                                   bounds=(a_po, 0.4999), method="bounded",
                                   options={"xatol": 1e-12}).x
    return float(optimize.brentq(lambda a: float(mean_pressure(a, alpha)) - p, a_po, top,
                                 xtol=1e-14))
