"""Convergence of the adhesive pull-off with the grid: the sphere and the wavy surface.

The touching cells' edge is pinned by the pixels, so on retraction the contact stays too
large and the tension too high, by an error first order in the pixel over the cohesive
zone l = pi E* w / (4 sigma0^2). Two cases against closed forms solved independently:

- sphere: Dugdale law at Maugis' lambda, periodic cell 4 x the JKR radius at zero load,
  24 retraction steps (tests/adhesion_cases.pull_off); truth Maugis-Dugdale
  (tests/maugis_reference.py);
- wavy: the sinusoid Delta (1 - cos 2 pi x / L) at Johnson's alpha on nx x 4 cells, a
  Dugdale zone of 0.005 L (JKR as the zone shrinks); truth Johnson's (1995) JKR pull-off
  (tests/johnson_wavy.py).

Measured (2 shared CPU cores, 2026-11-27; error of the pull-off against the truth):

    case            grid   zone_px  pull_off  truth    error_%
    sphere lam=1      64     6.60    1.7898   1.6007   +11.81
    sphere lam=1      96     9.91    1.7170   1.6007    +7.26
    sphere lam=1     128    13.21    1.6853   1.6007    +5.28
    sphere lam=2     128     3.30    1.7830   1.5346   +16.19
    sphere lam=2     256     6.60    1.6659   1.5346    +8.55
    sphere lam=3     256     2.94    1.7831   1.5168   +17.56
    sphere lam=3     512     5.87    1.6457   1.5168    +8.50
    wavy alpha=0.3   512     2.56    0.12162  0.09594  +26.76
    wavy alpha=0.3  1024     5.12    0.11008  0.09594  +14.73
    wavy alpha=0.3  2048    10.24    0.10396  0.09594   +8.36

(sphere loads over pi w R, wavy over p* = pi E* Delta / L). The error is about 0.7 pixel
per zone width in both geometries and halves with the pixel; the Richardson
extrapolation 2 F(2n) - F(n) gives -1.2 % (sphere lambda 1, 64/128), +0.9 % (sphere
lambda 2, 128/256: 3.3 % above JKR's 3/2, Maugis' own curve being 2.3 % above it), -0.6 %
(sphere lambda 3, 256/512: +0.5 % from JKR's 3/2) and +2.0 % (wavy, 1024/2048). With the
fused kernels of contact/adhesion/kernels.py a whole retraction took 109 s at 256^2
(lambda 2) and 436 s at 512^2 (lambda 3).

    python3 benchmarks/adhesion_convergence.py --sphere 64,96,128 --wavy 512,1024,2048

These are the plain Dugdale step's. Smoothing the step on the grid's scale
(contact.adhesion.laws.DugdaleLaw.on_grid) removes most of the trapping: at lambda = 1 the
pull-off error is +1.44 %, +0.92 %, +0.66 % on 48^2, 96^2, 144^2 (cell 6); see
benchmarks/adhesion_maugis.py and the table in tests/test_adhesion_validation.py.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]  # this checkout's packages and test truths


def wavy_pull_off(alpha: float, nx: int, zone: float = 0.005) -> float:
    """Largest tension / p* of a retraction of the wavy surface (amplitude 0.01, L = 1)."""
    from adhesion_cases import wavy_problem

    from contact.adhesion.cycle import refine_pull_off, run_branch

    delta = 0.01
    prob = wavy_problem(alpha, nx, zone, amplitude=delta)
    br, gaps = run_branch(prob, np.linspace(0.3 * delta, -0.6 * delta, 31),
                          (1.2 * delta, None), tol=1e-7)
    force, _ = refine_pull_off(prob, br, gaps, tol=1e-7)
    return force / (prob.gap0.size * prob.dx ** 2) / (np.pi * delta)


def _row(case: str, n: int, zone: float, got: float, truth: float, t: float) -> str:
    return (f"{case:<15} {n:5d}  {zone:7.2f}  {got:8.5f}  {truth:7.5f}  "
            f"{100 * (got / truth - 1):+7.2f}  {t:6.1f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lam", type=float, default=1.0, help="Maugis' lambda of the sphere")
    ap.add_argument("--alpha", type=float, default=0.3, help="Johnson's alpha of the wave")
    ap.add_argument("--sphere", default="48,64", help="sphere grids (cells a side)")
    ap.add_argument("--wavy", default="512,1024", help="wavy grids (cells a wavelength)")
    args = ap.parse_args()
    from adhesion_cases import pull_off, zone_pixels
    from johnson_wavy import pull_off as johnson_pull_off
    from maugis_reference import md_pull_off

    print("case            grid   zone_px  pull_off  truth    error_%  time_s")
    truth = md_pull_off(args.lam)
    for n in (int(s) for s in args.sphere.split(",") if s):
        t0 = time.perf_counter()
        got = pull_off(args.lam, n, steps=24)
        print(_row(f"sphere lam={args.lam:g}", n, zone_pixels(args.lam, n), got, truth,
                   time.perf_counter() - t0), flush=True)
    truth = johnson_pull_off(args.alpha)[0]
    for n in (int(s) for s in args.wavy.split(",") if s):
        t0 = time.perf_counter()
        got = wavy_pull_off(args.alpha, n)
        print(_row(f"wavy alpha={args.alpha:g}", n, 0.005 * n, got, truth,
                   time.perf_counter() - t0), flush=True)


if __name__ == "__main__":
    main()
