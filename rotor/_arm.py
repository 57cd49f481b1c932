"""The friction arm and its physical bound: the argument that decides the paper's question.

A rolling torque ``M_r`` at a contact is the normal force ``N`` acting ahead of the contact
centre by the friction arm ``s_r = M_r / N`` (Alaci et al. 2022, Fig. 3: "the eccentric
force N can be replaced by a normal force N passing through the center of the body and a
moment M_r = s_r N"). The resultant of a pressure distribution lies inside the contact, so

    s_r <= a,

``a`` the contact radius. On the rotor (Eqs. 43, 47-49) the two contacts' torques add up to

    T(theta) = M g R sin(theta) - eps_mean (J + M R^2),

so at ``lambda = 1`` the arm is ``s_r = T / sum N`` (``sum N`` the ball loads of a rotor,
equal for both collar positions). With ``M_r = s N**lambda`` the offset of group A over
group B is ``s (sum_B N**lambda - sum_A N**lambda) / (J + M R^2)`` with
``s = 2 T / (sum_A N**lambda + sum_B N**lambda)``:

    offset = T c(lambda) / (J + M R^2),
    c(lambda) = 2 (sum_B N**lambda - sum_A N**lambda) / (sum_A N**lambda + sum_B N**lambda),

the torque times a load contrast that vanishes at ``lambda = 1``. Hence:

* the arm the mean acceleration implies at the slope used, ``s_r = T(theta) / sum N``;
* the largest torque the bound allows, ``T_max = a sum N``, at the slope
  ``sin(theta_a) = (a sum N + eps_mean (J + M R^2)) / (M g R)``;
* the least ``lambda`` the offset needs there, ``c(lambda) = offset (J + M R^2) / T_max``:
  a smaller arm (a smaller slope) needs a larger ``lambda``, and ``lambda -> inf`` as the
  torque vanishes (at the slope where ``M g R sin(theta) = eps_mean (J + M R^2)``), so the
  value is a lower bound on ``lambda``, conditional on the slope, not a confidence interval;
* the torque ``lambda = 4/3`` (every Hertzian mechanism) needs to make the offset,
  ``T = offset (J + M R^2) / c(4/3)``, as an arm and as a slope.

The contact radius is Hertz's, ``a = (3 N R / (4 E*))**(1/3)``, at the ball load of the rig's
most nearly symmetric group (the paper's materials, steel on aluminium, unless ``e_star`` or the
rig's own ``e_star``, its plate's, is given). Roughness shrinks the real contact area (the
asperities carry the load on a fraction of it) but spreads the region the load acts over: on
the bundled scans the rough contact's extent a* at the symmetric load is about 2.6-2.9 times
the Hertz radius (``surfmet rotor --plate --ball`` states it beside this one). With scans the
larger radius is the bound; without them Hertz's is a bound of the smooth pair only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact._errors import ContactInputError
from contact._hertz import hertz_sphere
from contact._materials import Material, composite_modulus, material
from rotor._mechanics import G_STANDARD
from rotor._rig import Rig, slope_lower_bound, solve_lambda

__all__ = ["ArmBound", "arm_bound", "load_contrast", "rolling_torque", "torque_slope"]

LAMBDA_HERTZ = 4.0 / 3.0
"""The exponent of every Hertzian rolling-friction mechanism (Alaci et al. 2022, Eq. 7)."""
PAPER_PAIR = ("steel", "aluminium")
"""The paper's ball and plate materials (Section 2.2.1, Section 3.2.1)."""


def paper_materials() -> tuple[Material, Material]:
    """The paper's ball and plate (:data:`PAPER_PAIR`) as the material table's entries."""
    return material(PAPER_PAIR[0]), material(PAPER_PAIR[1])


def rolling_torque(rig: Rig, slope: float, mean_acceleration: float,
                   g: float = G_STANDARD) -> float:
    """Both contacts' rolling torque (N m) at ``slope`` (rad) for the mean acceleration:
    ``M g R sin(theta) - eps_mean (J + M R^2)`` (Eqs. 43, 47)."""
    return rig.mass * g * rig.ball_radius * math.sin(slope) - mean_acceleration * \
        rig.rolling_inertia


def torque_slope(rig: Rig, torque: float, mean_acceleration: float,
                 g: float = G_STANDARD) -> float:
    """The slope (rad) at which the rolling torque is ``torque`` (N m); NaN beyond 90 deg."""
    s = (torque + mean_acceleration * rig.rolling_inertia) / (rig.mass * g * rig.ball_radius)
    return math.asin(s) if 0.0 <= s <= 1.0 else math.nan


def _load_sums(rig: Rig, minuend: str, subtrahend: str, lam: float) -> tuple[float, float]:
    return (sum(n**lam for n in rig.group(minuend).ball_loads),
            sum(n**lam for n in rig.group(subtrahend).ball_loads))


def load_contrast(rig: Rig, minuend: str, subtrahend: str, lam: float) -> float:
    """``c(lambda) = 2 (sum_B N**lambda - sum_A N**lambda) / (sum_A + sum_B)``: the offset of
    ``minuend`` (A) over ``subtrahend`` (B) per unit torque, times ``J + M R^2``."""
    sa, sb = _load_sums(rig, minuend, subtrahend, lam)
    return 2.0 * (sb - sa) / (sa + sb)


@dataclass(frozen=True)
class ArmBound:
    """The arm argument (SI: m, rad, N, Pa).

    ``friction_arm``: ``s_r = M_r / N`` at ``lambda = 1`` at ``slope``; ``arm_bound``: the
    Hertz radius at ``bound_load`` (group ``bound_group``'s ball load, ``e_star``), said by
    ``bound_basis``; ``slope_at_bound``: where the arm equals the bound; ``lambda_at_bound``
    (``lambda_low``, ``lambda_high`` over the offset's interval): the least ``lambda`` the
    offset needs; ``slope_lambda_infinite``: the slope at which the torque, and so every
    finite ``lambda``'s offset, vanishes; ``arm_4_3``/``slope_4_3``: the arm and slope at
    which ``lambda = 4/3`` makes the offset (``*_low``/``*_high``: at the interval's ends
    nearer and farther from zero; NaN where no slope does).

    See Also
    --------
    arm_bound : builds it.

    Examples
    --------
    The Hertz radius of a 20 mm steel ball on aluminium under 4.67 N, about 0.11 mm (the
    paper's check: 136 µm at 10 N, times ``(4.67/10)**(1/3)``):

    >>> import math
    >>> from rotor import arm_bound, paper_rig
    >>> arm = arm_bound(paper_rig(), "as", "s", math.radians(1.0), 2.0, -0.05, -0.08, -0.02)
    >>> print(arm.bound_group, f"{arm.bound_load:.2f} N, a = {arm.arm_bound * 1e3:.3f} mm,"
    ...       f" E* = {arm.e_star / 1e9:.1f} GPa")
    s 4.67 N, a = 0.106 mm, E* = 58.6 GPa
    """

    friction_arm: float
    slope: float
    arm_bound: float
    bound_load: float
    bound_group: str
    e_star: float
    bound_basis: str
    slope_at_bound: float
    lambda_at_bound: float
    lambda_low: float
    lambda_high: float
    slope_lambda_infinite: float
    arm_4_3: float
    arm_4_3_low: float
    arm_4_3_high: float
    slope_4_3: float
    slope_4_3_low: float
    slope_4_3_high: float

    @property
    def arm_ratio(self) -> float:
        """``s_r / a``: above 1 the slope used is impossible at ``lambda = 1``."""
        return self.friction_arm / self.arm_bound


def _bound_group(rig: Rig) -> tuple[str, float]:
    """The most nearly symmetric group and its mean ball load (N)."""
    g = min(rig.groups, key=lambda g: abs(g.ball_loads[0] - g.ball_loads[1]) / sum(g.ball_loads))
    return g.name, 0.5 * sum(g.ball_loads)


def arm_bound(rig: Rig, minuend: str, subtrahend: str, slope: float,
              mean_acceleration: float, offset: float, ci_low: float, ci_high: float,
              e_star: float | None = None, radius: float | None = None,
              radius_basis: str = "") -> ArmBound:
    """The arm argument for an offset ``minuend - subtrahend`` of ``offset`` (rad/s²; its
    interval ``ci_low``-``ci_high``) at ``slope`` (rad) and ``mean_acceleration``.

    The bound is Hertz's radius at the symmetric group's ball load unless ``radius`` (m)
    is given: another measure of the region that carries the load (the rough contact's
    extent, said by ``radius_basis``).

    Parameters
    ----------
    rig : Rig
        The rotor and its groups.
    minuend, subtrahend : str
        The groups' names.
    slope : float
        The track's slope (rad) at which the friction arm is stated.
    mean_acceleration : float
        The launches' mean angular acceleration (rad/s²).
    offset, ci_low, ci_high : float
        The offset and its interval (rad/s²).
    e_star : float, optional
        Composite modulus (Pa); default the rig's (its ``e_star``, else its
        ``materials``'), else steel on aluminium.
    radius : float, optional
        A contact radius (m) to use instead of Hertz's.
    radius_basis : str
        What ``radius`` is, in words.

    Returns
    -------
    ArmBound
        The friction arm, the bound on it and the least ``lambda`` the offset needs.

    Raises
    ------
    ContactInputError
        A ``radius`` that is not a positive length, or a group the rig does not have.

    See Also
    --------
    solve_lambda : the exponent an offset needs at a given slope.
    judge_table : states the arm argument for a table.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 4
       (the Hertz radius).

    Examples
    --------
    An offset of -0.05 rad/s² (the asymmetric group slower) at a 1° slope: the friction arm
    ``M_r / N`` (0.23 mm) exceeds the Hertz radius (0.11 mm) that bounds it, so the slope
    must be smaller, and there the offset needs ``lambda`` of about 2:

    >>> import math
    >>> from rotor import arm_bound, paper_rig
    >>> arm = arm_bound(paper_rig(), "as", "s", math.radians(1.0), 2.0, -0.05, -0.08, -0.02)
    >>> print(f"arm {arm.friction_arm * 1e3:.2f} mm, bound {arm.arm_bound * 1e3:.2f} mm")
    arm 0.23 mm, bound 0.11 mm
    >>> print(f"slope at bound {math.degrees(arm.slope_at_bound):.2f} deg,"
    ...       f" lambda >= {arm.lambda_at_bound:.1f}")
    slope at bound 0.64 deg, lambda >= 2.2
    """
    basis = "given E*"
    if e_star is None and rig.e_star is not None:
        e_star, basis = rig.e_star, f"the rig's {rig.plate or 'plate'}"
    if e_star is None and rig.materials is not None:
        e_star = composite_modulus(material(rig.materials[0]), material(rig.materials[1]))
        basis = f"the rig's {rig.materials[0]} on {rig.materials[1]}"
    if e_star is None:
        e_star = composite_modulus(*paper_materials())
        basis = "steel ball on aluminium plate, the paper's materials"
    name, load = _bound_group(rig)
    if radius is not None:
        if not (math.isfinite(radius) and radius > 0):
            raise ContactInputError(f"the arm bound's radius must be a positive length, got "
                                  f"{radius!r} m")
        a, basis = float(radius), (radius_basis or "a given contact radius") + (
            "; the resultant of the contact pressure lies inside the contact")
    else:
        a = hertz_sphere(rig.ball_radius, load, e_star).a
        basis = (f"Hertz contact radius (3 N R / (4 E*))^(1/3) at group {name}'s ball load "
                 f"{load:.3g} N, R = {rig.ball_radius * 1e3:.3g} mm, E* = "
                 f"{e_star / 1e9:.3g} GPa ({basis}); the resultant of the contact pressure "
                 "lies inside the contact")
    sum_n = 0.5 * sum(_load_sums(rig, minuend, subtrahend, 1.0))
    arm = rolling_torque(rig, slope, mean_acceleration) / sum_n
    slope_a = torque_slope(rig, a * sum_n, mean_acceleration)
    args = (rig, minuend, subtrahend, slope_a, mean_acceleration)
    lam = [solve_lambda(v, *args) if math.isfinite(slope_a) else math.nan
           for v in (offset, ci_low, ci_high)]
    lo, hi = (min(lam[1:]), max(lam[1:])) if not any(map(math.isnan, lam[1:])) else (
        math.nan, math.nan)
    c43 = load_contrast(rig, minuend, subtrahend, LAMBDA_HERTZ)
    near, far = sorted((ci_low, ci_high), key=abs)
    arms, slopes = [], []
    for v in (offset, near, far):
        torque = v * rig.rolling_inertia / c43 if c43 else math.nan
        ok = math.isfinite(torque) and torque > 0
        arms.append(torque / sum_n if ok else math.nan)
        slopes.append(torque_slope(rig, torque, mean_acceleration) if ok else math.nan)
    return ArmBound(arm, slope, a, load, name, e_star, basis, slope_a, lam[0], lo, hi,
                    slope_lower_bound(rig, mean_acceleration), *arms, *slopes)
