"""The rig of a rotor table (what the verdict needs to turn an offset into an exponent), and
the exponent ``lambda`` of ``M_r = s_r N**lambda`` an offset between two groups needs.

On a shared track two groups of one rotor (same mass ``M``, inertia ``J``, rolling radius
``R``; only the ball loads differ) accelerate by

    eps_g = [M g R sin(theta) - s_r sum_balls N**lambda] / (J + M R^2)

(Alaci et al. 2022, Eqs. 47-49), so the offset of group A over group B is
``s_r (sum_B N**lambda - sum_A N**lambda) / (J + M R^2)``, zero at ``lambda = 1`` when the
load sums are equal. ``s_r`` follows from the mean torque
``M g R sin(theta) - eps_mean (J + M R^2)``, which needs the slope ``theta``; without it the
slope is bounded below by the mean acceleration (the torque cannot be negative) and the
paper's "slopes smaller than one degree" bound it above.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from scipy.optimize import brentq
from scipy.stats import nct
from scipy.stats import t as student_t

from contact._errors import ContactInputError
from rotor._mechanics import G_STANDARD, mass_properties, normal_reactions
from rotor._paper import FPS, MARK_STEP
from rotor._tables import GROUPS as PAPER_COLLARS

__all__ = ["RIG_KEYS", "Rig", "RigGroup", "launches_needed", "offset_for_lambda", "paper_rig",
           "rig_from_mapping", "slope_lower_bound", "solve_lambda"]

RIG_KEYS = ("ball_radius_m", "mass_kg", "axial_inertia_kg_m2", "fps", "step_deg", "slope_rad",
            "groups", "e_star_Pa", "plate", "materials")
"""The keys of a rig file (:data:`OPTIONAL_KEYS` optional)."""
OPTIONAL_KEYS = ("slope_rad", "e_star_Pa", "plate", "materials")
"""The rig file's optional keys: the slope, the contact's composite modulus (Pa), the plate
in words, and ``[ball, plate]`` names from the material table."""
UPPER_SLOPE = math.radians(1.0)
"""Slope assumed when none is given: the paper's "tilting angle smaller than one degree"."""
LAMBDA_RANGE = (0.05, 20.0)


@dataclass(frozen=True)
class RigGroup:
    """A group of launches: its ball loads (N) and the table columns it ran.

    Parameters
    ----------
    name : str
        The group's name (``"as"``, ``"s"`` for the paper's collars).
    ball_loads : tuple of float
        Normal loads on the two balls (N).
    columns : tuple of str
        The frame-table columns (launches) of this group.

    See Also
    --------
    Rig, paper_rig

    Examples
    --------
    >>> from rotor import paper_rig
    >>> group = paper_rig().group("as")
    >>> print(group.columns, [round(n, 3) for n in group.ball_loads])
    ('as1', 'as2', 'as3') [5.363, 3.968]
    """

    name: str
    ball_loads: tuple[float, float]
    columns: tuple[str, ...]


@dataclass(frozen=True)
class Rig:
    """The rotor and camera (SI): ``ball_radius`` (m), ``mass`` (kg), ``axial_inertia``
    (kg m²), ``fps`` (1/s), ``step`` (rad between marks), ``slope`` (rad, or None);
    ``e_star``: the ball-plate contact's composite modulus (Pa) that sets the friction arm's
    Hertz bound (:mod:`rotor._arm`) and the lateral creep's Hertz radius
    (:mod:`rotor._confounds`), None for the paper's steel on aluminium (or ``materials``');
    ``plate``: what it is, in words; ``materials``: (ball, plate) names in the material
    table (:mod:`contact._materials`), None where the rig does not state them.

    Parameters
    ----------
    ball_radius, mass, axial_inertia : float
        Rolling radius ``R`` (m), mass ``M`` (kg) and axial moment of inertia ``J``
        (kg m²) of the rotor.
    fps, step : float
        Camera frame rate (1/s) and the angle between marks (rad).
    slope : float or None
        The plate's slope along the track (rad), None when unknown.
    groups : tuple of RigGroup
        The two groups of launches.
    e_star : float, optional
        Composite modulus of the ball-plate contact (Pa).
    plate : str, optional
        The plate, in words.
    materials : (str, str), optional
        The ball's and the plate's materials (names in the material table).

    See Also
    --------
    paper_rig : the paper's rig.
    rig_from_mapping : a rig from a rig file's keys.
    solve_lambda : the exponent an offset between the groups needs.

    Examples
    --------
    >>> from rotor import paper_rig
    >>> rig = paper_rig()
    >>> print(f"M = {rig.mass:.3f} kg, J + M R² = {rig.rolling_inertia:.3e} kg m²")
    M = 0.951 kg, J + M R² = 5.438e-04 kg m²
    """

    ball_radius: float
    mass: float
    axial_inertia: float
    fps: float
    step: float
    slope: float | None
    groups: tuple[RigGroup, ...]
    e_star: float | None = None
    plate: str = ""
    materials: tuple[str, str] | None = None

    @property
    def rolling_inertia(self) -> float:
        """``J + M R²`` (kg m²): divides every torque in the equation of motion."""
        return self.axial_inertia + self.mass * self.ball_radius**2

    def group(self, name: str) -> RigGroup:
        for g in self.groups:
            if g.name == name:
                return g
        raise ContactInputError(f"the rig has no group {name!r}")


def _positive(d: Mapping, key: str) -> float:
    v = d.get(key)
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
        raise ContactInputError(f"rig: {key} must be a positive number (SI), got {v!r}")
    return float(v)


def rig_from_mapping(d: Mapping) -> Rig:
    """A :class:`Rig` from the keys of a rig file (:data:`RIG_KEYS`), checked.

    Parameters
    ----------
    d : Mapping
        ``ball_radius_m``, ``mass_kg``, ``axial_inertia_kg_m2``, ``fps``, ``step_deg``,
        optionally ``slope_rad``, ``e_star_Pa`` (the contact's E*), ``plate`` (words) and
        ``materials`` (``[ball, plate]`` in the material table), and ``groups``: exactly two
        entries ``{name: {"ball_loads_N": [N1, N2], "columns": [...]}}``, each with at least
        two columns.

    Returns
    -------
    Rig
        SI throughout (``step`` in rad).

    Raises
    ------
    ContactInputError
        Unknown or missing keys, a value that is not a positive number, a slope not below
        pi/2, or groups that are not two groups of at least two launches.

    See Also
    --------
    paper_rig

    Examples
    --------
    >>> from rotor import rig_from_mapping
    >>> rig = rig_from_mapping({
    ...     "ball_radius_m": 0.02, "mass_kg": 0.95, "axial_inertia_kg_m2": 1.6e-4,
    ...     "fps": 240, "step_deg": 45, "slope_rad": 0.01,
    ...     "groups": {"light": {"ball_loads_N": [4.0, 4.0], "columns": ["l1", "l2"]},
    ...                "heavy": {"ball_loads_N": [5.0, 4.5], "columns": ["h1", "h2"]}}})
    >>> print(f"{rig.step:.4f} rad", [g.name for g in rig.groups])
    0.7854 rad ['light', 'heavy']
    >>> rig_from_mapping({"fps": 120})
    Traceback (most recent call last):
    ...
    contact._errors.ContactInputError: rig: unknown keys [] / missing keys [...]...
    """
    if not isinstance(d, Mapping):
        raise ContactInputError("rig: the file must hold one JSON object")
    unknown = sorted(set(d) - set(RIG_KEYS))
    missing = sorted(set(RIG_KEYS) - set(OPTIONAL_KEYS) - set(d))
    if unknown or missing:
        raise ContactInputError(f"rig: unknown keys {unknown} / missing keys {missing}; a rig "
                                f"file holds exactly {', '.join(RIG_KEYS)} "
                                f"({', '.join(OPTIONAL_KEYS)} optional)")
    slope = None
    if d.get("slope_rad") is not None:
        slope = _positive(d, "slope_rad")
        if slope >= math.pi / 2:
            raise ContactInputError(f"rig: slope_rad {slope!r} is not below pi/2")
    groups = d["groups"]
    if not isinstance(groups, Mapping) or len(groups) != 2:
        raise ContactInputError("rig: groups must name exactly two groups, {NAME: {ball_loads_N:"
                                " [N1, N2], columns: [...]}}")
    out = []
    for name, g in groups.items():
        loads = g.get("ball_loads_N") if isinstance(g, Mapping) else None
        cols = g.get("columns") if isinstance(g, Mapping) else None
        if (not isinstance(loads, list) or len(loads) != 2 or not all(
                isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
                and x > 0 for x in loads)):
            raise ContactInputError(f"rig: group {name!r}: ball_loads_N must be two loads > 0 "
                                    f"(N), got {loads!r}")
        if not isinstance(cols, list) or not all(isinstance(c, str) for c in cols):
            raise ContactInputError(f"rig: group {name!r}: columns must be a list of names")
        if len(cols) < 2:
            raise ContactInputError(f"rig: group {name!r} has {len(cols)} launch; the verdict "
                                    f"needs at least 2 per group")
        out.append(RigGroup(str(name), (float(loads[0]), float(loads[1])), tuple(cols)))
    e_star = None if d.get("e_star_Pa") is None else _positive(d, "e_star_Pa")
    plate = d.get("plate") or ""
    if not isinstance(plate, str):
        raise ContactInputError(f"rig: plate must be words, got {plate!r}")
    return Rig(_positive(d, "ball_radius_m"), _positive(d, "mass_kg"),
               _positive(d, "axial_inertia_kg_m2"), _positive(d, "fps"),
               math.radians(_positive(d, "step_deg")), slope, tuple(out), e_star=e_star,
               plate=plate, materials=_materials(d.get("materials")))


def _materials(names: object) -> tuple[str, str] | None:
    """The rig file's ``materials``, ``[ball, plate]`` in the material table, checked."""
    if names is None:
        return None
    from contact._materials import material

    if not isinstance(names, list) or len(names) != 2 or not all(
            isinstance(n, str) for n in names):
        raise ContactInputError(f"rig: materials must be [ball, plate] names, got {names!r}")
    for n in names:
        material(n)  # an unknown name is refused here, with the table's names
    return str(names[0]), str(names[1])


def paper_rig() -> Rig:
    """The paper's rotor (:mod:`rotor._mechanics`), camera and Table 3's groups.

    Returns
    -------
    Rig
        The symmetric rotor's mass and inertia (the collar's position changes neither),
        120 frames/s, a mark every quarter turn, no stated slope, and the groups ``as``
        (collar against ball 1) and ``s`` (collar centred) with their ball loads on a
        level plate.

    See Also
    --------
    mass_properties, normal_reactions, judge_table

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    >>> from rotor import paper_rig
    >>> rig = paper_rig()
    >>> print(rig.fps, f"{rig.ball_radius * 1e3:.0f} mm", [g.name for g in rig.groups])
    120.0 20 mm ['as', 's']
    >>> [round(sum(g.ball_loads), 3) for g in rig.groups]
    [9.331, 9.331]
    """
    groups = []
    for name, collar in PAPER_COLLARS.items():
        loads = normal_reactions(mass_properties(collar_offset=collar))
        groups.append(RigGroup(name, loads, tuple(f"{name}{i}" for i in (1, 2, 3))))
    p = mass_properties(collar_offset="symmetric")
    return Rig(p.ball_radius, p.mass, p.axial_inertia, FPS, MARK_STEP, None, tuple(groups))


def slope_lower_bound(rig: Rig, mean_acceleration: float, g: float = G_STANDARD) -> float:
    """Smallest slope (rad) that gives the mean acceleration with no rolling friction."""
    s = mean_acceleration * rig.rolling_inertia / (rig.mass * g * rig.ball_radius)
    return math.asin(min(max(s, 0.0), 1.0))


def offset_for_lambda(lam: float, rig: Rig, minuend: str, subtrahend: str, slope: float,
                      mean_acceleration: float, g: float = G_STANDARD) -> float:
    """Offset ``eps_minuend - eps_subtrahend`` (rad/s²) that ``M_r = s_r N**lam`` gives on a
    shared track of ``slope`` (rad) at the observed mean acceleration."""
    torque = rig.mass * g * rig.ball_radius * math.sin(slope) - mean_acceleration * \
        rig.rolling_inertia
    sa = sum(n**lam for n in rig.group(minuend).ball_loads)
    sb = sum(n**lam for n in rig.group(subtrahend).ball_loads)
    s_r = 2.0 * torque / (sa + sb)
    return s_r * (sb - sa) / rig.rolling_inertia


def solve_lambda(offset: float, rig: Rig, minuend: str, subtrahend: str, slope: float,
                 mean_acceleration: float) -> float:
    """The ``lambda`` whose offset is ``offset`` (NaN where none in 0.05-20 gives it).

    Parameters
    ----------
    offset : float
        The observed ``eps_minuend - eps_subtrahend`` (rad/s²).
    rig : Rig
        The rotor and its groups.
    minuend, subtrahend : str
        The groups' names.
    slope : float
        The track's slope (rad).
    mean_acceleration : float
        The launches' mean angular acceleration (rad/s²), which sets ``s_r``.

    Returns
    -------
    float
        The exponent of ``M_r = s_r N**lambda`` that gives ``offset`` (the first root on a
        grid over 0.05-20), or NaN.

    Raises
    ------
    ContactInputError
        A group name the rig does not have.

    See Also
    --------
    arm_bound : the least exponent the contact's size allows.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, Materials 15 (2022) 2518, Eqs. (47)-(49).

    Examples
    --------
    The paper's two collars put the same total load on the balls, so no offset means the
    linear law; the asymmetric rotor lagging by 1 mrad/s² needs ``lambda`` just above 1:

    >>> import math
    >>> from rotor import paper_rig, solve_lambda
    >>> rig = paper_rig()
    >>> for offset in (0.0, -0.001):
    ...     lam = solve_lambda(offset, rig, "as", "s", math.radians(1.0), 2.0)
    ...     print(f"{offset:+.3f} rad/s² -> lambda = {lam:.3f}")
    +0.000 rad/s² -> lambda = 1.000
    -0.001 rad/s² -> lambda = 1.022
    """
    def f(lam: float) -> float:
        return offset_for_lambda(lam, rig, minuend, subtrahend, slope, mean_acceleration) - offset

    lo, hi = LAMBDA_RANGE
    grid = [lo + (hi - lo) * i / 400 for i in range(401)]
    vals = [f(x) for x in grid]
    for a, b, fa, fb in zip(grid, grid[1:], vals, vals[1:]):
        if fa == 0:
            return a
        if fa * fb < 0:
            return float(brentq(f, a, b, xtol=1e-10))
    return math.nan


def launches_needed(effect: float, launch_sd: float, alpha: float = 0.02,
                    power: float = 0.9, most: int = 100000) -> int | None:
    """Launches per group for a two-sided two-sample t test at ``alpha`` to detect
    ``effect`` with ``power`` when launches scatter by ``launch_sd`` (noncentral t)."""
    if not (effect and launch_sd > 0 and math.isfinite(launch_sd)):
        return None
    n = 2
    while n <= most:
        dof = 2 * n - 2
        crit = float(student_t.ppf(1 - alpha / 2, dof))
        nc = abs(effect) / (launch_sd * math.sqrt(2.0 / n))
        if float(nct.sf(crit, dof, nc)) >= power:
            return n
        n = n + 1 if n < 50 else int(n * 1.05) + 1
    return None
