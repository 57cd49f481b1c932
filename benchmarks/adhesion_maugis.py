"""Pull-off of an adhesive sphere against Maugis-Dugdale, across lambda and grids.

Retraction of a Dugdale sphere from a compressed state (displacement control, area-
controlled step halving, golden-section refinement of the largest tension) on n^2 grids
of a periodic cell 4 x the larger of the JKR radius at zero load and the zone reach
sqrt(2 R h0); the truth is Maugis' curve solved independently in
tests/maugis_reference.py. Prints lambda, n, the cohesive zone in pixels, the pull-off
over pi w R, Maugis' value, the error and the time.

    python3 benchmarks/adhesion_maugis.py --lambdas 0.3,1,2,5 --grids 64,128,256
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages and test truths

R, E_STAR, W = 1.0, 0.75, 1e-3 / math.pi
K = 4 * E_STAR / 3
A_SCALE = (math.pi * W * R * R / K) ** (1 / 3)
D_SCALE = (math.pi ** 2 * W * W * R / K ** 2) ** (1 / 3)


def pull_off(lam: float, n: int, steps: int) -> tuple[float, float]:
    """(pull-off / pi w R, cohesive zone in pixels) at Maugis parameter ``lam``."""
    from contact.adhesion.cycle import refine_pull_off, run_branch
    from contact.adhesion.laws import DugdaleLaw
    from contact.adhesion.solver import adhesive_problem

    law = DugdaleLaw(W, 0.5 * lam * (math.pi * W * K * K / R) ** (1 / 3))
    ell = max(A_SCALE * 6 ** (1 / 3), math.sqrt(2 * R * law.range))
    dx = 4 * ell / n
    x = (np.arange(n) - n / 2) * dx
    prob = adhesive_problem((x[:, None] ** 2 + x[None, :] ** 2) / (2 * R), dx, E_STAR, law)
    br, gaps = run_branch(prob, np.linspace(ell * ell / R, -1.5 * D_SCALE - 1.2 * law.range,
                                            steps), tol=1e-6)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-6)
    zone = math.pi * E_STAR * W / (4 * law.sigma0 ** 2)
    return force / (math.pi * W * R), zone / dx


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lambdas", default="0.3,1,2,5")
    ap.add_argument("--grids", default="64,128")
    ap.add_argument("--steps", type=int, default=24)
    args = ap.parse_args()
    from maugis_reference import md_pull_off

    print("lambda  n    zone_px  pull_off  maugis  error_%  time_s")
    for lam in (float(s) for s in args.lambdas.split(",")):
        truth = md_pull_off(lam)
        for n in (int(s) for s in args.grids.split(",")):
            t0 = time.perf_counter()
            got, zone = pull_off(lam, n, args.steps)
            print(f"{lam:<7g} {n:<4d} {zone:7.2f}  {got:8.4f}  {truth:6.4f}  "
                  f"{100 * (got / truth - 1):+7.2f}  {time.perf_counter() - t0:6.1f}",
                  flush=True)


if __name__ == "__main__":
    main()
