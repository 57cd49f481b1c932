"""The smooth sphere on axisymmetric rings against Maugis' closed form, over lambda.

``surfmet adhesion``'s default for a smooth sphere (:func:`surfmet.mechanics.adhesion.
ring_run`), on the issue's sphere (R 1 mm, E* 1 GPa, w 0.05 J/m^2, Dugdale law, the range
h0 setting lambda): pull-off and the approach at it against Maugis-Dugdale
(tests/maugis_reference.py, solved independently), the rings (graded beyond
contact.adhesion._ring_ball.GRADED_ABOVE uniform ones) and the CPU time of each cycle.
``--graded-above N`` moves that threshold (a large N keeps uniform rings: at lambda 10,
3,329 of them and about ten minutes). Results: benchmarks/adhesion_rings.md.

    python3 benchmarks/adhesion_rings.py [--lams 0.05,0.1,0.5,1,2,5,10] [--steps 40]
        [--law dugdale|exponential] [--graded-above 1000]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

R, E_STAR, W = 1e-3, 1e9, 0.05
#: h0 = SCALE / lambda: lambda = 2 (w / h0) (R / (pi w K^2))^(1/3), K = 4 E* / 3
SCALE = 2.0 * W * (R / (math.pi * W * (4 * E_STAR / 3) ** 2)) ** (1 / 3)


def main() -> None:
    from maugis_reference import md_pull_off, md_pull_off_approach

    from surfmet.mechanics.adhesion import adhesion

    ap = argparse.ArgumentParser()
    ap.add_argument("--lams", default="0.05,0.1,0.5,1,2,5,10")
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--law", default="dugdale")
    ap.add_argument("--graded-above", type=int, default=None)
    args = ap.parse_args()
    if args.graded_above is not None:
        import contact.adhesion._ring_ball as ring_ball

        ring_ball.GRADED_ABOVE = args.graded_above
    d_scale = (math.pi ** 2 * W * W * R / (4 * E_STAR / 3) ** 2) ** (1 / 3)
    for lam in (float(x) for x in args.lams.split(",")):
        t0 = time.process_time()
        run = adhesion(R, work=W, range_=SCALE / lam, e_star=E_STAR, interaction=args.law,
                       steps=args.steps)
        cpu = time.process_time() - t0
        res = run.result
        got_lam = res.maugis_parameter
        force = res.cycle.pull_off_force / (math.pi * W * R)
        delta = res.cycle.pull_off_approach / d_scale
        ref_p, ref_d = md_pull_off(got_lam), md_pull_off_approach(got_lam)
        kind = "graded " if res.graded else "uniform"
        print(f"lambda {got_lam:6.3g}  rings {res.rings:5d} {kind}  zone "
              f"{res.process_zone / res.dr:8.3g} rings  pull-off {force:.4f} pi w R "
              f"(Maugis {ref_p:.4f}, "
              f"{100 * (force / ref_p - 1):+.2f} %)  approach {delta:+.4f} (Maugis "
              f"{ref_d:+.4f})  {res.cycle.solve.solves} solves  {cpu:.1f} s CPU", flush=True)


if __name__ == "__main__":
    main()
