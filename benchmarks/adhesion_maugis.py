"""Pull-off and load-contact-radius curve of a Dugdale sphere against Maugis-Dugdale.

Retraction of a Dugdale sphere from a compressed state (displacement control, area-
controlled step halving, golden-section refinement of the largest tension) on n^2 grids
of a periodic cell ``cell`` x the larger of the JKR radius at zero load and the zone's
reach sqrt(2 R h0) (tests/adhesion_cases.py); the truth is Maugis' curve solved
independently in tests/maugis_reference.py. The Dugdale step is smoothed over
``smoothing`` x sigma0 dx / E* (contact.adhesion.laws.DugdaleLaw.on_grid; 0: the plain
step). Per (lambda, n): the cohesive zone in pixels, the pull-off's error, and the error
of the retraction's (a, P) pairs against P_MD(a), |P - P_MD(a)| / max(|P_MD(a)|, P_c)
(max and rms over the pairs with a of four pixels or more and a <= 1.9 l_M), with a read
sub-pixel (contact.adhesion.ball.edge_radius) and, for comparison, from the count of the
touching cells.

The zone in pixels is the JKR-limit width pi E* w / (4 sigma0^2) over the pixel (much
wider than the real zone at small lambda). Measured: the table in the module notes of
tests/test_adhesion_validation.py, e.g.

    python3 benchmarks/adhesion_maugis.py --lambdas 1 --grids 48,72,96,144 --cell 6
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages and test truths


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lambdas", default="0.1,0.3,1")
    ap.add_argument("--grids", default="48,96")
    ap.add_argument("--cell", type=float, default=6.0)
    ap.add_argument("--smoothing", type=float, default=None,
                    help="ramp width over sigma0 dx / E* (default the law's, 0: the step)")
    ap.add_argument("--steps", type=int, default=24)
    args = ap.parse_args()
    from maugis_sphere import maugis_run

    from contact.adhesion.laws import EDGE_SMOOTHING

    smoothing = EDGE_SMOOTHING if args.smoothing is None else args.smoothing
    print("lambda  n    cell zone_px pull_off pull_err_%  pts  max_sub_% rms_sub_% "
          "max_count_% rms_count_%  cpu_s")
    for lam in (float(s) for s in args.lambdas.split(",")):
        for n in (int(s) for s in args.grids.split(",")):
            t0 = time.process_time()
            r = maugis_run(lam, n, args.cell, smoothing, args.steps)
            sub, count = 100 * r.curve_error(), 100 * r.curve_error(counted=True)
            print(f"{lam:<7g} {n:<4d} {args.cell:4g} {r.zone_pixels:7.2f} {r.pull_off:8.4f} "
                  f"{100 * r.pull_off_error:+9.2f}  {sub.size:4d} {sub.max():9.2f} "
                  f"{np.sqrt(np.mean(sub ** 2)):9.2f} {count.max():11.2f} "
                  f"{np.sqrt(np.mean(count ** 2)):11.2f}  {time.process_time() - t0:6.1f}",
                  flush=True)


if __name__ == "__main__":
    main()
