"""Speed of the tangential (rolling-contact) solver, and the micro-slip sweep.

Cases (issue 19):

- ``free``: a steel ball (R = 20 mm) rolling freely on aluminium at 5 N, mu = 0.3, on an
  n x n grid over 2.5 a: the coupled normal-tangential solve with the creepage for zero
  force, against one frictionless normal solve of the same gap on the same grid
  (:func:`contact.bem.solve_normal`).
- ``sweep``: the micro-slip rolling resistance of the paper's pair over 10 loads
  (1-100 N, 32^2 per load), free rolling (:func:`contact.tangential._microslip.microslip_sweep`).
- ``compare``: micro-slip against the hysteresis (alpha_h = 1) and plastic rules at the
  rotor's ball loads 3.97-5.36 N, free rolling and with a traction ratio.

Wall times are min-of-N on a shared machine (noisy)::

    PYTHONPATH=$PWD python3 benchmarks/rolling_contact.py --sizes 64,128 --repeats 1
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def _best(fun, repeats: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeats):
        t = time.perf_counter()
        out = fun()
        best = min(best, time.perf_counter() - t)
    return best, out


def free_rolling(sizes: list[int], repeats: int) -> None:
    from contact._hertz import hertz_sphere
    from contact._materials import material
    from contact.bem import solve_normal
    from contact.tangential import pair_constants, sphere_grid, steady_rolling

    c = pair_constants(material("steel"), material("aluminium"))
    radius, load, mu = 0.02, 5.0, 0.3
    a = hertz_sphere(radius, load, c.e_star).a
    print(f"{'n':>5}{'normal (s)':>12}{'rolling (s)':>13}{'ratio':>8}{'creepage':>12}"
          f"{'slip %':>8}")
    # one small solve of each first: the compiled kernels load from the numba cache on
    # first use, which is not the solvers' time
    warm = sphere_grid(radius, 1.25 * a, 32)
    solve_normal(warm, e_star=c.e_star, load=load)
    steady_rolling(warm, c, load, mu, fx=0.0)
    for n in sizes:
        grid = sphere_grid(radius, 1.25 * a, n)
        tn, _ = _best(lambda g=grid: solve_normal(g, e_star=c.e_star, load=load),
                      repeats)
        tr, r = _best(lambda g=grid: steady_rolling(g, c, load, mu, fx=0.0), repeats)
        print(f"{n:5d}{tn:12.3f}{tr:13.3f}{tr / tn:8.1f}{r.creepage.xi:12.4e}"
              f"{100 * r.slip_area / r.contact_area:8.2f}")


def sweep() -> None:
    from contact._materials import material
    from contact.tangential._microslip import microslip_sweep

    t = time.perf_counter()
    s = microslip_sweep(0.02, material("steel"), material("aluminium"),
                        np.geomspace(1.0, 100.0, 10), 0.3, grid=32)
    print(f"10-load micro-slip sweep (32^2): {time.perf_counter() - t:.1f} s, "
          f"lambda = {s.lambda_eff:.6f}")


def compare() -> None:
    from contact import DomainSpec
    from contact._materials import composite_modulus, material
    from contact._rolling import sphere_sweep
    from contact.tangential._microslip import microslip_sweep

    steel, al = material("steel"), material("aluminium")
    loads = np.geomspace(3.97, 5.36, 4)
    hyst = sphere_sweep(0.02, composite_modulus(steel, al), loads, domain=DomainSpec(grid=128))
    print(f"{'load N':>8}{'hysteresis a_h=1':>18}{'microslip free':>16}"
          f"{'microslip T/N=0.003':>21}{'ratio free/hyst':>17}")
    free = microslip_sweep(0.02, steel, al, loads, 0.3, grid=32)
    driven = microslip_sweep(0.02, steel, al, loads, 0.3, traction_ratio=0.003, grid=32)
    for k, w in enumerate(loads):
        print(f"{w:8.3f}{hyst.moments[k]:18.4e}{free.moments[k]:16.4e}"
              f"{driven.moments[k]:21.4e}{free.moments[k] / hyst.moments[k]:17.3e}")
    print(f"lambda: hysteresis {hyst.lambda_eff:.4f}, microslip free {free.lambda_eff:.4f}, "
          f"T/N = 0.003 {driven.lambda_eff:.4f}")
    print("creepages free:", np.round(free.settings["microslip"]["creepages"], 7))
    print("creepages T/N = 0.003:", np.round(driven.settings["microslip"]["creepages"], 7))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="64,128,256")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--skip-free", action="store_true")
    args = ap.parse_args()
    if not args.skip_free:
        free_rolling([int(v) for v in args.sizes.split(",")], args.repeats)
    sweep()
    compare()


if __name__ == "__main__":
    main()
