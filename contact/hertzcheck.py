"""Does Hertz hold? The rough-contact solution measured against Hertz theory.

Two kinds of evidence are combined.

Classical criterion (Greenwood, Johnson & Matsubara 1984, Wear 100:47; Johnson 1985,
*Contact Mechanics*, sec. 13.4): the roughness parameter

    alpha = sigma R / a0^2 = sigma / delta0,

with sigma the combined rms roughness of the two surfaces (after form removal), R the ball
radius and a0, delta0 = a0^2/R the smooth (Hertz) contact radius and approach. It is the
roughness measured in units of the Hertz approach: the paper's remark that the asperities
are taller than the 0.936 µm approach is alpha > 1. GJM found Hertz accurate to about 7 %
for alpha < 0.05.

Measured criterion: the boundary-element solution on the actual roughness, compared with
Hertz at the same load:

- the radial pressure profile: the azimuthal average of the pressure field about the ball's
  apex against the Hertz pressure averaged over the same cells; the area-weighted rms of the
  difference within 1.5 a0, in units of p0 (``profile_deviation``);
- the effective contact radius: the radius a* of the Hertz distribution with the same
  second moment of pressure about the pressure centroid, a* = sqrt(5/2 <r^2>_p) (for
  Hertz <r^2>_p = 2 a^2 / 5, so a* = a exactly);
- the approach (from first touch) against delta0;
- whether the asperities yield: the area at the hardness (elastic-perfectly-plastic
  solution) as a fraction of the nominal Hertz area pi a0^2, and whether the Hertz peak
  pressure itself exceeds first yield below the surface, p0 = 1.60 Y for nu = 0.3 (Johnson
  sec. 6.2) with Y ~ H / 2.8 (Tabor 1951), i.e. p0 > 0.57 H;
- the peak pressure and the real contact area (fraction of pi a0^2).

Verdict: Hertz holds when alpha < 0.05 *and* the measured macroscopic comparison agrees
(profile within 10 % of p0, effective radius and approach within 10 %, yield on at most 1 %
of the nominal area and no first yield at the Hertz scale). The peak pressure and the real
contact area are reported with their numbers but do not decide: they are asperity-scale
quantities that grow (pmax) or shrink (area) as the lateral resolution of the scan is
refined (self-affine roughness has no smallest asperity), so no resolution-independent
limit exists for them. The profile, radius, approach and yield criteria average over the
asperities and are stable under refinement.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from contact.errors import ContactInputError
from contact.fields import (
    PROFILE_EXTENT,
    RadialProfile,
    effective_radius,
    profile_deviation,
    radial_average,
)
from contact.hertz import HertzSphere, hertz_sphere
from contact.roughstats import combined_rms, gjm_alpha

#: GJM (1984): Hertz is accurate to a few percent below this alpha.
ALPHA_LIMIT = 0.05
#: Largest rms deviation of the averaged pressure profile from Hertz, in units of p0.
PROFILE_TOLERANCE = 0.10
#: Largest relative deviation of the effective radius and of the approach from Hertz.
RADIUS_TOLERANCE = 0.10
APPROACH_TOLERANCE = 0.10
#: Largest yielded area, as a fraction of the nominal Hertz area pi a0^2.
PLASTIC_LIMIT = 0.01
#: First yield below the surface of a Hertz contact: p0 = 1.60 Y (nu = 0.3, Johnson
#: sec. 6.2) with Y = H / 2.8 (Tabor): p0 / H = 1.60 / 2.8.
FIRST_YIELD_P0_OVER_H = 1.60 / 2.8


@dataclass(frozen=True)
class Criterion:
    """One comparison behind the verdict.

    ``value`` is dimensionless (ratio or fraction); ``passed`` says whether it is within
    ``limit``; ``decisive`` whether it takes part in the verdict; ``reason`` is the
    sentence shown to the user, with its numbers.
    """

    name: str
    value: float
    limit: float
    passed: bool
    decisive: bool
    reason: str


@dataclass(frozen=True, eq=False)
class HertzComparison:
    """Boundary-element solution against Hertz, with the verdict.

    Attributes
    ----------
    hertz : HertzSphere
        Hertz solution at the load of the solution.
    sigma, alpha : float
        Combined rms roughness (m) and the GJM parameter.
    pmax : float
        Peak pressure of the (elastic-plastic, when a hardness was given) solution (Pa).
    elastic_pmax : float
        Peak pressure of the purely elastic solution (Pa).
    contact_radius : float
        Effective (second-moment) contact radius a* (m).
    approach : float
        Approach from first touch (m).
    area_fraction : float
        Real contact area / pi a0^2.
    plastic_fraction : float
        Area at the hardness / pi a0^2 (0 without a hardness).
    profile : RadialProfile
        Radial pressure profile (BEM and Hertz averaged over the same cells).
    profile_deviation : float
        Area-weighted rms of the profile difference within 1.5 a0, over p0.
    hardness : float or None
    criteria : tuple of Criterion
    hertz_holds : bool
    """

    hertz: HertzSphere
    sigma: float
    alpha: float
    pmax: float
    elastic_pmax: float
    contact_radius: float
    approach: float
    area_fraction: float
    plastic_fraction: float
    profile: RadialProfile
    profile_deviation: float
    hardness: float | None
    criteria: tuple[Criterion, ...]
    hertz_holds: bool

    @property
    def reasons(self) -> tuple[str, ...]:
        """The criteria's sentences: failed decisive ones first, then the others."""
        order = sorted(self.criteria, key=lambda c: (c.passed or not c.decisive, not c.decisive))
        return tuple(c.reason for c in order)

    def criterion(self, name: str) -> Criterion:
        """The criterion called ``name`` (alpha, profile, radius, approach, yield,
        first_yield, peak, area)."""
        for c in self.criteria:
            if c.name == name:
                return c
        raise KeyError(name)


def _um(v: float) -> str:
    return f"{v * 1e6:.3g} µm"


def _mpa(v: float) -> str:
    return f"{v / 1e9:.3g} GPa" if abs(v) >= 1e9 else f"{v / 1e6:.3g} MPa"


def compare_with_hertz(
    result: Any,
    *,
    radius: float,
    sigma: float,
    plastic: Any = None,
    hardness: float | None = None,
) -> HertzComparison:
    """Compare a ball-on-plate contact solution with Hertz and give the verdict.

    Parameters
    ----------
    result : contact.ContactResult
        Elastic solution on the grid of :mod:`contact.sphere` (apex at the origin).
    radius : float
        Ball radius R (m).
    sigma : float
        Combined rms roughness (m) for the GJM parameter (computed by the caller from the
        measured points only).
    plastic : contact.ContactResult, optional
        Elastic-perfectly-plastic solution at the same load (pressure capped at
        ``hardness``); when given, it is the solution the comparison is made on.
    hardness : float, optional
        The hardness (Pa) of the softer body; default ``plastic.hardness``.

    Returns
    -------
    HertzComparison
    """
    if result is None or not getattr(result, "load", 0) > 0:
        raise ContactInputError("the contact solution carries no load")
    main = plastic if plastic is not None else result
    if hardness is None and plastic is not None:
        hardness = plastic.hardness
    hz = hertz_sphere(radius, main.load, main.e_star)
    a0, p0, d0 = hz.a, hz.p0, hz.delta
    alpha = gjm_alpha(sigma, radius, a0)
    p = np.asarray(main.pressure)
    rr = np.hypot(main.x[None, :], main.y[:, None])
    loaded = rr[p > 0]
    r_extent = float(loaded.max()) if loaded.size else a0
    r_max = min(max(PROFILE_EXTENT * a0, 1.1 * r_extent),
                float(min(abs(main.x[0]), abs(main.x[-1]), abs(main.y[0]), abs(main.y[-1]))))
    width = max(main.dx, main.dy, a0 / 30.0, r_max / 120.0)
    prof = radial_average(p, main.x, main.y, width=width, r_max=r_max, hertz=hz)
    dev = profile_deviation(prof, p0, PROFILE_EXTENT * a0)
    a_star = effective_radius(p, main.x, main.y)
    nominal = math.pi * a0**2
    area_frac = main.contact_area / nominal
    plastic_frac = (main.plastic_area / nominal) if plastic is not None else 0.0
    e_pmax = float(result.pmax)

    crit: list[Criterion] = []
    ok = alpha < ALPHA_LIMIT
    rel = "≪" if alpha < 0.2 * ALPHA_LIMIT else ("<" if ok else (">" if alpha < 4 * ALPHA_LIMIT
                                                                else "≫"))
    if sigma > 0:
        text = (f"α = σR/a0² = {alpha:.3g} {rel} {ALPHA_LIMIT:g} (GJM 1984): the combined "
                f"roughness σ = {_um(sigma)} is {alpha:.3g} × the Hertz approach "
                f"δ0 = {_um(d0)}" + ("" if ok else "; Hertz is not expected to hold"))
    else:
        text = f"α = 0 < {ALPHA_LIMIT:g}: smooth surfaces (no roughness given)"
    crit.append(Criterion("alpha", alpha, ALPHA_LIMIT, ok, True, text))
    ok = dev <= PROFILE_TOLERANCE
    crit.append(Criterion(
        "profile", dev, PROFILE_TOLERANCE, ok, True,
        f"the azimuthally averaged pressure {'stays within' if ok else 'departs from'} the "
        f"Hertz profile by {100 * dev:.3g} % of p0 (rms within {PROFILE_EXTENT:g} a0; "
        f"limit {100 * PROFILE_TOLERANCE:g} %)",
    ))
    ratio = a_star / a0
    ok = abs(ratio - 1) <= RADIUS_TOLERANCE
    if ok:
        text = (f"the effective contact radius a* = {_um(a_star)} is {ratio:.3g} a0 "
                f"(a0 = {_um(a0)}; within {100 * RADIUS_TOLERANCE:g} %)")
    elif ratio > 1:
        text = (f"the load spreads to a* = {ratio:.3g} a0 ({_um(a_star)} against the Hertz "
                f"a0 = {_um(a0)}; second-moment radius)")
    else:
        text = (f"the load concentrates within a* = {ratio:.3g} a0 ({_um(a_star)} against "
                f"the Hertz a0 = {_um(a0)}; second-moment radius)")
    crit.append(Criterion("radius", ratio, RADIUS_TOLERANCE, ok, True, text))
    ratio = main.approach / d0
    ok = abs(ratio - 1) <= APPROACH_TOLERANCE
    crit.append(Criterion(
        "approach", ratio, APPROACH_TOLERANCE, ok, True,
        f"the approach from first touch is {ratio:.3g} × the Hertz δ0 "
        f"({_um(main.approach)} against {_um(d0)}; "
        f"{'within' if ok else 'beyond'} {100 * APPROACH_TOLERANCE:g} %)",
    ))
    if hardness is not None:
        if plastic is not None:
            ok = plastic_frac <= PLASTIC_LIMIT
            if plastic_frac > 0:
                text = (f"asperities yield on {100 * plastic_frac:.3g} % of the nominal area "
                        f"π a0² (pressure at the hardness H = {_mpa(hardness)}"
                        f"{'' if ok else f'; limit {100 * PLASTIC_LIMIT:g} %'})")
            else:
                text = f"no asperity reaches the hardness H = {_mpa(hardness)}"
            crit.append(Criterion("yield", plastic_frac, PLASTIC_LIMIT, ok, True, text))
        ratio = p0 / hardness
        ok = ratio < FIRST_YIELD_P0_OVER_H
        crit.append(Criterion(
            "first_yield", ratio, FIRST_YIELD_P0_OVER_H, ok, True,
            f"the Hertz peak pressure p0 = {_mpa(p0)} is {ratio:.3g} H "
            + (f"(below first yield under the surface, p0 = 1.6 Y ≈ "
               f"{FIRST_YIELD_P0_OVER_H:.2f} H)" if ok else
               f"(at or beyond first yield under the surface, p0 = 1.6 Y ≈ "
               f"{FIRST_YIELD_P0_OVER_H:.2f} H: the smooth contact itself is not elastic)"),
        ))
    ratio = e_pmax / p0
    where = "on asperities" if ratio > 1 + PROFILE_TOLERANCE else "at the centre"
    text = f"the peak pressure is {ratio:.3g} × p0 {where} ({_mpa(e_pmax)}, elastic solution"
    if plastic is not None and main.pmax < e_pmax * (1 - 1e-9):
        text += f"; {_mpa(main.pmax)} with yield"
    text += "; asperity scale, grows with the scan's lateral resolution: not used for the verdict)"
    crit.append(Criterion("peak", ratio, math.inf, True, False, text))
    crit.append(Criterion(
        "area", area_frac, math.inf, True, False,
        f"real contact covers {area_frac:.3g} × the Hertz area π a0² "
        f"({main.n_clusters} contact spot{'s' if main.n_clusters != 1 else ''}; asperity "
        "scale, not used for the verdict)",
    ))
    holds = all(c.passed for c in crit if c.decisive)
    return HertzComparison(
        hertz=hz, sigma=float(sigma), alpha=alpha, pmax=float(main.pmax), elastic_pmax=e_pmax,
        contact_radius=a_star, approach=float(main.approach), area_fraction=area_frac,
        plastic_fraction=plastic_frac, profile=prof, profile_deviation=dev, hardness=hardness,
        criteria=tuple(crit), hertz_holds=bool(holds),
    )


@dataclass(frozen=True, eq=False)
class SphereCheck:
    """:func:`check_sphere`'s outcome: the comparison and the solutions behind it."""

    comparison: HertzComparison
    elastic: Any
    plastic: Any
    notes: tuple[str, ...]


def solve_elastic_plastic(
    problem: Any,
    load: float,
    hardness: float,
    *,
    elastic: Any = None,
    plastic_start: np.ndarray | None = None,
    pressure_start: np.ndarray | None = None,
    tol: float = 1e-6,
    method: str = "auto",
    yield_tol: float = 1e-3,
    relax: float = 0.7,
    anderson: int = 6,
    max_outer: int = 300,
    engine_iterations: int = 2000,
) -> Any:
    """Elastic-perfectly-plastic solution of a ball on a plate.

    Two independent algorithms solve the same conditions (p <= H everywhere, p = H
    wherever the plastic displacement u_pl > 0, elastic complementarity elsewhere, load
    balance):

    - ``"capped"``: the solver's own capped Polonsky-Keer iteration
      (:func:`contact.bem.solve_normal` with ``hardness``; the plastic cells are a second
      active set, see the notes of :mod:`contact.bem`), warm-started from the elastic
      solution clipped at H. Exact to the solver tolerance and robust from elastic to
      fully plastic contacts; the default.
    - ``"fixed-point"``: a plastic-displacement iteration built on elastic solves only:
      solve the elastic contact of the gap h + u_pl, take the pressure above the hardness
      on the yielded set, and deepen u_pl there by the displacement that excess pressure
      makes (one convolution); where u_pl > 0 and p < H the indentation shrinks. The load
      constraint pushes part of the removed load back onto the yielded cells, a slow mode
      of the plain iteration when most of the contact yields; Anderson mixing (Walker & Ni
      2011, SIAM J. Numer. Anal. 49:1715) over the last ``anderson`` steps removes it.
      Every elastic solve is warm-started. It shares nothing with the capped iteration
      but the elastic solver, which makes it a cross-check; deeply plastic contacts (Hertz
      p0 tens of times H) converge slowly and may raise
      :class:`~contact.errors.ConvergenceError`.
    - ``"auto"``: ``"capped"``.

    Parameters
    ----------
    problem : contact.sphere.SphereContact
        The *elastic* problem (no hardness), on the domain to use.
    load : float
        Normal load (N).
    hardness : float
        Pressure cap H (Pa).
    elastic : ContactResult, optional
        Elastic solution of ``problem`` at ``load`` (solved here if absent).
    plastic_start, pressure_start : ndarray, optional
        Warm start of the plastic displacement (fixed-point iteration) and of the
        pressure (e.g. from a lower load of a sweep; plastic displacement only grows with
        the load).
    tol : float
        Tolerance of the solves (:func:`contact.bem.solve_normal`).
    method : {"auto", "capped", "fixed-point"}
        The algorithm (see above).
    yield_tol : float
        Fixed point: stop when the pressure exceeds H by at most this fraction of H.
    relax : float
        Fixed point: mixing parameter of the plastic-displacement update (0 < relax <= 1).
    anderson : int
        Fixed point: depth of the Anderson mixing history.
    max_outer : int
        Fixed point: outer-iteration limit.
    engine_iterations : int
        Capped solver: iteration limit.

    Returns
    -------
    ContactResult
        ``hardness`` set, the pressure at H on the yielded cells, ``plastic_displacement``
        the permanent (combined) indentation; ``extra["plastic_method"]`` says which
        method produced it.

    Raises
    ------
    ConvergenceError
        The chosen method did not converge.
    """
    import dataclasses
    import warnings

    from contact.bem import convolution, solve_normal
    from contact.errors import ConvergenceError, EdgeContactWarning
    from contact.result import build_result

    if not (math.isfinite(hardness) and hardness > 0):
        raise ContactInputError(f"the hardness must be a positive pressure, got {hardness!r}")
    if method not in ("auto", "capped", "fixed-point"):
        raise ContactInputError(
            f"method must be 'auto', 'capped' or 'fixed-point', got {method!r}")
    if getattr(problem, "hardness", None) is not None:
        raise ContactInputError("give the elastic problem (built without a hardness)")
    if method == "auto":
        method = "capped"
    n, dx = problem.domain.n, problem.domain.dx
    e_star = problem.e_star
    origin = (-(n // 2) * dx, -(n // 2) * dx)
    h = problem.gap0
    hz = hertz_sphere(problem.radius, load, e_star)
    if elastic is None and pressure_start is None:
        elastic = problem.solve(load, tol=tol, on_edge="warn")
    start = pressure_start if pressure_start is not None else np.asarray(elastic.pressure)
    if start.shape != h.shape:
        raise ContactInputError("the warm start does not match the problem's grid")

    def finish(res: Any, method: str, extra: dict[str, Any]) -> Any:
        notes = list(getattr(problem, "notes", []))
        if res.touches_edge:
            msg = ("contact pressure reaches the edge of the domain in the elastic-plastic "
                   "solution: the result is truncated")
            warnings.warn(msg, EdgeContactWarning, stacklevel=3)
            notes.append(msg)
        return dataclasses.replace(res, hertz=hz, notes=tuple(notes),
                                   extra={**res.extra, "plastic_method": method, **extra})

    if method == "capped":
        res = solve_normal(h, dx, e_star=e_star, load=load, hardness=hardness,
                           initial=np.minimum(start, hardness), tol=tol,
                           max_iter=engine_iterations, origin=origin, edge="ignore",
                           strict=True)
        return finish(res, "capped conjugate gradient (contact.bem)", {})

    conv = convolution(n, n, float(dx), float(dx), False)
    upl = (np.zeros_like(h) if plastic_start is None
           else np.maximum(np.asarray(plastic_start, dtype=float), 0.0))
    if upl.shape != h.shape:
        raise ContactInputError("the plastic warm start does not match the problem's grid")
    p = start
    its = 0
    hist_u: list[np.ndarray] = []
    hist_g: list[np.ndarray] = []
    best = math.inf
    res = None
    worst = math.inf
    n_outer = 0
    for n_outer in range(1, max_outer + 1):  # noqa: B007 (reported after the loop)
        res = solve_normal(h + upl, dx, e_star=e_star, load=load, initial=p, tol=tol,
                           origin=origin, edge="ignore")
        its += res.iterations
        p = np.asarray(res.pressure)
        excess = p - hardness
        active = (excess > 0) | (upl > 0)
        step = np.where(active, excess, 0.0)
        worst = float(np.abs(step).max()) / hardness
        if worst <= yield_tol:
            break
        # the fixed-point map u -> u + K*(excess)/E*; its slow mode (load pushed back onto
        # the yielded cells by the load constraint) is what Anderson mixing removes
        g = np.where(active, conv(step) / e_star, 0.0).ravel()
        if worst > 4.0 * best:  # a bad extrapolation: forget the history
            hist_u.clear()
            hist_g.clear()
        best = min(best, worst)
        hist_u.append(upl.ravel().copy())
        hist_g.append(g)
        if len(hist_u) > anderson + 1:
            hist_u.pop(0)
            hist_g.pop(0)
        new = hist_u[-1] + relax * hist_g[-1]
        if len(hist_u) >= 2:
            d_g = np.stack([b - a for a, b in itertools.pairwise(hist_g)], axis=1)
            d_u = np.stack([b - a for a, b in itertools.pairwise(hist_u)], axis=1)
            gamma, *_ = np.linalg.lstsq(d_g, hist_g[-1], rcond=None)
            new = new - (d_u + relax * d_g) @ gamma
        upl = np.maximum(new.reshape(h.shape), 0.0)
    else:
        raise ConvergenceError(
            f"the elastic-plastic iteration stopped after {max_outer} steps with the "
            f"pressure {100 * worst:.3g} % above the hardness (deeply plastic contacts, "
            "Hertz p0 many times the hardness, converge slowly); raise max_outer or use "
            "the rigid-plastic estimate", residual=worst, iterations=its,
        )
    pressure = np.where(upl > 0, hardness, np.minimum(p, hardness))
    x = origin[0] + np.arange(n) * dx
    out = build_result(
        pressure=pressure, gap=np.asarray(res.gap), displacement=np.asarray(res.displacement),
        plastic_displacement=upl, x=x, y=x.copy(), dx=dx, dy=dx, e_star=e_star,
        hardness=hardness, periodic=False, approach=res.approach, iterations=its,
        residual=res.residual, converged=True,
    )
    return finish(out, "plastic-displacement iteration on elastic solves",
                  {"outer_iterations": n_outer, "yield_excess": worst})


def check_sphere(
    radius: float,
    load: float,
    e_star: float,
    *,
    roughness: np.ndarray | None = None,
    roughness_dx: float | None = None,
    roughness_dy: float | None = None,
    sigma: float | None = None,
    hardness: float | None = None,
    grid: int | None = None,
    size: float | None = None,
    max_grid: int | None = 1024,
    on_edge: str = "enlarge",
    tol: float = 1e-6,
    centre: tuple[float, float] | None = None,
) -> SphereCheck:
    """Solve a (rough) ball on a plate elastically and, with a hardness, elastic-plastically,
    and compare with Hertz.

    Parameters
    ----------
    radius, load, e_star : float
        R (m), W (N), E* (Pa).
    roughness : ndarray, optional
        Composite roughness (m), NaN where not measured (see :mod:`contact.sphere`).
    roughness_dx, roughness_dy : float, optional
        Its pitch (m).
    sigma : float, optional
        Combined rms roughness for alpha (m); default the rms of the finite points of
        ``roughness`` after removing its least-squares plane (0 without roughness).
    hardness : float, optional
        Hardness of the softer body (Pa); adds the elastic-plastic solve.
    grid, size, max_grid, on_edge, tol
        Passed to :class:`contact.sphere.SphereContact` and its ``solve``.
    centre : (float, float), optional
        Scan coordinates of the ball's apex on the roughness map (m); default its middle.
    """
    from contact.geometry import remove_plane
    from contact.sphere import SphereContact

    if sigma is None:
        if roughness is None:
            sigma = 0.0
        else:
            dx = roughness_dx if roughness_dx else 1.0
            z, _ = remove_plane(np.asarray(roughness, dtype=float), dx, roughness_dy or dx)
            sigma = combined_rms(z)
    # memory check: the elastic and the plastic result are kept together, and the
    # plastic solve needs about one result's worth more (contact.memory)
    common = dict(roughness=roughness, roughness_dx=roughness_dx, roughness_dy=roughness_dy,
                  grid=grid, size=size, max_grid=max_grid, centre=centre,
                  results=1 if hardness is None else 3)
    el_problem = SphereContact(radius, e_star, load, **common)
    elastic = el_problem.solve(load, on_edge=on_edge, tol=tol)
    notes = list(elastic.notes)
    plastic = None
    if hardness is not None:
        # on the domain the elastic solve ended with (it may have been enlarged)
        plastic = solve_elastic_plastic(el_problem, load, hardness, elastic=elastic, tol=tol)
        notes += [n for n in plastic.notes if n not in notes]
    comp = compare_with_hertz(elastic, radius=radius, sigma=float(sigma), plastic=plastic,
                              hardness=hardness)
    return SphereCheck(comparison=comp, elastic=elastic, plastic=plastic, notes=tuple(notes))


def summary_lines(comp: HertzComparison) -> Sequence[str]:
    """Human-readable lines: the verdict and its reasons."""
    head = "Hertz holds" if comp.hertz_holds else "Hertz does not hold"
    return [head, *(f"- {r}" for r in comp.reasons)]
