"""Viscoelastic rolling at the surfmet layer: option text, the load sweep on scans, and the
side-by-side comparison of rolling-friction mechanisms for the paper's rotor.

Text forms
----------
``--viscoelastic BODY:Eg=..:Er=..:tau=..[:nu=..]``: BODY is ``ball`` or ``plate``; ``Eg``
and ``Er`` are the glassy and relaxed moduli (pressure units), ``tau`` the creep time
tau_c in CONTACT's convention (``s``, ``ms``, ``us``; a bare number is seconds; the
stress-relaxation time is tau_c Er/Eg, :mod:`contact.viscoelastic._rheology`). ``nu``
defaults to the body's material.

The mechanism comparison (:func:`rolling_mechanisms`) uses the rotor of Alaci et al.
(2022) (:mod:`rotor`) for the ball loads and J + M R^2, and Table 3's films for
the measured accelerations: each column fitted with the paper's constant-acceleration
parabola phi = phi0 + omega0 t + eps t^2/2 (frames at 120 /s, a quarter turn a row).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.material_spec import material_constant, poisson_ratio, spec_options

if TYPE_CHECKING:
    from contact._materials import Material
    from contact._rolling import RollingSweep
    from contact.viscoelastic._mechanisms import MechanismComparison
    from rotor import GroupOffset, RotorVerdict
    from surfmet.mechanics._types import Loads, Materials, Progress, ScanSource

_TIME = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "ns": 1e-9}


def _parse_time(text: str) -> float:
    t = text.strip()
    for unit in sorted(_TIME, key=len, reverse=True):
        if t.endswith(unit):
            number, scale = t[: -len(unit)], _TIME[unit]
            break
    else:
        number, scale = t, 1.0
    try:
        return float(number) * scale
    except ValueError:
        raise SurfmetInputError(f"cannot read the time {text!r}: write e.g. 2ms") from None


def parse_viscoelastic(text: str, ball: Material, plate: Material) -> tuple[str, Any]:
    """``BODY:Eg=..:Er=..:tau=..[:nu=..]`` -> (body, StandardLinearSolid).

    Parameters
    ----------
    text : str
        ``BODY:Eg=..:Er=..:tau=..[:nu=..]``, BODY ``ball`` or ``plate``.
    ball, plate : Material
        The elastic bodies (their Poisson's ratio is the default ``nu``).

    Returns
    -------
    (str, StandardLinearSolid)
        The body and its standard linear solid.

    Raises
    ------
    SurfmetInputError
        Unreadable text; contact.ContactInputError for Er > Eg or tau <= 0.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 6.6.

    Examples
    --------
    >>> from contact import material
    >>> from surfmet.mechanics.viscoelastic_rolling import parse_viscoelastic
    >>> parse_viscoelastic("plate:Eg=3GPa:Er=1GPa:tau=1ms", material("steel"), material("pmma"))
    ('plate', StandardLinearSolid(E_g=3000000000.0, E_r=1000000000.0, tau_c=0.001, nu=0.37))
    """
    from contact.viscoelastic import StandardLinearSolid

    body, *opts = [s.strip() for s in str(text).split(":")]
    body = body.lower()
    if body not in ("ball", "plate"):
        raise SurfmetInputError(f"--viscoelastic names the body first: ball or plate, got "
                                f"{body!r}")
    kw: dict[str, float] = {}
    for key, value in spec_options(opts, "viscoelastic"):
        if key in ("eg", "er"):
            kw[key] = material_constant(value, f"{body}: {key}")
        elif key in ("tau", "tau_c", "tc"):
            kw["tau"] = _parse_time(value)
        elif key == "nu":
            kw["nu"] = poisson_ratio(value)
        else:
            raise SurfmetInputError(f"unknown viscoelastic option {key!r}: use Eg, Er, tau, nu")
    missing = [k for k in ("eg", "er", "tau") if k not in kw]
    if missing:
        raise SurfmetInputError(f"--viscoelastic needs Eg, Er and tau; missing {missing}")
    nu = kw.get("nu", (ball if body == "ball" else plate).nu)
    return body, StandardLinearSolid(kw["eg"], kw["er"], kw["tau"], nu)


@dataclass(frozen=True, eq=False)
class ViscoRollingReport:
    """Viscoelastic rolling resistance over a load sweep (``surfmet rolling --model
    viscoelastic``).

    See Also
    --------
    viscoelastic_rolling : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling import viscoelastic_rolling
    >>> report = viscoelastic_rolling(radius=0.02, materials="steel,pmma", loads=[1.0, 3.0, 10.0],
    ...                               speed=0.01, viscoelastic=["plate:Eg=3GPa:Er=1GPa:tau=1ms"],
    ...                               grid=32)
    >>> report.sweep.moments.shape
    (3,)
    """

    sweep: RollingSweep
    radius: float
    bodies: tuple[Any, Any]
    notes: tuple[str, ...] = ()


def viscoelastic_rolling(plate: ScanSource | None = None, ball: ScanSource | None = None, *,
                         radius: float,
                         materials: Materials, loads: Loads, speed: float,
                         viscoelastic: list[str] | None = None,
                         loss: tuple[float, float] | None = None, grid: int = 128,
                         spikes: bool = True, progress: Progress | None = None
                         ) -> ViscoRollingReport:
    """Rolling resistance of viscoelastic bodies over a load sweep (smooth or scans).

    Each body is the ``--viscoelastic`` SLS given for it, else, with ``loss``, the SLS of
    that loss factor peaking at V/a (:func:`contact.viscoelastic._loss.sls_from_loss`), else
    elastic.

    Parameters
    ----------
    plate, ball : Topography or path, optional
        Scans (smooth surfaces without).
    radius : float
        Ball radius (m).
    materials : str or (Material, Material)
        ``"BALL,PLATE"``.
    loads : sequence of float
        Normal loads (N).
    speed : float
        Rolling speed V (m/s).
    viscoelastic : list of str, optional
        ``BODY:Eg=..:Er=..:tau=..`` per viscoelastic body (:func:`parse_viscoelastic`).
    loss : (float, float), optional
        Loss factors of ball and plate, instead of ``viscoelastic``.
    grid : int
        Cells per side.
    spikes : bool
        Remove the scans' spikes.
    progress : callable, optional
        Wraps the iterable of loads.

    Returns
    -------
    ViscoRollingReport
        The sweep (loads, moments, the fitted exponent) and the bodies.

    Raises
    ------
    SurfmetInputError, ContactError
        Unreadable bodies or loads, a solver failure.

    See Also
    --------
    surfmet.mechanics.rolling_resistance.rolling_resistance : the elastic-hysteresis model.

    References
    ----------
    .. [1] S. C. Hunter, "The rolling contact of a rigid cylinder with a viscoelastic half
       space", J. Appl. Mech. 28 (1961) 611-617.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 8.6.

    Examples
    --------
    A steel ball rolling slowly on a PMMA-like standard linear solid:

    >>> from surfmet.mechanics.viscoelastic_rolling import viscoelastic_rolling
    >>> report = viscoelastic_rolling(radius=0.02, materials="steel,pmma", loads=[1.0, 3.0, 10.0],
    ...                               speed=0.01, viscoelastic=["plate:Eg=3GPa:Er=1GPa:tau=1ms"],
    ...                               grid=32)
    >>> print(f"lambda = {report.sweep.fit.exponent:.2f}")
    lambda = 1.03
    """
    from contact._hertz import hertz_sphere
    from contact.viscoelastic._loss import sls_from_loss
    from contact.viscoelastic._sweep import viscoelastic_sweep
    from surfmet.mechanics.material_spec import material_pair, parse_materials
    from surfmet.mechanics.scan_preparation import prepare_scans

    mats = material_pair(materials)
    ball_m, plate_m = parse_materials(mats)
    bodies: dict[str, Any] = {"ball": ball_m, "plate": plate_m}
    if loss is not None:
        w_mid = float(np.sqrt(np.min(loads) * np.max(loads)))
        t_peak = hertz_sphere(radius, w_mid, mats.e_star).a / speed
        for name, eta in zip(("ball", "plate"), loss):
            m = bodies[name]
            bodies[name] = sls_from_loss(m.E, m.nu, eta, t_peak)
    for text in viscoelastic or []:
        name, sls = parse_viscoelastic(text, ball_m, plate_m)
        bodies[name] = sls
    prep = prepare_scans(plate, ball, spikes=spikes)
    pair = prep.pair
    sweep = viscoelastic_sweep(
        radius, bodies["ball"], bodies["plate"], loads, speed,
        roughness=None if pair is None else pair.roughness,
        roughness_dx=None if pair is None else pair.dx,
        roughness_dy=None if pair is None else pair.dy, n=grid, progress=progress)
    notes = [*(prep.notes if pair is not None else ()), *sweep.notes]
    if pair is not None:
        notes.append("roughness frozen in the contact frame (contact.viscoelastic._sweep)")
    return ViscoRollingReport(sweep, float(radius), (bodies["ball"], bodies["plate"]),
                              tuple(notes))


@dataclass(frozen=True, eq=False)
class MechanismsReport:
    """Mechanisms side by side with what Table 3 measures (``--model all``).

    See Also
    --------
    rolling_mechanisms : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling import rolling_mechanisms
    >>> type(rolling_mechanisms(mu=None, loads=(2.0, 12.0, 3))).__name__
    'MechanismsReport'
    """

    comparison: MechanismComparison
    verdict: RotorVerdict
    notes: tuple[str, ...] = field(default=())

    @property
    def group_offset(self) -> tuple[float, float, float]:
        """The rotor verdict's group offset ``eps_s - eps_as`` and its interval (rad/s²):
        the joint model of Table 3 (:func:`surfmet.mechanics.rotor_verdict.paper_verdict`),
        never a constant-acceleration fit."""
        o = self.verdict.offset
        return o.value, o.ci_low, o.ci_high


def microslip_sweep(radius: float, materials: Materials, mu: float,
                    grid: int | None = None) -> Any:
    """loads -> RollingSweep of micro-slip dissipation in free rolling (the tangential
    solver, :func:`surfmet.mechanics.rolling_contact.solve_rolling_contact`): F_r is the frictional
    power per unit rolling speed, M_r = F_r R.

    Parameters
    ----------
    radius : float
        Ball radius (m).
    materials : str or (Material, Material)
        ``"BALL,PLATE"``, a dissimilar pair (micro-slip needs Kalker's K ≠ 0).
    mu : float
        Coefficient of friction.
    grid : int, optional
        Elements per side of each frictional solve.

    Returns
    -------
    callable
        ``loads -> RollingSweep``.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 8.2
       (free rolling of dissimilar bodies).

    Examples
    --------
    Steel on aluminium in free rolling: the micro-slip moment grows as the load to 4/3, as
    every Hertzian mechanism does:

    >>> from surfmet.mechanics.viscoelastic_rolling import microslip_sweep
    >>> sweep = microslip_sweep(0.02, "steel,aluminium", 0.3, grid=16)([2.0, 4.0, 8.0])
    >>> print(f"lambda = {sweep.fit.exponent:.3f}")
    lambda = 1.333
    """
    from contact.viscoelastic._sweep import sweep_record
    from surfmet.mechanics.rolling_contact import solve_rolling_contact

    def run(loads: Loads) -> Any:
        w = np.asarray(loads, dtype=float)
        res = [solve_rolling_contact(radius, float(n), materials, mu, grid=grid).result
               for n in w]
        forces = np.array([r.frictional_power for r in res])
        return sweep_record("microslip", w, forces, radius,
                            {"model": "microslip", "mu": mu, "grid": grid}, res)

    return run


def rolling_mechanisms(*, radius: float = 0.02, materials: Materials = "steel,aluminium",
                       loads: Loads = (2.0, 12.0, 7), speed: float = 0.1,
                       loss: tuple[float, float] | None = None,
                       hardness: float | None = None, grid: int = 128,
                       mu: float | None = 0.3,
                       adhesion: tuple[float | None, float | None] = (None, None)
                       ) -> MechanismsReport:
    """Mechanisms at the rotor's ball loads (smooth pair) beside Table 3's measurement.

    ``loss`` defaults to the typical loss factors of :mod:`contact.viscoelastic._loss`;
    ``mu`` (assumed; dry steel on aluminium) sets the micro-slip mechanism, None leaves it
    out (it costs one 3D frictional solve per load). ``adhesion`` = (w, Delta_w) (J/m^2)
    sets the adhesion-hysteresis mechanism; None entries take steel on aluminium in air
    (:data:`contact.adhesion.rolling.STEEL_ALUMINIUM_AIR`, Delta_w = w), and another pair
    without a w leaves it out with a note.

    Parameters
    ----------
    radius : float
        Ball radius (m).
    materials : str or (Material, Material)
        ``"BALL,PLATE"``.
    loads : (float, float, int) or sequence of float
        The ball loads (N): a log range or the values.
    speed : float
        Rolling speed (m/s).
    loss : (float, float), optional
        Loss factors of ball and plate.
    hardness : float, optional
        Hardness of the softer body (Pa).
    grid : int
        Cells per side.
    mu : float or None
        Coefficient of friction of the micro-slip mechanism (None leaves it out).
    adhesion : (float or None, float or None)
        Work of adhesion and its hysteresis (J/m²).

    Returns
    -------
    MechanismsReport
        Each mechanism's exponent and the acceleration difference it implies, beside the
        rotor verdict.

    See Also
    --------
    surfmet.mechanics.rotor_verdict.paper_verdict : what Table 3 measures.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 8-9.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling import rolling_mechanisms
    >>> rolling_mechanisms(mu=None, loads=(2.0, 12.0, 3)).verdict.code
    'undetermined'
    """
    from contact._rolling import log_loads
    from contact.viscoelastic._loss import loss_data
    from contact.viscoelastic._mechanisms import compare_mechanisms
    from rotor import mass_properties, normal_reactions
    from surfmet.mechanics.material_spec import material_pair, parse_materials

    mats = material_pair(materials, hardness=hardness)
    ball_m, plate_m = parse_materials(mats)
    if loss is None:
        loss = (loss_data(ball_m.name).typical, loss_data(plate_m.name).typical)
    if mats.hardness is None:
        raise SurfmetInputError("the plastic mechanism needs a hardness (--hardness)")
    sym = mass_properties(collar_offset="symmetric")
    if not math.isclose(radius, sym.ball_radius, rel_tol=1e-9):
        # the implied offsets divide by the rotor's J + M R^2: another ball would set its
        # contacts beside a rotor it is not part of
        raise SurfmetInputError(
            f"--model all sets the mechanisms beside the paper's rotor, whose balls have "
            f"R = {sym.ball_radius * 1e3:g} mm; --radius {radius * 1e3:g} mm would compare "
            f"{radius * 1e3:g} mm contacts with the {sym.ball_radius * 1e3:g} mm rotor: give "
            f"--radius {sym.ball_radius * 1e3:g}mm, or another --model for another ball")
    asym = mass_properties(collar_offset="end")
    ns = normal_reactions(sym)[0]
    n1, n2 = normal_reactions(asym)
    sweep = log_loads(*loads) if isinstance(loads, tuple) else np.asarray(loads, float)
    loads_note = (f"lambda is fitted over the --loads sweep ({min(sweep):.3g}-{max(sweep):.3g} "
                  f"N, {len(sweep)} loads); the moments M_r(Ns), M_r(N1), M_r(N2) and the "
                  f"implied eps_s - eps_a are at the rotor's ball loads (symmetric {ns:.3g} N; "
                  f"asymmetric {min(n1, n2):.3g} and {max(n1, n2):.3g} N), which --loads does "
                  f"not set")
    ms = None if mu is None else microslip_sweep(radius, (ball_m, plate_m), mu)
    adh, adh_notes = _adhesion_numbers(ball_m.name, plate_m.name, *adhesion)
    comp = compare_mechanisms(radius, mats, loads=sweep, rotor_loads=(ns, n1, n2),
                              rolling_inertia=sym.rolling_inertia, speed=speed, loss=loss,
                              grid=grid, microslip=ms, adhesion=adh)
    notes = (loads_note,) + (() if mu is not None else (
        "micro-slip left out (no friction coefficient)",)) + adh_notes
    from surfmet.mechanics.rotor_verdict import paper_verdict

    return MechanismsReport(comp, paper_verdict(), notes)


def _adhesion_numbers(ball: str, plate: str, work: float | None, hysteresis: float | None
                      ) -> tuple[tuple[float, float] | None, tuple[str, ...]]:
    """(w, Delta_w) of the adhesion-hysteresis mechanism, and the notes saying whence."""
    from contact.adhesion.rolling import STEEL_ALUMINIUM_AIR

    if work is None:
        if {ball, plate} != {"steel", "aluminium"}:
            return None, ("adhesion hysteresis left out: no work of adhesion known for "
                          f"{ball} on {plate} (give --work-of-adhesion)",)
        work = STEEL_ALUMINIUM_AIR[0]
        source = f"adhesion hysteresis: {STEEL_ALUMINIUM_AIR[2]}"
    else:
        source = f"adhesion hysteresis: w = {work:g} J/m^2 as given"
    if not work > 0:
        raise SurfmetInputError(f"the work of adhesion must be positive, got {work!r}")
    dw = work if hysteresis is None else hysteresis
    if not 0 <= dw <= work:
        raise SurfmetInputError(f"the adhesion hysteresis must lie between 0 and the work of "
                                f"adhesion {work:g} J/m^2, got {dw!r}")
    return (work, dw), (source + "; an upper bound on the smooth pair, listed but not "
                        "ranked among the mechanisms",)


def reaches_offset(delta_eps: float, offset: GroupOffset) -> bool:
    """Whether an implied offset reaches the smallest one the verdict's interval allows.

    Parameters
    ----------
    delta_eps : float
        The acceleration difference a mechanism implies (rad/s²).
    offset : interval quantity
        The verdict's group offset (``value``, ``ci_low``, ``ci_high``).

    Returns
    -------
    bool
        True when the mechanism can make the measured offset.

    Examples
    --------
    Against the paper's offset of +0.20 rad/s² (95 % CI +0.12..+0.28):

    >>> from types import SimpleNamespace
    >>> from surfmet.mechanics.viscoelastic_rolling import reaches_offset
    >>> o = SimpleNamespace(value=0.20, ci_low=0.12, ci_high=0.28)
    >>> reaches_offset(0.022, o), reaches_offset(0.15, o), reaches_offset(-0.15, o)
    (False, True, False)
    """
    if offset.ci_low <= 0.0 <= offset.ci_high:
        return abs(delta_eps) >= abs(offset.value)
    return abs(delta_eps) >= min(abs(offset.ci_low), abs(offset.ci_high)) and \
        math.copysign(1.0, delta_eps) == math.copysign(1.0, offset.value)

