"""Line contact (plane strain): a cylinder, or any 2D profile, pressed on a half-plane.

Why a 1D solver rather than the 3D one with a periodic direction: the 3D FFT solver is
periodic in both directions or in neither, so a long cylinder would come with periodic
images along the rolling direction too, whose interaction changes the pressure by
O((a/L)^2) and the load exponent with it. The plane-strain problem is one-dimensional,
small (a few hundred unknowns) and exact: it is solved directly, with dense influence
coefficients and an active-set iteration.

The solve itself, and the conventions and influence coefficients it uses, are those of
:mod:`contact.bem._line` (the package's one plane-strain normal solve).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._errors import ContactInputError
from contact._grid import Grid
from contact._hertz import hertz_cylinder
from contact._material_pair import MaterialPair, modulus
from contact._record import SolveRecord, edge_contact, edge_warning
from contact._validate import frozen, positive
from contact.bem._line import active_set_record, solve_line_pressure


@dataclass(frozen=True, eq=False)
class LineContactResult:
    """Solution of a plane-strain line contact (all SI, per unit length along the line).

    Attributes
    ----------
    grid : Grid
        The cells (a line :class:`contact._grid.Grid`, without its gap): ``x`` the cell
        centres (m), ``dx`` the pitch (m).
    pressure : ndarray
        Contact pressure p (Pa).
    displacement : ndarray
        Combined normal displacement u (m), positive into the bodies, against the datum of
        the module notes (only differences are physical).
    gap : ndarray
        Deformed gap (m), 0 in contact.
    e_star : float
        Composite modulus (Pa).
    load : float
        Load per unit length W' (N/m).
    approach : float
        delta in g = h + u - delta, against the same datum as ``displacement``.
    pmax : float
        Peak pressure (Pa).
    half_width : float
        Half the extent of the contact (m): (last - first contact cell + 1) dx / 2.
    centre : float
        Mid-point of the contact extent (m).
    iterations : int
        Active-set iterations.
    solve : SolveRecord
        The solve record (:mod:`contact._record`): the residual is the largest gap error
        (gap on the contact set, interpenetration off it) over the range of the gap.
    hertz : HertzCylinder or None
        The Hertz solution of the same load, when the problem is a cylinder.
    """

    grid: Grid
    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    e_star: float
    load: float
    approach: float
    pmax: float
    half_width: float
    centre: float
    iterations: int
    solve: SolveRecord
    hertz: Any = None
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def x(self) -> np.ndarray:
        """Cell centres (m), read-only."""
        return self.grid.x

    @property
    def dx(self) -> float:
        """Cell pitch (m)."""
        return self.grid.dx

    @property
    def touches_edge(self) -> bool:
        """Pressure on the first or last cell (the record's ``edge_contact``): the domain
        may cut the contact short."""
        return self.solve.edge_contact


def solve_line(
    gap0: np.ndarray,
    dx: float,
    *,
    e_star: float | MaterialPair,
    load: float,
    origin: float = 0.0,
    max_iter: int = 200,
) -> LineContactResult:
    """Frictionless normal contact of two plane-strain bodies with initial gap ``gap0``.

    Active-set method: on the current contact set the pressures and the approach solve
    ``h + K p - delta = 0`` with ``sum(p) dx = W'``; cells with negative pressure leave
    the set, cells that interpenetrate enter it, until neither happens. Each step is a
    dense solve of the contact set (exact, no tolerance to choose).

    Parameters
    ----------
    gap0 : ndarray, shape (n,)
        Initial gap h (m), e.g. x^2/(2R) minus a roughness profile.
    dx : float
        Cell pitch (m).
    e_star : float or MaterialPair
        Composite modulus E* (Pa),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    load : float
        Load per unit length W' (N/m).
    origin : float
        x of the centre of cell 0 (m).
    max_iter : int
        Active-set iteration limit.

    Raises
    ------
    ContactInputError
        Bad gap, pitch, modulus or load.
    ConvergenceError
        The active set did not settle.
    """
    h = np.asarray(gap0, dtype=float)
    if h.ndim != 1 or h.size < 2 or not np.isfinite(h).all():
        raise ContactInputError("the line gap must be a finite 1D array of at least 2 cells")
    dx = positive(dx, "dx", "m")
    e_star = positive(modulus(e_star), "E*", "Pa")
    load = positive(load, "the load per length", "N/m")
    n = h.size
    sol = solve_line_pressure(h, dx, e_star, load, max_iter=max_iter)
    p, delta, it, K, active = (sol.pressure, sol.approach, sol.iterations, sol.influence,
                               sol.active)
    u = K @ p
    gap = np.maximum(h + u - delta, 0.0)
    gap[active] = 0.0
    record = active_set_record("plane-strain active set", h + u - delta, active, h, it,
                               edge_contact(p))
    edge_warning(record.edge_contact)
    x = origin + np.arange(n) * dx
    on = np.flatnonzero(p > 0)
    lo, hi = (x[on[0]], x[on[-1]]) if on.size else (math.nan, math.nan)
    return LineContactResult(
        grid=Grid(x=frozen(x), y=np.zeros(1), line=True, pitch=(float(dx), 1.0)),
        pressure=frozen(p), displacement=frozen(u), gap=frozen(gap),
        e_star=float(e_star), load=float(p.sum() * dx),
        approach=delta, pmax=float(p.max()),
        half_width=0.5 * (hi - lo + dx) if on.size else 0.0,
        centre=0.5 * (hi + lo) if on.size else math.nan, iterations=it, solve=record,
    )


def solve_cylinder(
    radius: float,
    load: float,
    e_star: float | MaterialPair,
    *,
    n: int = 1024,
    size: float | None = None,
    roughness: np.ndarray | None = None,
    roughness_dx: float | None = None,
) -> LineContactResult:
    """A cylinder (axis along y) of radius R on a flat, load W' per unit length.

    Parameters
    ----------
    radius : float
        R (m).
    load : float
        W' (N/m).
    e_star : float or MaterialPair
        E* (Pa),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    n : int
        Cells across the domain.
    size : float, optional
        Domain width (m); default 2.5 Hertz contact widths (5 a).
    roughness : ndarray, optional
        Composite roughness profile (m, closes the gap: h = x^2/(2R) - z), sampled at
        ``roughness_dx`` and centred on the cylinder's axis; resampled onto the grid.
    roughness_dx : float, optional
        Pitch of the roughness profile (m).

    Returns
    -------
    LineContactResult
        Pressure, gap and displacement on the line, ``pmax``, ``half_width`` and the
        ``hertz`` solution of the smooth cylinder.

    Raises
    ------
    ContactInputError
        A radius, load or modulus that is not positive and finite, or a roughness without
        its pitch.

    See Also
    --------
    contact.hertz_cylinder : the closed form.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.3.

    Examples
    --------
    >>> from contact import solve_cylinder
    >>> res = solve_cylinder(0.01, 1e4, 58.6e9, n=256)
    >>> print(f"pmax / p0 = {res.pmax / res.hertz.p0:.4f}")
    pmax / p0 = 1.0000
    """
    radius = positive(radius, "the cylinder's radius", "m")
    load = positive(load, "the cylinder's load", "N/m")
    e_star = positive(modulus(e_star), "the cylinder's E*", "Pa")
    if int(n) < 8:
        raise ContactInputError("the line grid needs at least 8 cells")
    hz = hertz_cylinder(radius, load, e_star)
    side = 5.0 * hz.a if size is None else positive(size, "the domain size", "m")
    n = int(n)
    dx = side / n
    x = (np.arange(n) - n // 2) * dx
    h = x**2 / (2.0 * radius)
    if roughness is not None:
        z = np.asarray(roughness, dtype=float)
        if z.ndim != 1 or not np.isfinite(z).all():
            raise ContactInputError("the roughness profile must be a finite 1D array")
        if not (roughness_dx and roughness_dx > 0):
            raise ContactInputError("give the roughness profile's pitch roughness_dx")
        xs = (np.arange(z.size) - (z.size - 1) / 2) * roughness_dx
        if x[0] < xs[0] or x[-1] > xs[-1]:
            raise ContactInputError("the roughness profile is shorter than the domain")
        h = h - np.interp(x, xs, z)
    res = solve_line(h - h.min(), dx, e_star=e_star, load=load, origin=float(x[0]))
    import dataclasses

    return dataclasses.replace(res, hertz=hz, extra={"radius": float(radius)})
