"""Adhesive line contact: a cylinder (or a rough profile) on a flat, in plane strain.

The adhesive solve of :mod:`contact.adhesion.solver` (the gap formulation, tensile
tractions solved) runs unchanged on a single row of cells: the stiffness is the core's
periodic Love spectrum (:func:`contact.halfspace.influence.periodic_kernel_spectrum`) for
one row, in which the alias sum keeps only the y-aliases of zero weight, so it is the
plane-strain response 2 / (E* |q|) of a pressure uniform along the axis, cell-averaged in
x. The cylinder's axis runs along y; x is periodic with the cell ``size``. Loads, energies
and the pull-off come out per unit length of the cylinder (N/m, J/m); the "contact area"
of a line cycle's branches is the contact width per unit length (m).

Closed forms quoted with the results (plane strain, composite modulus E*, radius R, work
of adhesion w):

- JKR line contact (Barquins 1988, J. Adhesion 26:1; Chaudhury, Weaver, Hui & Kramer
  1996, J. Appl. Phys. 80:30): a Hertz cylinder of half-width a carries
  P'_H = pi E* a^2 / (4 R); a flat-punch term P'_H - P' gives the stress intensity
  K = (P'_H - P') / sqrt(pi a) at the edges, and Griffith's balance K^2 / (2 E*) = w gives
  P' = pi E* a^2 / (4 R) - sqrt(2 pi E* w a). Its minimum (the pull-off under load
  control, reached too under stiff displacement control) is at
  a_c = (2 w R^2 / (pi E*))^(1/3) and is P'_c = -3 (pi w^2 E* R / 16)^(1/3); the contact
  half-width at zero load is a_0 = (32 w R^2 / (pi E*))^(1/3).
- The rigid (DMT-like) limit E* -> infinity: the undeformed gap x^2 / (2 R) pulls with the
  law's traction, P'_rigid = integral of t(x^2 / (2 R)) dx: 2 sqrt(2 R w sigma0) for the
  Dugdale law (width 2 sqrt(2 R h0) under sigma0), w sqrt(2 pi R / rho) for the
  exponential law. Unlike the sphere's 2 pi w R, it depends on the range: a line contact
  has no range-free DMT limit (Baney & Hui 1997, J. Adhesion Sci. Technol. 11:393, for
  the Maugis-Dugdale cylinder between the two).
- Between them, Maugis-Dugdale for the cylinder (Baney & Hui 1997; Johnson & Greenwood
  2008, J. Phys. D 41:155315): Hertz of half-width a plus the Dugdale field, tension
  sigma0 on a < |x| < c and -(2 sigma0 / pi) arctan(sqrt((c^2 - a^2) / (a^2 - x^2)))
  inside, so P' = pi E* a^2 / (4 R) - 2 sigma0 sqrt(c^2 - a^2), with c fixed by the gap
  h0 at x = c.

The transition is stated with Maugis' parameter of the cylinder's radius,
lambda = 2 sigma0 (R / (pi w K^2))^(1/3), K = 4 E* / 3 (the group sigma0 (R / (w E*^2))^(1/3)
governs the line contact's transition too; the constant is the sphere's, Maugis 1992, so
that a cylinder and a sphere of the same R, w, sigma0 and E* state the same lambda), with
Tabor's mu = (R w^2 / (E*^2 z^3))^(1/3) of the law's range z, and with the cohesive
zone's width against a_c. Resolution and domain follow :mod:`contact.adhesion.ball`:
the cohesive zone pi E* w / (4 sigma0^2) should span
:data:`contact._zone_resolution.MIN_ZONE_PIXELS_PLAIN` cells, and
the periodic images of the cylinder shift the load at a given width by about
(pi^2 / 6) (a / L)^2, so the default cell is 16 times the larger of a_0 and the
interaction's reach.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError
from contact._grid import Grid, centred_coordinates
from contact._material_pair import MaterialPair, modulus
from contact._validate import positive
from contact._zone_resolution import MIN_ZONE_PIXELS_PLAIN
from contact.adhesion.ball import coarse_zone_effect, rough_gap
from contact.adhesion.cycle import Branch, Cycle, Jump, approach_retraction
from contact.adhesion.laws import InteractionLaw, checked_law, tabor_parameter
from contact.adhesion.memory import check_adhesion_memory
from contact.adhesion.solver import AdhesiveProblem
from contact.halfspace.influence import periodic_kernel_spectrum

#: The default cell, in units of the larger of a_0 and the reach of the interaction.
CELL_WIDTHS = 16.0


@dataclass(frozen=True)
class AdhesiveLine:
    """An approach-retraction cycle of an adhesive cylinder on a flat, per unit length.

    Attributes
    ----------
    radius, e_star : float
        Cylinder radius R (m) and composite plane-strain modulus E* (Pa).
    law : InteractionLaw
        The adhesion law.
    cells : int
        Cells across the periodic cell.
    size, dx : float
        Period and pixel (m).
    cycle : Cycle
        The two legs per unit length: loads (N/m), contact widths (m, in ``contact_area``),
        energies and hysteresis (J/m), pull-off (N/m).
    maugis_parameter : float
        Maugis' lambda of the cylinder's radius (module notes).
    process_zone : float
        The cohesive zone width pi E* w / (4 sigma0^2) (m).
    warnings : tuple of str
        Resolution, domain and separation warnings.
    roughness_rms : float
        Rms of the roughness profile (m); 0 for a smooth cylinder.
    """

    radius: float
    e_star: float
    law: InteractionLaw
    cells: int
    size: float
    dx: float
    cycle: Cycle
    maugis_parameter: float
    process_zone: float
    warnings: tuple[str, ...]
    roughness_rms: float = 0.0

    @property
    def tabor_parameter(self) -> float:
        """Tabor's mu = (R w^2 / (E*^2 z^3))^(1/3) of the cylinder's radius, z the law's
        range (:func:`contact.adhesion.laws.tabor_parameter`, as the ball states it)."""
        return tabor_parameter(self.law.work, self.radius, self.e_star, self.law.range)

    @property
    def jkr_pull_off(self) -> float:
        """3 (pi w^2 E* R / 16)^(1/3) (N/m), the JKR line contact's (module notes)."""
        return jkr_line_pull_off(self.law.work, self.radius, self.e_star)

    @property
    def rigid_pull_off(self) -> float:
        """The rigid-cylinder limit of the pull-off (N/m, module notes)."""
        return rigid_line_pull_off(self.law, self.radius)

    @property
    def half_width(self) -> tuple[np.ndarray, np.ndarray]:
        """Contact half-widths (m) on the way in and on the way out."""
        return (0.5 * self.cycle.approach_leg.contact_area,
                0.5 * self.cycle.retraction_leg.contact_area)


def jkr_line_pull_off(work: float, radius: float, e_star: float) -> float:
    """3 (pi w^2 E* R / 16)^(1/3) (N/m): the JKR cylinder's pull-off, a positive magnitude."""
    return 3.0 * (math.pi * work * work * e_star * radius / 16.0) ** (1.0 / 3.0)


def jkr_line_load(half_width: np.ndarray, work: float, radius: float,
                  e_star: float) -> np.ndarray:
    """P' = pi E* a^2 / (4 R) - sqrt(2 pi E* w a) (N/m), the JKR cylinder's load."""
    a = np.asarray(half_width, dtype=float)
    return math.pi * e_star * a * a / (4.0 * radius) - np.sqrt(2.0 * math.pi * e_star * work * a)


def rigid_line_pull_off(law: InteractionLaw, radius: float) -> float:
    """The pull-off (N/m) of a rigid cylinder: the law's traction integrated over the
    undeformed gap x^2 / (2 R), as the law states it
    (:meth:`contact.adhesion.laws.InteractionLaw.rigid_line_pull_off`)."""
    return checked_law(law).rigid_line_pull_off(radius)


def line_scales(radius: float, e_star: float, law: InteractionLaw) -> tuple[float, float]:
    """(JKR half-width at zero load a_0, lateral reach of the interaction sqrt(2 R h)), m."""
    a0 = (32.0 * law.work * radius * radius / (math.pi * e_star)) ** (1.0 / 3.0)
    return a0, math.sqrt(2.0 * radius * law.reach)


def line_problem(grid: Grid, e_star: float, law: InteractionLaw) -> AdhesiveProblem:
    """The adhesive problem of a periodic line-contact grid (plane strain) and its gap (m).

    ``grid`` is a :class:`contact._grid.Grid` with ``line`` and ``periodic`` set and the
    undeformed gap ``h`` (see :func:`periodic_line_grid`). The stiffness is the inverse of
    the core's periodic Love spectrum for a single row (module notes), its q = 0 entry the
    mean-displacement spring of :func:`contact.adhesion.solver.adhesive_problem`.
    """
    if not isinstance(grid, Grid) or grid.h is None or not (grid.line and grid.periodic):
        raise ContactInputError("the adhesive line needs a periodic line-contact "
                                "contact._grid.Grid with its gap h")
    h = np.ascontiguousarray(grid.h, dtype=float).reshape(1, -1)
    dx = grid.dx
    if h.shape[1] < 8 or not np.isfinite(h).all():
        raise ContactInputError("the line gap must be a finite profile of at least 8 cells")
    if not (dx > 0 and e_star > 0):
        raise ContactInputError("the pitch and E* must be positive")
    with np.errstate(divide="ignore"):
        s = e_star / np.asarray(periodic_kernel_spectrum(1, h.shape[1], float(dx), float(dx)))
    s[0, 0] = 0.0
    s[0, 0] = s.max()
    return AdhesiveProblem(h, float(dx), float(e_star), law, s, grid)


def periodic_line_grid(cells: int, dx: float, h: np.ndarray | None = None) -> Grid:
    """A periodic line-contact grid of ``cells`` cells of pitch ``dx`` (m), the origin on
    cell ``cells // 2``, with the gap ``h`` (m, one value a cell) if given."""
    x = centred_coordinates(int(cells), dx)
    gap = None if h is None else np.asarray(h, dtype=float).reshape(1, -1)
    return Grid(x=x, y=np.zeros(1), h=gap, line=True, periodic=True, pitch=(float(dx), 1.0))


def _approach_of(problem: AdhesiveProblem, pressure: np.ndarray) -> float:
    """The rigid approach at which ``pressure`` (Pa) holds the gap closed at the apex.

    The displacement is the solve's own: the problem's periodic operator
    (:attr:`contact.adhesion.solver.AdhesiveProblem.operator`, the one-row Love kernel the
    stiffness inverts; its q = 0 coefficient is zero) plus the mean-plane spring's share,
    mean(p) / spring, the q = 0 entry of the stiffness. (The free strip operator,
    :class:`contact.halfspace.plane_strain.StripOperator`, would drop the periodic images
    the cycle is solved with.)
    """
    p = np.asarray(pressure, dtype=float).reshape(problem.gap0.shape)
    u = problem.operator(p)[0] / problem.e_star + float(p.mean()) / problem.spring
    k = int(np.argmin(problem.gap0))
    return float(problem.gap0[0, k] + u[k])


def _approach_range(problem: AdhesiveProblem, x: np.ndarray, radius: float,
                    z_rms: float) -> tuple[float, float]:
    """(farthest, deepest) approach: from out of reach to a Hertz width of about 1.5 a_0,
    and back past the JKR pull-off state (Hertz plus a tensile flat punch at a_c)."""
    e, law = problem.e_star, problem.law
    a0, _ = line_scales(radius, e, law)
    dx = problem.dx
    a = 1.5 * a0
    p_deep = np.where(np.abs(x) < a, e / (2 * radius) * np.sqrt(np.maximum(a * a - x * x, 0)),
                      0.0)
    ac = a0 / 16.0 ** (1.0 / 3.0)
    hertz = e / (2 * radius) * np.sqrt(np.maximum(ac * ac - x * x, 0))
    # the flat punch of load -pi E* a_c^2 / R: cell averages of P1 / (pi sqrt(a^2 - x^2))
    lo, hi = np.clip((x - dx / 2) / ac, -1, 1), np.clip((x + dx / 2) / ac, -1, 1)
    punch = -math.pi * e * ac * ac / radius / math.pi * (np.arcsin(hi) - np.arcsin(lo)) / dx
    d_c = _approach_of(problem, hertz + punch)
    deepest = _approach_of(problem, p_deep) + 3.0 * z_rms
    return min(2.0 * d_c, 0.0) - 1.5 * law.reach - 3.0 * z_rms, deepest


def adhesive_line(radius: float, e_star: float | MaterialPair, law: InteractionLaw, *,
                  cells: int = 2048, size: float | None = None, steps: int = 40, tol: float = 1e-7,
                  roughness: np.ndarray | None = None,
                  progress: Callable[[int, int], None] | None = None) -> AdhesiveLine:
    """Approach a cylinder to a flat until its contact is about 1.5 a_0 wide, then retract.

    Parameters
    ----------
    radius, e_star : float
        Cylinder radius (m) and composite plane-strain modulus (Pa),
        or a resolved :class:`contact._material_pair.MaterialPair` (its E*, bit for bit).
    law : InteractionLaw
        A registered law (:mod:`contact.adhesion.laws`: e.g.
        :class:`~contact.adhesion.laws.DugdaleLaw`).
    cells : int
        Cells across the period.
    size : float, optional
        Period (m); default :data:`CELL_WIDTHS` times the larger of a_0 and the reach.
    steps : int
        Approach steps on each leg (split where the contact width leaps).
    tol : float
        Equilibrium tolerance of each solve, relative to the law's peak tension.
    roughness : ndarray, shape (cells,), optional
        Roughness profile z (m) on the cells, positive where it closes the gap (the
        cylinder's apex in the middle); default a smooth cylinder.
    progress : callable, optional
        Called as ``progress(step, total)``.
    """
    positive(radius, "the radius", "m")
    e_star = modulus(e_star)
    positive(e_star, "E*", "Pa")
    checked_law(law)  # an unknown law is refused, never solved as another
    if int(cells) != cells or cells < 64:
        raise ContactInputError(f"the cells must be an integer of at least 64, got {cells!r}")
    if int(steps) != steps or steps < 4:
        raise ContactInputError(f"the steps must be an integer of at least 4, got {steps!r}")
    check_adhesion_memory(int(cells), steps=int(steps), line=True)  # before allocating
    a0, reach = line_scales(radius, e_star, law)
    size = CELL_WIDTHS * max(a0, reach) if size is None else \
        positive(size, "the domain size", "m")
    dx = size / cells
    grid = periodic_line_grid(cells, dx)
    x = grid.x
    h = x * x / (2.0 * radius)
    h, z_rms = rough_gap(h, roughness, f"a finite profile of {cells} points")
    problem = line_problem(grid.with_gap(h.reshape(1, -1)), e_star, law)
    far, deep = _approach_range(problem, x, radius, z_rms)
    cycle = approach_retraction(problem, np.linspace(far, deep, int(steps)), tol=tol,
                                progress=progress)
    zone = math.pi * e_star * law.work / (4.0 * law.peak ** 2)
    per = _per_length(cycle, dx)
    return AdhesiveLine(
        radius=float(radius), e_star=float(e_star), law=law, cells=int(cells),
        size=float(size), dx=dx, cycle=per, maugis_parameter=law.maugis(radius, e_star),
        process_zone=zone, warnings=_warnings(zone, a0, reach, dx, size, per),
        roughness_rms=z_rms)


def _per_length(cycle: Cycle, dx: float) -> Cycle:
    """The cycle of the one-row problem (cells dx by dx) per unit length of the cylinder."""
    def leg(b: Branch) -> Branch:
        return replace(b, load=b.load / dx, contact_area=b.contact_area / dx,
                       energy=b.energy / dx)

    def jump(j: Jump | None) -> Jump | None:
        return None if j is None else replace(j, load_before=j.load_before / dx,
                                              load_after=j.load_after / dx)

    return replace(cycle, approach_leg=leg(cycle.approach_leg),
                   retraction_leg=leg(cycle.retraction_leg),
                   pull_off_force=cycle.pull_off_force / dx, jump_in=jump(cycle.jump_in),
                   jump_out=jump(cycle.jump_out),
                   hysteresis_energy=cycle.hysteresis_energy / dx,
                   hysteresis_resolution=cycle.hysteresis_resolution / dx)


def _warnings(zone: float, a0: float, reach: float, dx: float, size: float,
              cycle: Cycle) -> tuple[str, ...]:
    """Resolution, domain and separation warnings of a line cycle."""
    out = []
    if zone < MIN_ZONE_PIXELS_PLAIN * dx:
        out.append(
            f"grid too coarse for the interaction: the cohesive zone (pi E* w / (4 sigma0^2) "
            f"= {zone:.3g} m) spans {zone / dx:.2g} cells, fewer than {MIN_ZONE_PIXELS_PLAIN:g}; "
            f"{coarse_zone_effect(cycle)}: raise the cells or shrink the period")
    ell = max(a0, reach)
    if size < 8.0 * ell:
        out.append(f"the period ({size:.3g} m) is under 8 times the contact's scale "
                   f"({ell:.3g} m): the periodic images shift the load by about "
                   f"{100 * math.pi ** 2 / 6 * (ell / size) ** 2:.2g} %; enlarge it")
    if cycle.retraction_leg.contact_area[-1] > 0.0:
        out.append("the retraction ended with the surfaces still touching: the pull-off may "
                   "lie beyond the last step")
    return tuple(out)
