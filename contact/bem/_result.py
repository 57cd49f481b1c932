"""The result of a normal-contact solve: fields, scalars and the quantities derived from them.

All values SI. Conventions (shared with :mod:`contact.bem`): row ``i`` is at
``y[i]``, column ``j`` at ``x[j]`` (cell centres, metres, relative to the solver's
reference point, the sphere apex for :func:`contact.setups._ball_on_plate.solve_sphere`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact._grid import Grid
from contact._record import SolveRecord, edge_contact
from contact._validate import frozen

#: What the normal solver's residual measures (see :class:`ContactResult`).
RESIDUAL_DEFINITION = ("rms gap error on the contact over the displacement of one cell at "
                       "the mean contact pressure")


@dataclass(frozen=True, eq=False)
class ContactResult:
    """Normal contact solution on a regular grid.

    The fields are arrays of shape (ny, nx) on :attr:`grid`; the rest are scalars (SI).

    Attributes
    ----------
    pressure : ndarray
        Contact pressure p (Pa), >= 0, <= hardness when a hardness is set.
    gap : ndarray
        Deformed gap between the surfaces (m), >= 0; 0 where in contact.
    displacement : ndarray
        Combined elastic normal displacement u of both surfaces, positive into the bodies
        (m). Body i takes the share ((1 - nu_i^2)/E_i) * E* of it
        (:func:`contact._materials.displacement_shares`).
    plastic_displacement : ndarray
        Permanent combined indentation where the pressure reached the hardness (m), 0
        elsewhere (Almqvist et al. 2007, Wear 262:1321).
    grid : Grid
        The grid solved on (its pitch, origin and boundary).
    e_star, hardness : float
        Composite modulus E* (Pa) and the hardness cap (Pa; None: no cap).
    load : float
        Total normal force (N).
    approach : float
        Rigid-body approach delta (m) in the gap equation g = h + u - delta.
    pmax : float
        Maximum pressure (Pa).
    contact_area, area_fraction : float
        Area of the cells with p > 0 (m^2), and that over the domain's area.
    contact_radius : float
        sqrt(contact_area / pi) (m): the radius of a disc of the real contact area. Not
        the macroscopic radius of a rough contact: that is :attr:`effective_radius` (a*),
        a different name for a different quantity.
    radius_95 : float
        Radius about the pressure centroid of the disc holding 95 % of the load (m).
    centroid : tuple of float
        (x, y) of the pressure centroid (m).
    n_clusters : int
        Number of contact spots (4-connected cells with p > 0; in a periodic domain spots
        that wrap around the boundary count once).
    plastic_area : float
        Area of the cells at the hardness (m^2).
    solve : SolveRecord
        The solve record (:mod:`contact._record`); the residual is the rms gap error on
        the contact divided by the displacement one cell at the mean contact pressure makes
        on itself (about the rms relative pressure error per cell); ``edge_contact`` is
        pressure on the outermost ring of a free-boundary domain
        (:func:`contact._record.edge_contact`). ``iterations``, ``residual``, ``converged``
        and ``touches_edge`` read it.
    notes : tuple of str
        Caveats of the set-up that made it.
    hertz : object or None
        Hertz's values for comparison, where a set-up (sphere, cylinder) gave them.
    extra : dict
        What a solve or set-up adds (``"levels"``, ``"kernel"``, ``"removed_plane"``...).

    See Also
    --------
    contact.solve_normal, contact.solve_sphere : make it.

    Examples
    --------
    >>> from contact import solve_sphere
    >>> from contact import DomainSpec
    >>> res = solve_sphere(0.02, 10.0, 58.6e9, domain=DomainSpec(grid=64))
    >>> res.pressure.shape, res.n_clusters, res.solve.converged
    ((64, 64), 1, True)
    >>> print(f"W = {res.load:.3f} N, pmax = {res.pmax / 1e6:.0f} MPa")
    W = 10.000 N, pmax = 255 MPa
    """

    pressure: np.ndarray
    gap: np.ndarray
    displacement: np.ndarray
    plastic_displacement: np.ndarray
    grid: Grid
    e_star: float
    hardness: float | None
    load: float
    approach: float
    pmax: float
    contact_area: float
    area_fraction: float
    contact_radius: float
    radius_95: float
    centroid: tuple[float, float]
    n_clusters: int
    plastic_area: float
    solve: SolveRecord
    notes: tuple[str, ...] = ()
    hertz: Any = None
    extra: dict[str, Any] = field(default_factory=dict)

    def __repr__(self) -> str:
        # one line of SI numbers: the dataclass's own repr printed every array in full
        ny, nx = self.pressure.shape
        return (f"ContactResult({nx} x {ny} cells, load={self.load:.4g} N, "
                f"contact_radius={self.contact_radius:.4g} m, pmax={self.pmax:.4g} Pa, "
                f"converged={self.converged})")

    @property
    def shape(self) -> tuple[int, int]:
        """Grid shape (ny, nx)."""
        return self.pressure.shape  # type: ignore[return-value]

    @property
    def x(self) -> np.ndarray:
        """Cell-centre x coordinates (m), read-only (the grid's)."""
        return self.grid.x

    @property
    def y(self) -> np.ndarray:
        """Cell-centre y coordinates (m), read-only (the grid's)."""
        return self.grid.y

    @property
    def dx(self) -> float:
        """Cell pitch along x (m)."""
        return self.grid.dx

    @property
    def dy(self) -> float:
        """Cell pitch along y (m)."""
        return self.grid.dy

    @property
    def periodic(self) -> bool:
        """Periodic domain (else a free boundary)."""
        return self.grid.periodic

    @property
    def iterations(self) -> int:
        """Iterations of the finest grid (the solve record's)."""
        return self.solve.iterations

    @property
    def residual(self) -> float:
        """The residual reached (the solve record's)."""
        return self.solve.residual

    @property
    def converged(self) -> bool:
        """The tolerance was reached (the solve record's)."""
        return self.solve.converged

    @property
    def touches_edge(self) -> bool:
        """Pressure on the edge of a free-boundary domain (the solve record's
        ``edge_contact``): the domain may cut the contact short."""
        return self.solve.edge_contact

    @property
    def contact(self) -> np.ndarray:
        """Boolean map of the cells in contact (p > 0)."""
        return self.pressure > 0

    @property
    def plastic(self) -> bool:
        """True if some cells reached the hardness."""
        return self.plastic_area > 0

    @property
    def regime(self) -> str:
        """"elastic", "plastic at the asperity scale" (some cells at the hardness while the
        Hertz peak pressure of the same load stays below it) or "plastic at the Hertz
        scale"; "elastic" also when no hardness was given."""
        if self.hardness is None or self.plastic_area <= 0:
            return "elastic"
        p0 = getattr(self.hertz, "p0", None)
        if p0 is not None and p0 < self.hardness:
            return "plastic at the asperity scale"
        return "plastic at the Hertz scale"

    @property
    def effective_radius(self) -> float:
        """Second-moment radius a* = sqrt(5/2 <r^2>_p) about the pressure centroid (m):
        the radius of the Hertz distribution with the same spread of load, comparable
        with the Hertz a for a rough contact (:func:`contact._fields.effective_radius`)."""
        from contact._fields import effective_radius

        return effective_radius(self.pressure, self.x, self.y)

    @property
    def mean_pressure(self) -> float:
        """Load over contact area (Pa); NaN without contact."""
        return self.load / self.contact_area if self.contact_area > 0 else math.nan

    def radial_coordinates(self, centre: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
        """Distance of every cell centre from ``centre`` (m), shape (ny, nx)."""
        return np.hypot(self.x[None, :] - centre[0], self.y[:, None] - centre[1])

    def summary(self) -> dict[str, Any]:
        """The scalar results as a plain dict (SI values, no arrays)."""
        out: dict[str, Any] = {
            "load": self.load,
            "approach": self.approach,
            "pmax": self.pmax,
            "mean_pressure": self.mean_pressure,
            "contact_area": self.contact_area,
            "area_fraction": self.area_fraction,
            "contact_radius": self.contact_radius,
            "radius_95": self.radius_95,
            "centroid": self.centroid,
            "n_clusters": self.n_clusters,
            "plastic_area": self.plastic_area,
            "regime": self.regime,
            "hardness": self.hardness,
            "e_star": self.e_star,
            "periodic": self.periodic,
            "grid": self.shape,
            "dx": self.dx,
            "dy": self.dy,
            "iterations": self.iterations,
            "residual": self.residual,
            "converged": self.converged,
            "touches_edge": self.touches_edge,
            "solve": dataclasses.asdict(self.solve),
            "notes": list(self.notes),
        }
        return out

    def arrays(self) -> dict[str, np.ndarray]:
        """The fields and coordinates, for ``np.savez``."""
        return {
            "pressure": self.pressure,
            "gap": self.gap,
            "displacement": self.displacement,
            "plastic_displacement": self.plastic_displacement,
            "x": self.x,
            "y": self.y,
        }


def cluster_labels(contact: np.ndarray, periodic: bool = False) -> tuple[np.ndarray, int]:
    """Label the 4-connected contact spots: ``(labels, n)`` with labels 1..n, 0 = no contact.

    In a periodic domain, spots that wrap across the boundary get one label (the
    scikit-image labelling of the cell grid, then a union-find over the opposite edges).
    """
    from skimage.measure import label

    contact = np.asarray(contact, dtype=bool)
    labels, n = label(contact, connectivity=1, return_num=True)
    if not periodic or n <= 1:
        return labels, int(n)
    parent = np.arange(n + 1)

    def root(a: int) -> int:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = int(parent[a])
        return a

    for first, last in ((labels[0, :], labels[-1, :]), (labels[:, 0], labels[:, -1])):
        both = (first > 0) & (last > 0)
        for a, b in zip(first[both], last[both]):
            ra, rb = root(int(a)), root(int(b))
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([root(k) for k in range(n + 1)])
    _, dense = np.unique(roots, return_inverse=True)  # 0 stays 0: root(0) == 0 is smallest
    return dense.reshape(-1)[labels], int(dense.max())


def count_clusters(contact: np.ndarray, periodic: bool = False) -> int:
    """Number of 4-connected clusters of True cells (merged across edges when periodic)."""
    if not np.any(contact):
        return 0
    return cluster_labels(contact, periodic)[1]


def load_radius(pressure: np.ndarray, x: np.ndarray, y: np.ndarray, centre: tuple[float, float],
                fraction: float = 0.95) -> float:
    """Radius about ``centre`` of the smallest disc of cell centres holding ``fraction``
    of the load (linear interpolation between the cells' distances)."""
    mask = pressure > 0
    if not mask.any():
        return 0.0
    yy, xx = np.nonzero(mask)
    r = np.hypot(x[xx] - centre[0], y[yy] - centre[1])
    w = pressure[mask]
    order = np.argsort(r, kind="stable")
    cum = np.cumsum(w[order])
    target = fraction * cum[-1]
    k = int(np.searchsorted(cum, target))
    if k == 0:
        return float(r[order[0]])
    r0, r1 = r[order[k - 1]], r[order[k]]
    c0, c1 = cum[k - 1], cum[k]
    return float(r0 + (r1 - r0) * (target - c0) / (c1 - c0)) if c1 > c0 else float(r1)


def build_result(
    *,
    pressure: np.ndarray,
    gap: np.ndarray,
    displacement: np.ndarray,
    plastic_displacement: np.ndarray,
    grid: Grid,
    e_star: float,
    hardness: float | None,
    approach: float,
    iterations: int,
    residual: float,
    converged: bool,
    tolerance: float = math.nan,
    method: str = "normal BEM",
    notes: tuple[str, ...] = (),
    hertz: Any = None,
    extra: dict[str, Any] | None = None,
) -> ContactResult:
    """Assemble a :class:`ContactResult`, computing every derived quantity from the fields
    (the solve record's ``edge_contact`` from the pressure). The result keeps ``grid``'s
    cells (read-only coordinates, pitch, boundary), not its gap."""
    dx, dy, periodic = float(grid.dx), float(grid.dy), bool(grid.periodic)
    x, y = frozen(np.asarray(grid.x, float)), frozen(np.asarray(grid.y, float))
    da = dx * dy
    contact = pressure > 0
    load = float(pressure.sum() * da)
    area = float(np.count_nonzero(contact) * da)
    if load > 0:
        cx = float((pressure.sum(axis=0) * x).sum() * da / load)
        cy = float((pressure.sum(axis=1) * y).sum() * da / load)
    else:
        cx = cy = math.nan
    plastic_area = 0.0
    if hardness is not None:
        plastic_area = float(np.count_nonzero(pressure >= hardness) * da)
    return ContactResult(
        pressure=frozen(pressure),
        gap=frozen(gap),
        displacement=frozen(displacement),
        plastic_displacement=frozen(plastic_displacement),
        grid=Grid(x=x, y=y, periodic=periodic, pitch=(dx, dy)),
        e_star=float(e_star),
        hardness=None if hardness is None else float(hardness),
        load=load,
        approach=float(approach),
        pmax=float(pressure.max()) if pressure.size else 0.0,
        contact_area=area,
        area_fraction=area / (pressure.size * da),
        contact_radius=math.sqrt(area / math.pi),
        radius_95=load_radius(pressure, x, y, (cx, cy)) if load > 0 else 0.0,
        centroid=(cx, cy),
        n_clusters=count_clusters(contact, periodic),
        plastic_area=plastic_area,
        solve=SolveRecord(method=method, iterations=int(iterations), residual=float(residual),
                          tolerance=float(tolerance), converged=bool(converged),
                          edge_contact=edge_contact(pressure, periodic),
                          residual_definition=RESIDUAL_DEFINITION, periodic=bool(periodic)),
        notes=tuple(notes),
        hertz=hertz,
        extra=dict(extra or {}),
    )
