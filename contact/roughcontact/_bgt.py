"""Bush, Gibson & Thomas (1975): elliptic-paraboloid summits of a Gaussian isotropic surface.

At low pressure BGT's real contact area is proportional to the load (Bush, Gibson & Thomas
1975, Wear 35, 87, Eq. 29; McCool 1986, Wear 107, 37, Eq. 28):

    A/A0 = √π p / (E* √m2) = κ_BGT p / (E* h'_rms),   κ_BGT = √(2π) ≈ 2.507,

with ``m2 = h'_rms²/2`` the profile slope variance of the isotropic surface. The linear law
is BGT's asymptote for separations large against σ (few, independent contacts); it is
capped at full contact here. BGT's load-separation relation has no closed form, so the
model gives no mean gap or stiffness.
"""

from __future__ import annotations

import math

import numpy as np

from contact._validate import positive
from contact.roughcontact._persson import ModelCurve, check_pressures

#: BGT's low-pressure area-load proportionality.
KAPPA_BGT = math.sqrt(2.0 * math.pi)


def bush_gibson_thomas(pressure: np.ndarray | float, e_star: float,
                       slope_rms: float) -> ModelCurve:
    """BGT's linear area-load law ``A/A0 = √(2π) p/(E* h'_rms)``, capped at 1."""
    p = check_pressures(pressure)
    positive(e_star, "e_star", "Pa")
    positive(slope_rms, "slope_rms")
    return ModelCurve("bgt", p, np.minimum(KAPPA_BGT * p / (e_star * slope_rms), 1.0),
                      None, None)
