"""The ball-on-plate set-up: a (rough) ball on a (rough) plate on the grid, edge detection
and enlargement, load sweeps, elastic and elastic-perfectly-plastic solves.

:class:`SphereContact` prepares the geometry once (levelled roughness, domain, gap) and
solves it for any number of loads, warm-starting each from the previous pressure field.
:func:`solve_sphere` is the one-call form.

Edge policy. A free-boundary solver can only put pressure inside its domain. When the
contact pressure reaches the outermost cells, the domain probably cut the contact short;
other codes return that truncated answer silently. Here the domain is enlarged (same
pitch, 1.5 times the side) and the solve repeated, with an
:class:`~contact._errors.EdgeContactWarning` that says so. When the roughness data do not
extend far enough, an :class:`~contact._errors.EdgeContactError` is raised instead
(``on_edge="warn"`` returns the flagged, truncated result with the warning).

Elastic-plastic contact has this one entry point: ``SphereContact(hardness=H)`` sizes the
domain for the plastic contact and caps every solve at H; ``solve(load, hardness=H,
initial=elastic)`` solves the capped contact on an elastic problem's domain, warm-started
from the elastic solution, which is how the verdicts (:mod:`contact._hertzcheck`,
:mod:`contact._resolution`) and the plastic rolling model compare the two at one load. Both
run the capped Polonsky-Keer iteration of :func:`contact.bem.solve_normal`; an independent
plastic-displacement fixed point on elastic solves cross-checks it in the tests.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable
from typing import Any

import numpy as np

from contact._errors import ContactInputError, EdgeContactError, EdgeContactWarning
from contact._geometry import (
    ON_EDGE,
    Domain,
    DomainSpec,
    auto_domain,
    centred_coordinates,
    contact_extent,
    domain_spec,
    fast_even,
    max_centred_cells,
    remove_plane,
    sphere_gap,
)
from contact._grid import scan_grid
from contact._hertz import hertz_sphere
from contact._material_pair import MaterialPair, modulus
from contact._record import TRUNCATED_ADVICE, edge_warning, raise_edge
from contact._sampling import fill_nan, sample_roughness
from contact._validate import positive
from contact.bem import solve_normal
from contact.bem._bounds import PressureBounds
from contact.bem._memory import check_grid_memory
from contact.bem._options import SolveOptions, options_of
from contact.bem._result import ContactResult
from contact.setups._composite import CompositeRoughness


class SphereContact:
    """A ball of radius R on a plate, with optional composite roughness, ready to solve.

    Parameters
    ----------
    radius : float
        Ball radius R (m).
    e_star : float or MaterialPair
        Composite modulus E* (Pa), or a resolved :class:`contact._material_pair.MaterialPair`
        (its E*, bit for bit). A pair's default hardness is not applied: the cap is
        ``hardness`` alone (give ``pair.hardness``).
    load : float
        The (largest) load the domain is sized for (N).
    roughness : CompositeRoughness, optional
        The composite roughness under the ball, its pitch, the apex position and whether
        it is levelled first (:class:`contact.setups._composite.CompositeRoughness`). The
        removed plane is kept in ``extra["removed_plane"]``; non-measured points are filled
        with the nearest measured value.
    hardness : float, optional
        Pressure cap (Pa) for an elastic-perfectly-plastic contact (the domain is sized for
        it). :meth:`solve` also takes a hardness for one solve on the domain at hand.
    domain : DomainSpec, optional
        Cells per side, side length (m), the largest automatic grid and whether the domain
        is periodic (:class:`contact._geometry.DomainSpec`), overriding the automatic choice
        of :func:`contact._geometry.auto_domain`; default all automatic, free boundary.
    results : int
        Results of this problem kept alive together (for the memory check,
        :func:`contact.bem._memory.check_grid_memory`).
    exact_sphere : bool
        Use R - sqrt(R^2 - r^2) instead of the Hertz paraboloid.

    Raises
    ------
    ContactInputError
        A radius, modulus, load or hardness that is not positive and finite.
    ContactMemoryError
        A grid that would not fit in memory.

    See Also
    --------
    contact.solve_sphere : one load in one call.
    contact.CompositeRoughness : the roughness under the ball.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.2.

    Examples
    --------
    A warm-started load sweep on one domain; the contact radius follows Hertz:

    >>> from contact import SphereContact
    >>> from contact import DomainSpec
    >>> problem = SphereContact(0.02, 58.6e9, 10.0, domain=DomainSpec(grid=64))
    >>> results = problem.sweep([1.0, 3.0, 10.0])
    >>> print([f"{r.contact_radius / r.hertz.a:.2f}" for r in results])
    ['1.00', '1.01', '1.01']
    """

    def __init__(
        self,
        radius: float,
        e_star: float | MaterialPair,
        load: float,
        *,
        roughness: CompositeRoughness | None = None,
        hardness: float | None = None,
        domain: DomainSpec | None = None,
        exact_sphere: bool = False,
        results: int = 1,
    ):
        self.radius = positive(radius, "the ball radius", "m")
        self.e_star = positive(modulus(e_star), "E*", "Pa")
        self.design_load = positive(load, "the load", "N")
        self.hardness = None if hardness is None else positive(hardness, "the hardness", "Pa")
        spec = domain_spec(domain)
        self.spec = spec
        self.periodic = bool(spec.periodic)
        self.exact_sphere = bool(exact_sphere)
        self.results = max(int(results), 1)
        self.notes: list[str] = []
        self.extra: dict[str, Any] = {}
        self._z = None
        self._uncovered: str | None = None
        rms = 0.0
        if roughness is not None:
            if not isinstance(roughness, CompositeRoughness):
                raise ContactInputError(
                    "give the roughness as a contact.setups.CompositeRoughness (heights, "
                    f"pitch, apex position), got {type(roughness).__name__}")
            z = np.array(roughness.heights)
            self.zdx, self.zdy = roughness.dx, roughness.dy
            if roughness.level:
                z, plane = remove_plane(z, self.zdx, self.zdy)
                self.extra["removed_plane"] = {"offset": plane[0], "slope_x": plane[1],
                                               "slope_y": plane[2]}
            z, filled = fill_nan(z)
            if filled > 0:
                self.notes.append(f"{100 * filled:.2f} % of the roughness map was not "
                                  "measured and was filled with the nearest measured value")
            self._z = z
            rms = float(np.sqrt(np.mean((z - z.mean()) ** 2)))
            self.centre = roughness.apex
        self.roughness_rms = rms
        dom = auto_domain(self.radius, self.design_load, self.e_star, roughness_rms=rms,
                          roughness_dx=self.zdx if self._z is not None else None,
                          hardness=self.hardness, spec=spec)
        if self._z is not None:
            fit = max_centred_cells(self._z.shape, self.zdx, self.zdy, self.centre, dom.dx)
            if fit < 8:
                raise ContactInputError(
                    "the roughness data are too small for even an 8 x 8 contact grid around "
                    "the apex; use a larger scan or a finer grid"
                )
            covered = fit * dom.dx
            reach = 2.0 * contact_extent(self.radius, self.design_load, self.e_star,
                                         hardness=self.hardness)
            if covered < reach:
                # checked in solve(): a truncated answer is still allowed with on_edge="warn"
                self._uncovered = (
                    "the scans do not overlap the contact: the roughness data end "
                    f"{covered * 5e5:.4g} µm from the ball's apex, inside the "
                    f"{reach * 1e6:.4g} µm contact diameter expected (Hertz); use larger "
                    f"scans or a smaller load{TRUNCATED_ADVICE}"
                )
            if dom.n > fit:
                self.notes.append(
                    f"the domain was limited to the roughness data: {fit} instead of {dom.n} "
                    "cells per side"
                )
                dom = Domain(fit, dom.dx, dom.reason + "; limited by the scan size")
        self._set_domain(dom)

    # -- grid -------------------------------------------------------------------------
    def _set_domain(self, dom: Domain) -> None:
        # before anything of the grid's size is allocated: refuse what cannot fit
        check_grid_memory(dom.n, plastic=self.hardness is not None, results=self.results)
        self.domain = dom
        n, dx = dom.n, dom.dx
        h = sphere_gap(n, dx, self.radius, exact=self.exact_sphere)
        if self._z is not None:
            h -= sample_roughness(self._z, self.zdx, self.zdy, dom.grid, centre=self.centre)
        # Approach counted from the first touch: offsets of the data drop out. (In place,
        # h being this method's own: no second gap of the grid's size.)
        h -= h.min()
        self.gap0 = h

    @property
    def x(self) -> np.ndarray:
        """Cell-centre x coordinates relative to the apex (m)."""
        return centred_coordinates(self.domain.n, self.domain.dx)

    def _can_enlarge(self) -> int:
        n_new = fast_even(math.ceil(1.5 * self.domain.n))
        if self._z is None:
            return n_new
        fit = max_centred_cells(self._z.shape, self.zdx, self.zdy, self.centre, self.domain.dx)
        return min(n_new, fit) if fit > self.domain.n else 0

    @staticmethod
    def _embed(p: np.ndarray, n: int) -> np.ndarray:
        m = p.shape[0]
        out = np.zeros((n, n))
        o = n // 2 - m // 2
        out[o:o + m, o:o + m] = p
        return out

    # -- solving ----------------------------------------------------------------------
    def solve(
        self,
        load: float | None = None,
        *,
        approach: float | None = None,
        initial: ContactResult | np.ndarray | None = None,
        hardness: float | None = None,
        on_edge: str | None = None,
        options: SolveOptions | None = None,
    ) -> ContactResult:
        """Solve at one load (or approach), enlarging the domain if the contact reaches it.

        Parameters
        ----------
        load : float, optional
            Normal load W (N); default the load the problem was built for.
        approach : float, optional
            Prescribed approach from first touch (m), instead of a load.
        initial : ContactResult or ndarray, optional
            Warm start (the solution at a nearby load, or the elastic solution at this load
            for an elastic-plastic solve: it is clipped at the hardness); resized if the
            grid changed.
        hardness : float, optional
            Pressure cap (Pa) of this solve, on the domain at hand: the elastic-perfectly-
            plastic contact of the capped Polonsky-Keer iteration
            (:func:`contact.bem.solve_normal`; ``plastic_displacement`` is the permanent
            indentation). Default the problem's own hardness. The notes on where the
            contact yields (asperity or Hertz scale) are given only for the problem's own
            hardness; with a per-solve hardness the caller compares the two solutions.
        on_edge : {"enlarge", "warn", "raise"}, optional
            What to do when pressure reaches the domain edge (see the module notes);
            default the problem's ``DomainSpec.on_edge``. At most
            ``DomainSpec.max_enlarge`` enlargements are made.
        options : SolveOptions, optional
            How each solve runs (:class:`contact.bem._options.SolveOptions`, passed to
            :func:`contact.bem.solve_normal`); its edge report is this method's
            ``on_edge``.
        """
        # the domain's edge is this method's business (on_edge), not the inner solve's
        opts = options_of(options).but(edge="ignore")
        on_edge = self.spec.on_edge if on_edge is None else on_edge
        max_enlarge = self.spec.max_enlarge
        if on_edge not in ON_EDGE:
            raise ContactInputError(f"on_edge must be one of {ON_EDGE}, got {on_edge!r}")
        if self._uncovered is not None and on_edge != "warn":
            raise EdgeContactError(self._uncovered)
        cap = self.hardness if hardness is None else positive(hardness, "the hardness", "Pa")
        if approach is None:
            load = self.design_load if load is None else positive(load, "the load", "N")
        elif load is not None:
            raise ContactInputError("give a load or an approach, not both")
        notes = list(self.notes)
        p0 = None
        if initial is not None:
            p0 = np.asarray(initial.pressure if isinstance(initial, ContactResult) else initial)
        for attempt in range(max_enlarge + 1):
            n, dx = self.domain.n, self.domain.dx
            if p0 is not None and p0.shape != (n, n):
                p0 = self._embed(p0, n) if p0.shape[0] < n else None
            origin = (-(n // 2) * dx, -(n // 2) * dx)
            grid = scan_grid((n, n), dx, origin=origin, periodic=self.periodic, h=self.gap0)
            res = solve_normal(grid, e_star=self.e_star, load=load, approach=approach,
                               bounds=PressureBounds.elastic(cap), options=opts, initial=p0)
            if not res.touches_edge:
                break
            side = n * dx
            where = f"the {side * 1e3:.4g} mm domain"
            if on_edge == "raise":
                raise_edge("on_edge='raise' refuses a truncated result (on_edge='enlarge' "
                           "enlarges it)", where)
            if on_edge == "warn":
                notes.append(edge_warning(True, where))
                break
            n_new = self._can_enlarge()
            if n_new <= n or attempt == max_enlarge:
                why = ("the roughness data end there" if self._z is not None and n_new <= n
                       else f"gave up after {max_enlarge} enlargements")
                raise_edge(f"it cannot be enlarged ({why}); use a larger scan or a smaller "
                           f"load{TRUNCATED_ADVICE}", where)
            msg = (f"contact pressure reached the edge of the {side * 1e3:.4g} mm domain; "
                   f"enlarged to {n_new * dx * 1e3:.4g} mm ({n_new} cells) and solved again")
            warnings.warn(msg, EdgeContactWarning, stacklevel=2)
            notes.append(msg)
            self._set_domain(Domain(n_new, dx, self.domain.reason + "; enlarged"))
            p0 = self._embed(np.asarray(res.pressure), n_new)
        W = res.load
        hz = hertz_sphere(self.radius, W, self.e_star) if W > 0 else None
        notes += [n for n in resolution_notes(res, hz, self.e_star) if n not in notes]
        own_cap = hardness is None and self.hardness is not None
        if own_cap and res.plastic_area > 0 and hz is not None:
            frac = res.plastic_area / res.contact_area
            if hz.p0 < self.hardness:
                notes.append(
                    f"plastic at the asperity scale ({100 * frac:.3g} % of the contact area at "
                    f"the hardness) although elastic at the Hertz scale (Hertz p0 = "
                    f"{hz.p0 / 1e6:.4g} MPa < hardness {self.hardness / 1e6:.4g} MPa)"
                )
            else:
                notes.append(f"plastic at the Hertz scale (Hertz p0 = {hz.p0 / 1e6:.4g} MPa "
                             f">= hardness {self.hardness / 1e6:.4g} MPa)")
        extra = {**res.extra, **self.extra, "domain": self.domain.reason,
                 "roughness_rms": self.roughness_rms}
        return _with(res, notes=tuple(notes), hertz=hz, extra=extra)

    def sweep(self, loads: Iterable[float], **kwargs: Any) -> list[ContactResult]:
        """Solve at each load in turn, each warm-started from the previous solution."""
        out: list[ContactResult] = []
        prev = None
        for w in loads:
            prev = self.solve(w, initial=prev, **kwargs)
            out.append(prev)
        return out


#: Fewer grid cells than this per Hertz radius: the grid cannot resolve the contact.
MIN_CELLS_PER_RADIUS = 4
#: Fewer loaded cells than this: the contact is a handful of cells, not a pressure field.
MIN_CONTACT_CELLS = 20


def resolution_notes(res: ContactResult, hz: Any, e_star: float) -> list[str]:
    """Sentences for an answer the grid or the model cannot stand behind.

    - the pixel leaves fewer than :data:`MIN_CELLS_PER_RADIUS` cells per Hertz radius;
    - fewer than :data:`MIN_CONTACT_CELLS` cells carry pressure (typically a spike of the
      scan standing above the rest);
    - the peak pressure exceeds E*: surface slopes of order one, outside the linear
      elastic half-space (small slopes) the solver assumes.
    """
    out = []
    if hz is not None and hz.a < MIN_CELLS_PER_RADIUS * res.dx:
        out.append(f"the grid is too coarse for this contact: {hz.a / res.dx:.2g} cells per "
                   f"Hertz radius (a0 = {hz.a * 1e6:.4g} µm, pixel {res.dx * 1e6:.4g} µm; "
                   f"at least {MIN_CELLS_PER_RADIUS} are needed to resolve it)")
    cells = int(np.count_nonzero(res.contact))
    if not out and 0 < cells < MIN_CONTACT_CELLS:
        out.append(f"the contact covers only {cells} cell{'s' if cells > 1 else ''} of "
                   f"{res.dx * 1e6:.4g} µm: a handful of points carries the load (a spike in "
                   "the scan?), not a resolved contact")
    if res.pmax > e_star:
        out.append(f"the peak pressure {res.pmax / 1e9:.4g} GPa exceeds E* = "
                   f"{e_star / 1e9:.4g} GPa: slopes of order one, outside the linear elastic "
                   "half-space the solver assumes (a spike in the scan?)")
    return out


def _with(res: ContactResult, **changes: Any) -> ContactResult:
    import dataclasses

    return dataclasses.replace(res, **changes)


def solve_sphere(
    radius: float,
    load: float,
    e_star: float | MaterialPair,
    *,
    roughness: CompositeRoughness | None = None,
    hardness: float | None = None,
    domain: DomainSpec | None = None,
    exact_sphere: bool = False,
    **solve_kwargs: Any,
) -> ContactResult:
    """Normal contact of a (rough) ball on a (rough) plate in one call.

    See :class:`SphereContact` for the geometry parameters and
    :meth:`SphereContact.solve` for the solver ones (``on_edge``, ``options``: a
    :class:`contact.bem._options.SolveOptions` with the tolerance, callback...).

    Examples
    --------
    >>> from contact import solve_sphere, composite_modulus, material
    >>> E = composite_modulus(material("steel"), material("aluminium"))
    >>> res = solve_sphere(0.02, 10.0, E)
    >>> abs(res.pmax / res.hertz.p0 - 1) < 1e-4
    True

    On measured roughness (``z`` the composite height map, 5 µm pitch), the apex 0.1 mm
    to the right of the map's middle::

        rough = CompositeRoughness(z, 5e-6).shifted((1e-4, 0.0))
        res = solve_sphere(0.02, 10.0, E, roughness=rough, hardness=0.9e9)
    """
    problem = SphereContact(radius, e_star, load, roughness=roughness, hardness=hardness,
                            domain=domain, exact_sphere=exact_sphere)
    return problem.solve(load, **solve_kwargs)
