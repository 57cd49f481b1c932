"""``surfmet adhesion``'s facade: an adhesive sphere (or cylinder) on a flat, approached
and retracted.

:func:`adhesion` resolves the modulus (a material pair or E* itself), builds the adhesion
law (:mod:`contact.adhesion.laws`), samples the scans' roughness onto the solver's grid
(:func:`rough_grid`) and runs the cycle of :func:`contact.adhesion.ball.adhesive_ball`
(the line contact's facade, on :func:`contact.adhesion.line.adhesive_line`, is
:mod:`surfmet.mechanics.adhesion_line`);
:func:`surfmet.records._adhesion.adhesion_record` is its JSON record, :func:`plot`
its figure. The range means h0 = w / sigma0 for the Dugdale law and rho for
the exponential one.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics._adhesion_scans import (  # noqa: F401  (the facade's face)
    rough_grid,
    scan_too_small,
)
from surfmet.mechanics.adhesion_laws import (  # noqa: F401  (the facade's face)
    INTERACTION,
    interaction_law,
    interaction_name,
)
from surfmet.mechanics.scan_preparation import SPIKES

if TYPE_CHECKING:

    from contact.adhesion._ring_ball import RingBall
    from contact.adhesion.ball import AdhesiveBall
    from contact.adhesion.default_grid import GridChoice
    from contact.adhesion.line import AdhesiveLine
    from surfmet.mechanics._types import AdhesionLaw, Materials, PathLike, ScanSource, Spikes
    from surfmet.mechanics.scan_preparation import ScansUsed

@dataclass(frozen=True, eq=False)
class Adhesion:
    """What ``surfmet adhesion`` computed: the cycle and the scans it was run on.

    Attributes
    ----------
    result : AdhesiveBall or AdhesiveLine
        :class:`contact.adhesion.ball.AdhesiveBall` (a sphere) or
        :class:`contact.adhesion.line.AdhesiveLine` (a cylinder, per unit length).
    scans : ScansUsed or None
        What scans were used and what was done to them (None: smooth surfaces).
    grid_why : str
        How the grid was chosen (the default resolves the cohesive zone, within memory).

    See Also
    --------
    adhesion : makes it.
    surfmet.records._adhesion.adhesion_record : its JSON record.

    Examples
    --------
    A coarse run: the result's warnings say what the grid does not resolve:

    >>> from surfmet.mechanics.adhesion import adhesion
    >>> run = adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=16, steps=6)
    >>> type(run.result).__name__, run.scans, run.result.warnings[0][:32]
    ('AdhesiveBall', None, 'grid too coarse for the interact')
    """

    result: AdhesiveBall | AdhesiveLine | RingBall
    scans: ScansUsed | None = None
    grid_why: str = "given by the user"

    @property
    def line(self) -> bool:
        """Whether this is a line contact (results per unit length)."""
        return hasattr(self.result, "cells")

    @property
    def axisymmetric(self) -> bool:
        """Whether the sphere was solved on rings
        (:class:`contact.adhesion._ring_ball.RingBall`) rather than a periodic 3D grid."""
        return hasattr(self.result, "rings")


#: The discretisations of the sphere: ``auto`` takes rings for a smooth sphere without
#: ``grid`` or ``size`` (the periodic grid's), the 3D grid otherwise.
MODELS = ("auto", "axisymmetric", "3d")


def adhesion(radius: float, *, work: float | None = None, range_: float | None = None,
             materials: Materials | None = None, e_star: float | None = None,
             interaction: str | AdhesionLaw = INTERACTION,
             grid: int | None = None, size: float | None = None, steps: int = 40,
             plate: ScanSource | None = None, ball: ScanSource | None = None,
             spikes: Spikes = SPIKES, model: str = "auto",
             progress: Callable[[int, int], None] | None = None) -> Adhesion:
    """The approach-retraction cycle of a sphere of ``radius`` on a flat (a cylinder:
    :func:`surfmet.mechanics.adhesion_line.line_adhesion`).

    Give exactly one of ``materials`` ("BALL,PLATE" text or two materials) and ``e_star``
    (Pa). ``plate`` and ``ball`` are scans (paths or Topography): levelled, the ball's
    sphere removed, paired and sampled onto the solver's grid
    (:func:`rough_grid`); the scans are read and checked before any solve. ``grid`` is
    the cells per side (default :func:`default_grid`: for the Dugdale law the grid, at
    least 128, that gives the cohesive zone two pixels, within memory). The Dugdale law's
    step is smoothed on the grid's scale
    (:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`: same work and peak, so the same
    Maugis parameter), which removes most of the pixel pinning of the zone's end;
    the Maugis-Dugdale validation (tests/test_adhesion_validation.py) is of this law.

    Parameters
    ----------
    radius : float
        Ball radius R (m).
    work, range_ : float, optional
        Work of adhesion w (J/m²) and the interaction's range (m), for a law named by
        ``interaction`` that is stated by the two.
    materials : str or (Material, Material), optional
        ``"BALL,PLATE"``; or give ``e_star``.
    e_star : float, optional
        Composite modulus E* (Pa).
    interaction : str or InteractionLaw
        The adhesion law's name (:func:`contact.adhesion.laws.law_names`,
        built by :func:`interaction_law`), or a law itself (without ``work`` and
        ``range_``).
    grid, size : optional
        Cells per side (default :func:`default_grid`) and domain side (m).
    steps : int
        Approach and retraction steps.
    plate, ball : Topography or path, optional
        Scans (smooth surfaces without).
    spikes : {"remove", "keep"} or bool
        Spike handling of the scans.
    model : {"auto", "axisymmetric", "3d"}
        The discretisation (:data:`MODELS`): a smooth sphere without ``grid`` and
        ``size`` is solved on rings by default (:func:`ring_run`: axisymmetric, the
        cohesive zone resolved at any lambda for the price of a radius), a rough one or
        one given a grid on the periodic 3D grid.
    progress : callable, optional
        ``progress(done, total)`` after each step.

    Returns
    -------
    Adhesion
        The cycle (loads, approaches, contact radii, jumps), the pull-off force beside
        JKR's and DMT's, the Tabor and Maugis parameters.

    Raises
    ------
    SurfmetInputError, ContactError
        Both or neither of ``materials`` and ``e_star``, bad values, scans too small for
        the domain, a solver failure.

    See Also
    --------
    surfmet.mechanics.adhesion_line.line_adhesion : the cylinder.
    surfmet.mechanics.hertz_adhesion.assess_adhesion : whether adhesion matters at all.

    References
    ----------
    .. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
       J. Colloid Interface Sci. 150 (1992) 243-269.
    .. [2] K. L. Johnson, K. Kendall, A. D. Roberts, "Surface energy and the contact of
       elastic solids", Proc. R. Soc. Lond. A 324 (1971) 301-313.
    .. [3] B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, "Effect of contact deformations
       on the adhesion of particles", J. Colloid Interface Sci. 53 (1975) 314-326.

    Examples
    --------
    A 10 µm sphere, w = 0.05 J/m², E* = 1 GPa: the Maugis parameter 1.6 lies between the
    JKR and DMT limits, and so does the pull-off force (1.5 π w R = 2.36 µN, 2 π w R =
    3.14 µN); this coarse grid overestimates it slightly, as its warning says:

    >>> from surfmet.mechanics.adhesion import adhesion
    >>> from surfmet.records._adhesion import adhesion_record
    >>> run = adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=32, steps=6)
    >>> rec = adhesion_record(run)
    >>> print(f"lambda = {rec['maugis_parameter']['value']:.2f}")
    lambda = 1.65
    >>> for key in ("jkr_pull_off_force", "pull_off_force", "dmt_pull_off_force"):
    ...     print(key, f"{rec[key]['value'] * 1e6:.2f} µN")
    jkr_pull_off_force 2.36 µN
    pull_off_force 2.68 µN
    dmt_pull_off_force 3.14 µN
    """
    from contact import DomainSpec
    from contact.adhesion.ball import adhesive_ball, default_size
    from contact.adhesion.memory import check_adhesion_memory

    mats = adhesion_pair(materials, e_star)
    law = interaction_law(interaction, work, range_)
    if _on_rings(model, grid, size, plate, ball):
        return ring_run(radius, mats, law, steps, progress)
    if size is None:
        size = default_size(radius, mats.e_star, law)
    choice = None
    if grid is None:
        choice = default_grid(size, mats.e_star, law, steps)
        grid = choice.grid
    if isinstance(grid, int) and grid >= 16:
        check_adhesion_memory(grid, steps=steps)  # before the scans are sampled onto it
    z, scans = rough_grid(plate, ball, grid, size, spikes)
    if law.smoothing == 0.0:  # a step smoothed on the grid, where the law has one
        law = law.on_grid(size / grid, mats.e_star)
    res = adhesive_ball(radius, mats, law, domain=DomainSpec(grid=grid, size=size),
                        steps=steps, roughness=z, progress=progress)
    if choice is not None and choice.capped:
        res = dataclasses.replace(res, warnings=(*res.warnings, choice.why))
    why = choice.why if choice is not None else "given by the user"
    return Adhesion(res, scans, why)


def _on_rings(model: str, grid: int | None, size: float | None, plate: Any, ball: Any) -> bool:
    """Whether the sphere is solved on rings (:data:`MODELS`); a ring model asked for
    with a grid, a cell or scans is one line."""
    if model not in MODELS:
        raise SurfmetInputError(f"the model must be one of {', '.join(MODELS)}, got {model!r}")
    given = [name for name, v in (("a grid", grid), ("a periodic cell size", size),
                                  ("a plate scan", plate), ("a ball scan", ball))
             if v is not None]
    if model == "axisymmetric" and given:
        raise SurfmetInputError(
            f"the axisymmetric model is the smooth sphere's: {', '.join(given)} need "
            "--model 3d")
    return model == "axisymmetric" or (model == "auto" and not given)


def ring_run(radius: float, mats: Any, law: AdhesionLaw, steps: int,
             progress: Callable[[int, int], None] | None = None) -> Adhesion:
    """The smooth sphere's cycle on rings (:func:`contact.adhesion._ring_ball.adhesive_sphere`),
    the law's step smoothed on the rings' width as on a grid's pixel.

    Parameters
    ----------
    radius : float
        Sphere radius (m).
    mats : MaterialPair
        The resolved pair (:func:`adhesion_pair`).
    law : InteractionLaw
        The law (:func:`interaction_law`).
    steps : int
        Approach and retraction steps.
    progress : callable, optional
        ``progress(done, total)``.

    Returns
    -------
    Adhesion
        The run; ``grid_why`` states the rings and their resolution of the zone.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion import adhesion_pair, interaction_law, ring_run
    >>> run = ring_run(1e-3, adhesion_pair(None, 1e9), interaction_law("dugdale", 0.05,
    ...                1.53e-7), 8)
    >>> run.axisymmetric, run.result.rings
    (True, 416)
    """
    from contact._zone_resolution import process_zone
    from contact.adhesion._ring_ball import (
        ZONE_RINGS,
        adhesive_sphere,
        ring_edges,
        ring_law,
        ring_width,
        smoothing_width,
    )
    from surfmet.units import format_length

    dr, outer = ring_width(radius, mats.e_star, law)
    smooth = smoothing_width(radius, mats.e_star, law, dr, outer)
    if law.smoothing == 0.0:  # a step smoothed on the rings, where the law has one
        law = ring_law(law, mats.e_star, ring_edges(radius, mats.e_star, law, dr, outer),
                       smooth)
    res = adhesive_sphere(radius, mats, law, dr=dr, steps=steps, progress=progress)
    zone = process_zone(mats.e_star, law.work, law.peak)
    rings = (f"graded axisymmetric rings ({res.rings}: {format_length(dr)} about the "
             f"contact edge at pull-off, {format_length(smooth)} over its travel, the "
             "step smoothed on these)" if res.graded else
             f"axisymmetric rings ({res.rings} of {format_length(dr)})")
    why = (f"default for a smooth sphere: {rings}, the cohesive zone {zone / dr:.3g} rings "
           f"wide (at least {ZONE_RINGS:g}, or 200 across the contact's scale where the "
           "zone is wider); --model 3d for the periodic 3D grid")
    return Adhesion(res, None, why)


def default_grid(size: float, e_star: float, law: AdhesionLaw, steps: int) -> GridChoice:
    """The default grid (:class:`contact.adhesion.default_grid.GridChoice`) of a cell of
    side ``size`` (m): for a law whose step is smoothed on the grid (the Dugdale law), the
    grid that resolves the cohesive zone within memory
    (:func:`contact.adhesion.default_grid.resolving_grid`); for another (the exponential
    law, whose plain step would ask ten zone pixels), the fixed :data:`LEAST_GRID` (its
    coarse-grid warning says when that is too coarse).

    Parameters
    ----------
    size : float
        Side of the periodic cell (m).
    e_star : float
        Composite modulus E* (Pa).
    law : InteractionLaw
        The interaction (:func:`interaction_law`); whether its step is smoothed on the grid
        is its ``grid_smoothed``.
    steps : int
        Approach and retraction steps (the memory estimate keeps every state).

    Returns
    -------
    contact.adhesion.default_grid.GridChoice
        The cells per side, the cells the zone would want, and why (with the pull-off's
        measured excess where memory caps the grid).

    Examples
    --------
    Halving the range (at the same work) narrows the cohesive zone, so the default grid
    that gives it two pixels grows:

    >>> from surfmet.mechanics.adhesion import default_grid, interaction_law
    >>> for range_ in (2e-9, 1e-9):
    ...     law = interaction_law("dugdale", 0.05, range_)
    ...     print(default_grid(4e-6, 1e9, law, 40).grid)
    128
    512
    """
    from contact._zone_resolution import process_zone
    from contact.adhesion.default_grid import LEAST_GRID, GridChoice, resolving_grid

    if not law.grid_smoothed:
        return GridChoice(LEAST_GRID, LEAST_GRID, f"default for the {law.name} law: "
                          f"{LEAST_GRID} cells")
    return resolving_grid(size, process_zone(e_star, law.work, law.peak), steps=steps)


def adhesion_pair(materials: Materials | None, e_star: float | None) -> Any:
    """The resolved pair (:class:`contact._material_pair.MaterialPair`) of exactly one of a
    material pair and E* itself (Pa), by
    :func:`surfmet.mechanics.material_spec.material_pair`.

    Parameters
    ----------
    materials : str or (Material, Material) or None
        ``"BALL,PLATE"``.
    e_star : float or None
        Composite modulus (Pa).

    Returns
    -------
    contact._material_pair.MaterialPair
        The pair.

    Raises
    ------
    SurfmetInputError
        Both or neither given.

    Examples
    --------
    >>> from surfmet.mechanics.adhesion import adhesion_pair
    >>> print(f"{adhesion_pair('steel,aluminium', None).e_star / 1e9:.2f} GPa")
    58.61 GPa
    """
    from surfmet.mechanics.material_spec import material_pair

    if (materials is None) == (e_star is None):
        raise SurfmetInputError("give exactly one of the materials and E*")
    return material_pair(materials, e_star=e_star)


def plot(run: Adhesion, path: PathLike | None = None) -> Any:
    """Load against approach, and contact radius against load, in and out.

    Parameters
    ----------
    run : Adhesion
        A run.
    path : path-like, optional
        Image file to write; None returns the figure only.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Raises
    ------
    SurfmetInputError
        A line contact's run (its figure is
        :func:`surfmet.mechanics.adhesion_line.line_plot`).

    Examples
    --------
    >>> from surfmet.mechanics.adhesion import adhesion, plot
    >>> fig = plot(adhesion(1e-5, work=0.05, range_=2e-9, e_star=1e9, grid=16, steps=6))
    >>> len(fig.axes)
    2
    """
    from contact.adhesion.line import AdhesiveLine
    from surfmet.plots._style import finish, new_figure

    ball = run.result
    if isinstance(ball, AdhesiveLine):
        raise SurfmetInputError("plot draws a sphere's cycle; a line contact's is "
                                "surfmet.mechanics.adhesion_line.line_plot")
    fig, (a1, a2) = new_figure(1, 2, size=(10, 4.2))
    for leg, style, name in ((ball.cycle.approach_leg, "C0o-", "approach"),
                             (ball.cycle.retraction_leg, "C3s-", "retraction")):
        a1.plot(leg.surface_approach * 1e9, leg.load * 1e6, style, ms=3, label=name)
        a2.plot(leg.load * 1e6, leg.contact_radius * 1e6, style, ms=3, label=name)
    a1.axhline(-ball.jkr_pull_off * 1e6, color="0.5", ls=":", label="JKR pull-off")
    a1.axhline(-ball.dmt_pull_off * 1e6, color="0.5", ls="--", label="DMT pull-off")
    a1.set_xlabel("approach (nm)")
    a1.set_ylabel("load (µN)")
    a2.set_xlabel("load (µN)")
    a2.set_ylabel("contact radius (µm)")
    a1.set_title(f"Maugis lambda = {ball.maugis_parameter:.3g}")
    for ax in (a1, a2):
        ax.legend(fontsize=8)
    return finish(fig, path)
