"""The grid window of a viscoelastic rolling contact, in one place.

The contact of a rolling viscoelastic body is never larger than the fully relaxed Hertz
contact (the softest modulus gives the widest contact at any speed; Hunter 1961,
J. Appl. Mech. 28:611), and at speed the pressure shifts forward inside it. Every
viscoelastic grid therefore spans +-1.6 relaxed Hertz sizes: the relaxed contact with
room for the shift. The Hertz sizes use the relaxed compliance C of
:class:`contact.viscoelastic._rheology.CreepSeries` (C = 1 / E*_relaxed; Johnson 1985,
eqs. 4.22 and 5.1).
"""

from __future__ import annotations

import math

#: Half-width of a viscoelastic rolling grid over the relaxed Hertz size.
WINDOW_FACTOR = 1.6


def relaxed_sphere_radius(load: float, radius: float, relaxed: float) -> float:
    """Hertz contact radius (3 W R C / 4)^(1/3) of a sphere with compliance C (m)."""
    return (3.0 * load * radius * relaxed / 4.0) ** (1.0 / 3.0)


def relaxed_cylinder_half_width(load_per_length: float, radius: float, relaxed: float) -> float:
    """Hertz half-width sqrt(4 W' R C / pi) of a cylinder with compliance C (m)."""
    return math.sqrt(4.0 * load_per_length * radius * relaxed / math.pi)


def sphere_window(load: float, radius: float, relaxed: float) -> float:
    """Half-width of the square grid of a rolling sphere (m)."""
    return WINDOW_FACTOR * relaxed_sphere_radius(load, radius, relaxed)


def cylinder_window(load_per_length: float, radius: float, relaxed: float) -> float:
    """Half-length of the grid of a rolling cylinder (m)."""
    return WINDOW_FACTOR * relaxed_cylinder_half_width(load_per_length, radius, relaxed)
