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
- the peak pressure and the real contact area (fraction of pi a0^2);
- whether the scan resolves the contact at all: its pixel against the Hertz radius. A scan
  with fewer than :data:`MIN_SCAN_PIXELS_PER_RADIUS` measured points per a0 holds (almost)
  no measured asperity inside the contact: the boundary elements then see the
  interpolation between the scan's points, a smooth surface, and their agreement with
  Hertz is no evidence either way. The verdict is then "cannot be judged" (``hertz_holds``
  false, ``judged`` false).

Verdict: Hertz holds when the scan resolves the contact, alpha < 0.05 *and* the measured
macroscopic comparison agrees (profile within 10 % of p0, effective radius and approach
within 10 %, yield on at most 1 % of the nominal area and no first yield at the Hertz
scale). The peak pressure and the real contact area are reported with their numbers but do
not decide: they are asperity-scale quantities that grow (pmax) or shrink (area) as the
lateral resolution of the scan is refined (self-affine roughness has no smallest asperity),
so no resolution-independent limit exists for them. The profile, radius, approach and yield
criteria average over the asperities and are stable under refinement.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from contact._errors import ContactInputError
from contact._fields import (
    PROFILE_EXTENT,
    RadialProfile,
    effective_radius,
    profile_deviation,
    radial_average,
)
from contact._hertz import HertzSphere, hertz_sphere
from contact._material_pair import MaterialPair, modulus
from contact._roughstats import combined_rms, gjm_alpha
from contact.setups._composite import CompositeRoughness

if TYPE_CHECKING:  # the check builds its solves lazily; only the annotations name these
    from contact._geometry import DomainSpec
    from contact.bem._options import SolveOptions

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
#: Fewest scan pixels per Hertz radius for the scan to resolve the contact: 4 puts about
#: 50 measured points (pi 4^2) inside the contact circle; with fewer, the contact sees the
#: interpolation between a handful of points, not the asperities (judgment: Gwyddion and
#: MountainsMap users expect a few measured points per feature before a statistic on it).
MIN_SCAN_PIXELS_PER_RADIUS = 4.0


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
    effective_radius : float
        Effective (second-moment) contact radius a* (m); not the real-area radius
        sqrt(A/pi), which is the result's ``contact_radius``.
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
    effective_radius: float
    approach: float
    area_fraction: float
    plastic_fraction: float
    profile: RadialProfile
    profile_deviation: float
    hardness: float | None
    criteria: tuple[Criterion, ...]
    hertz_holds: bool

    @property
    def judged(self) -> bool:
        """False when the scan does not resolve the contact (its ``resolution`` criterion
        failed): neither the boundary elements nor alpha can then decide."""
        return all(c.passed for c in self.criteria if c.name == "resolution")

    @property
    def headline(self) -> str:
        """The verdict in words: holds, does not hold, or cannot be judged."""
        if not self.judged:
            return "Hertz cannot be judged from this scan (its pixel does not resolve the contact)"
        return "Hertz holds" if self.hertz_holds else "Hertz does not hold"

    @property
    def reasons(self) -> tuple[str, ...]:
        """The criteria's sentences: failed decisive ones first (an unresolved scan before
        all), then the others."""
        order = sorted(self.criteria, key=lambda c: (c.passed or not c.decisive,
                                                     c.name != "resolution", not c.decisive))
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
    scan_pixel: float | None = None,
) -> HertzComparison:
    """Compare a ball-on-plate contact solution with Hertz and give the verdict.

    Parameters
    ----------
    result : contact.ContactResult
        Elastic solution on the grid of :mod:`contact.setups._ball_on_plate` (apex at the origin).
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
    scan_pixel : float, optional
        The measured roughness's pixel (m), before any refinement of the contact grid;
        adds the decisive ``resolution`` criterion (None: smooth surfaces, no criterion).

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
    alpha = gjm_alpha(sigma, radius, hz.a)
    prof, dev = _radial_profile(main, hz)
    a_star = effective_radius(np.asarray(main.pressure), main.x, main.y)
    nominal = math.pi * hz.a**2
    area_frac = main.contact_area / nominal
    plastic_frac = (main.plastic_area / nominal) if plastic is not None else 0.0
    e_pmax = float(result.pmax)
    crit = [
        _alpha_criterion(alpha, sigma, hz.delta),
        _profile_criterion(dev),
        _radius_criterion(a_star, hz.a),
        _approach_criterion(main.approach, hz.delta),
    ]
    if hardness is not None:
        crit += _yield_criteria(hardness, hz.p0, None if plastic is None else plastic_frac)
    crit += _asperity_criteria(main, e_pmax, hz.p0, area_frac, plastic is not None)
    if scan_pixel is not None:
        crit.append(resolution_criterion(scan_pixel, hz.a))
    holds = all(c.passed for c in crit if c.decisive)
    return HertzComparison(
        hertz=hz, sigma=float(sigma), alpha=alpha, pmax=float(main.pmax), elastic_pmax=e_pmax,
        effective_radius=a_star, approach=float(main.approach), area_fraction=area_frac,
        plastic_fraction=plastic_frac, profile=prof, profile_deviation=dev, hardness=hardness,
        criteria=tuple(crit), hertz_holds=bool(holds),
    )


def _radial_profile(main: Any, hz: HertzSphere) -> tuple[RadialProfile, float]:
    """The radial profile against Hertz (bins out to 1.5 a0 or past the loaded cells, inside
    the domain) and its rms deviation within 1.5 a0, over p0."""
    a0 = hz.a
    p = np.asarray(main.pressure)
    rr = np.hypot(main.x[None, :], main.y[:, None])
    loaded = rr[p > 0]
    r_extent = float(loaded.max()) if loaded.size else a0
    r_max = min(max(PROFILE_EXTENT * a0, 1.1 * r_extent),
                float(min(abs(main.x[0]), abs(main.x[-1]), abs(main.y[0]), abs(main.y[-1]))))
    width = max(main.dx, main.dy, a0 / 30.0, r_max / 120.0)
    prof = radial_average(p, main.x, main.y, width=width, r_max=r_max, hertz=hz)
    return prof, profile_deviation(prof, hz.p0, PROFILE_EXTENT * a0)


def resolution_criterion(pixel: float, a0: float) -> Criterion:
    """Does a scan of this pixel (m) resolve a contact of Hertz radius ``a0`` (m)?"""
    cells = a0 / pixel
    ok = cells >= MIN_SCAN_PIXELS_PER_RADIUS
    if ok:
        text = (f"the scan resolves the contact: pixel {_um(pixel)}, {cells:.3g} pixels per "
                f"Hertz radius a0 = {_um(a0)} (at least {MIN_SCAN_PIXELS_PER_RADIUS:g})")
    else:
        text = (f"the scan's pixel {_um(pixel)} does not resolve the contact: {cells:.2g} "
                f"pixels per Hertz radius a0 = {_um(a0)} (at least "
                f"{MIN_SCAN_PIXELS_PER_RADIUS:g} needed); the boundary elements see the "
                "interpolation between the scan's points, not its asperities, so neither "
                "their agreement with Hertz nor α decides: measure with a pixel below "
                f"{_um(a0 / MIN_SCAN_PIXELS_PER_RADIUS)}")
    return Criterion("resolution", cells, MIN_SCAN_PIXELS_PER_RADIUS, ok, True, text)


def _alpha_criterion(alpha: float, sigma: float, d0: float) -> Criterion:
    ok = alpha < ALPHA_LIMIT
    rel = "≪" if alpha < 0.2 * ALPHA_LIMIT else ("<" if ok else (">" if alpha < 4 * ALPHA_LIMIT
                                                                else "≫"))
    if sigma > 0:
        text = (f"α = σR/a0² = {alpha:.3g} {rel} {ALPHA_LIMIT:g} (GJM 1984): the combined "
                f"roughness σ = {_um(sigma)} is {alpha:.3g} × the Hertz approach "
                f"δ0 = {_um(d0)}" + ("" if ok else "; Hertz is not expected to hold"))
    else:
        text = f"α = 0 < {ALPHA_LIMIT:g}: smooth surfaces (no roughness given)"
    return Criterion("alpha", alpha, ALPHA_LIMIT, ok, True, text)


def _profile_criterion(dev: float) -> Criterion:
    ok = dev <= PROFILE_TOLERANCE
    return Criterion(
        "profile", dev, PROFILE_TOLERANCE, ok, True,
        f"the azimuthally averaged pressure {'stays within' if ok else 'departs from'} the "
        f"Hertz profile by {100 * dev:.3g} % of p0 (rms within {PROFILE_EXTENT:g} a0; "
        f"limit {100 * PROFILE_TOLERANCE:g} %)",
    )


def _radius_criterion(a_star: float, a0: float) -> Criterion:
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
    return Criterion("radius", ratio, RADIUS_TOLERANCE, ok, True, text)


def _approach_criterion(approach: float, d0: float) -> Criterion:
    ratio = approach / d0
    ok = abs(ratio - 1) <= APPROACH_TOLERANCE
    return Criterion(
        "approach", ratio, APPROACH_TOLERANCE, ok, True,
        f"the approach from first touch is {ratio:.3g} × the Hertz δ0 "
        f"({_um(approach)} against {_um(d0)}; "
        f"{'within' if ok else 'beyond'} {100 * APPROACH_TOLERANCE:g} %)",
    )


def _yield_criteria(hardness: float, p0: float, plastic_frac: float | None
                    ) -> list[Criterion]:
    """Yield of the asperities (when an elastic-plastic solution was given: its yielded
    fraction of π a0²) and first yield under the surface at the Hertz scale."""
    crit = []
    if plastic_frac is not None:
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
    return crit


def _asperity_criteria(main: Any, e_pmax: float, p0: float, area_frac: float,
                       with_plastic: bool) -> list[Criterion]:
    """The peak pressure and the real area: reported, not decisive (asperity scale)."""
    ratio = e_pmax / p0
    where = "on asperities" if ratio > 1 + PROFILE_TOLERANCE else "at the centre"
    text = f"the peak pressure is {ratio:.3g} × p0 {where} ({_mpa(e_pmax)}, elastic solution"
    if with_plastic and main.pmax < e_pmax * (1 - 1e-9):
        text += f"; {_mpa(main.pmax)} with yield"
    text += "; asperity scale, grows with the scan's lateral resolution: not used for the verdict)"
    return [
        Criterion("peak", ratio, math.inf, True, False, text),
        Criterion(
            "area", area_frac, math.inf, True, False,
            f"real contact covers {area_frac:.3g} × the Hertz area π a0² "
            f"({main.n_clusters} contact spot{'s' if main.n_clusters != 1 else ''}; asperity "
            "scale, not used for the verdict)",
        ),
    ]


@dataclass(frozen=True, eq=False)
class SphereCheck:
    """:func:`check_sphere`'s outcome: the comparison and the solutions behind it."""

    comparison: HertzComparison
    elastic: Any
    plastic: Any
    notes: tuple[str, ...]


def check_sphere(
    radius: float,
    load: float,
    e_star: float | MaterialPair,
    *,
    roughness: CompositeRoughness | None = None,
    sigma: float | None = None,
    hardness: float | None = None,
    domain: DomainSpec | None = None,
    options: SolveOptions | None = None,
) -> SphereCheck:
    """Solve a (rough) ball on a plate elastically and, with a hardness, elastic-plastically,
    and compare with Hertz.

    Parameters
    ----------
    radius, load : float
        R (m), W (N).
    e_star : float or MaterialPair
        E* (Pa), or a resolved :class:`contact._material_pair.MaterialPair` (its E*); its
        default hardness is not applied: ``hardness`` alone adds the plastic solve.
    roughness : CompositeRoughness, optional
        Composite roughness under the ball, with its pitch and the apex position
        (:class:`contact.setups.CompositeRoughness`); None for smooth surfaces.
    sigma : float, optional
        Combined rms roughness for alpha (m); default the rms of the finite points of the
        roughness after removing its least-squares plane (0 without roughness).
    hardness : float, optional
        Hardness of the softer body (Pa); adds the elastic-plastic solve, on the elastic
        solve's final domain, warm-started from it (``SphereContact.solve(hardness=)``).
    domain, options : DomainSpec, SolveOptions, optional
        The domain (with the elastic solve's ``on_edge``) and how each solve runs, as for
        :class:`contact.setups._ball_on_plate.SphereContact` and its ``solve``.

    Returns
    -------
    SphereCheck
        ``comparison`` (the criteria against Hertz and the verdict ``hertz_holds``), the
        ``elastic`` and, with a hardness, the ``plastic`` :class:`ContactResult`.

    Raises
    ------
    ContactInputError
        A radius, load, modulus or hardness that is not positive and finite.

    See Also
    --------
    contact.solve_sphere, contact.gjm_alpha

    References
    ----------
    .. [1] H. Hertz, "Über die Berührung fester elastischer Körper", J. reine angew. Math.
       92 (1882) 156-171.
    .. [2] J. A. Greenwood, K. L. Johnson, E. Matsubara, "A surface roughness parameter in
       Hertz contact", Wear 100 (1984) 47-57.

    Examples
    --------
    The bundled plate's roughness (α ≈ 2.6) is far from Hertz's smooth surfaces:

    >>> import surfmet
    >>> from contact import CompositeRoughness, DomainSpec, check_sphere
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> rough = CompositeRoughness(plate.heights[128:384, 384:640], plate.dx)
    >>> check = check_sphere(0.02, 10.0, 58.6e9, roughness=rough,
    ...                      domain=DomainSpec(grid=64)).comparison
    >>> print(check.hertz_holds, f"alpha = {check.alpha:.1f}")
    False alpha = 2.6
    """
    from contact._geometry import remove_plane
    from contact.setups._ball_on_plate import SphereContact

    e_star = modulus(e_star)
    scan_pixel = None if roughness is None else max(roughness.dx, roughness.dy)
    if sigma is None:
        if roughness is None:
            sigma = 0.0
        else:
            z, _ = remove_plane(np.asarray(roughness.heights), roughness.dx, roughness.dy)
            sigma = combined_rms(z)
    # memory check: the elastic and the plastic result are kept together, and the
    # plastic solve needs about one result's worth more (contact.bem._memory)
    problem = SphereContact(radius, e_star, load, roughness=roughness, domain=domain,
                            results=1 if hardness is None else 3)
    elastic = problem.solve(load, options=options)
    notes = list(elastic.notes)
    plastic = None
    if hardness is not None:
        # the domain is the elastic one (never enlarged again): a plastic contact that
        # reaches its edge is reported as truncated
        plastic = problem.solve(load, hardness=hardness, initial=elastic, on_edge="warn",
                                options=options)
        notes += [n for n in plastic.notes if n not in notes]
    comp = compare_with_hertz(elastic, radius=radius, sigma=float(sigma), plastic=plastic,
                              hardness=hardness, scan_pixel=scan_pixel)
    return SphereCheck(comparison=comp, elastic=elastic, plastic=plastic, notes=tuple(notes))
