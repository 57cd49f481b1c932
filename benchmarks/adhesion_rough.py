"""Adhesive against non-adhesive solve of one rough, nominally flat periodic surface.

Times :func:`contact.adhesion.solve_adhesive` (exponential law) and
:func:`contact.bem.solve_normal` (periodic, one FFT worker) at the same approach, cold
started, and prints the CPU times, their ratio, the loads and the contact fractions.

    python3 benchmarks/adhesion_rough.py --n 256 --work 0.05 --rho 2e-9
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages, test surfaces


def main() -> None:
    from contact_synth import rough_surface

    from contact import SolveOptions
    from contact._grid import gap_grid
    from contact.adhesion import ExponentialLaw, adhesive_problem, solve_adhesive
    from contact.bem import solve_normal

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--e-star", type=float, default=1e9)
    ap.add_argument("--work", type=float, default=0.05)
    ap.add_argument("--rho", type=float, default=2e-9)
    args = ap.parse_args()
    dx = 0.5e-6
    z = rough_surface(args.n, dx, 0.1e-6, seed=7, corr=20 * dx)
    h = z.max() - z
    approach = 0.25e-6
    t0 = time.process_time()
    law = ExponentialLaw(args.work, args.rho)
    ad = solve_adhesive(adhesive_problem(h, dx, args.e_star, law), approach, tol=1e-6)
    t_ad = time.process_time() - t0
    t0 = time.process_time()
    bare = solve_normal(gap_grid(h, dx, periodic=True), e_star=args.e_star, approach=ad.approach,
                        options=SolveOptions(tol=1e-6, workers=1))
    t_bare = time.process_time() - t0
    area = h.size * dx * dx
    print(f"n {args.n}  adhesive {t_ad:.2f} s CPU ({ad.iterations} iterations), load "
          f"{ad.load:.4g} N, contact {ad.contact_area / area:.4f}")
    print(f"n {args.n}  non-adhesive {t_bare:.2f} s CPU ({bare.iterations} iterations), load "
          f"{bare.load:.4g} N, contact {bare.contact_area / area:.4f}")
    print(f"ratio adhesive / non-adhesive CPU: {t_ad / t_bare:.1f}")


if __name__ == "__main__":
    main()
