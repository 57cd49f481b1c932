"""One steady viscoelastic rolling solve (``surfmet rolling-contact --viscoelastic``): the
normal problem, the tangential one where the model can answer it, and its JSON record in
the elastic command's vocabulary
(:func:`~surfmet.records._rolling_contact.visco_rolling_contact_record`: the elastic
record's keys, sign convention and grid record).

What the tangential solve leaves out. The plane-strain traction solver
(:func:`contact.viscoelastic.steady_traction`) is that of quasi-identical bodies: Kalker's
difference parameter K = 0, no normal-tangential coupling. In free rolling (no creepage
prescribed) the tractions of a pair with K != 0 come from that coupling alone (the
elastic solve of steel on PMMA finds a creepage of 9e-4 and a slip band), while the
uncoupled problem has the trivial solution q = 0: free rolling of a dissimilar pair in
plane strain is reported as *not solved*, with the reason, instead of as zeros. The 3D
solver (:func:`contact.viscoelastic._traction3d.visco_steady_tractions`) takes the
coupling one way: the tangential displacement of the pressure, with its own hereditary
integral (:func:`contact.viscoelastic._traction3d.pressure_tangential`), joins the slip;
the tractions' normal displacement does not change the pressure. In its relaxed and
glassy limits it gives the elastic solver's creepage and areas for the same pressure;
against the elastic two-way coupled solve of steel on PMMA (48 x 48) the free-rolling
creepage differs by 0.5 % and the slip area by 14 % (a few edge elements).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from surfmet._errors import SurfmetInputError

if TYPE_CHECKING:
    from contact._materials import Material
    from contact.tangential._results import TangentialResult
    from contact.viscoelastic._result import RollingResult
    from contact.viscoelastic._rheology import CreepSeries, StandardLinearSolid
    from contact.viscoelastic._traction import TractionResult
    from surfmet.mechanics._types import Materials, ScanSource

#: ``|K|`` at or below this is quasi-identical (the viscoelastic traction solvers' model).
QUASI_IDENTICAL_K = 1e-6


@dataclass(frozen=True, eq=False)
class ViscoRollingContact:
    """A solved viscoelastic rolling contact and the set-up it came from.

    Attributes
    ----------
    normal : contact.viscoelastic.RollingResult
        The normal problem.
    traction : TractionResult (line), TangentialResult (ball) or None
        The tractions; None without ``mu`` or where :attr:`not_solved` says why.
    kalker_k : (float, float)
        The pair's K with glassy and with relaxed moduli (body 1 = ball).
    not_solved : str or None
        Why the tangential problem was not solved (None: solved, or no ``mu``).

    See Also
    --------
    viscoelastic_rolling_contact : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling_contact import viscoelastic_rolling_contact
    >>> vc = viscoelastic_rolling_contact(radius=0.02, load=10.0, materials="steel,pmma",
    ...                                   viscoelastic=["plate:Eg=3GPa:Er=1GPa:tau=1ms"],
    ...                                   speed=0.01, grid=32)
    >>> vc.traction is None, vc.normal.pressure.ndim
    (True, 2)
    """

    normal: RollingResult
    traction: TractionResult | TangentialResult | None
    radius: float
    load: float
    line: bool
    mu: float | None
    free_rolling: bool
    grid: int
    kalker_k: tuple[float, float]
    not_solved: str | None = None
    notes: tuple[str, ...] = ()


def _shear(body: Material | StandardLinearSolid, glassy: bool) -> tuple[float, float]:
    """(G, nu) of an elastic Material or, glassy or relaxed, a standard linear solid."""
    from contact.viscoelastic._rheology import StandardLinearSolid

    if isinstance(body, StandardLinearSolid):
        e = body.E_g if glassy else body.E_r
        return e / (2.0 * (1.0 + body.nu)), float(body.nu)
    return float(body.shear_modulus), float(body.nu)


def pair_kalker_k(ball: Material, plate: Material) -> tuple[float, float]:
    """Kalker's K of the pair (ball = body 1) with glassy and with relaxed moduli
    (:func:`contact.halfspace.constants.pair_constants_from`).

    Parameters
    ----------
    ball, plate : Material or StandardLinearSolid
        The bodies (ball = body 1).

    Returns
    -------
    (float, float)
        K with the glassy and with the relaxed moduli.

    References
    ----------
    .. [1] J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer
       (1990).

    Examples
    --------
    Quasi-identical bodies have no normal-tangential coupling:

    >>> from contact import material
    >>> from surfmet.mechanics.viscoelastic_rolling_contact import pair_kalker_k
    >>> pair_kalker_k(material("steel"), material("steel"))
    (0.0, 0.0)
    """
    from contact.halfspace.constants import pair_constants_from

    # a tuple() of a two-item generator: mypy cannot count its items
    return tuple(pair_constants_from(*_shear(ball, g), *_shear(plate, g)).K  # type: ignore[return-value]
                 for g in (True, False))


def coupling_reason(kalker_k: tuple[float, float], free_rolling: bool) -> str | None:
    """Why the tangential problem is not solved (free rolling of a dissimilar pair), or
    None.

    Parameters
    ----------
    kalker_k : (float, float)
        The pair's K (glassy, relaxed).
    free_rolling : bool
        No creepage imposed.

    Returns
    -------
    str or None
        The sentence, or None when the tangential problem is solved.

    Examples
    --------
    >>> from surfmet.mechanics.viscoelastic_rolling_contact import coupling_reason
    >>> coupling_reason((0.0, 0.0), True) is None
    True
    >>> print(coupling_reason((-0.1, -0.12), True)[:40])
    tangential problem not solved: in free r
    """
    if not free_rolling or max(abs(k) for k in kalker_k) <= QUASI_IDENTICAL_K:
        return None
    kg, kr = kalker_k
    return (f"tangential problem not solved: in free rolling the tractions of this pair come "
            f"only from its normal-tangential coupling (Kalker's K = {kg:.3g} glassy, "
            f"{kr:.3g} relaxed), which the viscoelastic traction solve leaves out "
            f"(quasi-identical bodies, K = 0, for which free rolling carries no traction); "
            f"give --creepage for the uncoupled tractions, or leave out --viscoelastic for "
            f"the coupled elastic solve")


def viscoelastic_rolling_contact(*, radius: float, load: float, materials: Materials,
                                 viscoelastic: list[str], speed: float, line: bool = False,
                                 grid: int | None = None, plate: ScanSource | None = None,
                                 ball: ScanSource | None = None,
                                 spikes: bool = True, mu: float | None = None,
                                 creepage: float | None = None) -> ViscoRollingContact:
    """One steady viscoelastic rolling solve of a ball or a cylinder: the normal problem,
    and with ``mu`` the tangential one (quasi-identical bodies, see the module notes).

    Parameters
    ----------
    radius : float
        Ball or cylinder radius (m).
    load : float
        N (N), or N/m with ``line``.
    materials : str or (Material, Material)
        ``"BALL,PLATE"``; the ``viscoelastic`` texts replace either body by an SLS.
    viscoelastic : list of str
        ``BODY:Eg=..:Er=..:tau=..`` texts
        (:func:`surfmet.mechanics.viscoelastic_rolling.parse_viscoelastic`).
    speed : float
        V (m/s), > 0.
    line : bool
        Plane strain (cylinder) instead of a ball.
    grid : int, optional
        Cells (line: default 1024) or cells per side (ball: default 128).
    plate, ball : Topography or path, optional
        Scans for a rough ball contact (the roughness frozen in the contact frame).
    mu, creepage : float, optional
        Coefficient of friction and creepage (default free rolling) for the tangential
        tractions: plane strain (:func:`contact.viscoelastic.steady_traction`) or, for a
        ball, 3D (:func:`contact.viscoelastic._traction3d.visco_steady_tractions`).

    Returns
    -------
    ViscoRollingContact
        The normal solution, the tractions (with ``mu``) and the pair's Kalker constants.

    Raises
    ------
    SurfmetInputError, ContactError
        Unreadable bodies, bad values, a solver failure.

    See Also
    --------
    surfmet.records._rolling_contact.visco_rolling_contact_record : its JSON record.
    surfmet.mechanics.rolling_contact.solve_rolling_contact : the elastic case.

    References
    ----------
    .. [1] S. C. Hunter, "The rolling contact of a rigid cylinder with a viscoelastic half
       space", J. Appl. Mech. 28 (1961) 611-617.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 8.6.

    Examples
    --------
    The delayed recovery of the viscoelastic plate behind the ball resists the rolling:

    >>> from surfmet.mechanics.viscoelastic_rolling_contact import viscoelastic_rolling_contact
    >>> vc = viscoelastic_rolling_contact(radius=0.02, load=10.0, materials="steel,pmma",
    ...                                   viscoelastic=["plate:Eg=3GPa:Er=1GPa:tau=1ms"],
    ...                                   speed=0.01, grid=32)
    >>> bool(vc.normal.rolling_resistance > 0)
    True
    """
    from contact.tangential._memory import check_rolling_memory
    from contact.viscoelastic import pair_creep
    from surfmet.mechanics.material_spec import parse_materials
    from surfmet.mechanics.viscoelastic_rolling import parse_viscoelastic

    ball_m, plate_m = parse_materials(materials)
    bodies: dict[str, Any] = {"ball": ball_m, "plate": plate_m}
    for text in viscoelastic:
        name, sls = parse_viscoelastic(text, ball_m, plate_m)
        bodies[name] = sls
    creep = pair_creep(bodies["ball"], bodies["plate"])
    kk = pair_kalker_k(bodies["ball"], bodies["plate"])
    dissimilar = max(abs(k) for k in kk) > QUASI_IDENTICAL_K
    reason = None if mu is None or not line else coupling_reason(kk, creepage is None)
    notes = []
    if mu is not None and dissimilar and line and reason is None:
        notes.append(f"the tractions are those of quasi-identical bodies: the pair's "
                     f"normal-tangential coupling (Kalker's K = {kk[0]:.3g} glassy, "
                     f"{kk[1]:.3g} relaxed) is left out")
    elif mu is not None and dissimilar:
        notes.append(f"normal-tangential coupling one way (Kalker's K = {kk[0]:.3g} glassy, "
                     f"{kk[1]:.3g} relaxed): the pressure's tangential displacement is in "
                     f"the slip, the tractions' effect on the pressure is left out (in the "
                     f"elastic limit 0.5 % on the free-rolling creepage of steel on PMMA)")
    n = grid or (1024 if line else 128)
    solve_tr = mu is not None and reason is None
    tr: TractionResult | TangentialResult | None
    if line:
        if plate is not None or ball is not None:
            raise SurfmetInputError("--line takes no scans")
        res, tr = _line(radius, load, creep, speed, n, mu if solve_tr else None, creepage)
    else:
        check_rolling_memory(n)
        res, tr = _ball(radius, load, creep, speed, n, plate, ball, spikes, bodies,
                        mu if solve_tr else None, creepage, dissimilar)
    return ViscoRollingContact(res, tr, float(radius), float(load), line, mu,
                               creepage is None, n, kk, reason, tuple(notes))


def _line(radius: float, load: float, creep: CreepSeries, speed: float, n: int, mu: float | None,
          creepage: float | None) -> tuple[RollingResult, TractionResult | None]:
    """The plane-strain normal solve and, with ``mu``, Carter's problem with creep."""
    from contact.tangential._memory import check_rolling_memory
    from contact.viscoelastic._line import influence_matrix, rolling_cylinder

    check_rolling_memory(n, line=True, dense=True)
    res = rolling_cylinder(radius, load, creep, speed, n=n)
    if mu is None:
        return res, None
    from contact.viscoelastic import steady_traction

    dx = float(res.x[1] - res.x[0])
    A = influence_matrix(res.x.size, dx, creep, speed)
    return res, steady_traction(A, res.pressure, dx, mu, creepage=creepage)


def _ball(radius: float, load: float, creep: CreepSeries, speed: float, n: int,
          plate: ScanSource | None, ball: ScanSource | None, spikes: bool,
          bodies: dict[str, Any], mu: float | None, creepage: float | None,
          coupled: bool) -> tuple[RollingResult, TangentialResult | None]:
    """The 3D normal solve (smooth or with the scans) and, with ``mu``, the tractions
    (``coupled``: with the pressure's tangential displacement of a dissimilar pair)."""
    from contact.viscoelastic._surface import rolling_sphere

    z = None
    if plate is not None or ball is not None:
        from contact.viscoelastic._sweep import roughness_window
        from contact.viscoelastic._window import sphere_window
        from surfmet.mechanics.scan_preparation import prepare_scans

        pair = prepare_scans(plate, ball, spikes=spikes).paired()
        half = sphere_window(load, radius, creep.relaxed)
        z = roughness_window(pair.roughness, pair.dx, pair.dy, None, half, n)
    res = rolling_sphere(radius, load, creep, speed, n=n, roughness=z)
    if mu is None:
        return res, None
    from contact._grid import Grid
    from contact.viscoelastic._traction3d import ViscoRolling, pair_poisson, visco_steady_tractions

    x, y = np.asarray(res.x), np.asarray(res.y)
    grid3 = Grid(x=x, y=y, h=(x[None, :] ** 2 + y[:, None] ** 2) / (2.0 * radius))
    nu = pair_poisson(bodies["ball"], bodies["plate"])
    bodies_pair = (bodies["ball"], bodies["plate"]) if coupled else None
    return res, visco_steady_tractions(grid3, np.asarray(res.pressure),
                                       ViscoRolling(creep, nu, speed), mu,
                                       creepage=creepage, coupling=bodies_pair)


#: What the viscoelastic record's rolling-resistance coefficient is (beside the elastic
#: record's :data:`surfmet.mechanics.rolling_contact.RESISTANCE_DEFINITION`).
VISCO_RESISTANCE_DEFINITION = (
    "rolling_resistance_coefficient = the pressure's moment about the axis / (N R), the "
    "viscoelastic hysteresis (for elastic bodies the record calls this asymmetry "
    "pressure_moment_coefficient and it dissipates nothing); the frictional micro-slip "
    "dissipation (frictional_power) is not in it"
)
