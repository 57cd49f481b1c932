"""A Dugdale sphere's retraction read against Maugis-Dugdale (tests and benchmarks share it).

The sphere of tests/adhesion_cases.py (Maugis' units, periodic cell ``cell`` x the larger
of the JKR radius at zero load and the zone's reach) is retracted from a compressed state
(displacement control, area-controlled step halving, golden-section refinement of the
largest tension), with the Dugdale step smoothed for the grid
(:meth:`contact.adhesion.laws.DugdaleLaw.on_grid`; ``smoothing`` 0 keeps the step). Each
state's contact radius is read sub-pixel (:func:`contact.adhesion.ball.edge_radius`) and
by counting the touching cells; the curve's error is :func:`maugis_reference.md_curve_error`
over the states whose touching zone spans four pixels or more and a <= 1.9 l_M (beyond,
the images of the periodic cell bend the sphere by about 1 % of its load).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from adhesion_cases import A_SCALE, D_SCALE, E_STAR, P_SCALE, R, extent, sphere_problem
from maugis_reference import md_curve_error, md_pull_off

from contact.adhesion.ball import edge_radius
from contact.adhesion.cycle import refine_pull_off, run_branch
from contact.adhesion.laws import EDGE_SMOOTHING
from contact.adhesion.solver import adhesive_problem


@dataclass(frozen=True)
class MaugisRun:
    """One retraction in Maugis' units (radii over l_M, loads over pi w R)."""

    lam: float
    n: int
    zone_pixels: float
    pull_off: float
    radius: np.ndarray  # sub-pixel (edge_radius)
    counted: np.ndarray  # disc of the touching cells
    load: np.ndarray
    kept: np.ndarray  # the states compared with the curve

    @property
    def pull_off_error(self) -> float:
        """Pull-off over Maugis' minus one."""
        return self.pull_off / md_pull_off(self.lam) - 1.0

    def curve_error(self, counted: bool = False) -> np.ndarray:
        """md_curve_error of the kept states, radius sub-pixel or counted."""
        a = (self.counted if counted else self.radius)[self.kept]
        return md_curve_error(self.lam, a, self.load[self.kept])


def maugis_run(lam: float, n: int, cell: float = 6.0, smoothing: float = EDGE_SMOOTHING,
               steps: int = 24) -> MaugisRun:
    """Retract the sphere of Maugis parameter ``lam`` on an n^2 grid (module notes)."""
    base = sphere_problem(lam, n, cell)
    law = base.law.on_grid(base.dx, E_STAR, smoothing) if smoothing > 0 else base.law
    prob = adhesive_problem(base.gap0, base.dx, E_STAR, law)
    ell = extent(lam)
    br, gaps = run_branch(prob, np.linspace(ell * ell / R, -1.5 * D_SCALE - 1.2 * law.reach,
                                            steps), tol=1e-6)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-6)
    counted = np.sqrt(br.contact_area / math.pi) / A_SCALE
    radius = np.array([edge_radius(g, prob.dx, 0.5 * law.range) for g in gaps]) / A_SCALE
    zone = math.pi * E_STAR * law.work / (4.0 * law.sigma0 ** 2)
    return MaugisRun(lam=lam, n=n, zone_pixels=zone / prob.dx, pull_off=force / P_SCALE,
                     radius=radius, counted=counted, load=br.load / P_SCALE,
                     kept=(counted >= 4.0 * prob.dx / A_SCALE) & (radius <= 1.9))
