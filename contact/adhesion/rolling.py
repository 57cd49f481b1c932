"""Adhesion hysteresis as a rolling-resistance mechanism of a ball on a flat.

A rolling contact closes a crack at its leading edge, where the surfaces come together
with the work of adhesion of approach w_app, and opens one at its trailing edge, where
they part with the larger work of separation w_sep. Per unit rolling distance the ball
seals and peels one contact width 2a of interface, so the energy lost is

    F_r = (w_sep - w_app) 2a = Delta_w 2a,     M_r = F_r R

(Kendall 1975, "Rolling friction and adhesion between smooth solids", Wear 33:351;
Greenwood & Johnson 1981, Phil. Mag. A 43:697, for the crack closing and opening on the
two sides of a contact; Johnson 1985, Contact Mechanics, sec. 8.6). The contact radius is
JKR's at the load with the work of separation (Johnson, Kendall & Roberts 1971):

    a^3 = 3 R / (4 E*) [N + 3 pi w R + sqrt(6 pi w R N + (3 pi w R)^2)],

which reduces to Hertz's for w = 0, so M_r grows as N^(1/3) when adhesion is weak
against the load.

Numbers for steel on aluminium in air (:data:`STEEL_ALUMINIUM_AIR`): in air both metals
carry oxide and adsorbed films, and their adhesion is that of van der Waals forces across
the films, w = A / (12 pi D0^2) with D0 = 0.165 nm (Israelachvili 2011, Intermolecular
and Surface Forces, 3rd ed., ch. 13) and Hamaker constants of the oxides about
1e-19 to 1.5e-19 J (Al2O3 across vacuum: Bergstrom 1997, Adv. Colloid Interface Sci.
70:125; Ackler, French & Chiang 1996, J. Colloid Interface Sci. 179:460), giving w of about
0.1 to 0.15 J/m^2; 0.1 J/m^2 is taken. No measured
hysteresis of this pair is known to the project: Delta_w = w (the surfaces approach with
no adhesion and part with all of it) is the largest it can be, so the mechanism is an
upper bound for a smooth pair, and a rough pair that Pastewka & Robbins' criterion finds
non-sticky (:mod:`contact.adhesion.stickiness`) loses far less.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from contact._validate import positive

#: (work of adhesion w in J/m^2, hysteresis Delta_w in J/m^2, source) for steel on
#: aluminium in air; Delta_w = w is an upper bound (see the module notes).
STEEL_ALUMINIUM_AIR = (
    0.1, 0.1,
    "w = A / (12 pi D0^2), D0 = 0.165 nm (Israelachvili 2011, ch. 13), A ~ 1e-19 J of the "
    "oxide films (Al2O3: Bergstrom 1997; Ackler, French & Chiang 1996): about 0.1 J/m^2; "
    "Delta_w = w is the upper bound (complete hysteresis; "
    "none measured for this pair)")


def jkr_radius(load: float, radius: float, e_star: float, work: float) -> float:
    """JKR contact radius (m) of a sphere at ``load`` (N) with work of adhesion ``work``."""
    p_a = 3.0 * math.pi * work * radius
    inner = load + p_a + math.sqrt(max(6.0 * math.pi * work * radius * load + p_a * p_a, 0.0))
    return (3.0 * radius * inner / (4.0 * e_star)) ** (1.0 / 3.0)


def adhesion_hysteresis_forces(loads: Sequence[float], radius: float, e_star: float,
                               work: float, hysteresis: float) -> np.ndarray:
    """F_r = Delta_w 2a at each load (N): energy lost per unit rolling distance.

    Parameters
    ----------
    loads : sequence of float
        Normal loads (N).
    radius, e_star : float
        Ball radius (m) and composite modulus (Pa).
    work, hysteresis : float
        Work of separation w (J/m^2, sets the JKR radius) and Delta_w = w_sep - w_app
        (J/m^2).
    """
    positive(radius, "the radius", "m")
    positive(e_star, "E*", "Pa")
    positive(work, "the work of adhesion", "J/m^2")
    if not (math.isfinite(hysteresis) and 0.0 <= hysteresis <= work):
        from contact._errors import ContactInputError

        raise ContactInputError(f"the adhesion hysteresis must lie between 0 and the work of "
                                f"adhesion {work:g} J/m^2, got {hysteresis!r}")
    return np.array([2.0 * hysteresis * jkr_radius(float(n), radius, e_star, work)
                     for n in loads])
