"""The two-ball rotor of Alaci, Ciornei & Romanu (2022) rolling on a slightly inclined plate.

The rotor is two steel balls (radius ``R``) joined by an aluminium rod, with a steel collar that
slides on the rod: moving the collar moves the centre of mass ``G`` along the axis while the
mass ``M`` and the axial moment of inertia ``J`` stay the same. Rolling without sliding on a
plane of inclination ``alpha``, along a direction at ``beta`` from the plane's horizontal, the
rotor is driven by ``M g sin(alpha) sin(beta)`` and braked by the rolling-friction torques
``M_r = s_r N**lambda`` at the two ball contacts.

What is here (equation numbers of the paper):

* mass properties from the parts, and the collar's ``xi_G(h)`` curve with its optimum (Fig. 9);
* normal reactions, Eqs. (41)-(42); angular acceleration, Eqs. (47)-(49); tangential contact
  forces, Eqs. (44)-(45), and the pure-rolling check, Eq. (46);
* the inverse problem: the ``lambda`` and ``s_r`` that a symmetric and an asymmetric rotor's
  accelerations imply for an assumed equivalent slope ``S = sin(alpha) sin(beta)``.

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
from dataclasses import dataclass, field

import numpy as np

from contact._validate import positive
from contact.errors import ContactInputError

G_STANDARD = 9.80665
"""Standard gravity, m/s^2 (the paper does not print the value it used)."""

__all__ = [
    "G_STANDARD",
    "IDENTIFIABILITY",
    "MassProperties",
    "PureRollingCheck",
    "RollingLawInference",
    "RotorGeometry",
    "angular_acceleration",
    "angular_acceleration_linear",
    "collar_com_offset",
    "driving_slope_for",
    "infer_rolling_law",
    "mass_properties",
    "normal_reactions",
    "optimal_collar_length",
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

    ball_radius: float = 0.02
    ball_density: float = 7800.0
    centre_distance: float = 0.14
    rod_radius: float = 0.006
    rod_density: float = 2700.0
    collar_length: float = 0.05
    collar_outer_radius: float = 0.019
    collar_inner_radius: float = 0.006
    collar_density: float = 7800.0

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


def paper_rotor(collar_length: float = 0.05) -> RotorGeometry:
    """The rotor built in the paper (Section 2.2.2): R = 20 mm steel balls 140 mm apart, a
    6 mm aluminium rod, and a steel collar of radius 19 mm and length ``collar_length``."""
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
    """Total rolling-friction torque ``s_r (N1**lam + N2**lam)``, N m."""
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


# --------------------------------------------------------------------------------------------
# inverse problem
# --------------------------------------------------------------------------------------------

IDENTIFIABILITY = (
    "Two measured accelerations (symmetric and asymmetric collar) give two equations in "
    "three unknowns: the equivalent slope S = sin(alpha) sin(beta), s_r and lambda. The paper "
    "prints neither alpha nor beta, so S is unknown and only a one-parameter family (lambda(S), "
    "s_r(S)) is identified. Without S: (i) lambda = 1 predicts equal accelerations for any S "
    "(Eq. 49), so a significant difference contradicts lambda = 1 only if both rotors ran on the "
    "same S and nothing else differed; (ii) the sign of the difference gives the side of 1 "
    "(asymmetric slower <=> lambda > 1 on the physical branch); (iii) the rolling torque cannot "
    "exceed the driving torque, so S >= (J + M R^2) eps / (M g R), and an upper bound on S (the "
    "paper says below 1 degree) gives a lower bound on |lambda - 1|. s_r can never be separated "
    "from S: at fixed lambda it moves one-for-one with the assumed slope."
)


@dataclass(frozen=True)
class RollingLawInference:
    """``lambda`` and ``s_r`` implied by two accelerations, for each assumed slope.

    Arrays are indexed like ``slope``. ``lam``/``s_r`` are the solutions for the nominal
    accelerations; ``*_low``/``*_high`` the 16th/84th percentiles under the accelerations'
    uncertainties (Monte Carlo); NaN where no solution exists (``feasible`` is False: the
    slope is too small to overcome the resistance, or the measured ratio of torques is out of
    reach of any ``lambda`` on the physical branch ``lambda >= lambda_min``).
    ``lever_arm`` is ``s_r N_s**(lam - 1)``, m: the linear-law coefficient that the fitted law
    gives at the symmetric rotor's ball load ``N_s``.
    """

    slope: np.ndarray
    lam: np.ndarray
    lam_low: np.ndarray
    lam_high: np.ndarray
    s_r: np.ndarray
    s_r_low: np.ndarray
    s_r_high: np.ndarray
    lever_arm: np.ndarray
    torque_sym: np.ndarray
    torque_asym: np.ndarray
    torque_ratio: np.ndarray
    feasible: np.ndarray
    min_slope: float
    lambda_branch_min: float
    note: str = field(default=IDENTIFIABILITY)


def _quantiles(sorted_values: np.ndarray) -> tuple[float, float]:
    """16th and 84th percentiles of sorted samples (which may hold +inf)."""
    n = len(sorted_values)
    return (float(sorted_values[int(0.16 * (n - 1))]), float(sorted_values[int(0.84 * (n - 1))]))


def _ratio(lam: np.ndarray, na: tuple[float, float], ns: tuple[float, float]) -> np.ndarray:
    return (na[0] ** lam + na[1] ** lam) / (ns[0] ** lam + ns[1] ** lam)


def infer_rolling_law(
    eps_sym: float,
    eps_asym: float,
    slope: float | np.ndarray,
    *,
    u_sym: float = 0.0,
    u_asym: float = 0.0,
    props_sym: MassProperties | None = None,
    props_asym: MassProperties | None = None,
    g: float = G_STANDARD,
    n_samples: int = 4000,
    seed: int = 0,
    lam_max: float = 60.0,
) -> RollingLawInference:
    """Solve Eqs. (47)-(48) for ``lambda`` and ``s_r`` given both rotors' accelerations.

    Parameters
    ----------
    eps_sym, eps_asym : float
        Angular accelerations (rad/s^2) of the symmetric and asymmetric rotors, measured on the
        same equivalent slope.
    slope : float or array
        Assumed equivalent slope(s) ``S = sin(alpha) sin(beta)`` (small ``alpha``: cos = 1 and
        no lateral load shift, which changes the loads by ``R/d tan(alpha)`` < 0.5 % below 1°).
    u_sym, u_asym : float
        Standard uncertainties of the accelerations, propagated by Monte Carlo.
    props_sym, props_asym : MassProperties
        Default: the paper's rotor with the collar centred and against a ball.
    lam_max : float
        Upper end of the search for ``lambda``.

    Notes
    -----
    The total rolling torques are ``M_x = M g R S - (J + M R^2) eps_x``. Their ratio
    ``Q = M_a/M_s = (N_a1**lam + N_a2**lam)/(N_s1**lam + N_s2**lam)`` is 1 at ``lam = 0`` and
    ``lam = 1`` and has a single minimum between; the physical branch is the one through 1
    (and the Hertzian 4/3), ``lam >= lam_min``. See :data:`IDENTIFIABILITY`.
    """
    ps = mass_properties(collar_offset="symmetric") if props_sym is None else props_sym
    pa = mass_properties(collar_offset="end") if props_asym is None else props_asym
    for name, val in (("eps_sym", eps_sym), ("eps_asym", eps_asym)):
        if not math.isfinite(val):
            raise ContactInputError(f"{name} must be finite")
    if u_sym < 0 or u_asym < 0:
        raise ContactInputError("uncertainties must be >= 0")
    slopes = np.atleast_1d(np.asarray(slope, dtype=float))
    if np.any(~np.isfinite(slopes)) or np.any(np.abs(slopes) > 1):
        raise ContactInputError("slopes must be finite values of sin(alpha) sin(beta) in [-1, 1]")
    ns = normal_reactions(ps, 0.0, math.pi / 2, g)
    na = normal_reactions(pa, 0.0, math.pi / 2, g)

    # the minimum of Q(lambda) separates the two branches
    grid = np.linspace(0.0, 1.0, 2001)
    lam_min = float(grid[np.argmin(_ratio(grid, na, ns))])
    q_min = float(_ratio(np.array(lam_min), na, ns))
    q_max = float(_ratio(np.array(lam_max), na, ns))

    def solve(q: np.ndarray, clip: bool = False) -> np.ndarray:
        # vectorised bisection on the increasing branch [lam_min, lam_max]
        lo = np.full(q.shape, lam_min)
        hi = np.full(q.shape, lam_max)
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            up = _ratio(mid, na, ns) < q
            lo = np.where(up, mid, lo)
            hi = np.where(up, hi, mid)
        lam = 0.5 * (lo + hi)
        if clip:
            # for the uncertainty band: a ratio below the branch's minimum is best explained
            # by lam_min, one above reach by "lambda beyond lam_max"
            return np.where(q < q_min, lam_min, np.where(q > q_max, np.inf, lam))
        return np.where((q >= q_min) & (q <= q_max), lam, np.nan)

    mgr_s = ps.mass * g * ps.ball_radius
    mgr_a = pa.mass * g * pa.ball_radius
    rng = np.random.default_rng(seed)
    es = eps_sym + u_sym * rng.standard_normal(n_samples)
    ea = eps_asym + u_asym * rng.standard_normal(n_samples)

    out = {k: np.full(slopes.shape, np.nan) for k in (
        "lam", "lam_low", "lam_high", "s_r", "s_r_low", "s_r_high", "lever", "ms", "ma", "q")}
    for i, s in enumerate(slopes):
        m_s = mgr_s * s - ps.rolling_inertia * eps_sym
        m_a = mgr_a * s - pa.rolling_inertia * eps_asym
        out["ms"][i], out["ma"][i] = m_s, m_a
        if m_s <= 0 or m_a <= 0:
            continue
        q = m_a / m_s
        out["q"][i] = q
        lam = float(solve(np.array([q]))[0])
        out["lam"][i] = lam
        if math.isfinite(lam):
            out["s_r"][i] = m_s / (ns[0] ** lam + ns[1] ** lam)
            out["lever"][i] = out["s_r"][i] * ns[0] ** (lam - 1)
        ms_mc = mgr_s * s - ps.rolling_inertia * es
        ma_mc = mgr_a * s - pa.rolling_inertia * ea
        ok = (ms_mc > 0) & (ma_mc > 0)
        if ok.mean() <= 0.5:
            continue
        lam_mc = np.sort(solve(ma_mc[ok] / ms_mc[ok], clip=True))
        finite = np.isfinite(lam_mc)
        sr_mc = np.sort(
            ms_mc[ok][finite] / (ns[0] ** lam_mc[finite] + ns[1] ** lam_mc[finite])
        ) if finite.any() else np.array([np.nan])
        out["lam_low"][i], out["lam_high"][i] = _quantiles(lam_mc)
        out["s_r_low"][i], out["s_r_high"][i] = _quantiles(sr_mc)
    min_slope = max(ps.rolling_inertia * eps_sym / mgr_s, pa.rolling_inertia * eps_asym / mgr_a)
    return RollingLawInference(
        slope=slopes,
        lam=out["lam"],
        lam_low=out["lam_low"],
        lam_high=out["lam_high"],
        s_r=out["s_r"],
        s_r_low=out["s_r_low"],
        s_r_high=out["s_r_high"],
        lever_arm=out["lever"],
        torque_sym=out["ms"],
        torque_asym=out["ma"],
        torque_ratio=out["q"],
        feasible=np.isfinite(out["lam"]),
        min_slope=float(min_slope),
        lambda_branch_min=lam_min,
    )
