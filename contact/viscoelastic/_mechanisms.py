"""Which mechanism makes a rolling ball's friction: side by side at given ball loads.

For each mechanism the rolling-friction moment M_r(N) is computed over a load sweep (its
exponent lambda with the confidence band and the local exponent) and at the rotor's three
ball loads (N_s on each ball of the symmetric rotor, N_1 and N_2 on the asymmetric one).
For the two-ball rotor of Alaci et al. (2022) rolling on the same slope, the difference
of the angular accelerations is, from its Eq. (47),

    eps_s - eps_a = [M_r(N_1) + M_r(N_2) - 2 M_r(N_s)] / (J + M R^2),

zero for a linear law and positive for a convex one. That difference is about 1 % of
M_r, below the grid noise of one moment, so it is taken from the mechanism's power law
fitted over the sweep (M_r(N_s) (N_i/N_s)^lambda), not from three separate solves.
Mechanisms (all from first
principles except the hysteresis rule's loss fraction):

- ``viscoelastic``: steady rolling on standard linear solids whose loss peak (the loss
  factor eta of :mod:`contact.viscoelastic._loss`) sits at the contact's loading frequency
  V/a at the symmetric load: the largest resistance that eta can give.
- ``hysteresis``: the rule of :mod:`contact._rolling` with alpha_h = 2 pi eta (the specific
  damping capacity psi = 2 pi eta of one load-unload cycle; Lazan 1968), each body's
  eta weighted by its share of the displacement.
- ``plastic``: first-pass plastic work at the softer body's hardness (:mod:`contact._rolling`).
- ``microslip``: frictional dissipation of free rolling between the dissimilar elastic
  bodies (Bentall & Johnson 1967), from a tangential solver passed as ``microslip=``.
- ``adhesion_hysteresis``: the work of adhesion lost between the sealing front and the
  peeling rear of the contact, Delta_w 2a per unit distance (Kendall 1975;
  :mod:`contact.adhesion.rolling`), when ``adhesion=(w, Delta_w)`` is given. Its Delta_w
  is an upper bound, not a measurement, so it is listed but not ranked by
  :meth:`MechanismComparison.dominant`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._errors import ContactInputError

#: Mechanisms whose number is a bound on an unmeasured parameter: listed, not ranked.
BOUNDS_ONLY = ("adhesion_hysteresis",)


@dataclass(frozen=True)
class Mechanism:
    """One mechanism's moments.

    Attributes
    ----------
    name : str
    sweep : contact._rolling.RollingSweep
        Over the load sweep (lambda, band, local exponent).
    rotor_moments : (float, float, float)
        M_r at (N_s, N_1, N_2) (N m).
    delta_eps : float
        Implied eps_s - eps_a (rad/s^2), from M_r(N_s) and the fitted lambda.
    assumption : str
    rotor_loads : (float, float, float)
        (N_s, N_1, N_2) (N).
    """

    name: str
    sweep: Any
    rotor_moments: tuple[float, float, float]
    delta_eps: float
    assumption: str
    rotor_loads: tuple[float, float, float]

    @property
    def torque_symmetric(self) -> float:
        """2 M_r(N_s), the symmetric rotor's rolling torque (N m)."""
        return 2.0 * self.rotor_moments[0]

    @property
    def local_lambda(self) -> float:
        """ln[M(N_2)/M(N_1)] / ln(N_2/N_1) across the rotor's loads (NaN if M = 0)."""
        m1, m2 = self.rotor_moments[1], self.rotor_moments[2]
        n1, n2 = self.rotor_loads[1], self.rotor_loads[2]
        if min(m1, m2) <= 0 or n1 == n2:
            return math.nan
        return math.log(m2 / m1) / math.log(n2 / n1)


@dataclass(frozen=True)
class MechanismComparison:
    """Mechanisms side by side (see the module notes)."""

    mechanisms: tuple[Mechanism, ...]
    rotor_loads: tuple[float, float, float]
    rolling_inertia: float
    assumptions: dict = field(default_factory=dict)

    def dominant(self) -> tuple[str, float]:
        """(name of the largest symmetric-rotor torque, factor over the next one), among
        the mechanisms estimated from their materials (:data:`BOUNDS_ONLY` left out)."""
        ranked = sorted((m for m in self.mechanisms if m.name not in BOUNDS_ONLY),
                        key=lambda m: m.torque_symmetric, reverse=True)
        top = ranked[0].torque_symmetric
        nxt = ranked[1].torque_symmetric if len(ranked) > 1 else 0.0
        return ranked[0].name, (top / nxt if nxt > 0 else math.inf)


def _rotor_eps(moment_s: float, lam: float, loads: Sequence[float], inertia: float) -> float:
    ns, n1, n2 = loads
    if moment_s <= 0 or not math.isfinite(lam):
        return 0.0
    return moment_s * ((n1 / ns) ** lam + (n2 / ns) ** lam - 2.0) / inertia


def _with_rotor(name: str, sweep: Any, at: Callable[[float], float],
                loads: tuple[float, float, float], inertia: float, text: str) -> Mechanism:
    moms = tuple(float(at(n)) for n in loads)
    eps = _rotor_eps(moms[0], sweep.lambda_eff, loads, inertia)
    return Mechanism(name, sweep, moms, eps, text, loads)


def compare_mechanisms(radius: float, ball: Any, plate: Any = None, *,
                       loads: Sequence[float] | np.ndarray,
                       rotor_loads: tuple[float, float, float], rolling_inertia: float,
                       speed: float, loss: tuple[float, float], hardness: float | None = None,
                       grid: int = 128,
                       microslip: Callable[[Sequence[float]], Any] | None = None,
                       adhesion: tuple[float, float] | None = None
                       ) -> MechanismComparison:
    """M_r per mechanism over ``loads`` and at the rotor's ball loads.

    Parameters
    ----------
    radius : float
        Ball radius (m).
    ball, plate : contact._materials.Material
        The bodies; or ``ball`` a resolved :class:`contact._material_pair.MaterialPair` and
        ``plate`` None (the pair's bodies, E*, shares and default hardness).
    loads : sequence of float
        Load sweep for lambda (N).
    rotor_loads : (N_s, N_1, N_2)
        Ball loads of the symmetric rotor and of the asymmetric rotor's two balls (N).
    rolling_inertia : float
        J + M R^2 (kg m^2).
    speed : float
        Rolling speed V (m/s).
    loss : (eta_ball, eta_plate)
        Loss factors.
    hardness : float, optional
        Flow pressure of the softer body (Pa); default the pair's hardness.
    microslip : callable, optional
        loads -> RollingSweep of the micro-slip mechanism (the tangential solver).
    adhesion : (w, Delta_w), optional
        Work of adhesion and its hysteresis (J/m^2): the adhesion-hysteresis mechanism.
    """
    from contact._dissipation import Dissipation
    from contact._geometry import DomainSpec
    from contact._hertz import hertz_sphere
    from contact._material_pair import MaterialPair, resolve_pair
    from contact._rolling import sphere_sweep
    from contact.viscoelastic._loss import sls_from_loss
    from contact.viscoelastic._sweep import viscoelastic_sweep

    if not all(math.isfinite(v) and v > 0 for v in (*loss, speed, rolling_inertia)):
        raise ContactInputError("loss factors, speed and inertia must be positive")
    pair = ball if isinstance(ball, MaterialPair) and plate is None else resolve_pair(ball, plate)
    ball, plate = pair.body1, pair.body2
    if ball is None or plate is None:
        raise ContactInputError("the mechanisms need both bodies' materials")
    hardness = pair.with_hardness(hardness).hardness  # the user's, else the softer body's
    if hardness is None:
        raise ContactInputError("the plastic mechanism needs a hardness")
    e_star = pair.e_star
    a_s = hertz_sphere(radius, rotor_loads[0], e_star).a
    t_peak = a_s / speed
    vb = sls_from_loss(ball.E, ball.nu, loss[0], t_peak)
    vp = sls_from_loss(plate.E, plate.nu, loss[1], t_peak)
    share = pair.shares
    alpha = 2 * math.pi * (share[0] * loss[0] + share[1] * loss[1])
    every = np.unique(np.concatenate((np.asarray(loads, float), rotor_loads)))
    out = []
    ve = viscoelastic_sweep(radius, vb, vp, every, speed, n=grid)
    out.append(_with_rotor("viscoelastic", ve, _lookup(ve), rotor_loads, rolling_inertia,
                           f"SLS loss peaks eta = {loss[0]:g} (ball), {loss[1]:g} (plate) at "
                           f"omega = V/a = {1 / t_peak:.3g} 1/s (upper bound)"))
    hy = sphere_sweep(radius, e_star, every, dissipation=Dissipation(alpha_h=alpha),
                      domain=DomainSpec(grid=grid))
    out.append(_with_rotor("hysteresis", hy, _lookup(hy), rotor_loads, rolling_inertia,
                           f"alpha_h = 2 pi eta (displacement-weighted) = {alpha:.3g}"))
    pl = sphere_sweep(radius, e_star, every,
                      dissipation=Dissipation(model="plastic", hardness=hardness),
                      domain=DomainSpec(grid=grid))
    out.append(_with_rotor("plastic", pl, _lookup(pl), rotor_loads, rolling_inertia,
                           f"first pass, H = {hardness:.3g} Pa"))
    if microslip is not None:
        ms = microslip(every)
        mu = ms.settings.get("mu")
        out.append(_with_rotor("microslip", ms, _lookup(ms), rotor_loads, rolling_inertia,
                               f"tangential solver, free rolling, mu = {mu}"))
    if adhesion is not None:
        out.append(_adhesion_mechanism(radius, e_star, every, adhesion, rotor_loads,
                                       rolling_inertia))
    assumptions = {"speed": speed, "loss_ball": loss[0], "loss_plate": loss[1],
                   "alpha_h": alpha, "hardness": hardness, "peak_time": t_peak,
                   "contact_radius_symmetric": a_s, "grid": grid}
    return MechanismComparison(tuple(out), tuple(float(v) for v in rotor_loads),
                               float(rolling_inertia), assumptions)


def _lookup(sweep: Any) -> Callable[[float], float]:
    loads = np.asarray(sweep.loads, dtype=float)
    moments = np.asarray(sweep.moments, dtype=float)

    def at(n: float) -> float:
        k = int(np.argmin(np.abs(loads - n)))
        if abs(loads[k] - n) > 1e-9 * n:
            raise ContactInputError(f"load {n} N is not in the sweep")
        return float(moments[k])

    return at


def _adhesion_mechanism(radius: float, e_star: float, loads: np.ndarray,
                        adhesion: tuple[float, float], rotor_loads: tuple[float, float, float],
                        inertia: float) -> Mechanism:
    """Adhesion hysteresis over the sweep (:mod:`contact.adhesion.rolling`)."""
    from contact.adhesion.rolling import adhesion_hysteresis_forces
    from contact.viscoelastic._sweep import sweep_record

    w, dw = adhesion
    forces = adhesion_hysteresis_forces(loads, radius, e_star, w, dw)
    sweep = sweep_record("adhesion_hysteresis", loads, forces, radius,
                         {"model": "adhesion_hysteresis", "work_of_adhesion": w,
                          "adhesion_hysteresis": dw})
    return _with_rotor("adhesion_hysteresis", sweep, _lookup(sweep), rotor_loads, inertia,
                       f"Delta_w 2a (Kendall 1975), w = {w:g} J/m^2, Delta_w = {dw:g} J/m^2 "
                       "(an upper bound, smooth pair; not ranked)")
