"""The two-ball rotor of Alaci, Ciornei & Romanu (2022) rolling on a slightly inclined plate.

The rotor is two steel balls (radius ``R``) joined by an aluminium rod, with a steel collar that
slides on the rod: moving the collar moves the centre of mass ``G`` along the axis while the
mass ``M`` and the axial moment of inertia ``J`` stay the same. Rolling without sliding on a
plane of inclination ``alpha``, along a direction at ``beta`` from the plane's horizontal, the
rotor is driven by ``M g sin(alpha) sin(beta)`` and braked by the rolling-friction torques
``M_r = s_r N**lambda`` at the two ball contacts.

What is here (equation numbers of the paper):

* mass properties from the parts, and the collar's ``xi_G(h)`` curve with its optimum (Fig. 9);
* normal reactions, Eqs. (41)-(42), and the paper's loads per ball; angular acceleration,
  Eqs. (47)-(49); tangential contact forces, Eqs. (44)-(45), and the pure-rolling check,
  Eq. (46).

The inverse problem (``lambda`` and ``s_r`` from two rotors' accelerations) is in
:mod:`rotor._inference`; the paper's dimensions in :mod:`rotor._paper`.

Two misprints in the paper, found while reproducing it: the ball's axial inertia is printed
``3.746e-6 kg m^2`` but ``(2/5) m R^2 = 4.18e-5 kg m^2``, and only the latter gives the
rotor's ``J = 1.632e-4 kg m^2``; the printed parts (0.261 + 0.261 + 0.031 + 0.398 kg) sum to
0.951 kg (0.9515 kg unrounded), not the printed ``M = 0.954 kg`` (CAD: 0.958 kg).

All quantities SI: m, kg, kg m^2, N, N m, rad, rad/s^2. ``s_r`` has the unit
``N**(1 - lambda) m``.

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Validation of nonlinear dependence of rolling
friction moment on the normal force for elastic materials. Materials 15(7):2518,
doi:10.3390/ma15072518.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact._errors import ContactInputError
from contact._validate import positive
from rotor import _paper as paper

G_STANDARD = 9.80665
"""Standard gravity, m/s^2 (the paper does not print the value it used)."""

__all__ = [
    "G_STANDARD",
    "MassProperties",
    "PureRollingCheck",
    "RotorGeometry",
    "angular_acceleration",
    "angular_acceleration_linear",
    "collar_com_offset",
    "driving_slope_for",
    "mass_properties",
    "normal_reactions",
    "optimal_collar_length",
    "paper_ball_loads",
    "paper_rotor",
    "pure_rolling_check",
    "rolling_torque",
    "tangential_forces",
]


# --------------------------------------------------------------------------------------------
# geometry and mass properties
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class RotorGeometry:
    """Dimensions and densities of the rotor's parts (SI).

    The rod joins the balls' surfaces: its length is ``centre_distance - 2 ball_radius``. The
    collar is a steel tube of length ``collar_length`` bored to the rod's radius.
    """

    ball_radius: float = paper.BALL_RADIUS
    ball_density: float = paper.BALL_DENSITY
    centre_distance: float = paper.CENTRE_DISTANCE
    rod_radius: float = paper.ROD_RADIUS
    rod_density: float = paper.ROD_DENSITY
    collar_length: float = paper.COLLAR_LENGTH
    collar_outer_radius: float = paper.COLLAR_OUTER_RADIUS
    collar_inner_radius: float = paper.COLLAR_INNER_RADIUS
    collar_density: float = paper.COLLAR_DENSITY

    def __post_init__(self) -> None:
        for name in (
            "ball_radius", "ball_density", "centre_distance", "rod_radius", "rod_density",
            "collar_outer_radius", "collar_density",
        ):
            positive(getattr(self, name), name)
        if not self.collar_length >= 0:
            raise ContactInputError(f"collar_length must be >= 0, got {self.collar_length!r}")
        if not 0 <= self.collar_inner_radius < self.collar_outer_radius:
            raise ContactInputError("collar_inner_radius must lie in [0, collar_outer_radius)")
        if not self.centre_distance > 2 * self.ball_radius:
            raise ContactInputError("centre_distance must exceed the balls' diameter")
        if self.collar_length > self.rod_length:
            raise ContactInputError(
                f"a collar {self.collar_length} m long does not fit on a rod "
                f"{self.rod_length} m long"
            )
        if self.collar_outer_radius >= self.ball_radius:
            raise ContactInputError(
                "the collar must be thinner than the balls, or it would touch the plate"
            )

    @property
    def rod_length(self) -> float:
        """Free rod length between the balls' surfaces, m."""
        return self.centre_distance - 2 * self.ball_radius

    @property
    def collar_mass_per_length(self) -> float:
        """Collar mass per unit length, kg/m."""
        return self.collar_density * math.pi * (
            self.collar_outer_radius**2 - self.collar_inner_radius**2
        )


def paper_rotor(collar_length: float = paper.COLLAR_LENGTH) -> RotorGeometry:
    """The rotor built in the paper (Section 2.2.2): R = 20 mm steel balls 140 mm apart, a
    6 mm aluminium rod, and a steel collar of radius 19 mm and length ``collar_length``.

    Parameters
    ----------
    collar_length : float
        Length of the collar (m); the paper's is 50 mm.

    Returns
    -------
    RotorGeometry
        The dimensions and densities of the parts.

    Raises
    ------
    ContactInputError
        A collar longer than the free rod (100 mm) or of negative length.

    See Also
    --------
    mass_properties : the rotor's mass, inertia and centre of mass.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    >>> from rotor import paper_rotor
    >>> rotor = paper_rotor()
    >>> print(f"R = {rotor.ball_radius * 1e3:.0f} mm, free rod {rotor.rod_length * 1e3:.0f} mm,"
    ...       f" collar {rotor.collar_length * 1e3:.0f} mm")
    R = 20 mm, free rod 100 mm, collar 50 mm
    """
    return RotorGeometry(collar_length=collar_length)


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of the assembled rotor.

    Attributes
    ----------
    mass, axial_inertia : float
        ``M`` (kg) and ``J_Cy`` (kg m^2), the moment of inertia about the rotor's axis.
    rolling_inertia : float
        ``J + M R^2`` (kg m^2), the inertia about the contact line, which divides every
        torque in the equation of motion.
    com_offset : float
        ``xi_G`` (m): axial distance from the mid-plane between the balls to ``G``, positive
        towards ball 1.
    d1, d2 : float
        Axial distances (m) from ``G`` to the centres of ball 1 and ball 2 (``d'``, ``d''``).
    ball_mass, ball_inertia, rod_mass, rod_inertia, collar_mass, collar_inertia : float
        The parts (one ball).
    ball_radius : float
        Rolling radius ``R`` (m).

    See Also
    --------
    mass_properties : builds it from a :class:`RotorGeometry`.

    Examples
    --------
    >>> from rotor import mass_properties
    >>> props = mass_properties(collar_offset="end")
    >>> print(f"M = {props.mass:.3f} kg, N1/N2 = {props.load_ratio:.3f}")
    M = 0.951 kg, N1/N2 = 1.351
    """

    mass: float
    axial_inertia: float
    rolling_inertia: float
    com_offset: float
    d1: float
    d2: float
    ball_mass: float
    ball_inertia: float
    rod_mass: float
    rod_inertia: float
    collar_mass: float
    collar_inertia: float
    ball_radius: float

    @property
    def load_ratio(self) -> float:
        """``N1/N2`` on a level plane, Eq. (52): ``d2/d1``."""
        return self.d2 / self.d1


def mass_properties(
    geometry: RotorGeometry | None = None, collar_offset: float | str = 0.0
) -> MassProperties:
    """Mass, inertia and centre of mass of the rotor with its collar at ``collar_offset``.

    Parameters
    ----------
    geometry : RotorGeometry, optional
        Defaults to :func:`paper_rotor`.
    collar_offset : float or {"symmetric", "end"}
        Axial position (m) of the collar's centre from the mid-plane between the balls,
        positive towards ball 1. ``"symmetric"`` is 0; ``"end"`` puts the collar against
        ball 1, the largest eccentricity this collar can give (the paper's asymmetric rotor).

    Returns
    -------
    MassProperties

    Raises
    ------
    ContactInputError
        An unknown collar position name, or an offset that puts the collar off the rod.

    See Also
    --------
    angular_acceleration : uses them.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    The paper's rotor: two 20 mm steel balls on a rod, with a collar:

    >>> from rotor import mass_properties
    >>> props = mass_properties()
    >>> print(f"M = {props.mass:.3f} kg, J + M R² = {props.rolling_inertia:.3e} kg m²")
    M = 0.951 kg, J + M R² = 5.438e-04 kg m²
    >>> end = mass_properties(collar_offset="end")
    >>> print(f"collar at the end: centre of mass {end.com_offset * 1e3:.2f} mm off")
    collar at the end: centre of mass 10.46 mm off
    """
    g = paper_rotor() if geometry is None else geometry
    half_span = g.rod_length / 2
    max_offset = half_span - g.collar_length / 2
    if isinstance(collar_offset, str):
        if collar_offset == "symmetric":
            offset = 0.0
        elif collar_offset == "end":
            offset = max_offset
        else:
            raise ContactInputError(
                f"collar_offset must be a length or 'symmetric'/'end', got {collar_offset!r}"
            )
    else:
        offset = float(collar_offset)
        if not (math.isfinite(offset) and abs(offset) <= max_offset * (1 + 1e-12)):
            raise ContactInputError(
                f"collar_offset {offset!r} m puts the collar off the rod "
                f"(|offset| <= {max_offset:.6g} m)"
            )
    r_b = g.ball_radius
    m_b = g.ball_density * 4.0 / 3.0 * math.pi * r_b**3
    j_b = 0.4 * m_b * r_b**2
    m_r = g.rod_density * math.pi * g.rod_radius**2 * g.rod_length
    j_r = 0.5 * m_r * g.rod_radius**2
    m_c = g.collar_mass_per_length * g.collar_length
    j_c = 0.5 * m_c * (g.collar_outer_radius**2 + g.collar_inner_radius**2)
    mass = 2 * m_b + m_r + m_c
    inertia = 2 * j_b + j_r + j_c
    xi = m_c * offset / mass
    half = g.centre_distance / 2
    return MassProperties(
        mass=mass,
        axial_inertia=inertia,
        rolling_inertia=inertia + mass * r_b**2,
        com_offset=xi,
        d1=half - xi,
        d2=half + xi,
        ball_mass=m_b,
        ball_inertia=j_b,
        rod_mass=m_r,
        rod_inertia=j_r,
        collar_mass=m_c,
        collar_inertia=j_c,
        ball_radius=r_b,
    )


def collar_com_offset(h: float | np.ndarray, geometry: RotorGeometry | None = None) -> np.ndarray:
    """``xi_G(h)``: offset of the centre of mass for a collar of length ``h`` pushed against a
    ball (Fig. 9 of the paper), m.

    A longer collar is heavier but its centre moves towards the mid-plane, so ``xi_G`` has a
    maximum (:func:`optimal_collar_length`).
    """
    g = paper_rotor() if geometry is None else geometry
    h = np.asarray(h, dtype=float)
    if np.any(~np.isfinite(h)) or np.any(h < 0) or np.any(h > g.rod_length):
        raise ContactInputError(f"collar lengths must lie in [0, {g.rod_length:.6g}] m")
    base = mass_properties(RotorGeometry(**{**g.__dict__, "collar_length": 0.0}))
    m0 = base.mass
    mu = g.collar_mass_per_length
    half_span = g.rod_length / 2
    return mu * h * (half_span - h / 2) / (m0 + mu * h)


def optimal_collar_length(geometry: RotorGeometry | None = None) -> tuple[float, float]:
    """The collar length ``h*`` that maximises ``xi_G`` and that maximum, both in m.

    Setting ``d xi_G/dh = 0`` for ``xi_G = mu h (L/2 - h/2)/(M0 + mu h)`` gives
    ``h^2 + 2 a h - a L = 0`` with ``a = M0/mu`` and ``L`` the free rod length.

    Parameters
    ----------
    geometry : RotorGeometry, optional
        The rotor (its ``collar_length`` is ignored); defaults to :func:`paper_rotor`.

    Returns
    -------
    h_star, xi_max : float
        The best collar length and the centre-of-mass offset it gives against a ball (m).

    See Also
    --------
    mass_properties

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, Materials 15 (2022) 2518, Fig. 9.

    Examples
    --------
    The paper's 50 mm collar is close to the best one, 39 mm, which moves the centre of mass
    11 mm off the mid-plane:

    >>> from rotor import optimal_collar_length
    >>> h, xi = optimal_collar_length()
    >>> print(f"h* = {h * 1e3:.1f} mm, xi_G = {xi * 1e3:.1f} mm")
    h* = 39.0 mm, xi_G = 11.0 mm
    """
    g = paper_rotor() if geometry is None else geometry
    m0 = mass_properties(RotorGeometry(**{**g.__dict__, "collar_length": 0.0})).mass
    a = m0 / g.collar_mass_per_length
    h = -a + math.sqrt(a * a + a * g.rod_length)
    h = min(h, g.rod_length)
    return h, float(collar_com_offset(h, g))


# --------------------------------------------------------------------------------------------
# forward model, Eqs. (41)-(49)
# --------------------------------------------------------------------------------------------


def normal_reactions(
    props: MassProperties, alpha: float = 0.0, beta: float = math.pi / 2, g: float = G_STANDARD
) -> tuple[float, float]:
    """Normal reactions ``N1, N2`` at the two balls, Eqs. (41)-(42), N.

    ``N1 = M g cos(a) d2/(d1+d2) (1 - R/d2 tan(a) cos(b))`` and
    ``N2 = M g cos(a) d1/(d1+d2) (1 + R/d1 tan(a) cos(b))``: the lateral slope component
    ``sin(a) cos(b)`` shifts load towards ball 2. On a level plane they reduce to Eqs. (50)-(51).

    Parameters
    ----------
    props : MassProperties
        The rotor (:func:`mass_properties`).
    alpha, beta : float
        Plate inclination and the direction of rolling on it (rad).
    g : float
        Gravity (m/s²).

    Returns
    -------
    n1, n2 : float
        The normal loads on ball 1 (the collar's side) and ball 2 (N).

    Raises
    ------
    ContactInputError
        A sideways slope so steep that a ball lifts off.

    See Also
    --------
    paper_ball_loads, rolling_torque

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, Materials 15 (2022) 2518, Eqs. (41)-(42).

    Examples
    --------
    On a level plate the symmetric rotor puts half its weight on each ball:

    >>> from rotor import mass_properties, normal_reactions
    >>> n1, n2 = normal_reactions(mass_properties())
    >>> print(f"{n1:.3f} N, {n2:.3f} N")
    4.665 N, 4.665 N
    >>> n1, n2 = normal_reactions(mass_properties(collar_offset="end"))
    >>> print(f"{n1:.3f} N, {n2:.3f} N, sum {n1 + n2:.3f} N")
    5.363 N, 3.968 N, sum 9.331 N
    """
    mg = props.mass * g * math.cos(alpha)
    d = props.d1 + props.d2
    lateral = math.tan(alpha) * math.cos(beta)
    r = props.ball_radius
    n1 = mg * props.d2 / d * (1 - r / props.d2 * lateral)
    n2 = mg * props.d1 / d * (1 + r / props.d1 * lateral)
    if n1 <= 0 or n2 <= 0:
        raise ContactInputError("the slope is so steep sideways that a ball lifts off the plate")
    return n1, n2


def rolling_torque(
    s_r: float, lam: float, props: MassProperties, alpha: float = 0.0,
    beta: float = math.pi / 2, g: float = G_STANDARD,
) -> float:
    """Total rolling-friction torque ``s_r (N1**lam + N2**lam)``, N m.

    Parameters
    ----------
    s_r, lam : float
        Rolling-friction coefficient (``N**(1 - lam) m``) and load exponent of
        ``M_r = s_r N**lam``.
    props : MassProperties
        The rotor (:func:`mass_properties`).
    alpha, beta : float
        Plate inclination and the direction of rolling on it (rad).
    g : float
        Gravity (m/s²).

    Returns
    -------
    float
        The braking torque of both contacts (N m).

    Raises
    ------
    ContactInputError
        A sideways slope so steep that a ball lifts off.

    See Also
    --------
    normal_reactions, angular_acceleration

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, Materials 15 (2022) 2518, Eqs. (43)-(48).

    Examples
    --------
    With the linear law (``lam = 1``) the torque is ``s_r M g``, wherever the collar sits:

    >>> from rotor import mass_properties, rolling_torque
    >>> sym = rolling_torque(1e-5, 1.0, mass_properties())
    >>> end = rolling_torque(1e-5, 1.0, mass_properties(collar_offset="end"))
    >>> print(f"{sym:.3e} N m, {end:.3e} N m")
    9.331e-05 N m, 9.331e-05 N m
    """
    n1, n2 = normal_reactions(props, alpha, beta, g)
    return s_r * (n1**lam + n2**lam)


def angular_acceleration(
    s_r: float, lam: float, alpha: float, beta: float, props: MassProperties,
    g: float = G_STANDARD,
) -> float:
    """Angular acceleration of the rotor in pure rolling, Eqs. (43)/(47)/(48), rad/s^2.

    ``eps = [M g R sin(a) sin(b) - s_r (N1**lam + N2**lam)] / (J + M R^2)``. For the symmetric
    collar (``d1 = d2``) this is Eq. (48); for ``lam = 1`` it is Eq. (49) and does not depend
    on the collar's position.

    Parameters
    ----------
    s_r, lam : float
        Rolling-friction coefficient and load exponent of ``M = s_r N**lam`` (SI).
    alpha, beta : float
        Plate inclination and the direction of rolling on it (rad).
    props : MassProperties
        The rotor (:func:`mass_properties`).
    g : float
        Gravity (m/s²).

    Returns
    -------
    float
        The angular acceleration (rad/s²).

    See Also
    --------
    mass_properties

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Eqs. (43)-(49).

    Examples
    --------
    Without rolling friction the rotor accelerates as ``M g R sin(a) / (J + M R²)``:

    >>> import math
    >>> from rotor import angular_acceleration, mass_properties
    >>> props = mass_properties()
    >>> a = math.radians(1.0)
    >>> eps = angular_acceleration(0.0, 1.0, a, math.pi / 2, props)
    >>> free = props.mass * 9.80665 * props.ball_radius * math.sin(a) / props.rolling_inertia
    >>> print(f"{eps:.4f} {free:.4f} rad/s²")
    5.9889 5.9889 rad/s²
    """
    drive = props.mass * g * props.ball_radius * math.sin(alpha) * math.sin(beta)
    return (drive - rolling_torque(s_r, lam, props, alpha, beta, g)) / props.rolling_inertia


def angular_acceleration_linear(
    s_r: float, alpha: float, beta: float, props: MassProperties, g: float = G_STANDARD
) -> float:
    """Eq. (49), the linear law ``M_r = s_r N``:
    ``eps = M g R cos(a) (tan(a) sin(b) - s_r/R) / (J + M R^2)``."""
    r = props.ball_radius
    return (
        props.mass * g * r * math.cos(alpha) * (math.tan(alpha) * math.sin(beta) - s_r / r)
        / props.rolling_inertia
    )


def tangential_forces(
    s_r: float, lam: float, alpha: float, beta: float, props: MassProperties,
    g: float = G_STANDARD,
) -> tuple[float, float]:
    """Magnitudes of the tangential contact forces ``T_x1, T_x2`` along the motion,
    Eqs. (44)-(45), N.

    From ``M R eps = M g S + T_x`` and ``J eps = -R T_x - M_r``:
    ``|T_x| = (J g S / R^2 + M_r / R) / (1 + J/(M R^2))``, shared as ``d1 T_x1 = d2 T_x2``.
    """
    r = props.ball_radius
    slope = math.sin(alpha) * math.sin(beta)
    m_r = rolling_torque(s_r, lam, props, alpha, beta, g)
    total = (props.axial_inertia * g * slope / r**2 + m_r / r) / (
        1 + props.axial_inertia / (props.mass * r**2)
    )
    d = props.d1 + props.d2
    return total * props.d2 / d, total * props.d1 / d


@dataclass(frozen=True)
class PureRollingCheck:
    """Outcome of Eq. (46): ``T_x1 < mu N1`` and ``T_x2 < mu N2``.

    ``required_mu`` is the smallest sliding-friction coefficient that keeps both contacts
    rolling; ``rolls`` is whether the given ``mu`` exceeds it.
    """

    tangential: tuple[float, float]
    normal: tuple[float, float]
    required_mu: float
    mu: float
    rolls: bool


def pure_rolling_check(
    s_r: float, lam: float, alpha: float, beta: float, props: MassProperties, mu: float,
    g: float = G_STANDARD,
) -> PureRollingCheck:
    """Check the pure-rolling condition, Eq. (46)."""
    if not mu >= 0:
        raise ContactInputError(f"friction coefficient must be >= 0, got {mu!r}")
    t1, t2 = tangential_forces(s_r, lam, alpha, beta, props, g)
    n1, n2 = normal_reactions(props, alpha, beta, g)
    req = max(t1 / n1, t2 / n2)
    return PureRollingCheck((t1, t2), (n1, n2), req, float(mu), bool(req < mu))


def driving_slope_for(
    eps: float, s_r: float, lam: float, props: MassProperties, g: float = G_STANDARD
) -> float:
    """The equivalent slope ``S = sin(a) sin(b)`` that gives acceleration ``eps`` (small-angle
    reactions, ``cos(a) = 1``, no lateral load shift)."""
    torque = rolling_torque(s_r, lam, props, 0.0, math.pi / 2, g)
    s = (props.rolling_inertia * eps + torque) / (props.mass * g * props.ball_radius)
    if not -1 <= s <= 1:
        raise ContactInputError("no slope gives that acceleration")
    return s


def paper_ball_loads(g: float = G_STANDARD) -> dict[str, float]:
    """Normal load per ball of the paper's rotor on a level plate, Eqs. (41)-(42) and
    (50)-(51), N: ``symmetric`` (both balls), ``asymmetric_ball1`` (the collar's side) and
    ``asymmetric_ball2``.

    Parameters
    ----------
    g : float
        Gravity (m/s²).

    Returns
    -------
    dict of str to float
        The three loads (N).

    See Also
    --------
    normal_reactions

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, Materials 15 (2022) 2518, Eqs. (50)-(51).

    Examples
    --------
    >>> from rotor import paper_ball_loads
    >>> {name: round(n, 2) for name, n in paper_ball_loads().items()}
    {'symmetric': 4.67, 'asymmetric_ball1': 5.36, 'asymmetric_ball2': 3.97}
    """
    sym = normal_reactions(mass_properties(paper_rotor(), "symmetric"), g=g)
    asym = normal_reactions(mass_properties(paper_rotor(), "end"), g=g)
    return {"symmetric": sym[0], "asymmetric_ball1": asym[0], "asymmetric_ball2": asym[1]}
