"""Does Hertz hold for this scan? Scan-level Hertz check: pairing, boundary elements, verdict.

:func:`hertz_check` takes the plate scan (and optionally the ball scan), removes spikes
(optical outliers are not asperities: a single 50 µm spike would carry newtons in an
elastic solution), levels the plate, removes the ball's sphere, pairs the two on one grid
(:func:`surfmet.mechanics.pairing.prepare_pair`), solves the contact elastically and with the softer
body's hardness (:func:`contact._hertzcheck.check_sphere`) and compares with Hertz
(criteria and verdict in :mod:`contact._hertzcheck`).

The combined roughness sigma of the GJM parameter is sqrt(sigma_plate^2 + sigma_ball^2),
each the rms of its scan's *measured* points after its own form removal (plane for the
plate, best-fit sphere for the ball), over the whole scan: non-measured points neither
count nor are replaced by anything in sigma (the contact solver sees them filled with the
nearest measured value, which the notes report).

Its record (:func:`surfmet.records._hertz.hertz_check_record`) has the keys
``hertz_holds``, ``judged`` (false: the scan's pixel does not resolve the contact, no
verdict), ``alpha``, ``sigma``, ``hertz`` {a, delta, p0}, ``bem`` {pmax,
effective_radius, contact_radius, approach, area_fraction, plastic_fraction},
``reasons`` and ``radial_profile`` {r, p_bem, p_hertz}, and ``models``
{hertz, bem, greenwood_tripp[, greenwood_tripp_plastic]} each with ``effective_radius``,
``approach``, ``peak_pressure``, ``radial_profile`` {r, p}, ``radius_error`` and
``profile_error`` against the BEM, ``verdict`` {model, reasons} (the simplest model within
tolerance, :mod:`contact.roughcontact._hierarchy`) and ``summits`` (the combined spectral
summit parameters; absent for smooth scans); every
dimensional value is ``{"value": v, "unit": "..."}`` (``area_fraction`` and
``plastic_fraction`` are fractions of the nominal Hertz area pi a0^2;
``effective_radius`` is the second-moment radius a*, see :mod:`contact._hertzcheck`;
``contact_radius`` is sqrt(A_real/pi), the same quantity under the same name as in
``surfmet contact``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.material_spec import parse_materials
from surfmet.mechanics.scan_preparation import MAX_GRID, SPIKES, PreparedScans, prepare_scans

if TYPE_CHECKING:
    from contact._hertzcheck import HertzComparison, SphereCheck
    from contact._material_pair import MaterialPair
    from contact._materials import Material
    from contact.bem._result import ContactResult
    from contact.roughcontact import SummitParameters
    from contact.roughcontact._hierarchy import ModelHierarchy
    from surfmet.mechanics._types import Materials, ScanSource, Spikes
    from surfmet.mechanics.hertz_adhesion import HertzAdhesion


@dataclass(frozen=True, eq=False)
class HertzCheck:
    """Outcome of :func:`hertz_check`.

    Attributes
    ----------
    comparison : contact._hertzcheck.HertzComparison
        Criteria, verdict and the compared quantities.
    elastic, plastic : contact.ContactResult
        Elastic solution, and the elastic-plastic one (None without a hardness).
    radius, load, e_star : float
    ball_material, plate_material : contact._materials.Material
    scans : PreparedScans
    notes : tuple of str
    materials : contact._material_pair.MaterialPair
        The resolved pair (E*, the default hardness and its source).

    See Also
    --------
    hertz_check : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.hertz_check import hertz_check
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> check = hertz_check(patch, radius=0.02, load=10.0, grid=64)
    >>> print(check.hertz_holds, f"alpha = {check.alpha:.2f}")
    False alpha = 2.42
    """

    comparison: HertzComparison
    elastic: ContactResult
    plastic: ContactResult | None
    radius: float
    load: float
    e_star: float
    ball_material: Material
    plate_material: Material
    scans: PreparedScans
    notes: tuple[str, ...]
    hierarchy: ModelHierarchy | None = None
    summits: SummitParameters | None = None
    grid: int | None = None
    adhesion: HertzAdhesion | None = None
    materials: MaterialPair | None = None

    @property
    def verdict(self) -> str:
        """The simplest model within tolerance (hertz, greenwood_tripp,
        greenwood_tripp_plastic or bem; see :mod:`contact.roughcontact._hierarchy`)."""
        if self.hierarchy is None:
            return "hertz" if self.hertz_holds else "bem"
        return self.hierarchy.verdict

    @property
    def hertz_holds(self) -> bool:
        return self.comparison.hertz_holds

    @property
    def reasons(self) -> tuple[str, ...]:
        return self.comparison.reasons

    @property
    def alpha(self) -> float:
        return self.comparison.alpha

    @property
    def sigma(self) -> float:
        return self.comparison.sigma

    @property
    def result(self) -> Any:
        """The solution the comparison was made on (elastic-plastic when available)."""
        return self.plastic if self.plastic is not None else self.elastic

    @property
    def warnings(self) -> list[str]:
        """A grid too coarse for the contact (fewer cells per Hertz radius than
        :data:`surfmet.mechanics.ball_contact.MIN_CELLS_PER_RADIUS`): the verdict rests
        on an unresolved solution; a scan whose pixel does not resolve the contact
        (:data:`contact._hertzcheck.MIN_SCAN_PIXELS_PER_RADIUS`): no verdict."""
        from surfmet.mechanics.ball_contact import grid_warnings

        c = self.comparison
        scan = [] if c.judged else [c.criterion("resolution").reason]
        return [*scan, *grid_warnings(self.result)]

    def __repr__(self) -> str:
        from surfmet.units import format_quantity as q

        return (f"HertzCheck(verdict={self.verdict!r}, alpha={self.alpha:.4g}, "
                f"load={q(self.load, 'N')}, radius={q(self.radius, 'm')})")

    def _repr_html_(self) -> str:
        """The verdict and the numbers it rests on: GJM alpha, sigma, load, radius, E*,
        Hertz's and the boundary elements' contact radius and peak pressure (Jupyter)."""
        from surfmet._display import quantity_table

        c = self.comparison
        return quantity_table("Hertz check", [
            ("verdict", self.verdict, ""),
            ("Hertz holds", "yes" if self.hertz_holds else "no", ""),
            ("GJM alpha", self.alpha, ""),
            ("sigma", self.sigma, "m"),
            ("load", self.load, "N"),
            ("ball radius", self.radius, "m"),
            ("E*", self.e_star, "Pa"),
            ("Hertz contact radius a0", c.hertz.a, "m"),
            ("Hertz peak pressure p0", c.hertz.p0, "Pa"),
            ("BEM contact radius", self.result.contact_radius, "m"),
            ("BEM peak pressure", c.pmax, "Pa"),
        ])

    def figure(self, path: str | Path | None = None) -> Any:
        """Pressure map and radial profile against Hertz (:mod:`surfmet.plots.hertz`)."""
        from surfmet.plots.hertz import hertz_check_figure

        return hertz_check_figure(self, path)


def hertz_check(
    scan: ScanSource | None = None,
    *,
    radius: float,
    load: float,
    materials: Materials = "steel,aluminium",
    ball: ScanSource | None = None,
    hardness: float | None = None,
    plastic: bool = True,
    spikes: Spikes = SPIKES,
    grid: int | None = None,
    max_grid: int | None = MAX_GRID,
    on_edge: str = "enlarge",
    offset: tuple[float, float] | None = None,
    work_of_adhesion: float | None = None,
    adhesion_range: float | None = None,
) -> HertzCheck:
    """Does Hertz hold for this plate (and ball) at this load?

    Parameters
    ----------
    scan : Topography or path, optional
        Scan of the plate; None for a smooth plate.
    radius : float
        Ball radius R (m).
    load : float
        Normal load W (N).
    materials : str or (Material, Material)
        ``"BALL,PLATE"``, e.g. ``"steel,aluminium"`` or ``"steel,al:H=0.9GPa"``.
    ball : Topography or path, optional
        Scan of the ball (its best-fit sphere is removed).
    hardness : float, optional
        Flow pressure of the softer body (Pa); default the materials' (softer) hardness.
    plastic : bool
        Solve the elastic-plastic contact too (needs a hardness).
    spikes : {"remove", "keep"} or bool
        Remove spikes from the scans before anything else (the default), or keep them
        (:mod:`surfmet.mechanics.scan_preparation`).
    grid, max_grid : int, optional
        Contact grid (cells per side) and the largest automatic grid; ``max_grid=None``
        runs on the scans' own pixel at any size that fits in memory (native resolution).
    on_edge : {"enlarge", "warn", "raise"}
        Contact reaching the domain edge (see :mod:`contact.setups._ball_on_plate`).
    offset : (float, float), optional
        Apex position (x, y) relative to the middle of the paired roughness map (m): a
        track position. Default the middle.
    work_of_adhesion, adhesion_range : float, optional
        Work of adhesion (J/m^2) and interaction range (m, default
        :data:`surfmet.mechanics.hertz_adhesion.DEFAULT_RANGE`): adds the adhesion
        assessment (:mod:`surfmet.mechanics.hertz_adhesion`); without a work of adhesion it
        is left out, with a note.

    Returns
    -------
    HertzCheck
        The verdict (``hertz_holds``, ``reasons``), the roughness parameter ``alpha``, the
        elastic and elastic-plastic solutions and the scans' preparation, and
        ``figure()`` (its record: :func:`surfmet.records._hertz.hertz_check_record`).

    Raises
    ------
    SurfmetInputError, ContactError
        Bad inputs, a scan too small for the contact, a solver failure.

    See Also
    --------
    contact.check_sphere : the engine's check, on arrays.
    surfmet.mechanics.ball_contact.ball_contact : the contact alone.

    References
    ----------
    .. [1] H. Hertz, "Über die Berührung fester elastischer Körper", J. reine angew. Math.
       92 (1882) 156-171.
    .. [2] J. A. Greenwood, K. L. Johnson, E. Matsubara, "A surface roughness parameter in
       Hertz contact", Wear 100 (1984) 47-57.
    .. [3] J. A. Greenwood, J. H. Tripp, "The elastic contact of rough spheres", J. Appl.
       Mech. 34 (1967) 153-159.
    .. [4] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    The paper's 20 mm steel ball at 10 N on a 0.64 mm patch of the bundled aluminium
    plate: its roughness (α = σR/a0² ≈ 2.4) is far beyond Hertz's smooth surfaces:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.hertz_check import hertz_check
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> check = hertz_check(patch, radius=0.02, load=10.0, grid=64)
    >>> print(check.hertz_holds, f"alpha = {check.alpha:.2f}")
    False alpha = 2.42

    Smooth surfaces (no scan) do follow Hertz:

    >>> hertz_check(radius=0.02, load=10.0, grid=64).hertz_holds
    True
    """
    from contact import DomainSpec
    from contact._hertzcheck import check_sphere
    from surfmet.mechanics.material_spec import material_pair
    from surfmet.units import parse_force, parse_length

    radius = parse_length(radius) if isinstance(radius, str) else float(radius)
    load = parse_force(load) if isinstance(load, str) else float(load)
    if not (math.isfinite(radius) and radius > 0):
        raise SurfmetInputError(f"the ball radius must be a positive length, got {radius!r}")
    if not (math.isfinite(load) and load > 0):
        raise SurfmetInputError(f"the load must be a positive force in N, got {load!r}")
    mats = material_pair(materials)
    ball_m, plate_m = parse_materials(mats)
    e_star = mats.e_star
    if adhesion_range is not None and work_of_adhesion is None:
        raise SurfmetInputError("an interaction range needs a work of adhesion "
                                "(--work-of-adhesion)")
    if not plastic:
        hardness = None
    if hardness is not None and not (math.isfinite(hardness) and hardness > 0):
        raise SurfmetInputError(f"the hardness must be a positive pressure, got {hardness!r}")
    # the one home of the default hardness (contact._material_pair.resolve_pair): the
    # user's, else the softer body's table value
    mats = mats.with_hardness(hardness)
    hardness = mats.hardness if plastic else None
    prep = prepare_scans(scan, ball, spikes=spikes)
    pair = prep.pair
    check = check_sphere(
        radius, load, mats,
        roughness=None if pair is None else pair.composite(offset),
        sigma=prep.sigma, hardness=hardness,
        domain=DomainSpec(grid=grid, max_grid=max_grid, on_edge=on_edge),
    )
    notes = [*prep.notes, *check.notes]
    if hardness is None:
        notes.append("no hardness known: elastic solution only, yield not checked")
    summits = scan_summits(prep)
    hierarchy = rough_ball_models(check, summits, radius=radius, load=load, e_star=e_star,
                                  hardness=hardness)
    if summits is None:
        notes.append("no usable roughness spectrum: Greenwood-Tripp not evaluated")
    notes += [f"{name} left out of the models: {why}"
              for name, why in hierarchy.left_out.items()]
    adhesion = _adhesion(summits, radius, load, e_star, work_of_adhesion, adhesion_range)
    if adhesion is None:
        notes.append("adhesion not assessed: give a work of adhesion (--work-of-adhesion W, "
                     "and --range, default 0.3 nm) for the Tabor and Pastewka-Robbins "
                     "parameters")
    return HertzCheck(comparison=check.comparison, elastic=check.elastic,
                      plastic=check.plastic, radius=radius, load=load, e_star=e_star,
                      ball_material=ball_m, plate_material=plate_m, scans=prep,
                      notes=tuple(notes), hierarchy=hierarchy, summits=summits, grid=grid,
                      adhesion=adhesion, materials=mats)


def _adhesion(summits: SummitParameters | None, radius: float, load: float, e_star: float,
              work: float | None, range_: float | None) -> HertzAdhesion | None:
    """The adhesion assessment, or None without a work of adhesion."""
    from surfmet.mechanics.hertz_adhesion import DEFAULT_RANGE, assess_adhesion

    if work is None:
        return None
    return assess_adhesion(summits, radius=radius, load=load, e_star=e_star, work=work,
                           range_=DEFAULT_RANGE if range_ is None else range_)


def scan_summits(prep: PreparedScans) -> SummitParameters | None:
    """Combined Greenwood-Williamson summit parameters of the plate and ball residuals.

    Each residual's areal PSD (:func:`surfmet.psd.areal_psd`, Hann-windowed) gives its
    profile moments m0, m2, m4 (:meth:`surfmet.psd.ArealPSD.profile_moments`); for two
    independent surfaces the moments of the composite (sum) surface add, and Nayak/McCool
    (:func:`contact.roughcontact.summit_parameters`) turn the sums into η, R_s, σ_s.
    None when no scan has roughness. The results depend on the scans' lateral resolution.

    Parameters
    ----------
    prep : PreparedScans
        The prepared scans.

    Returns
    -------
    contact.roughcontact.SummitParameters or None
        Spectral moments, summit density, radius and height spread (None without scans).

    References
    ----------
    .. [1] P. R. Nayak, "Random process model of rough surfaces", J. Lubr. Technol. 93
       (1971) 398-407.
    .. [2] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
       Proc. R. Soc. Lond. A 295 (1966) 300-319.

    Examples
    --------
    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.hertz_check import scan_summits
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> s = scan_summits(prepare_scans(patch))
    >>> print(f"summit radius {s.radius * 1e6:.1f} µm, Nayak alpha {s.alpha:.2f}")
    summit radius 8.6 µm, Nayak alpha 2.99
    """
    from contact.roughcontact import summit_parameters
    from surfmet.psd import areal_psd

    total = [0.0, 0.0, 0.0]
    for topo in prep.residuals.values():
        mom = areal_psd(topo).profile_moments()
        total = [a + b for a, b in zip(total, mom, strict=True)]
    if not all(math.isfinite(v) and v > 0 for v in total):
        return None
    from contact._errors import ContactInputError

    try:
        return summit_parameters(*total)
    except ContactInputError:  # moments no Gaussian surface has: no GW population
        return None


def rough_ball_models(check: SphereCheck, summits: SummitParameters | None, *, radius: float,
                      load: float, e_star: float, hardness: float | None) -> Any:
    """Hertz, Greenwood-Tripp (elastic, and capped at the hardness) against the BEM.

    Parameters
    ----------
    check : contact._hertzcheck.SphereCheck
        The BEM check.
    summits : SummitParameters or None
        The scans' summit parameters (:func:`scan_summits`).
    radius, load, e_star : float
        Ball radius (m), load (N), composite modulus (Pa).
    hardness : float or None
        Hardness of the softer body (Pa): adds the plastic Greenwood-Tripp model.

    Returns
    -------
    contact.roughcontact._hierarchy.ModelHierarchy
        The models side by side, the verdict on which one the contact needs, and the
        models left out with their reasons.

    References
    ----------
    .. [1] J. A. Greenwood, J. H. Tripp, "The elastic contact of rough spheres", J. Appl.
       Mech. 34 (1967) 153-159.

    Examples
    --------
    >>> import surfmet
    >>> from contact import DomainSpec, check_sphere
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.hertz_check import rough_ball_models, scan_summits
    >>> from surfmet.mechanics.scan_preparation import prepare_scans
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> prep = prepare_scans(surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy))
    >>> check = check_sphere(0.02, 10.0, 58.6e9, roughness=prep.pair.composite(None),
    ...                      sigma=prep.sigma, hardness=1.05e9, domain=DomainSpec(grid=64))
    >>> models = rough_ball_models(check, scan_summits(prep), radius=0.02, load=10.0,
    ...                            e_star=58.6e9, hardness=1.05e9)
    >>> list(models.models)
    ['hertz', 'greenwood_tripp', 'greenwood_tripp_plastic', 'bem']
    """
    from contact._errors import ContactInputError, ConvergenceError
    from contact.roughcontact._greenwood_tripp import Asperities, greenwood_tripp
    from contact.roughcontact._hierarchy import model_hierarchy

    extended: dict[str, Any] = {}
    left_out: dict[str, str] = {}
    if summits is not None:
        kw: dict[str, Any] = dict(asperities=Asperities.of(summits))
        # a model that cannot be solved is left out of the hierarchy with its reason, not
        # fatal to the check
        for name, h in (("greenwood_tripp", None), ("greenwood_tripp_plastic", hardness)):
            if name.endswith("plastic") and hardness is None:
                continue
            try:
                extended[name] = greenwood_tripp(load, radius, e_star, hardness=h, **kw)
            except (ConvergenceError, ContactInputError) as exc:
                left_out[name] = str(exc)
    ref = check.plastic if check.plastic is not None else check.elastic
    return model_hierarchy(check.comparison, ref, extended, left_out)
