"""Adhesive rough flat contact at a mean pressure: ours against our non-adhesive solve and Tamaas.

The issue's speed targets (issue 26): on 512^2, the adhesive solve of a nominally flat
rough surface at a mean pressure within 5x the non-adhesive solve of the same surface
and pressure, and within Tamaas' CPU time on the same case. Tamaas is not imported here:
its CPU times and answers are read from ``tests/data/tamaas_adhesion.json``, written on
this kind of machine by ``benchmarks/tamaas_adhesion.py`` from the surfaces this script
writes (``--write-surfaces``). Every time is ``time.process_time`` of one process with one
FFT worker and one BLAS thread (``--blas-threads`` leaves BLAS at its default; Tamaas'
wheel has the serial C++ backend).

Timed, per size, each a cold start at the same surface and pressure:

- ``non-adhesive``: :func:`contact.bem.solve_normal` at the load p A (periodic);
- ``adhesive``: :func:`contact.adhesion.flat.adhesive_flat`, the adhesive solve of
  ``surfmet flat-contact --work-of-adhesion``, called as that command calls it (with the
  non-adhesive solve's mean gap and contact stiffness, which only a tensile pressure's
  secant uses; the stiffness costs one more warm-started non-adhesive solve at 1.01 p,
  reported on its own line). A compressive pressure is imposed inside the solve and
  reached along the quasi-static load path from the first touch
  (:func:`contact.adhesion.flat.load_path`).

The answers (contact fraction, mean gap, attractive and repulsive pressure) are printed
beside Tamaas' stored ones::

    python3 benchmarks/adhesion_flat.py --sizes 256,512

Measured 2026-11-27, 20:13-20:15 UTC, on the shared 2-core AMD EPYC sandbox under a load
average of 3 to 5 (five agents), ``--repeat 4``, least CPU s of the four (one BLAS
thread; Tamaas 2.9.0 stored from an earlier session, OMP_NUM_THREADS=1); main 34330db
(836 iterations) and this version (542) alternately, the same script:

    512^2      ours bare  ours adhesive  ratio  (per run)               Tamaas adhesive
    34330db      1.29        7.13        5.5    5.7, 4.5, 4.9, 4.8          78.01
    this         1.29        4.71        3.7    4.0, 3.1, 3.4, 4.1
    34330db      1.04        6.17        5.9    4.4, 4.5, 5.3, 6.8
    this         1.34        4.27        3.2    2.8, 2.6, 3.7, 3.5

    (At 20:01-20:05, load 6 to 10, with the free cells' shift not yet weighted by their
    share, 539 iterations: 3.6, 3.5, 3.1 against 5.8, 4.4, 5.0, every run <= 3.6.)

    adhesive at 512^2: 15 solves, 542 iterations (13 load steps to 3e-3 and the final
    state to 3e-5 with float32 FFTs, then to 1e-6 in float64); area fraction 0.254822,
    mean gap 4.65359e-4, the same cells as before (Tamaas -0.57 % and +0.31 %).

Three changes to the load-controlled solve (:mod:`contact.adhesion.solver`), none to the
non-adhesive one: the step 1.3 / (the largest stiffness) instead of 1 (836 -> 732
iterations at 512^2); after each step the free cells moved by 4 more times the step's mean
over them times their share of the cells, the load-controlled q = 0 mode having no elastic
stiffness (732 -> 542; 654 -> 360 at 128^2, 690 -> 442 at 256^2); a pass over memory less
per iteration (no copy of the iterate, the spectrum scaled and shifted in one kernel; bit
for bit the same). The contact cells are the same at 128^2, 256^2 and 512^2, the mean gap
within the solve tolerance (refined to 1e-10, the old and the new answers agree to 1.2e-10).
The first of the 15 solves, the snap-in from the first touch
to 1/32 of the pressure, took a third of the iterations (297 of 836): the flat falls
freely under the load until the avalanche of contacts stops it; the free cells' shift
alone shortens it to about 150 (from 259 at the step 1.3).

Before these changes, 17:55 UTC (load 3.4, ``--repeat 3``): 256^2 ratio 5.0 (0.76 s;
4.0, 5.0, 6.0), 512^2 4.4 (3.92 s, 836 iterations; 3.4, 5.0, 4.6); 18:34 (load 0.4):
512^2 5.3 (0.87 and 4.59 s; 3.5, 3.9, 5.3). Until this version the first timed run's
non-adhesive solve also built the shared influence spectrum (0.4 s at 512^2), which the
later runs and the adhesive solve found cached: that run's ratio came out low. Each size
is now warmed by one untimed non-adhesive solve (:func:`warm`).

The same day at 17:35 (load 5.3), before the three earlier changes below, the ratio was 5.7 at 512^2
(adhesive 5.40 s; 4.7, 6.7, 5.6 per run) and 6.3 at 256^2; at 17:45 (load 2.9), 5.45
(5.75 s; 4.5, 5.5, 5.3). Each change, measured alone at 512^2: touching cells skip the
exponential, the float32 solves take it in float32 and get their FFT input from the
momentum kernel (adhesive 5.75 -> 4.82 s, least of three); the final state first to 3e-5
in float32 (its stage 0.64 -> 0.60 s, least of six paired runs); the float32 solves'
exponential from a table and a quartic (load path 4.59 -> 4.08 s, least of three
alternating runs).

Before the load path (secant on the approach, every try a displacement-controlled path
from the non-contact state; main c8d3f1e, this machine, one run each): 512^2 bare 1.28 s,
adhesive 125 s (42 solves, 6197 iterations), ratio 98 (measured earlier the same day);
256^2 ratio 79 (18.0 s, 38 solves, 3749 iterations) and 128^2 44 (2.12 s, 34 solves),
at 17:37 UTC. The ratio moves by about 1 from run to run with the machine's load (the
bare solve's time most of all).

With OpenBLAS' default threads the adhesive solve was 2x slower at 512^2 (measured
before the load path): np.vdot wakes the BLAS threads, whose spinning bills as CPU time
on a loaded machine; the solver now calls it once per solve.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

# One BLAS thread unless --blas-threads: on a shared machine OpenBLAS' worker threads spin
# in np.vdot and would bill their waiting as CPU time (measured: 8 ms per 128^2 vdot).
if "--blas-threads" not in sys.argv:
    for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ[_var] = "1"

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # this checkout's packages

#: The case, in reduced units (lengths in the box side L, stresses in E*): a self-affine
#: surface of rms slope 0.1 on a unit periodic box, the exponential law t = (w/rho)
#: exp(-g/rho) of peak tension w/rho = 2x the mean pressure. The cohesive zone
#: pi E* rho^2 / (4 w) = 0.0785 L spans 10 pixels at 128^2 and 40 at 512^2.
CASE = {"box_side": 1.0, "hurst": 0.8, "slope_rms": 0.1, "roll_off": 0.25, "seed": 2026,
        "e_star": 1.0, "work_of_adhesion": 1e-5, "range": 1e-3, "mean_pressure": 5e-3,
        "tolerance": 1e-6}
DATA = ROOT / "tests" / "data" / "tamaas_adhesion.json"


def surface(n: int) -> np.ndarray:
    """The case's heights on an n x n grid (surfmet's seeded random-phase generator)."""
    from surfmet.synth import self_affine

    return np.asarray(self_affine(n, CASE["box_side"] / n, hurst=CASE["hurst"],
                                  slope_rms=CASE["slope_rms"], roll_off=CASE["roll_off"],
                                  seed=CASE["seed"]).heights)


def write_surfaces(folder: Path, sizes: list[int]) -> None:
    """z<N>.npy per size and case.json (values with units) for the Tamaas driver."""
    folder.mkdir(parents=True, exist_ok=True)
    units = {"box_side": "m", "roll_off": "m", "e_star": "Pa", "work_of_adhesion": "J/m^2",
             "range": "m", "mean_pressure": "Pa", "slope_rms": "1", "hurst": "1"}
    case = {k: ({"value": v, "unit": units[k]} if k in units else {"value": v})
            for k, v in CASE.items()}
    case["generator"] = ("surfmet.synth.self_affine(n, box_side / n, hurst, slope_rms, "
                         "roll_off, seed): random-phase, periodic, no short cut-off")
    case["units_note"] = "reduced units: lengths in the box side, stresses in E*"
    case["tolerance"]["note"] = ("ours: equilibrium violation relative to max(w/rho, pmax); "
                                 "Tamaas: its PolonskyKeerRey error")
    case["surfaces"] = {}
    for n in sizes:
        z = surface(n)
        np.save(folder / f"z{n}.npy", z)
        # fingerprints, so that a test can tell it regenerated the very array Tamaas got
        case["surfaces"][str(n)] = {"rms": {"value": float(np.sqrt(np.mean(z * z))),
                                            "unit": "m"},
                                    "max": {"value": float(z.max()), "unit": "m"},
                                    "z00": {"value": float(z[0, 0]), "unit": "m"}}
    (folder / "case.json").write_text(json.dumps(case, indent=1) + "\n")


def run_ours(n: int) -> dict:
    """CPU times and answers of our non-adhesive and adhesive solves at size n."""
    from contact import SolveOptions
    from contact._grid import gap_grid
    from contact.adhesion import ExponentialLaw
    from contact.adhesion.flat import adhesive_flat
    from contact.bem import solve_normal

    z = surface(n)
    dx, p0, tol = CASE["box_side"] / n, CASE["mean_pressure"], CASE["tolerance"]
    h, e_star = z.max() - z, CASE["e_star"]
    load = p0 * z.size * dx * dx
    kw = dict(e_star=e_star, options=SolveOptions(tol=tol, workers=1, edge="ignore"))
    t0 = time.process_time()
    bare = solve_normal(gap_grid(h, dx, periodic=True), load=load, **kw)
    t_bare = time.process_time() - t0
    gap = float(np.mean(np.asarray(bare.gap)))
    t0 = time.process_time()
    more = solve_normal(gap_grid(h, dx, periodic=True), load=1.01 * load,
                        initial=bare.pressure, **kw)
    t_stiff = time.process_time() - t0
    stiffness = 0.01 * p0 / (gap - float(np.mean(np.asarray(more.gap))))
    law = ExponentialLaw(CASE["work_of_adhesion"], CASE["range"])
    t0 = time.process_time()
    ad = adhesive_flat(h, dx, e_star, law, [p0], [gap], [stiffness], tol=tol)
    t_adh = time.process_time() - t0
    pt = ad.points[0]
    return {"bare_s": t_bare, "stiff_s": t_stiff, "adh_s": t_adh,
            "bare": {"area_fraction": float(bare.area_fraction), "mean_gap": gap},
            "adh": {"area_fraction": pt.area_fraction, "mean_gap": pt.mean_gap,
                    "attractive_pressure": pt.attractive_pressure,
                    "repulsive_pressure": pt.repulsive_pressure},
            "solves": pt.solves, "iterations": pt.iterations,
            "bare_iterations": int(bare.iterations), "warnings": ad.warnings}


def warm(n: int) -> None:
    """One untimed non-adhesive solve at size n: it builds and caches the periodic
    influence spectrum, which both solves share, so that every timed run finds it (else
    the first run's non-adhesive time includes it, 0.4 s at 512^2, and that run's ratio
    comes out low)."""
    from contact import SolveOptions
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    z = surface(n)
    dx = CASE["box_side"] / n
    solve_normal(gap_grid(z.max() - z, dx, periodic=True),
                 load=CASE["mean_pressure"] * z.size * dx * dx, e_star=CASE["e_star"],
                 options=SolveOptions(tol=CASE["tolerance"], workers=1, edge="ignore"))


def _row(name: str, ours: float, theirs: float | None) -> str:
    if theirs is None:
        return f"  {name:<22} {ours:>12.6g} {'-':>12}"
    return f"  {name:<22} {ours:>12.6g} {theirs:>12.6g} {ours / theirs - 1:>+9.2%}"


def report(n: int, r: dict, ref: dict | None) -> None:
    """The timing table and the answers of one size."""
    tm = ref["results"].get(str(n), {}).get("omp1") if ref else None
    t_tm = tm["adhesive_pressure_controlled"]["cpu_s"]["value"] if tm else math.nan
    t_tm_gap = tm["adhesive_gap_controlled"]["cpu_s"]["value"] if tm else math.nan
    t_tm_bare = tm["non_adhesive"]["cpu_s"]["value"] if tm else math.nan
    threads = os.environ.get("OPENBLAS_NUM_THREADS", "default")
    print(f"\n{n}^2  CPU s (process_time; BLAS threads: {threads})")
    print(f"  ours non-adhesive      {r['bare_s']:8.2f}   ({r['bare_iterations']} iterations)")
    print(f"  ours adhesive          {r['adh_s']:8.2f}   ({r['solves']} solves, "
          f"{r['iterations']} iterations; + {r['stiff_s']:.2f} s for the start's stiffness)")
    print(f"  Tamaas adhesive        {t_tm:8.2f}   (mean pressure imposed; stored)")
    print(f"  Tamaas adhesive, gap   {t_tm_gap:8.2f}   (its mean gap imposed, one solve; stored)")
    print(f"  Tamaas non-adhesive    {t_tm_bare:8.2f}   (stored)")
    print(f"  ours adhesive / ours non-adhesive: {r['adh_s'] / r['bare_s']:.2f}  (target <= 5); "
          f"with the stiffness solve {(r['adh_s'] + r['stiff_s']) / r['bare_s']:.2f}")
    if len(r.get("ratios", ())) > 1:
        print("  per run, adhesive / non-adhesive: "
              + ", ".join(f"{x:.2f}" for x in r["ratios"]))
    print(f"  ours adhesive / Tamaas adhesive:   {r['adh_s'] / t_tm:.2f}  (target <= 1); "
          f"against its gap-imposed solve {r['adh_s'] / t_tm_gap:.2f}")
    print(f"  {'answer':<22} {'ours':>12} {'Tamaas':>12} {'ours/T-1':>9}")
    ta = tm["adhesive_pressure_controlled"] if tm else {}
    tb = tm["non_adhesive"] if tm else {}
    for key in ("area_fraction", "mean_gap", "attractive_pressure", "repulsive_pressure"):
        print(_row(f"adhesive {key}", r["adh"][key], ta[key]["value"] if ta else None))
    for key in ("area_fraction", "mean_gap"):
        print(_row(f"bare {key}", r["bare"][key], tb[key]["value"] if tb else None))
    for w in r["warnings"]:
        print(f"  warning: {w}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="512", help="comma-separated grid sizes")
    ap.add_argument("--repeat", type=int, default=1,
                    help="run each size this many times and keep each solve's least CPU "
                         "time (the machine is shared: the least is the least disturbed)")
    ap.add_argument("--blas-threads", action="store_true",
                    help="leave the BLAS/OpenMP thread counts at their defaults")
    ap.add_argument("--write-surfaces", type=Path, metavar="DIR",
                    help="write z<N>.npy and case.json for benchmarks/tamaas_adhesion.py")
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    if args.write_surfaces:
        write_surfaces(args.write_surfaces, sizes)
        return
    ref = json.loads(DATA.read_text()) if DATA.exists() else None
    run_ours(64)  # compile and warm the kernels, untimed
    for n in sizes:
        warm(n)
        runs = [run_ours(n) for _ in range(max(1, args.repeat))]
        best = dict(runs[0])
        for key in ("bare_s", "stiff_s", "adh_s"):
            best[key] = min(r[key] for r in runs)
        best["ratios"] = [r["adh_s"] / r["bare_s"] for r in runs]
        report(n, best, ref)


if __name__ == "__main__":
    main()
