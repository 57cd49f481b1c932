"""Shared adhesive test cases: a Dugdale sphere in Maugis' units and its retraction.

Units in which K = 4 E* / 3 = 1, R = 1 and the Maugis length (pi w R^2 / K)^(1/3) = 0.1;
the periodic cell is ``cell`` times the larger of the JKR radius at zero load and the
reach sqrt(2 R h0) of the cohesive zone. Loads are reported over pi w R, radii over the
Maugis length, as in Johnson & Greenwood (1997).
"""

from __future__ import annotations

import math

import numpy as np

from contact.adhesion.cycle import refine_pull_off, run_branch
from contact.adhesion.laws import DugdaleLaw
from contact.adhesion.solver import AdhesiveProblem, adhesive_problem

R, E_STAR, W = 1.0, 0.75, 1e-3 / math.pi
K = 4 * E_STAR / 3
A_SCALE = (math.pi * W * R * R / K) ** (1 / 3)
D_SCALE = (math.pi ** 2 * W * W * R / K ** 2) ** (1 / 3)
P_SCALE = math.pi * W * R


def dugdale(lam: float) -> DugdaleLaw:
    """The Dugdale law of Maugis parameter ``lam`` in these units."""
    return DugdaleLaw(W, 0.5 * lam * (math.pi * W * K * K / R) ** (1 / 3))


def zone_pixels(lam: float, n: int, cell: float = 4.0) -> float:
    """The cohesive zone pi E* w / (4 sigma0^2) in pixels of an n^2 sphere grid."""
    law = dugdale(lam)
    return math.pi * E_STAR * W / (4 * law.sigma0 ** 2) / (cell * extent(lam) / n)


def extent(lam: float) -> float:
    """The larger of the JKR radius at zero load and the cohesive zone's reach."""
    return max(A_SCALE * 6 ** (1 / 3), math.sqrt(2 * R * dugdale(lam).range))


def sphere_problem(lam: float, n: int, cell: float = 4.0) -> AdhesiveProblem:
    """The paraboloid r^2 / (2 R) in the middle of an n^2 periodic cell."""
    dx = cell * extent(lam) / n
    x = (np.arange(n) - n / 2) * dx
    return adhesive_problem((x[:, None] ** 2 + x[None, :] ** 2) / (2 * R), dx, E_STAR,
                            dugdale(lam))


def retraction(lam: float, n: int, steps: int = 24, cell: float = 4.0, tol: float = 1e-6):
    """A retraction from a compressed state past pull-off: (problem, branch, gaps)."""
    prob = sphere_problem(lam, n, cell)
    ell = extent(lam)
    br, gaps = run_branch(prob, np.linspace(ell * ell / R, -1.5 * D_SCALE
                                            - 1.2 * dugdale(lam).range, steps), tol=tol)
    return prob, br, gaps


def pull_off(lam: float, n: int, steps: int = 30, cell: float = 4.0) -> float:
    """Pull-off / pi w R of a whole retraction on an n^2 grid (golden-section refined)."""
    prob, br, gaps = retraction(lam, n, steps, cell)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-6)
    return force / P_SCALE


def contact_radius(gap: np.ndarray, dx: float) -> float:
    """Radius of the disc of the touching cells' area (m): Maugis' inner radius a."""
    return math.sqrt(float((gap <= 0.0).sum()) * dx * dx / math.pi)


def wavy_problem(alpha: float, nx: int, zone: float, amplitude: float = 0.01,
                 e_star: float = 1.0) -> AdhesiveProblem:
    """A 1D sinusoid Delta (1 - cos(2 pi x)) of wavelength 1 on an nx x 4 periodic grid.

    The work of adhesion is set by Johnson's ``alpha``; the Dugdale tension so that the
    cohesive zone pi E* w / (4 sigma0^2) is ``zone`` wavelengths long (JKR as zone -> 0).
    The four rows are uniform, so the solve is the plane-strain one.
    """
    work = alpha * alpha * math.pi ** 2 * e_star * amplitude ** 2 / 2.0
    law = DugdaleLaw(work, math.sqrt(math.pi * e_star * work / (4.0 * zone)))
    dx = 1.0 / nx
    x = (np.arange(nx) - nx / 2) * dx
    h = np.tile(amplitude * (1.0 - np.cos(2.0 * math.pi * x)), (4, 1))
    return adhesive_problem(h, dx, e_star, law)


def strip_half_width(gap: np.ndarray, dx: float) -> float:
    """Half the touching length of the first row (m): the strip's half-width a."""
    return 0.5 * float((gap[0] <= 0.0).sum()) * dx
