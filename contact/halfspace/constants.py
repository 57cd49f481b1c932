"""The combined elastic constants of two half-spaces in contact (Kalker 1990, sec. 1.5).

Two bodies touch over a plane; body 1 receives the surface tractions (p, q_x, q_y) and
body 2 the opposite ones. Boussinesq's and Cerruti's point-load solutions (Johnson 1985,
*Contact Mechanics*, eqs. 3.19 and 3.86-3.87) for the *difference* of the two surface
displacements combine the bodies into three constants:

    1/G = (1/G1 + 1/G2)/2,  nu/G = (nu1/G1 + nu2/G2)/2,
    K/G = ((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2)/4,

G the combined modulus of rigidity, nu the combined Poisson ratio and K Kalker's
difference parameter; (1 - nu)/G = 1/E* and Dundurs' beta = K/(1 - nu). The influence
coefficients that use them are in :mod:`contact.halfspace.cerruti`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact._errors import ContactInputError
from contact._materials import Material


@dataclass(frozen=True)
class PairConstants:
    """Combined elastic constants of two bodies (Kalker 1990, sec. 1.5).

    Attributes
    ----------
    G : float
        Combined modulus of rigidity (Pa), 2/G = 1/G1 + 1/G2.
    nu : float
        Combined Poisson ratio.
    K : float
        Kalker's difference parameter (dimensionless); zero for quasi-identical bodies.
    """

    G: float
    nu: float
    K: float

    @property
    def e_star(self) -> float:
        """Composite modulus E* = G/(1 - nu) in Pa."""
        return self.G / (1.0 - self.nu)

    @property
    def beta(self) -> float:
        """Dundurs' second parameter beta = K/(1 - nu)."""
        return self.K / (1.0 - self.nu)


def shear_modulus(m: Material) -> float:
    """G in Pa: the material's own :attr:`~contact._materials.Material.shear_modulus`."""
    return m.shear_modulus


def pair_constants(body1: Material, body2: Material) -> PairConstants:
    """The combined constants G, nu, K of body 1 (receives +q) and body 2."""
    g1, g2 = shear_modulus(body1), shear_modulus(body2)
    inv_g = 0.5 * (1.0 / g1 + 1.0 / g2)
    G = 1.0 / inv_g
    nu = 0.5 * G * (body1.nu / g1 + body2.nu / g2)
    K = 0.25 * G * ((1.0 - 2.0 * body1.nu) / g1 - (1.0 - 2.0 * body2.nu) / g2)
    return PairConstants(G=G, nu=nu, K=K)


def pair_constants_from(g1: float, nu1: float, g2: float, nu2: float) -> PairConstants:
    """As :func:`pair_constants`, from the moduli of rigidity G1, G2 (Pa) and nu1, nu2."""
    for g in (g1, g2):
        if not (math.isfinite(g) and g > 0):
            raise ContactInputError("modulus of rigidity must be a positive number in Pa")
    inv_g = 0.5 * (1.0 / g1 + 1.0 / g2)
    G = 1.0 / inv_g
    return PairConstants(G=G, nu=0.5 * G * (nu1 / g1 + nu2 / g2),
                         K=0.25 * G * ((1.0 - 2.0 * nu1) / g1 - (1.0 - 2.0 * nu2) / g2))
