"""Maugis-Dugdale theory of the adhesive cylinder (plane strain), solved here independently
of the package by quadrature (test truth).

Baney & Hui (1997), J. Adhesion Sci. Technol. 11:393; Johnson & Greenwood (2008), J. Phys.
D 41:155315. With the contact |x| < a and the Dugdale zone a < |x| < c the pressure is
Hertz's (E* / (2 R)) sqrt(a^2 - x^2) plus the Dugdale field: -sigma0 in the zone and
-(2 sigma0 / pi) arctan(sqrt((c^2 - a^2) / (a^2 - x^2))) inside (no singularity at a; the
displacement it makes inside is uniform). The load per unit length is
P' = pi E* a^2 / (4 R) - 2 sigma0 sqrt(c^2 - a^2), and c is where the gap is h0:

    g(c) = [c s - a^2 ln((c + s) / a)] / (2 R)
           - (2 / (pi E*)) * integral of p_D(t) ln|(c - t) / (a - t)| dt = h0,  s = sqrt(c^2 - a^2),

the first term Hertz's gap outside a cylinder's contact (Johnson 1985, sec. 5.6), the
second the Dugdale field's, from du/dx = -(2 / (pi E*)) PV integral of p(t) / (x - t) dt
(Johnson 1985, eq. 2.25a) integrated from a to c.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import integrate, optimize


def _dugdale_gap(a: float, c: float, sigma0: float, e_star: float) -> float:
    """The gap the Dugdale field opens between x = a and x = c (m, negative: it closes)."""
    def kern(t: float) -> float:
        return math.log(abs((c - t) / (a - t)))

    def inside(theta: float) -> float:  # t = a sin(theta), dt = a cos(theta) dtheta
        t = a * math.sin(theta)
        ct = a * math.cos(theta)
        p = -(2 * sigma0 / math.pi) * math.atan(math.sqrt(c * c - a * a) / max(ct, 1e-300))
        return p * kern(t) * ct

    def prim(v: float) -> float:  # an antiderivative of ln|v|
        return v * math.log(abs(v)) - v if v != 0.0 else 0.0

    total = 0.0
    if a > 0:
        total += integrate.quad(inside, -0.5 * math.pi, 0.5 * math.pi, limit=400,
                                epsabs=0.0, epsrel=1e-10)[0]
    # the zones carry -sigma0: the integral of ln|c - t| - ln|a - t| in closed form
    for lo, hi in ((-c, -a), (a, c)):
        total += -sigma0 * ((prim(c - lo) - prim(c - hi)) - (prim(a - lo) - prim(a - hi)))
    return -2.0 / (math.pi * e_star) * total


def md_line_state(a: float, work: float, sigma0: float, radius: float,
                  e_star: float) -> tuple[float, float]:
    """(c, P') of the Maugis-Dugdale cylinder at contact half-width ``a`` (m, N/m)."""
    h0 = work / sigma0

    def excess(c: float) -> float:
        s = math.sqrt(max(c * c - a * a, 0.0))
        hertz = (c * s - a * a * math.log((c + s) / a)) / (2 * radius) if a > 0 else \
            c * c / (2 * radius)
        return hertz + _dugdale_gap(a, c, sigma0, e_star) - h0

    lo, step = a * (1 + 1e-12) + 1e-300, max(a, math.sqrt(2 * radius * h0)) * 1e-3
    hi = a + step
    while excess(hi) < 0:
        lo, hi = hi, a + 2 * (hi - a)
    c = optimize.brentq(excess, lo, hi, xtol=1e-15 * hi, rtol=1e-13)
    load = math.pi * e_star * a * a / (4 * radius) - 2 * sigma0 * math.sqrt(c * c - a * a)
    return c, load


def md_line_pull_off(work: float, sigma0: float, radius: float, e_star: float) -> float:
    """The largest tension (N/m, positive) over the Maugis-Dugdale cylinder's curve."""
    a_c = (2 * work * radius ** 2 / (math.pi * e_star)) ** (1 / 3)
    grid = a_c * np.concatenate([[1e-6], np.linspace(0.02, 3.0, 25)])
    loads = [md_line_state(a, work, sigma0, radius, e_star)[1] for a in grid]
    k = int(np.argmin(loads))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    res = optimize.minimize_scalar(lambda a: md_line_state(a, work, sigma0, radius, e_star)[1],
                                   bounds=(lo, hi), method="bounded",
                                   options={"xatol": 1e-6 * a_c})
    return -float(min(res.fun, loads[k]))
