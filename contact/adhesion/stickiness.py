"""Does adhesion matter for a rough contact? Tabor's parameter and Pastewka & Robbins.

- Tabor's parameter mu = (R w^2 / (E*^2 z0^3))^(1/3) (Tabor 1977, J. Colloid Interface
  Sci. 58:2; :func:`contact.adhesion.laws.tabor_parameter`) of a body of radius R: the
  elastic neck that adhesion pulls up against the range z0 of the interaction. Small mu:
  the DMT side (rigid-like, pull-off 2 pi w R); large mu: the JKR side.
- Pastewka & Robbins (2014), "Contact between rough surfaces and a criterion for
  macroscopic adhesion", PNAS 111:3298, their eq. 10: a randomly rough surface is sticky
  (a finite force separates it) when

      Pi = (h'_rms rho / (kappa_rep l_a)) (h'_rms d_rep / (4 rho))^(2/3) < 1,

  with l_a = w / E* the elastocapillary length, rho the interaction range, kappa_rep = 2
  and d_rep = 4 h'_rms / h''_rms (h'_rms the rms gradient, h''_rms the rms of half the
  Laplacian); this is the evaluation of their criterion used in the ContactMechanics
  adhesive rough-contact example (Pastewka group). It depends on the finest scales of the
  roughness only (Ciavarella 2016, J. Tribol. 139:031404, compares it with asperity
  models). Below the threshold the surfaces are sticky; above it adhesion only adds to
  the area in proportion to its strength (Pastewka & Robbins 2014, fig. 2).
"""

from __future__ import annotations

import math

from contact._validate import positive

#: Pastewka & Robbins' prefactor of the repulsive area-load slope.
KAPPA_REP = 2.0


def rms_gradient_curvature(m2: float, m4: float) -> tuple[float, float]:
    """(h'_rms, h''_rms) of an isotropic surface from its profile moments m2, m4.

    h'_rms = sqrt(<|grad h|^2>) = sqrt(2 m2); h''_rms = rms of half the Laplacian,
    sqrt(<(lap h)^2>) / 2 = sqrt(2 m4 / 3), since m4 = 3/8 <(lap h)^2> (Nayak 1971).
    """
    return math.sqrt(2.0 * positive(m2, "m2")), math.sqrt(2.0 * positive(m4, "m4", "1/m^2")
                                                          / 3.0)


def pastewka_robbins(slope_rms: float, curvature_rms: float, e_star: float, work: float,
                     range_: float) -> float:
    """Pastewka & Robbins' stickiness parameter Pi (sticky when Pi < 1), see the module.

    Parameters
    ----------
    slope_rms, curvature_rms : float
        h'_rms (1) and h''_rms (1/m) of the combined roughness.
    e_star, work, range_ : float
        E* (Pa), work of adhesion w (J/m^2) and interaction range rho (m).
    """
    hp = positive(slope_rms, "the rms gradient")
    hpp = positive(curvature_rms, "the rms curvature", "1/m")
    rho = positive(range_, "the interaction range", "m")
    l_a = positive(work, "the work of adhesion", "J/m^2") / positive(e_star, "E*", "Pa")
    d_rep = 4.0 * hp / hpp
    return hp * rho / (KAPPA_REP * l_a) * (hp * d_rep / (4.0 * rho)) ** (2.0 / 3.0)
