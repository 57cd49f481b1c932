"""A budget of the causes besides ``M_r(N)`` that could make two groups of one rotor accelerate
differently: each as the equivalent angular acceleration (rad/s²) it can make, with its
formula, its assumption and its source, beside the measured group offset.

Every torque ``T`` about the contact line is an acceleration ``T / (J + M R^2)`` (Alaci et al.
2022, Eq. 43); the driving one is ``eps_drive = M g R sin(theta) / (J + M R^2)``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from contact._hertz import hertz_sphere
from contact._material_pair import resolve_pair
from contact._materials import Material, material
from rotor._arm import PAPER_PAIR
from rotor._mechanics import G_STANDARD
from rotor._rig import Rig, offset_for_lambda

__all__ = ["Confound", "CreepModuli", "confound_budget", "creep_moduli"]

DIRECTION_ERROR = math.radians(1.0)
UNBALANCE = 17.5e-6
LATERAL_CREEP = 1e-3
RUN_IN_FRACTION = 0.1
AIR_DENSITY = 1.2
DRAG_COEFFICIENT = 1.0
KALKER_C22 = 3.67
FRICTION = 0.3
#: Poisson's ratio of the shear modulus G = (1 - nu) E* taken for a rig that states its E*
#: but not its materials (two bodies of one material: E* = E / (2 (1 - nu^2)),
#: G = E / (2 (1 + nu)); the paper's steel on aluminium has G / E* = 0.68).
RIG_POISSON = 0.3


@dataclass(frozen=True)
class CreepModuli:
    """The lateral creep's moduli: ``e_star`` (Pa) for the Hertz radius, ``shear`` the
    combined shear modulus G (Pa), and ``basis``, where they came from, in words."""

    e_star: float
    shear: float
    basis: str


@dataclass(frozen=True)
class Confound:
    """One cause: ``equivalent_acceleration`` (rad/s²) it can make between the groups under
    ``assumption``; ``can_explain``: whether that reaches the measured offset; ``moduli``:
    the lateral creep's elastic constants and where they came from (None for the others)."""

    name: str
    equivalent_acceleration: float
    can_explain: bool
    formula: str
    assumption: str
    source: str
    moduli: CreepModuli | None = None


def creep_moduli(rig: Rig, materials: tuple[Material, Material] | None = None) -> CreepModuli:
    """The moduli of the lateral creep: the ``materials`` given (ball, plate); else the
    rig's own (its ``materials``, its ``e_star`` for E* where it states one); else, where
    the rig states only ``e_star``, that E* with G = (1 - :data:`RIG_POISSON`) E*; else the
    paper's steel on aluminium. G is Kalker's ``2 / (1/G1 + 1/G2)``."""
    if materials is None and rig.materials is not None:
        materials = (material(rig.materials[0]), material(rig.materials[1]))
        e_star = rig.e_star
        where = "the rig's materials" + (", its stated E*" if e_star is not None else "")
    elif materials is None and rig.e_star is not None:
        e_star = float(rig.e_star)
        return CreepModuli(e_star, (1.0 - RIG_POISSON) * e_star,
                           f"the rig's E* ({rig.plate or 'its plate'}), G = (1 - "
                           f"{RIG_POISSON:g}) E* (no materials stated)")
    elif materials is None:
        materials = (material(PAPER_PAIR[0]), material(PAPER_PAIR[1]))
        e_star, where = None, "the paper's pair: the rig states no E* or materials"
    else:
        e_star, where = None, "the materials given"
    pair = resolve_pair(*materials)
    g1, g2 = pair.shear_moduli
    e_star = pair.e_star if e_star is None else float(e_star)
    return CreepModuli(e_star, 2.0 / (1.0 / g1 + 1.0 / g2),
                       f"{materials[0].name} on {materials[1].name} ({where})")


def lateral_creep(rig: Rig, materials: tuple[Material, Material] | None = None) -> float:
    """Torque (N m) of lateral creep of both balls at yaw ``LATERAL_CREEP``: the creep force
    ``min(G a² C22 nu, mu N)`` times the lateral slip ``nu`` per unit rolled, times ``R``;
    ``G`` the pair's combined shear modulus and ``a`` the Hertz radius of the ball on the
    plate, both from :func:`creep_moduli` (the ``materials`` given, else the rig's)."""
    moduli = creep_moduli(rig, materials)
    torque = 0.0
    for load in rig.groups[0].ball_loads:
        a = hertz_sphere(rig.ball_radius, load, moduli.e_star).a
        force = min(moduli.shear * a * a * KALKER_C22 * LATERAL_CREEP, FRICTION * load)
        torque += force * LATERAL_CREEP * rig.ball_radius
    return torque


def confound_budget(rig: Rig, offset: float, smallest: float, slope: float,
                    mean_acceleration: float, track_range: float, span: float,
                    minuend: str, subtrahend: str,
                    mechanisms: Mapping[str, float] | None = None, *,
                    materials: tuple[Material, Material] | None = None,
                    ) -> tuple[Confound, ...]:
    """The budget for an offset ``offset`` whose smallest size the data allow is ``smallest``
    (rad/s²), on a track of ``span`` rad whose shared profile ranges over ``track_range``
    rad/s², at ``slope`` (rad). ``mechanisms``: ``{name: implied offset}`` (rad/s²) of contact
    mechanisms computed elsewhere (``surfmet rolling --model all``); ``materials``: the
    (ball, plate) materials of the lateral creep (default the rig's own E* and materials
    where it states them, else the paper's pair: :func:`creep_moduli`)."""
    i_roll = rig.rolling_inertia
    mgr = rig.mass * G_STANDARD * rig.ball_radius
    eps_drive = mgr * math.sin(slope) / i_roll
    torque = mgr * math.sin(slope) - mean_acceleration * i_roll
    speed = math.sqrt(2.0 * max(mean_acceleration, 0.0) * span) * rig.ball_radius
    area = 2 * math.pi * rig.ball_radius**2
    drag = 0.5 * AIR_DENSITY * DRAG_COEFFICIENT * area * speed**2 * rig.ball_radius / i_roll
    unbalance = 0.4 * rig.mass * G_STANDARD * UNBALANCE / i_roll * 2.0 / max(span, 1e-9)
    moduli = creep_moduli(rig, materials)
    lam43 = abs(offset_for_lambda(4 / 3, rig, minuend, subtrahend, slope, mean_acceleration))
    rows = [
        ("launch_direction", eps_drive * (1 - math.cos(DIRECTION_ERROR)),
         "eps_drive (1 - cos d_beta), eps_drive = M g R sin(theta)/(J + M R^2)",
         f"launch {math.degrees(DIRECTION_ERROR):g} deg off the line of greatest slope",
         "Alaci et al. 2022, Eq. 49 (the sin(beta) of the driving term)"),
        ("plate_flatness", track_range,
         "range of the shared track's acceleration profile along the span rolled",
         "the groups ran on lanes as different as the track's own profile",
         "this table's joint model (rotor._track)"),
        ("collar_unbalance", unbalance,
         "2 A / span, A = m_c g e / (J + M R^2): the largest mean of A sin(phi + psi)",
         f"collar mass 0.4 M off the axis by e = {UNBALANCE * 1e6:g} um (half the largest "
         "clearance of an H7/g6 fit on a 12 mm rod)", "ISO 286-2 (fit tolerances)"),
        ("run_in", RUN_IN_FRACTION * max(torque, 0.0) / i_roll,
         "f M_r / (J + M R^2), M_r = M g R sin(theta) - eps_mean (J + M R^2)",
         f"the rolling torque changed by f = {RUN_IN_FRACTION:.0%} between the groups' runs "
         "(plastic shakedown of the track)", "Johnson 1985, Contact Mechanics, sec. 9.3"),
        ("lateral_creep", lateral_creep(rig, materials) / i_roll,
         "sum_balls min(G a^2 C22 nu, mu N) nu R / (J + M R^2)",
         f"axle yawed nu = {LATERAL_CREEP:g} rad (1 mm per m), E* = "
         f"{moduli.e_star / 1e9:.3g} GPa and G = {moduli.shear / 1e9:.3g} GPa from "
         f"{moduli.basis}, C22 = {KALKER_C22}, mu = {FRICTION}",
         "Kalker 1990, Table E.3; Hertz radius"),
        ("air_drag", drag,
         "rho C_d A v^2 R / (2 (J + M R^2)) at the end of the track",
         f"C_d = {DRAG_COEFFICIENT:g}, A = two ball sections, v = {speed:.2g} m/s; the same "
         "for both collar positions, so its difference is zero",
         "Hoerner 1965, Fluid-Dynamic Drag (sphere C_d ~ 0.5-1)"),
        ("contact_mechanisms_lambda_4_3", lam43,
         "s_r (sum_B N^(4/3) - sum_A N^(4/3)) / (J + M R^2) with the whole torque M_r",
         "every Hertzian mechanism (elastic hysteresis, micro-slip, Cherepanov's law) has "
         "lambda = 4/3; none can exceed the whole rolling torque",
         "Cherepanov 2015; Alaci et al. 2022, Eq. 7"),
    ]
    for name, value in (mechanisms or {}).items():
        rows.append((f"mechanism_{name}", abs(value), "(sum_B M_r(N) - sum_A M_r(N))/(J + M R^2)",
                     "surfmet rolling --model all on the rig's ball loads",
                     "surfmet rolling --model all"))
    return tuple(Confound(n, float(v), bool(v >= smallest and _can_differ(n)), f, a, s,
                          moduli if n == "lateral_creep" else None)
                 for n, v, f, a, s in rows)


def _can_differ(name: str) -> bool:
    """Air drag is the same for both collar positions: it cannot make a difference."""
    return name != "air_drag"
