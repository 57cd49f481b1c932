"""Hunter's closed-form solution: a rigid cylinder rolling on a standard linear solid.

S. C. Hunter (1961), "The rolling contact of a rigid cylinder with a viscoelastic half
space", J. Appl. Mech. 28:611-617; summarised in K. L. Johnson (1985), *Contact Mechanics*,
sec. 8.4 (figs. 8.14-8.15). The derivation below follows Hunter's route (reduce the
hereditary integral to a first-order differential operator, then invert a finite Hilbert
transform) and writes the result as a Chebyshev series whose coefficients are modified
Bessel functions. It shares nothing with the boundary-element solver of
:mod:`contact.viscoelastic._line` except the physics, so it serves as that solver's
independent check.

Setting. The cylinder (radius R, load W per unit length) moves at speed V towards +x over
a half-space with combined creep compliance C(t) = C_g + (C_r - C_g)(1 - exp(-t/tau_c))
(plane strain: C = (1 - nu^2) J). In the cylinder's frame a material point at x was at
x + xi a time xi/V earlier, so the surface displacement is

    u(x) = C_g w(x) + (C_r - C_g) F(x),   F(x) = (1/l) int_0^inf exp(-xi/l) w(x + xi) dxi,

with w the displacement of a unit-compliance half-plane (w' = -2 H[p],
H[p](x) = (1/pi) int p(s)/(x - s) ds) and l = V tau_c. Since (1 - l d/dx) F = w, applying
(1 - l d/dx) to u' = -x/R inside the contact (-a, b) gives, with l' = V tau_sigma =
l C_g / C_r (the relaxation length),

    H[p](x) = (x + l' - l) / (2 R C_r) + A exp(x / l')      on (-a, b).

With x = c + h t (c the offset of the centre, h the half-width), exp(kappa t) =
I_0(kappa) + 2 sum I_n(kappa) T_n(t), kappa = h/l', and the finite-Hilbert pair
(1/pi) int sqrt(1-s^2) U_{n-1}(s)/(t - s) ds = T_n(t) (|t| < 1), = z^n (t > 1,
z = t - sqrt(t^2 - 1)), the pressure bounded at both edges is

    p = sum_{n>=1} c_n sin(n theta),   t = cos(theta),

with c_0 = 0 (boundedness, fixes A), c_1 = h/(2 R C_r) + 2 B I_1, c_n = 2 B I_n (n >= 2),
B = A exp(c/l'). The load gives W = pi h c_1 / 2; the lost integration constant is the
leading-edge condition u'(b) = -b/R:

    b / (2R) = C_g H(b) + (C_r - C_g) (1/l) int_0^inf exp(-xi/l) H(b + xi) dxi.

These two equations fix h and c. The rolling-resistance coefficient (the pressure's moment
about the axis over W R) is mu_r = (c W + pi h^2 c_2 / 4) / (W R).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError, ConvergenceError


@dataclass(frozen=True)
class HunterSolution:
    """Hunter's steady rolling solution (SI; per unit length of the cylinder).

    Attributes
    ----------
    trailing, leading : float
        Contact edges x = -a and x = b (m), the cylinder rolling towards +x.
    coefficients : ndarray
        c_1..c_n of p = sum c_n sin(n theta) (Pa).
    rolling_resistance : float
        mu_r = moment of the pressure about the axis / (W R).
    load, radius : float
    """

    trailing: float
    leading: float
    coefficients: np.ndarray
    rolling_resistance: float
    load: float
    radius: float

    @property
    def centre(self) -> float:
        """c = (b - a)/2 (m), the offset of the strip's centre ahead of the axis."""
        return 0.5 * (self.leading + self.trailing)

    @property
    def half_width(self) -> float:
        """h = (a + b)/2 (m)."""
        return 0.5 * (self.leading - self.trailing)

    def pressure(self, x: np.ndarray | float) -> np.ndarray:
        """p(x) in Pa (0 outside the strip)."""
        t = (np.asarray(x, dtype=float) - self.centre) / self.half_width
        inside = np.abs(t) < 1
        theta = np.arccos(np.clip(t, -1.0, 1.0))
        n = np.arange(1, self.coefficients.size + 1)
        p = np.sin(np.multiply.outer(theta, n)) @ self.coefficients
        return np.where(inside, p, 0.0)

    def pmax(self) -> float:
        """Peak pressure (Pa), from a fine sampling of the series."""
        x = np.linspace(self.trailing, self.leading, 4001)
        return float(self.pressure(x).max())


def _series(h: float, c: float, R: float, cg: float, cr: float, ell: float) -> np.ndarray:
    """c_1..c_n for a strip of half-width h centred at c (the boundedness condition used)."""
    from scipy.special import ive

    lp = ell * cg / cr
    kappa = h / lp
    nmax = int(kappa + 12.0 * math.sqrt(kappa) + 40)
    n = np.arange(0, nmax + 1)
    ratio = ive(n, kappa) / ive(0, kappa)  # I_n / I_0, scaled against overflow
    coef = -(c + lp - ell) / (R * cr) * ratio[1:]
    coef[0] += h / (2.0 * R * cr)
    return coef


def _ahead_mean(coef: np.ndarray, h: float, ell: float) -> float:
    """(1/l) int_0^inf exp(-xi/l) H(b + xi) dxi, with x = cosh(s): H = sum c_n e^{-n s}."""
    from scipy.integrate import quad

    n = np.arange(1, coef.size + 1)

    def f(s: float) -> float:
        xi = h * (math.cosh(s) - 1.0)
        return math.exp(-xi / ell) * float(coef @ np.exp(-n * s)) * h * math.sinh(s) / ell

    smax = math.acosh(1.0 + 60.0 * ell / h)
    val, _ = quad(f, 0.0, smax, limit=200, epsabs=0.0, epsrel=1e-11)
    return val


def _half_width(c: float, W: float, R: float, cg: float, cr: float, ell: float) -> float:
    from scipy.optimize import brentq

    def load_gap(h: float) -> float:
        return math.pi * h / 2.0 * _series(h, c, R, cg, cr, ell)[0] - W

    lo = math.sqrt(4.0 * W * R * cg / math.pi) * 0.3
    hi = math.sqrt(4.0 * W * R * cr / math.pi) * 3.0
    return brentq(load_gap, lo, hi, xtol=1e-15 * hi, rtol=1e-13)


def hunter_cylinder(radius: float, load_per_length: float, glassy: float, relaxed: float,
                    tau_c: float, speed: float) -> HunterSolution:
    """Hunter's solution for a rigid cylinder on a standard linear solid.

    Parameters
    ----------
    radius : float
        R (m).
    load_per_length : float
        W (N/m).
    glassy, relaxed : float
        Plane-strain compliances C_g = (1 - nu^2)/E_g and C_r = (1 - nu^2)/E_r (1/Pa).
    tau_c : float
        Creep time (s).
    speed : float
        V (m/s).
    """
    from scipy.optimize import brentq

    R, W, cg, cr = (float(v) for v in (radius, load_per_length, glassy, relaxed))
    if not all(math.isfinite(v) and v > 0 for v in (R, W, cg, cr, tau_c, speed)):
        raise ContactInputError("Hunter's solution needs positive R, W, compliances, tau, V")
    if cg >= cr:
        raise ContactInputError("Hunter's solution needs C_g < C_r (a relaxing solid)")
    ell = speed * tau_c

    def residual(c: float) -> float:
        h = _half_width(c, W, R, cg, cr, ell)
        coef = _series(h, c, R, cg, cr, ell)
        b = c + h
        return cg * float(coef.sum()) + (cr - cg) * _ahead_mean(coef, h, ell) - b / (2 * R)

    a_r = math.sqrt(4.0 * W * R * cr / math.pi)
    grid = np.linspace(-0.05 * a_r, 0.99 * a_r, 40)
    vals = [residual(c) for c in grid]
    for k in range(len(grid) - 1):
        if vals[k] == 0 or vals[k] * vals[k + 1] < 0:
            c = brentq(residual, grid[k], grid[k + 1], xtol=1e-14 * a_r, rtol=1e-13)
            break
    else:
        raise ConvergenceError("Hunter's solution: no leading-edge root bracketed")
    h = _half_width(c, W, R, cg, cr, ell)
    coef = _series(h, c, R, cg, cr, ell)
    c2 = coef[1] if coef.size > 1 else 0.0
    mu = (c * W + math.pi * h**2 * c2 / 4.0) / (W * R)
    return HunterSolution(trailing=c - h, leading=c + h, coefficients=coef,
                          rolling_resistance=mu, load=W, radius=R)
