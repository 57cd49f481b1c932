"""The coarse-grid threshold of ``surfmet adhesion``: pull-off error against cohesive-zone
pixels, the sphere run exactly as the command runs it, against Maugis-Dugdale.

The command's sphere (:func:`surfmet.mechanics.adhesion.adhesion`: Dugdale law with its
step smoothed on the grid's scale, periodic cell 4 x the larger of the JKR radius at zero
load and the zone's reach, 40 approach steps per leg) for R = 10 µm, E* = 1 GPa,
w = 50 mJ/m² and a range h0 setting Maugis' lambda; the grid is varied, so the cohesive
zone l = pi E* w / (4 sigma0^2) spans more or fewer pixels. The truth is Maugis' pull-off
solved independently (tests/maugis_reference.md_pull_off at the run's own lambda).
The threshold :data:`contact._zone_resolution.MIN_ZONE_PIXELS` is read off this table
(measured 2026-12-02 on 2 shared cores; runs whose JKR radius spans fewer than 8 pixels
left out, they are warned about on their own):

    range_nm lambda  grid zone_px contact_px pull_off/piwR  maugis  error_%
           2  1.648    32    1.22        8.0        1.7040  1.5478   +10.09
           2  1.648    40    1.52       10.0        1.5899  1.5478    +2.72
           2  1.648    48    1.82       12.0        1.6070  1.5478    +3.83
           2  1.648    56    2.13       14.0        1.5710  1.5478    +1.50
           2  1.648    64    2.43       16.0        1.5698  1.5478    +1.42
           2  1.648    96    3.65       24.0        1.5699  1.5478    +1.43
           2  1.648   128    4.86       32.0        1.5658  1.5478    +1.16
           2  1.648   192    7.29       48.0        1.5642  1.5478    +1.06
         1.1  2.996    64    0.74       16.0        1.7232  1.5168   +13.61
         1.1  2.996    96    1.10       24.0        1.5861  1.5168    +4.57
         1.1  2.996   128    1.47       32.0        1.5514  1.5168    +2.28
         1.1  2.996   192    2.21       48.0        1.5314  1.5168    +0.96
         1.1  2.996   256    2.94       64.0        1.5345  1.5168    +1.17
         3.3  0.999    32    3.31        8.0        1.6346  1.6009    +2.11
         3.3  0.999    48    4.96       12.0        1.6280  1.6009    +1.69
         3.3  0.999    64    6.62       16.0        1.6255  1.6009    +1.54
        0.66  4.994   192    0.79       48.0        1.5721  1.5064    +4.37
        0.66  4.994   256    1.06       64.0        1.5457  1.5064    +2.61
        0.66  4.994   128    0.53       32.0        1.9064  1.5064   +26.55
        0.66  4.994   160    0.66       40.0        1.7247  1.5064   +14.49
        0.33  9.988   192    0.20       48.0        3.7473  1.5016  +149.55
        0.33  9.988   256    0.26       64.0        3.0013  1.5016   +99.87

(the last four rows: 2026-12-02, issue 38, 9 to 33 s CPU each; their upper envelope with
the rows above is the measured convergence law contact._zone_resolution.ZONE_PULL_OFF_EXCESS)

From 2 pixels up the pull-off is within 2.1 % of Maugis'; between 1.5 and 2 up to +3.8 %;
at about a pixel and below +2.6 % to +14 %: the warning starts below 2.

    python3 benchmarks/adhesion_zone_threshold.py --cases 2nm:32,40,48,56,64,96,128,192 \
        1.1nm:64,96,128,192,256 3.3nm:32,48,64 0.66nm:192,256
    python3 benchmarks/adhesion_zone_threshold.py --cases 0.66nm:128,160 0.33nm:192,256
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages and test truths


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="+", default=["2nm:32,48,64,96,128"],
                    help="RANGE:GRID,GRID,... (one lambda per range)")
    args = ap.parse_args()
    from maugis_reference import md_pull_off

    from surfmet.mechanics.adhesion import adhesion
    from surfmet.units import parse_length

    radius, e_star, work = 10e-6, 1e9, 0.05
    print("range_nm lambda  grid zone_px contact_px pull_off/piwR  maugis  error_%  cpu_s")
    for case in args.cases:
        rng, grids = case.split(":")
        for n in (int(g) for g in grids.split(",")):
            t0 = time.process_time()
            run = adhesion(radius, work=work, range_=parse_length(rng), e_star=e_star,
                           grid=n)
            res = run.result
            lam = res.maugis_parameter
            got = res.cycle.pull_off_force / (math.pi * work * radius)
            ref = md_pull_off(lam)
            a0 = (4.5 * math.pi * work * radius ** 2 / e_star) ** (1 / 3)
            print(f"{parse_length(rng) * 1e9:8.3g} {lam:6.3f} {n:5d} "
                  f"{res.process_zone / res.dx:7.2f} {a0 / res.dx:10.1f} {got:13.4f} "
                  f"{ref:7.4f} {100 * (got / ref - 1):+8.2f} "
                  f"{time.process_time() - t0:6.1f}", flush=True)


if __name__ == "__main__":
    main()
