"""Does Richardson extrapolation over grids give ``surfmet adhesion``'s pull-off within 2 %
at far smaller grids than resolving the cohesive zone (issue 38 item 1)? Measured: no.

The command's sphere (benchmarks/adhesion_zone_threshold.py: R = 10 µm, E* = 1 GPa,
w = 50 mJ/m², Dugdale step smoothed on the grid's scale, cell 4 a0, 40 steps a leg) on
grids N; the truth is Maugis-Dugdale's pull-off (tests/maugis_reference.py). Two
extrapolations of the measured pull-offs F(N) (dx = size / N):

- Richardson over N and 2N: F0 = 2 F(2N) - F(N) (first order in dx);
- a least-squares line F(dx) = F0 + c dx over three grids.

Measured pull-offs (over pi w R; 2 shared cores, 2026-12-02; the lambda 1.65, 3 and 5 rows
at 128 to 256 are those of benchmarks/adhesion_zone_threshold.py):

    lambda  grid  zone_px  F/piwR   error_%   cpu_s
    2.000     32    0.83   1.7803   +16.01     2.2
    2.000     40    1.03   1.6550    +7.85     0.6
    2.000     48    1.24   1.6134    +5.13     0.7
    2.000     64    1.65   1.5813    +3.04     1.0
    2.000     80    2.06   1.5597    +1.64     1.5
    2.000     96    2.48   1.5570    +1.46     2.1
    2.000    128    3.30   1.5566    +1.43     7.7
    5.002    160    0.66   1.7247   +14.49
    5.002    320    1.32   1.5327    +1.75    52.3

Run as below, it prints the extrapolations against Maugis (the table, as run):

    pair/fit              lambda  F0/piwR  maugis   error_%
    R 32/64                2.000   1.3823  1.5346    -9.92
    R 40/80                2.000   1.4644  1.5346    -4.57
    R 48/96                2.000   1.5006  1.5346    -2.22
    R 64/128               2.000   1.5319  1.5346    -0.18
    fit 32,48,64           2.000   1.3603  1.5346   -11.36
    fit 40,64,80           2.000   1.4627  1.5346    -4.69
    fit 48,64,96           2.000   1.4993  1.5346    -2.30
    R 160/320              5.002   1.3407  1.5063   -11.00
    R 128/256              4.994   1.1850  1.5064   -21.33
    R 64/128               2.996   1.3796  1.5168    -9.05
    R 96/192               2.996   1.4767  1.5168    -2.64
    R 128/256              2.996   1.5176  1.5168    +0.05
    R 32/64                1.648   1.4356  1.5478    -7.25
    R 48/96                1.648   1.5328  1.5478    -0.97
    R 64/128               1.648   1.5618  1.5478    +0.90

Why: with the step smoothed on the grid the error is not first order in dx/l. It is
about +1.4 % and nearly flat from 2 pixels of zone up (lambda 2: +1.64, +1.46, +1.43 % at 2.1,
2.5, 3.3 pixels), and below about 1.5 pixels it rises steeply and not as a power of dx
(lambda 5: +14.5 % at 0.66, +4.4 % at 0.79, +2.6 % at 1.06, +1.75 % at 1.32 pixels),
because there the smoothing width reaches its cap h0 and the pixels pin the zone's end
again. Extrapolating from a grid below 1.5 pixels overshoots by 2 to 22 % (too small
pull-offs); from 1.5 pixels up the direct answer of the finer grid is already within
2 %, so the extrapolation saves nothing. (The plain step's error is first order, about
0.7 dx / l, and its Richardson pairs are within 2 % (benchmarks/adhesion_convergence.py),
but only from about 3 pixels on the coarse grid: more cells than the smoothed step's
direct 2 pixels.) The default therefore stays the grid resolving the zone 2 pixels
(contact/adhesion/default_grid.py): 1952^2 at lambda 10, about an hour of CPU.

    python3 benchmarks/adhesion_richardson.py            # the table above, no solve
    python3 benchmarks/adhesion_richardson.py --run 0.659nm:160,320   # new solves
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages and test truths

#: Measured (lambda, grid, pull-off / pi w R), the table of the module notes (and of
#: benchmarks/adhesion_zone_threshold.py's, marked there).
MEASURED = {
    2.000: {32: 1.7803, 40: 1.6550, 48: 1.6134, 64: 1.5813, 80: 1.5597, 96: 1.5570,
            128: 1.5566},
    5.002: {160: 1.7247, 320: 1.5327},
    4.994: {128: 1.9064, 256: 1.5457},
    2.996: {64: 1.7232, 96: 1.5861, 128: 1.5514, 192: 1.5314, 256: 1.5345},
    1.648: {32: 1.7040, 48: 1.6070, 64: 1.5698, 96: 1.5699, 128: 1.5658},
}


def richardson(coarse: float, fine: float) -> float:
    """First-order Richardson extrapolation of pull-offs at pitches dx and dx / 2."""
    return 2.0 * fine - coarse


def line_fit(grids: list[int], values: list[float]) -> float:
    """F0 of the least-squares line F = F0 + c dx through (1 / N, F)."""
    dx = 1.0 / np.asarray(grids, dtype=float)
    return float(np.polyfit(dx, np.asarray(values), 1)[1])


def table(measured: dict[float, dict[int, float]]) -> None:
    """Print every Richardson pair (N, 2N) and the three-grid fits of the notes."""
    from maugis_reference import md_pull_off

    print("pair/fit              lambda  F0/piwR  maugis   error_%")
    for lam, runs in measured.items():
        ref = md_pull_off(lam)
        rows = [(f"R {n}/{2 * n}", richardson(runs[n], runs[2 * n]))
                for n in sorted(runs) if 2 * n in runs]
        for grids in ((32, 48, 64), (40, 64, 80), (48, 64, 96)):
            if all(g in runs for g in grids) and lam == 2.0:
                rows.append((f"fit {','.join(map(str, grids))}",
                             line_fit(list(grids), [runs[g] for g in grids])))
        for name, f0 in rows:
            print(f"{name:21s} {lam:6.3f}  {f0:7.4f}  {ref:6.4f}  {100 * (f0 / ref - 1):+7.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", nargs="*", default=None,
                    help="RANGE:GRID,GRID,... to solve anew (benchmarks/adhesion_zone_"
                         "threshold.py's cases) instead of the measured table")
    args = ap.parse_args()
    if not args.run:
        table(MEASURED)
        return
    import math

    from surfmet.mechanics.adhesion import adhesion
    from surfmet.units import parse_length

    measured: dict[float, dict[int, float]] = {}
    for case in args.run:
        rng, grids = case.split(":")
        for n in (int(g) for g in grids.split(",")):
            res = adhesion(10e-6, work=0.05, range_=parse_length(rng), e_star=1e9,
                           grid=n).result
            lam = round(res.maugis_parameter, 3)
            measured.setdefault(lam, {})[n] = res.cycle.pull_off_force / (
                math.pi * 0.05 * 10e-6)
    table(measured)


if __name__ == "__main__":
    main()
