"""Rolling resistance from a contact solution, and its load exponent lambda.

Alaci et al. (2022) write the rolling-friction moment as M_r = s_r N^lambda. Here M_r is
computed from the contact solution itself, under two dissipation models, over a sweep of
loads, and lambda is fitted.

Hysteresis model (Greenwood, Minshall & Tabor 1961, Proc. R. Soc. A 259:480; Johnson 1985,
*Contact Mechanics*, sec. 9.2). A fraction alpha_h of the work done on the material as it
is loaded on entering the contact is lost. With the body rolling towards +x, material
passes through the contact in -x; per unit rolling distance the work put in is

    W_in = iint p [-du_z/dx]_+ dA,      F_r = alpha_h W_in,      M_r = F_r R,

with u_z the normal surface displacement (positive into the body). For a smooth Hertz
sphere u_z = delta - r^2/(2R) inside the contact and F_r = (3/16) alpha_h N a / R (Johnson
eq. 9.19), so M_r ∝ N^(4/3); for a cylinder F_r' = 2 alpha_h W' a / (3 pi R) and
M_r ∝ W'^(3/2).

Which displacement. (1) *Which body.* Under one frictionless pressure each half-space
deflects in proportion to its compliance (1 - nu_i^2)/E_i, so body i takes the share
``contact._materials.displacement_shares`` of the combined displacement the solver returns,
and the work on it is that share of W_in. ``share`` selects the body that loses energy;
the default 1 (the combined displacement) means both bodies lose the same fraction
alpha_h. Neither the share nor alpha_h changes lambda. (2) *Which derivative.* The
formula's d/dx stands for the rate at which a material point is loaded as it travels, the
material derivative. For a smooth ball the field is steady in the contact frame and the
two coincide. On rough surfaces in pure rolling, both surfaces' asperities travel *with*
the material (at -V in the contact frame), so the asperity pattern is not steady: inside
the contact u = delta - h with h = r^2/(2R) - z(material point), hence
Du/Dt = V x / R exactly and the asperity slopes cancel. ``kinematics="rolling"`` (the
default) evaluates this: W_in = (1/R) iint p [x]_+ dA. ``kinematics="frozen"`` evaluates
the formula literally on the snapshot, -du/dx of the computed displacement field, in which
the asperity slopes dz/dx enter; that is the loading of material flowing past asperities
that stay put in the contact frame (a rough rigid slider, not rolling), kept for
comparison.

Plastic model (first pass). On its first pass the ball leaves a permanent track; the
work of plastic flow at the flow pressure H per unit rolling distance is

    F_pl = H * (permanent indentation volume per unit length of track)
         = H * int d(y) dy,

where d(y) is the mean permanent indentation of the material at lateral position y.
A material point reaches its largest interference with the ball where it crosses the line
x = 0 (the macroscopic interference delta - (x^2 + y^2)/(2R) is largest there), so its
plastic indentation in the quasi-static elastic-plastic solution near x = 0 is its final
one. d(y) is the mean of the solution's plastic displacement over the band |x| <= b
around that line, with b chosen so that the macroscopic interference changes across the
band by at most ``band`` (default 5 %) of the depth scale (the largest plastic
displacement plus the roughness rms): a resolution-independent, nearly unbiased sample of
the material's final state (one column for a smooth ball). Quasi-static: the asymmetry
the track itself gives the pressure (the rear half meets already flattened material) is
neglected. M_pl = F_pl R.

Exponent. log M_r is fitted against log N by least squares over the sweep: lambda_eff is
the slope, with a Student-t confidence interval; the local exponent d ln M / d ln N
(second-order finite differences on the log grid) shows how lambda drifts with the load
(both in :mod:`contact._exponent`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from contact._dissipation import (  # noqa: F401 (MODELS, KINEMATICS: re-exported)
    KINEMATICS,
    MODELS,
    Dissipation,
    check_fraction,
    dissipation_of,
)
from contact._errors import ContactInputError
from contact._exponent import ExponentFit, dissipating_exponents
from contact._material_pair import MaterialPair, modulus
from contact._validate import positive
from contact.setups._composite import CompositeRoughness

if TYPE_CHECKING:  # the solves load lazily; only the annotations name these
    from contact._geometry import DomainSpec
    from contact.bem._options import SolveOptions

_DIRECTIONS = {"+x": (1, 1.0), "-x": (1, -1.0), "+y": (0, 1.0), "-y": (0, -1.0)}


def _direction(direction: str) -> tuple[int, float]:
    try:
        return _DIRECTIONS[direction]
    except KeyError:
        raise ContactInputError(
            f"direction must be one of {sorted(_DIRECTIONS)}, got {direction!r}"
        ) from None


def _fields(result: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, bool]:
    """(pressure, displacement, x, y, cell area, is_line) of a 2D or a line result."""
    p = np.asarray(result.pressure, dtype=float)
    u = np.asarray(result.displacement, dtype=float)
    if p.ndim == 1:
        x = np.asarray(result.x, dtype=float)
        return p[None, :], u[None, :], x, np.zeros(1), float(result.dx), True
    return p, u, np.asarray(result.x, float), np.asarray(result.y, float), \
        float(result.dx * result.dy), False


def hysteresis_work(
    result: Any,
    radius: float | None = None,
    *,
    kinematics: str = "rolling",
    direction: str = "+x",
    share: float = 1.0,
    apex: tuple[float, float] = (0.0, 0.0),
) -> float:
    """Work put into the material per unit rolling distance, iint p [-du_z/dx]_+ dA.

    Parameters
    ----------
    result : contact.ContactResult or contact.setups._line.LineContactResult
        Contact solution (for a line contact, per unit length along the line: N/m).
    radius : float
        Radius R of the ball or cylinder (m); needed by ``kinematics="rolling"``.
    kinematics : {"rolling", "frozen"}
        "rolling": material derivative with the roughness travelling with the material,
        -du_z/dx = (x - x_apex)/R in the contact (see the module notes); "frozen": the
        snapshot's -du_z/dx of the computed displacement field (central differences).
    direction : {"+x", "-x", "+y", "-y"}
        Direction the ball rolls in (the material passes through the contact the other
        way); a line contact rolls along x only.
    share : float
        Fraction of the combined displacement taken by the body that loses energy
        (``contact._materials.displacement_shares``); 1 = the combined displacement.
    apex : (float, float)
        Coordinates of the ball's apex on the grid (m); the origin in
        :mod:`contact.setups._ball_on_plate`.

    Returns
    -------
    float
        Work per unit rolling distance (J/m = N; N for a line contact per unit length).

    Examples
    --------
    A smooth ball: the work is Johnson's (3/16) W a / R (eq. 9.19, alpha_h = 1):

    >>> from contact import DomainSpec, hertz_sphere, hysteresis_work, solve_sphere
    >>> res = solve_sphere(0.02, 10.0, 58.6e9, domain=DomainSpec(grid=64))
    >>> a = hertz_sphere(0.02, 10.0, 58.6e9).a
    >>> print(f"{hysteresis_work(res, 0.02) / (3 / 16 * 10.0 * a / 0.02):.3f}")
    0.999
    """
    if kinematics not in KINEMATICS:
        raise ContactInputError(f"kinematics must be one of {KINEMATICS}, got {kinematics!r}")
    share = check_fraction(share, "the displacement share")
    axis, sign = _direction(direction)
    p, u, x, y, da, line = _fields(result)
    if line and axis != 1:
        raise ContactInputError("a line contact rolls along x: direction must be +x or -x")
    if kinematics == "rolling":
        if radius is None or not (math.isfinite(radius) and radius > 0):
            raise ContactInputError("kinematics='rolling' needs the ball radius R (m)")
        coord = (x - apex[0])[None, :] if axis == 1 else (y - apex[1])[:, None]
        rate = sign * coord / radius
    else:
        if p.shape[axis] < 3:
            raise ContactInputError("the grid is too small to differentiate the displacement")
        step = float(result.dx) if axis == 1 else float(result.dy)
        rate = -sign * np.gradient(u, step, axis=axis)
    return share * float((p * np.clip(rate, 0.0, None)).sum() * da)


def plastic_work(
    result: Any,
    radius: float,
    *,
    band: float = 0.05,
    roughness_rms: float = 0.0,
    direction: str = "+x",
    apex: tuple[float, float] = (0.0, 0.0),
) -> float:
    """Plastic work per unit rolling distance on a first pass, H * int d(y) dy.

    Parameters
    ----------
    result : contact.ContactResult
        Elastic-perfectly-plastic solution (``hardness`` set).
    radius : float
        Ball radius R (m).
    band : float
        The band |x| <= b sampled for d(y) is as wide as lets the macroscopic
        interference change by ``band`` times the depth scale (see the module notes).
    roughness_rms : float
        Rms of the roughness (m), part of the depth scale.
    direction : {"+x", "-x", "+y", "-y"}
        Rolling direction; the band lies across it.
    apex : (float, float)
        The ball's apex (m).

    Returns
    -------
    float
        F_pl in N (J per metre rolled); 0 when nothing yields.
    """
    H = getattr(result, "hardness", None)
    if H is None:
        raise ContactInputError("the plastic model needs an elastic-plastic solution "
                                "(solve with a hardness)")
    positive(radius, "the radius", "m")
    positive(band, "band")
    axis, _ = _direction(direction)
    upl = np.asarray(result.plastic_displacement, dtype=float)
    depth = float(upl.max()) + max(float(roughness_rms), 0.0)
    if depth <= 0 or not (upl > 0).any():
        return 0.0
    x = np.asarray(result.x, float) - apex[0]
    y = np.asarray(result.y, float) - apex[1]
    along, across = (x, float(result.dy)) if axis == 1 else (y, float(result.dx))
    step = float(result.dx) if axis == 1 else float(result.dy)
    half = max(math.sqrt(2.0 * radius * band * depth), 0.5 * step * (1 + 1e-9))
    sel = np.abs(along) <= half
    d = upl[:, sel].mean(axis=1) if axis == 1 else upl[sel, :].mean(axis=0)
    return float(H) * float(d.sum()) * across


def log_loads(lo: float, hi: float, n: int) -> np.ndarray:
    """``n`` log-spaced loads from ``lo`` to ``hi`` (both included)."""
    if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo < hi):
        raise ContactInputError(f"need 0 < lo < hi, got {lo!r}, {hi!r}")
    if int(n) < 2:
        raise ContactInputError("a load sweep needs at least 2 loads")
    return np.geomspace(lo, hi, int(n))


@dataclass(frozen=True, eq=False)
class RollingSweep:
    """Rolling resistance over a load sweep and its exponent.

    Attributes
    ----------
    model : {"hysteresis", "plastic"}
    loads : ndarray
        Normal loads N (N; N/m for a line contact).
    forces : ndarray
        F_r, the dissipated work per unit rolling distance (N; N/m for a line).
    moments : ndarray
        M_r = F_r R (N m; N m/m for a line).
    fit : ExponentFit or None
        Power-law fit over the loads with a positive moment (None if fewer than 3).
    local_lambda : ndarray
        d ln M / d ln N (NaN where the moment is 0).
    radius : float
    settings : dict
        alpha_h, share, kinematics, hardness, grid, ...
    notes : tuple of str
    results : tuple
        The contact solutions (for figures; not part of JSON records).

    Examples
    --------
    >>> from contact import DomainSpec, sphere_sweep
    >>> sweep = sphere_sweep(0.02, 58.6e9, [1.0, 3.0, 10.0], domain=DomainSpec(grid=64))
    >>> sweep.model, sweep.loads.size, f"{sweep.lambda_eff:.2f}"
    ('hysteresis', 3, '1.33')
    """

    model: str
    loads: np.ndarray
    forces: np.ndarray
    moments: np.ndarray
    fit: ExponentFit | None
    local_lambda: np.ndarray
    radius: float
    settings: dict[str, Any] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    results: tuple[Any, ...] = field(default=(), repr=False)

    @property
    def solve(self) -> Any:
        """One solve record for the contact solutions of the sweep
        (:func:`contact._record.combine`); None for a sweep solved in closed form."""
        from contact._record import combine

        records = [r.solve for r in self.results if getattr(r, "solve", None) is not None]
        return combine(records, f"{records[0].method}, one solve per load") if records else None

    @property
    def lambda_eff(self) -> float:
        """The fitted exponent (NaN without a fit)."""
        return self.fit.exponent if self.fit is not None else math.nan

    @property
    def lambda_ci(self) -> tuple[float, float]:
        """Its confidence interval (NaN, NaN without a fit)."""
        return self.fit.ci if self.fit is not None else (math.nan, math.nan)


def _finish(model: str, loads: np.ndarray, forces: np.ndarray, radius: float,
            settings: dict[str, Any], notes: list[str], results: Sequence[Any],
            confidence: float) -> RollingSweep:
    moments = forces * radius
    pos = moments > 0
    fit, local = dissipating_exponents(loads, moments, confidence)
    if fit is None:
        notes.append(f"only {int(pos.sum())} of {loads.size} loads dissipate: no exponent "
                     "fitted (3 needed)")
    if (~pos).any() and pos.any():
        notes.append(f"no dissipation at {int((~pos).sum())} load(s) "
                     f"({', '.join(f'{w:.4g}' for w in loads[~pos])}); fitted over the rest")
    return RollingSweep(model=model, loads=loads, forces=forces, moments=moments, fit=fit,
                        local_lambda=local, radius=float(radius), settings=settings,
                        notes=tuple(notes), results=tuple(results))


def sweep_loads(loads: Iterable[float]) -> np.ndarray:
    """The loads of a sweep (N), sorted; at least one, each positive and finite."""
    arr = np.asarray(list(loads), dtype=float)
    if arr.ndim != 1 or arr.size < 1:
        raise ContactInputError("give at least one load")
    if not (np.isfinite(arr).all() and (arr > 0).all()):
        raise ContactInputError("loads must be positive and finite (N)")
    return np.sort(arr)


def sphere_sweep(
    radius: float,
    e_star: float | MaterialPair,
    loads: Iterable[float],
    *,
    dissipation: Dissipation | None = None,
    roughness: CompositeRoughness | None = None,
    domain: DomainSpec | None = None,
    options: SolveOptions | None = None,
    progress: Callable[[Iterable[Any]], Iterable[Any]] | None = None,
) -> RollingSweep:
    """Rolling resistance of a (rough) ball on a plate over a load sweep.

    One domain is sized for the largest load (enlarged if a solution reaches its edge)
    and every load is warm-started from the previous one, in increasing order.

    Parameters
    ----------
    radius, e_star : float
        Ball radius R (m), composite modulus E* (Pa) or a resolved
        :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    loads : iterable of float
        Normal loads (N), e.g. ``numpy.geomspace(1.0, 100.0, 7)``.
    dissipation : Dissipation, optional
        The dissipation model and its settings (:class:`contact._dissipation.Dissipation`:
        model, hardness, alpha_h, share, kinematics, band, roughness_rms, the level of
        the exponent's confidence interval); default elastic hysteresis, alpha_h = 1.
    roughness : CompositeRoughness, optional
        Composite roughness with its pitch and the apex position (a track position), as
        for :class:`contact.setups._ball_on_plate.SphereContact`.
    domain, options : DomainSpec, SolveOptions, optional
        Domain and solver settings, as for :class:`contact.setups._ball_on_plate.SphereContact`
        and its ``solve``.
    progress : callable, optional
        Wraps the iterable of loads (e.g. a progress bar).

    Returns
    -------
    RollingSweep
        Loads, forces, moments, the fitted load exponent and the local exponents.

    Raises
    ------
    ContactInputError
        An unknown model, ``"plastic"`` without a hardness, or non-positive loads.

    See Also
    --------
    cylinder_sweep, contact.fit_exponent

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 9.

    Examples
    --------
    Elastic hysteresis under a smooth ball grows as W^(4/3):

    >>> from contact import DomainSpec, sphere_sweep
    >>> sweep = sphere_sweep(0.02, 58.6e9, [1.0, 3.0, 10.0], domain=DomainSpec(grid=64))
    >>> print(f"{sweep.fit.exponent:.2f}")
    1.33
    """
    from contact.setups._ball_on_plate import SphereContact

    e_star = modulus(e_star)  # a resolved pair or its E*
    d = dissipation_of(dissipation)
    model, hardness, alpha_h, share = d.model, d.hardness, d.alpha_h, d.share
    kinematics, band = d.kinematics, d.band
    w = sweep_loads(loads)
    problem = SphereContact(radius, e_star, float(w[-1]), roughness=roughness, domain=domain,
                            results=w.size + 1)
    rms = problem.roughness_rms if d.roughness_rms is None else float(d.roughness_rms)
    forces = np.zeros(w.size)
    results: list[Any] = []
    notes = list(problem.notes)
    prev = None
    sequence = progress(range(w.size)) if progress is not None else range(w.size)
    for k in sequence:
        el = problem.solve(float(w[k]), initial=prev, options=options)
        prev = el
        if model == "hysteresis":
            res = el
            forces[k] = alpha_h * hysteresis_work(el, radius, kinematics=kinematics,
                                                  share=share)
        else:
            # capped on the elastic domain, warm-started from the elastic solution
            res = problem.solve(float(w[k]), hardness=float(hardness), initial=el,
                                on_edge="warn", options=options)
            forces[k] = plastic_work(res, radius, band=band, roughness_rms=rms)
        results.append(res)
    for r in results:
        notes.extend(n for n in r.notes if n not in notes)
    settings = {"model": model, "alpha_h": alpha_h if model == "hysteresis" else None,
                "share": share if model == "hysteresis" else None,
                "kinematics": kinematics if model == "hysteresis" else None,
                "band": band if model == "plastic" else None, "hardness": hardness,
                "e_star": float(e_star), "grid": problem.domain.n, "dx": problem.domain.dx,
                "roughness_rms": rms, "contact": "sphere"}
    return _finish(model, w, forces, float(radius), settings, notes, results, d.confidence)


def cylinder_sweep(
    radius: float,
    e_star: float,
    loads_per_length: Iterable[float],
    *,
    dissipation: Dissipation | None = None,
    progress: Callable[[Iterable[Any]], Iterable[Any]] | None = None,
    **line: Any,
) -> RollingSweep:
    """Hysteresis rolling resistance of a cylinder (plane strain) over a load sweep.

    Loads, forces and moments are per unit length of the cylinder (N/m, N/m, N m/m). One
    domain, 2.5 contact widths of the largest load (unless ``size``), serves every load.

    Parameters
    ----------
    radius, e_star : float
        Cylinder radius R (m), composite modulus E* (Pa).
    loads_per_length : iterable of float
        Loads per unit length (N/m).
    dissipation, progress : as for :func:`sphere_sweep`
        (the hysteresis model only: alpha_h, share, kinematics, confidence)
    **line
        ``n``, ``size``, ``roughness``, ``roughness_dx``: cells and width of the domain
        (m; default 2.5 contact widths of the largest load), a roughness profile and its
        pitch, as for :func:`contact.solve_cylinder`.

    Returns
    -------
    RollingSweep
        Loads, forces and moments per unit length, the fitted exponent.

    Raises
    ------
    ContactInputError
        Non-positive loads.

    Examples
    --------
    Elastic hysteresis of a smooth line contact grows as W'^(3/2):
    >>> from contact import cylinder_sweep
    >>> print(f"{cylinder_sweep(0.01, 58.6e9, [1e3, 3e3, 1e4], n=256).fit.exponent:.2f}")
    1.50
    """
    from contact._hertz import hertz_cylinder
    from contact.setups._line import solve_cylinder

    d = dissipation_of(dissipation)
    if d.model != "hysteresis":
        raise ContactInputError("a line-contact sweep has the hysteresis model only")
    w = sweep_loads(loads_per_length)
    n = int(line.setdefault("n", 1024))
    if line.get("size") is None:
        line["size"] = 5.0 * hertz_cylinder(radius, float(w[-1]), e_star).a
    forces = np.zeros(w.size)
    results = []
    sequence = progress(range(w.size)) if progress is not None else range(w.size)
    for k in sequence:
        res = solve_cylinder(radius, float(w[k]), e_star, **line)
        forces[k] = d.alpha_h * hysteresis_work(res, radius, kinematics=d.kinematics,
                                                share=d.share)
        results.append(res)
    settings = {"model": "hysteresis", "alpha_h": d.alpha_h, "share": d.share,
                "kinematics": d.kinematics, "e_star": float(e_star), "grid": n,
                "dx": line["size"] / n, "contact": "cylinder"}
    return _finish("hysteresis", w, forces, float(radius), settings, [], results,
                   d.confidence)
