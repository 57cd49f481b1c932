"""A rough surface pressed on a flat: the boundary elements along increasing pressures.

The gap to the flat is ``h = max(z) - z`` (the flat touches the highest point at zero
load). Each nominal pressure p is a load-controlled solve of :func:`contact.bem.solve_normal`
with ``W = p A0``; the pressures are solved in increasing order, each warm-started from the
previous pressure field (rescaled to the new load), which cuts the iterations several-fold.
The domain is periodic when the surface is (then the BEM matches periodic theories such as
Persson's), and otherwise has a free boundary (no pressure outside the scan).

Per pressure the driver reports the area fraction, the mean gap ū (mean of the deformed gap,
the separation of the flat from the deformed surface's mean plane), the number of contact
clusters, the perimeter-corrected area of Yastrebov, Anciaux & Molinari (2015, Phys. Rev.
E 92, 063210; the coefficient (π - 1 + ln 2)/24 of their 2017 Int. J. Solids Struct.
paper), and the normal contact stiffness per unit nominal area ``K = -dp/dū``.

The stiffness comes from the computed curve itself when two or more pressures are solved:
``K = -p d(ln p)/dū``, with ``d(ln p)/dū`` the derivative at each point of the quadratic
through it and its neighbours in ``(ū, ln p)`` (a secant with two pressures). Rough contact
is close to the exponential law ``p ∝ exp(-ū/u₀)`` over a decade of pressure (Persson 2007,
Yang & Persson 2008), for which ``ln p`` is linear in ū and this derivative is exact, so
the curve costs no extra solve. ``stiffness="solve"`` (and a single pressure) measures it
by a second, warm-started solve at ``p (1 + ε)`` instead (a forward difference; its error
is of order ε/2 times the relative curvature of ū(ln p), about 0.5 % for ε = 1 %).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from contact._errors import ContactInputError
from contact._fields import corrected_area
from contact._grid import Grid
from contact._material_pair import MaterialPair, modulus
from contact._record import SolveRecord, combine, edge_message
from contact._validate import positive

if TYPE_CHECKING:  # the solver loads lazily; only the annotation names it
    from contact.bem._options import SolveOptions

#: Relative pressure step of the stiffness solve.
STIFFNESS_STEP = 0.01


@dataclass(frozen=True)
class FlatPoint:
    """The BEM state at one nominal pressure (SI).

    Attributes
    ----------
    pressure : float
        Nominal pressure p, Pa.
    area_fraction : float
        Cells in contact / all cells.
    corrected_area_fraction : float
        Perimeter-corrected area / nominal area (Yastrebov et al. 2015).
    mean_gap : float
        ū, m.
    stiffness : float
        ``-dp/dū``, Pa/m.
    n_clusters : int
        Contact spots (4-connected; wrapping ones counted once when periodic).
    max_pressure : float
        Largest local pressure, Pa.
    plastic_fraction : float
        Fraction of the nominal area at the hardness (0 without one).
    solve : SolveRecord
        The main solve's record (:mod:`contact._record`); ``iterations`` and
        ``converged`` read it.
    """

    pressure: float
    area_fraction: float
    corrected_area_fraction: float
    mean_gap: float
    stiffness: float
    n_clusters: int
    max_pressure: float
    plastic_fraction: float
    solve: SolveRecord

    @property
    def iterations(self) -> int:
        """Iterations of the main solve."""
        return self.solve.iterations

    @property
    def converged(self) -> bool:
        """The main solve reached its tolerance."""
        return self.solve.converged


@dataclass(frozen=True, eq=False)
class FlatContact:
    """A flat-contact sweep: the points in increasing pressure and how they were solved.

    Attributes
    ----------
    points : tuple of FlatPoint
        One solved point per nominal pressure, in increasing pressure.
    pressure, area_fraction, mean_gap, stiffness : ndarray
        Those of the points: nominal pressure (Pa), real contact area over the nominal one,
        mean gap ū (m) and normal contact stiffness per area (Pa/m).
    periodic, e_star, hardness, shape, dx, dy
        The set-up.

    See Also
    --------
    flat_contact : makes it.

    Examples
    --------
    >>> import surfmet
    >>> from contact import flat_contact
    >>> from contact._geometry import remove_plane
    >>> from contact._grid import gap_grid
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> z, _ = remove_plane(plate.heights[:64, :64], plate.dx, plate.dx)
    >>> grid = gap_grid(z.max() - z, plate.dx, periodic=True)
    >>> sweep = flat_contact(grid, pressures=[1e7, 3e7], e_star=58.6e9)
    >>> sweep.pressure.tolist(), bool((sweep.area_fraction > 0).all())
    ([10000000.0, 30000000.0], True)
    """

    points: tuple[FlatPoint, ...]
    periodic: bool
    e_star: float
    hardness: float | None
    shape: tuple[int, int]
    dx: float
    dy: float
    notes: tuple[str, ...] = ()

    @property
    def pressure(self) -> np.ndarray:
        return np.array([pt.pressure for pt in self.points])

    @property
    def area_fraction(self) -> np.ndarray:
        return np.array([pt.area_fraction for pt in self.points])

    @property
    def mean_gap(self) -> np.ndarray:
        return np.array([pt.mean_gap for pt in self.points])

    @property
    def stiffness(self) -> np.ndarray:
        return np.array([pt.stiffness for pt in self.points])

    @property
    def solve(self) -> SolveRecord:
        """One record for the main solves of every pressure (:func:`contact._record.combine`)."""
        return combine([pt.solve for pt in self.points], "normal BEM, one solve per pressure")


def flat_contact(
    grid: Grid,
    *,
    pressures: np.ndarray | list[float],
    e_star: float | MaterialPair,
    hardness: float | None = None,
    options: SolveOptions | None = None,
    stiffness: str = "curve",
    progress: Callable[[int, int], Any] | None = None,
) -> FlatContact:
    """Press a rough surface on a rigid or elastic flat at the given nominal pressures.

    Parameters
    ----------
    grid : Grid
        The pixels, their pitch and boundary (periodic, or free) and, as ``grid.h``, the
        separation of the rough surface from the flat (m, positive apart; any offset:
        ``z.max() - z`` for levelled heights z), e.g.
        ``contact._grid.gap_grid(z.max() - z, dx, dy, periodic=True)``.
    pressures : array_like
        Nominal pressures, Pa (any order; solved in increasing order, returned so).
    e_star : float or MaterialPair
        Composite modulus, Pa (a rigid flat: ``E/(1-ν²)`` of the rough body),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
        A pair's default hardness is not applied: the cap is ``hardness`` alone.
    hardness : float, optional
        Pressure cap (elastic-perfectly-plastic), Pa.
    options : SolveOptions, optional
        How each solve runs (:class:`contact.bem._options.SolveOptions`; its edge report is
        this function's note).
    stiffness : {"curve", "solve"}
        ``"curve"`` (default): ``K`` from the slope of the computed ``ln p(ū)`` curve, no
        extra solve (needs two pressures; one pressure falls back to ``"solve"``).
        ``"solve"``: one more warm-started solve at ``p (1 + 1 %)`` per pressure.
    progress : callable, optional
        Called as ``progress(done, total)`` after each pressure.

    Returns
    -------
    FlatContact
        Area fraction, mean gap and stiffness per pressure, with the solve records.

    Raises
    ------
    ContactInputError
        Non-finite heights, a flat surface, non-positive pressures or moduli, or a pressure
        at or above the hardness (full plastic contact, no solution to compare).

    See Also
    --------
    surfmet.mechanics.flat_contact.flat_contact : the same on a scan, against the theories.
    contact.solve_normal : the solver of each pressure.

    References
    ----------
    .. [1] I. A. Polonsky, L. M. Keer, "A numerical method for solving rough contact
       problems based on the multi-level multi-summation and conjugate gradient
       techniques", Wear 231 (1999) 206-219.

    Examples
    --------
    A 64 x 64 patch of the bundled plate pressed at 10 and 30 MPa: the real contact area
    grows with the load:

    >>> import surfmet
    >>> from contact import flat_contact
    >>> from contact._geometry import remove_plane
    >>> from contact._grid import gap_grid
    >>> from surfmet.data import path
    >>> plate = surfmet.read(path("paper_plate.x3p"))
    >>> z, _ = remove_plane(plate.heights[:64, :64], plate.dx, plate.dx)
    >>> grid = gap_grid(z.max() - z, plate.dx, periodic=True)
    >>> sweep = flat_contact(grid, pressures=[1e7, 3e7], e_star=58.6e9)
    >>> a1, a2 = sweep.area_fraction
    >>> bool(a2 > a1), sweep.solve.converged
    (True, True)
    """
    from contact.bem import PressureBounds, solve_normal
    from contact.bem._options import options_of

    if not isinstance(grid, Grid) or grid.h is None or grid.line:
        raise ContactInputError("flat_contact takes a 3D contact._grid.Grid carrying the "
                                "separation from the flat (contact._grid.gap_grid)")
    z = np.asarray(grid.h, dtype=float)
    dx, dy, periodic = grid.dx, grid.dy, grid.periodic
    if z.ndim != 2 or min(z.shape) < 8:
        raise ContactInputError("the surface must be a 2D height map of at least 8 x 8")
    if not np.all(np.isfinite(z)):
        raise ContactInputError("the surface has non-measured (NaN) points: fill or crop them "
                                "before the contact solve")
    if not np.ptp(z) > 0:
        raise ContactInputError("the surface is flat: there is no roughness to press")
    p = np.sort(np.atleast_1d(np.asarray(pressures, dtype=float)))
    if p.size == 0 or not np.all(np.isfinite(p)) or np.any(p <= 0):
        raise ContactInputError("nominal pressures must be finite and positive")
    e_star = modulus(e_star)
    positive(e_star, "E*", "Pa")
    if hardness is not None and p[-1] >= hardness:
        raise ContactInputError(
            f"the nominal pressure {p[-1]:.4g} Pa reaches the hardness {hardness:.4g} Pa: "
            "the whole surface would yield"
        )
    if stiffness not in ("curve", "solve"):
        raise ContactInputError(f"stiffness must be 'curve' or 'solve', got {stiffness!r}")
    by_solve = stiffness == "solve" or p.size == 1 or np.unique(p).size != p.size
    # first touch at zero approach (no-op for a separation of zero minimum)
    h = z - float(z.min())
    grid = grid.with_gap(h)
    opts = options_of(options).but(edge="ignore")  # the edge is said once, below
    area0 = z.size * dx * dy
    points = []
    notes: list[str] = []
    warm = None
    for k, pk in enumerate(p):
        kw = dict(e_star=e_star, bounds=PressureBounds.elastic(hardness), options=opts)
        res = solve_normal(grid, load=pk * area0, initial=warm, **kw)
        warm = np.asarray(res.pressure)
        gap1 = _mean_gap(res)
        stiff = math.nan
        if by_solve:
            res2 = solve_normal(grid, load=pk * (1 + STIFFNESS_STEP) * area0,
                                initial=res.pressure, **kw)
            gap2 = _mean_gap(res2)
            stiff = -pk * STIFFNESS_STEP / (gap2 - gap1) if gap2 < gap1 else math.inf
        contact = np.asarray(res.pressure) > 0
        points.append(FlatPoint(
            pressure=float(pk), area_fraction=float(res.area_fraction),
            corrected_area_fraction=corrected_area(contact, dx, dy) / area0,
            mean_gap=gap1, stiffness=float(stiff), n_clusters=int(res.n_clusters),
            max_pressure=float(res.pmax), plastic_fraction=float(res.plastic_area / area0),
            solve=res.solve))
        if res.touches_edge and not notes:  # the record's edge_contact: never when periodic
            notes.append(f"{edge_message('the scan')} (on a free boundary the missing "
                         "neighbours make the surface softer than in the bulk; a periodic scan "
                         "has no edge)")
        if progress is not None:
            progress(k + 1, p.size)
    if not by_solve:
        gaps = np.array([pt.mean_gap for pt in points])
        k = curve_stiffness(p, gaps)
        points = [replace(pt, stiffness=float(kk)) for pt, kk in zip(points, k)]
        bent = bent_points(p, gaps)
        if bent.any():
            notes.append("stiffness at " + ", ".join(f"{pk:.3g} Pa" for pk in p[bent])
                         + ": the quadratic through the neighbouring pressures bends the "
                         "wrong way (pressures too few or too far apart), so the secant is "
                         "given; add pressures or use stiffness='solve' (--stiffness solve)")
    return FlatContact(points=tuple(points), periodic=periodic, e_star=float(e_star),
                       hardness=hardness, shape=(int(z.shape[0]), int(z.shape[1])),
                       dx=float(dx), dy=float(dy), notes=tuple(notes))


def _mean_gap(res: Any) -> float:
    """Mean separation of the flat from the deformed surface's mean plane: the mean of
    the deformed gap ``g = h + u - δ`` (zero on the contact)."""
    return float(np.mean(np.asarray(res.gap)))


def curve_stiffness(pressure: np.ndarray, mean_gap: np.ndarray) -> np.ndarray:
    """``K = -dp/dū`` at each point of a computed load-separation curve, Pa/m.

    ``d(ln p)/dū`` is the derivative at each point of the quadratic (Lagrange) through the
    point and its two neighbours in ``(ū, ln p)``, one-sided at the ends, the secant with
    two points; exact whenever ``ln p`` is quadratic in ū, the exponential law of rough
    contact included. Where pressures too few or too far apart make that quadratic bend
    the wrong way (a stiffness <= 0, which no contact has), the secant through the
    neighbouring points is used instead (:func:`bent_points` says where). Points whose
    gap does not decrease give ``inf``.
    """
    p = np.asarray(pressure, dtype=float)
    u = np.asarray(mean_gap, dtype=float)
    if p.size < 2:
        raise ContactInputError("the curve stiffness needs at least two pressures")
    if np.any(np.diff(u) >= 0):
        return np.full(p.size, math.inf)
    out = _quadratic_stiffness(p, u)
    bent = ~(out > 0)
    if bent.any():
        y = np.log(p)
        lo = np.maximum(np.arange(p.size) - 1, 0)
        hi = np.minimum(np.arange(p.size) + 1, p.size - 1)
        secant = -p * (y[hi] - y[lo]) / (u[hi] - u[lo])
        out = np.where(bent, secant, out)
    return out


def bent_points(pressure: np.ndarray, mean_gap: np.ndarray) -> np.ndarray:
    """Where :func:`curve_stiffness` fell back to the secant (boolean per point)."""
    p = np.asarray(pressure, dtype=float)
    u = np.asarray(mean_gap, dtype=float)
    if p.size < 3 or np.any(np.diff(u) >= 0):
        return np.zeros(p.size, dtype=bool)
    return ~(_quadratic_stiffness(p, u) > 0)


def _quadratic_stiffness(p: np.ndarray, u: np.ndarray) -> np.ndarray:
    y = np.log(p)
    n = p.size
    if n == 2:
        slope = (y[1] - y[0]) / (u[1] - u[0])
        return -p * slope
    out = np.empty(n)
    for i in range(n):
        j = min(max(i - 1, 0), n - 3)  # the three points j, j+1, j+2 around (or next to) i
        x0, x1, x2 = u[j], u[j + 1], u[j + 2]
        y0, y1, y2 = y[j], y[j + 1], y[j + 2]
        x = u[i]
        # derivative of the Lagrange quadratic through the three points, at x
        d = (y0 * (2 * x - x1 - x2) / ((x0 - x1) * (x0 - x2))
             + y1 * (2 * x - x0 - x2) / ((x1 - x0) * (x1 - x2))
             + y2 * (2 * x - x0 - x1) / ((x2 - x0) * (x2 - x1)))
        out[i] = -p[i] * d
    return out
