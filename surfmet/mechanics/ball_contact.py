"""``surfmet contact``'s facade: the normal contact of a (rough) ball on a (rough) plate from
scans, solved by the FFT boundary-element method of :mod:`contact`.

:func:`ball_contact` prepares the scans as every contact does (spikes, levelling, the ball's
sphere, one grid: :func:`surfmet.mechanics.scan_preparation.prepare_scans`),
resolves the materials (:func:`surfmet.mechanics.material_spec.parse_materials`), and solves
the ball-on-plate set-up; :class:`BallContact` holds the result with what it was computed
from, and gives its JSON record (:func:`surfmet.records.contact_record`) and its figure.
Without a scan the smooth (Hertz) case is solved.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from surfmet._errors import SurfmetInputError
from surfmet.mechanics.scan_preparation import MAX_GRID, SPIKES

if TYPE_CHECKING:
    from contact._material_pair import MaterialPair
    from contact._materials import Material
    from contact.bem._result import ContactResult
    from surfmet.mechanics._types import Materials, ScanSource, Spikes
    from surfmet.mechanics.pairing import PairedRoughness
    from surfmet.mechanics.scan_preparation import PreparedScans

#: Fewest cells a contact may cover before the answer is called under-resolved.
MIN_CONTACT_CELLS = 20
#: Fewest cells per Hertz contact radius a0 before the grid is called too coarse: below
#: it the pressure profile is sampled at a handful of points (the Hertz approach and a0
#: converge as (dx/a0)^2, about 4 % at 5 cells).
MIN_CELLS_PER_RADIUS = 5


@dataclass(frozen=True, eq=False)
class BallContact:
    """A solved ball-on-plate contact and what it was solved from.

    Attributes
    ----------
    result : contact.ContactResult
        The solution (pressure, gap, contact area, Hertz's values for comparison).
    ball_material, plate_material : contact._materials.Material
    pair : surfmet.mechanics.pairing.PairedRoughness or None
        The paired scans; None for smooth surfaces.
    radius : float
        Ball radius (m).
    plate_file, ball_file : str or None
        The scan files, for the record.
    warnings : tuple of str
        Warnings of the solve (a contact reaching the domain's edge, a pressure above the
        elastic limit, a contact on a handful of cells): :func:`solution_warnings`.
    preparation : surfmet.mechanics.scan_preparation.PreparedScans or None
        What was done to the scans.

    See Also
    --------
    ball_contact : makes it.

    Examples
    --------
    >>> from surfmet.mechanics.ball_contact import ball_contact
    >>> run = ball_contact(radius=0.02, load=10.0, grid=64)
    >>> run.result.pressure.shape, run.warnings
    ((64, 64), ())
    >>> print(f"{run.result.pmax / 1e6:.0f} MPa")
    255 MPa
    """

    result: ContactResult
    ball_material: Material
    plate_material: Material
    pair: PairedRoughness | None
    radius: float
    plate_file: str | None = None
    ball_file: str | None = None
    warnings: tuple[str, ...] = ()
    preparation: PreparedScans | None = None

    def __repr__(self) -> str:
        from surfmet.units import format_quantity as q

        res = self.result
        return (f"BallContact(load={q(res.load, 'N')}, radius={q(self.radius, 'm')}, "
                f"contact radius={q(res.contact_radius, 'm')}, pmax={q(res.pmax, 'Pa')})")

    def _repr_html_(self) -> str:
        """Load, approach, contact radius and area, peak pressure, with units (Jupyter)."""
        from surfmet._display import quantity_table

        res = self.result
        rows = [("load", res.load, "N"), ("ball radius", self.radius, "m"),
                ("E*", res.e_star, "Pa"), ("approach", res.approach, "m"),
                ("contact radius", res.contact_radius, "m"),
                ("contact area", res.contact_area, "m^2"), ("peak pressure", res.pmax, "Pa"),
                ("grid", f"{res.pressure.shape[1]} × {res.pressure.shape[0]}", "cells")]
        if res.hertz is not None:
            rows += [("Hertz contact radius a0", res.hertz.a, "m"),
                     ("Hertz peak pressure p0", res.hertz.p0, "Pa")]
        return quantity_table("Ball contact", rows)

    def figure(self, path: str | Path | None = None) -> Any:
        """The pressure map (:func:`surfmet.plots.contact.pressure_map`)."""
        from surfmet.plots.contact import pressure_map

        return pressure_map(self.result, path)


def _hardness(hardness: float | None, plastic: bool, mats: MaterialPair) -> float | None:
    if hardness is not None and plastic:
        raise SurfmetInputError("give a hardness or plastic=True, not both")
    if not plastic:
        return hardness
    h = mats.hardness
    if h is None:
        raise SurfmetInputError("--plastic: neither material has a hardness; give --hardness")
    return h


def _file(obj: ScanSource | None) -> str | None:
    if obj is None:
        return None
    if isinstance(obj, (str, Path)):
        return str(obj)
    return getattr(obj, "metadata", {}).get("source")  # a scan read by the caller


def grid_warnings(res: ContactResult) -> list[str]:
    """A grid too coarse for the contact: fewer than :data:`MIN_CELLS_PER_RADIUS` cells
    per Hertz contact radius a0 (empty for a grid fine enough, or without a Hertz value).

    Parameters
    ----------
    res : ContactResult
        A solved contact.

    Returns
    -------
    list of str
        The sentence, or nothing.

    Examples
    --------
    Eight cells over the paper's Hertz contact are too few:

    >>> from surfmet.mechanics.ball_contact import grid_warnings, solve_on_pair
    >>> res, _ = solve_on_pair(None, radius=0.02, load=10.0, e_star=58.6e9, grid=8)
    >>> print(grid_warnings(res)[0][:44])
    the grid is too coarse for this contact: pix
    """
    from surfmet.units import format_length

    hz = getattr(res, "hertz", None)
    if hz is None or not hz.a > 0:
        return []
    cells = hz.a / res.dx
    if cells >= MIN_CELLS_PER_RADIUS:
        return []
    return [f"the grid is too coarse for this contact: pixel {format_length(res.dx)} against "
            f"the Hertz radius a0 = {format_length(hz.a)}, {cells:.2g} cells per radius "
            f"(at least {MIN_CELLS_PER_RADIUS} are needed); use a finer --grid or the "
            "scans' own pixel"]


def solution_warnings(res: ContactResult, mats: MaterialPair) -> list[str]:
    """What makes a solved contact's answer doubtful, as sentences.

    - an elastic solution whose peak pressure exceeds the softer body's hardness (or, with
      no hardness known, the composite modulus E*): the material would have yielded, and
      beyond E* the small-slope half-space model itself no longer holds;
    - a contact on fewer than :data:`MIN_CONTACT_CELLS` cells: the area and the peak
      pressure are not resolved by the grid;
    - a grid with fewer than :data:`MIN_CELLS_PER_RADIUS` cells per Hertz radius
      (:func:`grid_warnings`).

    Parameters
    ----------
    res : ContactResult
        A solved contact.
    mats : MaterialPair
        The pair (its hardness).

    Returns
    -------
    list of str
        One sentence per doubt.

    See Also
    --------
    grid_warnings

    Examples
    --------
    The bundled plate's asperities carry the ball at pressures beyond aluminium's hardness:

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.ball_contact import solution_warnings, solve_on_pair
    >>> from surfmet.mechanics.material_spec import material_pair
    >>> from surfmet.mechanics.pairing import prepare_pair
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> res, _ = solve_on_pair(prepare_pair(patch), radius=0.02, load=10.0, e_star=58.6e9,
    ...                        grid=64)
    >>> print(solution_warnings(res, material_pair("steel,aluminium"))[0][:60])
    max pressure 3.367 GPa exceeds the softer body's hardness (1
    """
    from surfmet.units import format_length, format_quantity

    out = []
    if res.hardness is None:
        h = mats.hardness
        limit, what = (h, "the softer body's hardness") if h else (res.e_star, "E*")
        if res.pmax > limit:
            out.append(f"max pressure {format_quantity(res.pmax, 'Pa')} exceeds {what} "
                       f"({format_quantity(limit, 'Pa')}): beyond the elastic limit this model "
                       "allows; "
                       "solve elastic-plastic (--plastic or --hardness), and check the scans "
                       "for spikes")
    coarse = grid_warnings(res)
    out.extend(coarse)
    cells = res.contact_area / (res.dx * res.dx)
    if cells < MIN_CONTACT_CELLS and not coarse:
        out.append(f"the contact covers {cells:.3g} cells of {format_length(res.dx)}: fewer "
                   f"than {MIN_CONTACT_CELLS}, the area and the peak pressure are not resolved;"
                   " use a finer --grid")
    return out


#: The facade keywords that choose the engine's domain (:class:`contact.DomainSpec`).
DOMAIN_KEYWORDS = ("grid", "size", "periodic", "max_grid", "on_edge")


def _engine_settings(**options: Any) -> tuple[Any, Any]:
    """The engine's :class:`contact.DomainSpec` and :class:`contact.SolveOptions` from a
    facade's flat keywords (``grid``, ``size``, ``periodic``, ``max_grid``, ``on_edge``;
    ``tol``, ``max_iter``, ``callback``...): the one translation of every ball facade."""
    from contact import DomainSpec, SolveOptions

    domain = {k: options.pop(k) for k in DOMAIN_KEYWORDS if k in options}
    return DomainSpec(**domain), SolveOptions(**options)


def solve_on_pair(pair: PairedRoughness | None, *, radius: float, load: float,
                  e_star: MaterialPair | float,
                  hardness: float | None = None, offset: tuple[float, float] | None = None,
                  max_grid: int | None = MAX_GRID, **options: Any) -> tuple[Any, tuple[str, ...]]:
    """Solve the ball-on-plate set-up on a paired roughness (None: smooth surfaces).

    ``e_star`` is the resolved :class:`contact._material_pair.MaterialPair` (or its E*, Pa).
    ``options`` go to the set-up and the solver (``grid``, ``size``, ``periodic``,
    ``max_grid``, ``on_edge``, ``tol``, ``max_iter``, ``callback``). Returns the result and
    the warnings of the solve as text (a contact reaching the domain's edge).

    Returns
    -------
    (ContactResult, tuple of str)
        The solution and the solve's warnings.

    Raises
    ------
    ContactError
        A solver failure, a grid that does not fit in memory.

    See Also
    --------
    ball_contact : reads and prepares the scans, then calls this.

    Examples
    --------
    >>> from surfmet.mechanics.ball_contact import solve_on_pair
    >>> res, warnings = solve_on_pair(None, radius=0.02, load=10.0, e_star=58.6e9, grid=64)
    >>> print(f"{res.pmax / 1e6:.0f} MPa", warnings)
    255 MPa ()
    """
    from contact._errors import EdgeContactWarning
    from contact.setups._ball_on_plate import solve_sphere

    domain, solve = _engine_settings(max_grid=max_grid, **options)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", EdgeContactWarning)
        res = solve_sphere(
            radius, load, e_star,
            roughness=None if pair is None else pair.composite(offset),
            hardness=hardness, domain=domain, options=solve,
        )
    found = tuple(str(w.message) for w in caught if issubclass(w.category, EdgeContactWarning))
    return res, found


def ball_contact(
    plate: ScanSource | None = None,
    ball: ScanSource | None = None,
    *,
    radius: float,
    load: float,
    materials: Materials = "steel,aluminium",
    hardness: float | None = None,
    plastic: bool = False,
    grid: int | None = None,
    size: float | None = None,
    periodic: bool = False,
    on_edge: str = "enlarge",
    tol: float = 1e-6,
    max_iter: int = 2000,
    max_grid: int | None = MAX_GRID,
    callback: Callable[[int, float], None] | None = None,
    spikes: Spikes = SPIKES,
    offset: tuple[float, float] | None = None,
) -> BallContact:
    """Normal contact of a ball on a plate from their scans.

    Parameters
    ----------
    plate, ball : Topography or path, optional
        The scans (either, both or none: smooth surfaces). Spikes removed (unless
        ``spikes="keep"``), the plate levelled, the ball's best-fit sphere removed, and
        both paired on one grid (:func:`surfmet.mechanics.scan_preparation.prepare_scans`).
    radius, load : float
        Ball radius (m) and normal load (N).
    materials : str or pair of Material
        Ball and plate, e.g. ``"steel,aluminium"``.
    hardness : float, optional
        Cap the pressure at this hardness (Pa): elastic-perfectly-plastic.
    plastic : bool
        Cap the pressure at the softer material's table hardness.
    grid, size, periodic, on_edge, tol, max_iter, max_grid, callback
        The set-up and the solver (:func:`contact.setups._ball_on_plate.solve_sphere`);
        ``max_grid`` defaults to :data:`~surfmet.mechanics.scan_preparation.MAX_GRID`
        (None: the scans' own pixel at any size), the same for every entry point.
    spikes : {"remove", "keep"} or bool
        What to do with the scans' spikes (default remove).
    offset : (float, float), optional
        The ball's apex (x, y) from the middle of the paired map (m): a track position.

    Returns
    -------
    BallContact

    Raises
    ------
    SurfmetInputError, ContactError
        Bad inputs, scans that cannot be paired, a solver failure.

    See Also
    --------
    contact.solve_sphere : the engine's solve, on arrays.
    surfmet.mechanics.hertz_check.hertz_check : the same contact against Hertz.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.2.
    .. [2] I. A. Polonsky, L. M. Keer, "A numerical method for solving rough contact
       problems based on the multi-level multi-summation and conjugate gradient
       techniques", Wear 231 (1999) 206-219.

    Examples
    --------
    Smooth surfaces give the Hertz peak pressure; the bundled plate's roughness
    concentrates the load on a few asperities, far above the aluminium's hardness (the
    warnings say so):

    >>> import surfmet
    >>> from surfmet.data import path
    >>> from surfmet.mechanics.ball_contact import ball_contact
    >>> smooth = ball_contact(radius=0.02, load=10.0, grid=64)
    >>> print(f"{smooth.result.pmax / smooth.result.hertz.p0:.3f}")
    1.000
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> patch = surfmet.Topography(plate.heights[:128, :128], plate.dx, plate.dy)
    >>> rough = ball_contact(patch, radius=0.02, load=10.0, grid=64)
    >>> bool(rough.result.pmax > 5 * smooth.result.pmax), len(rough.warnings) > 0
    (True, True)
    """
    from surfmet.mechanics.material_spec import material_pair, parse_materials
    from surfmet.mechanics.scan_preparation import prepare_scans

    mats = material_pair(materials)
    ball_m, plate_m = parse_materials(mats)
    cap = _hardness(hardness, plastic, mats)
    if not (tol > 0):
        raise SurfmetInputError("--tol must be positive")
    prep = None
    if plate is not None or ball is not None:
        prep = prepare_scans(plate, ball, spikes=spikes)
    pair = None if prep is None else prep.pair
    if offset is not None:
        from surfmet.mechanics.pairing import apex_centre

        apex_centre(pair, offset)  # refuses a track position without a scan
    res, found = solve_on_pair(pair, offset=offset, radius=radius, load=load, e_star=mats,
                               hardness=cap,
                               periodic=periodic, grid=grid, size=size, max_grid=max_grid,
                               tol=tol, max_iter=max_iter, callback=callback,
                               on_edge=on_edge)
    found = (*found, *solution_warnings(res, mats))
    return BallContact(result=res, ball_material=ball_m, plate_material=plate_m, pair=pair,
                       radius=radius, plate_file=_file(plate), ball_file=_file(ball),
                       warnings=found, preparation=prep)
