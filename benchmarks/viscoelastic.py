"""Speed and grid convergence of the viscoelastic rolling solvers (contact.viscoelastic).

    python3 benchmarks/viscoelastic.py            # speed: 2D on 1024 cells, 3D on 256^2
    python3 benchmarks/viscoelastic.py --convergence   # the tables of docs/viscoelastic_rolling.md

Speed targets (issue 20): a 2D solve on 1024 cells under 1 s; a 3D solve on 256^2 within
5x a normal (elastic) solve of the same grid. Timings are the best of ``--repeat`` runs.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from contact._grid import gap_grid
from contact._hertz import hertz_sphere
from contact._materials import composite_modulus, material
from contact.bem import solve_normal
from contact.viscoelastic import StandardLinearSolid, hunter_cylinder, pair_creep
from contact.viscoelastic._line import rolling_cylinder
from contact.viscoelastic._loss import sls_from_loss
from contact.viscoelastic._surface import rolling_sphere

# Hunter's case: rigid cylinder, PA6-like SLS (Eg/Er = 2), V tau = a_r
R2, W2, NU2, EG2, ER2 = 0.05, 6.0e5, 0.4, 3.2e9, 1.6e9
# 3D case: rigid ball on a rubber-like SLS (Eg/Er = 3)
R3, W3, NU3, EG3, ER3 = 0.01, 1.0, 0.5, 30e6, 10e6


def best(fn, repeat: int) -> tuple[float, object]:
    out, t = None, math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        t = min(t, time.perf_counter() - t0)
    return t, out


def speed(repeat: int) -> None:
    cr = (1 - NU2**2) / ER2
    a_r = math.sqrt(4 * W2 * R2 * cr / math.pi)
    creep2 = pair_creep(None, StandardLinearSolid(EG2, ER2, a_r, NU2))
    rolling_cylinder(R2, W2, creep2, 1.0, n=128)
    t2, _ = best(lambda: rolling_cylinder(R2, W2, creep2, 1.0, n=1024), repeat)
    print(f"2D, 1024 cells, V tau = a (Eg/Er = 2):            {t2:7.3f} s   (target < 1 s)")
    _sphere_speed(repeat)


def _sphere_speed(repeat: int) -> None:
    n = 256
    cr = (1 - NU3**2) / ER3
    hz = hertz_sphere(R3, W3, 1 / cr)
    cases = [("rubber-like, Eg/Er = 3, V tau = a", R3, W3, 1.0,
              pair_creep(None, StandardLinearSolid(EG3, ER3, hz.a, NU3)), 1 / cr)]
    st, al = material("steel"), material("al")
    es = composite_modulus(st, al)
    a = hertz_sphere(0.02, 4.67, es).a
    cases.append(("steel on Al, eta = 3e-4 / 5e-4 at V/a", 0.02, 4.67, 0.1,
                  pair_creep(sls_from_loss(st.E, st.nu, 3e-4, a / 0.1),
                             sls_from_loss(al.E, al.nu, 5e-4, a / 0.1)), es))
    for case in cases:
        _one_sphere(n, repeat, *case)


def _one_sphere(n: int, repeat: int, name: str, R: float, W: float, V: float, creep,
                e_el: float) -> None:
    a_r = (3 * W * R * creep.relaxed / 4) ** (1 / 3)
    L = 1.6 * a_r
    dx = 2 * L / n
    x = -L + dx / 2 + np.arange(n) * dx
    h = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * R)
    solve_normal(gap_grid(h, dx), e_star=e_el, load=W)
    tn, _ = best(lambda: solve_normal(gap_grid(h, dx), e_star=e_el, load=W), repeat)
    tv, res = best(lambda: rolling_sphere(R, W, creep, V, n=n), repeat)
    print(f"3D, 256^2, {name:38s} {tv:7.3f} s = {tv / tn:5.1f} x normal ({tn:.3f} s), "
          f"{res.iterations} outer steps")


def convergence() -> None:
    cg, cr = (1 - NU2**2) / EG2, (1 - NU2**2) / ER2
    a_r = math.sqrt(4 * W2 * R2 * cr / math.pi)
    print("2D, Hunter's cylinder, V tau_c = a_r: relative error against the closed form")
    print(f"{'cells':>6}{'contact width':>15}{'mu_r':>12}{'pmax':>12}{'offset':>12}")
    ref = hunter_cylinder(R2, W2, cg, cr, a_r, 1.0)
    creep = pair_creep(None, StandardLinearSolid(EG2, ER2, a_r, NU2))
    for n in (64, 128, 256, 512, 1024, 2048):
        r = rolling_cylinder(R2, W2, creep, 1.0, n=n)
        width = (r.leading - r.trailing) / (ref.leading - ref.trailing) - 1
        mu = r.rolling_resistance / ref.rolling_resistance - 1
        pm = r.pmax / ref.pmax() - 1
        off = r.pressure_offset / (ref.rolling_resistance * R2) - 1
        print(f"{n:6d}{width:15.2e}{mu:12.2e}{pm:12.2e}{off:12.2e}")
    print("\n3D, rigid ball on Eg/Er = 3, V tau_c = a_r: mu_r R / a_r, pmax / p0_r, edges / a_r")
    hz = hertz_sphere(R3, W3, ER3 / (1 - NU3**2))  # relaxed Hertz
    creep3 = pair_creep(None, StandardLinearSolid(EG3, ER3, hz.a, NU3))
    print(f"{'cells':>6}{'mu_r R/a':>12}{'pmax/p0':>10}{'trailing':>10}{'leading':>10}")
    for n in (32, 64, 128, 256):
        r = rolling_sphere(R3, W3, creep3, 1.0, n=n)
        print(f"{n:6d}{r.rolling_resistance * R3 / hz.a:12.5f}{r.pmax / hz.p0:10.4f}"
              f"{r.trailing / hz.a:10.4f}{r.leading / hz.a:10.4f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--convergence", action="store_true")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    if args.convergence:
        convergence()
    else:
        speed(args.repeat)


if __name__ == "__main__":
    main()
