"""Tamaas' answers and CPU times on the adhesive rough flat case (run in a peer virtualenv).

This script is the provenance of ``tests/data/tamaas_adhesion.json``. It never runs in
the test suite and nothing in the package imports Tamaas: it needs an interpreter with
Tamaas and numpy only, e.g.::

    python3 -m venv /work/venv-tamaas && /work/venv-tamaas/bin/pip install tamaas numpy
    python3 benchmarks/adhesion_flat.py --write-surfaces /tmp/t26     # our generator
    /work/venv-tamaas/bin/python benchmarks/tamaas_adhesion.py /tmp/t26 \
        --sizes 128,256,512 --out tests/data/tamaas_adhesion.json

The case (its numbers are in the JSON's ``case``) is a periodic self-affine surface on a
unit box pressed on a flat with E* = 1 at a mean pressure, in reduced units (lengths in
the box side, stresses in E*). Tamaas (Frérot, Anciaux, Rey, Molinari 2020, J. Open
Source Softw. 5:2121) solves it with its Polonsky-Keer solver on the gap (Rey, Anciaux &
Molinari 2017, Comput. Mech. 60:69) with the exponential adhesion functional
-w exp(-g / rho) added, in two ways:

- ``pressure``: the mean pressure imposed (the question surfmet's flat-contact asks);
- ``gap``: the mean gap imposed at the value the first solve found (its fastest mode,
  one solve, as a lower bound on its cost for the same equilibrium);

and without adhesion (its default Polonsky-Keer solver on the pressure). Each solve runs
in its own process with ``OMP_NUM_THREADS`` set as asked (``1`` and the default) and is
timed with ``time.process_time``. The answers are computed from its fields with the
same definitions as surfmet's: contact where the gap is zero, the mean gap, the law's
traction averaged over all cells (touching ones included), and the equilibrium residual
(largest violation per cell: |p + t| apart, the tension beyond t(0) touching) over w/rho.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np

#: The case: the generator's parameters are those of benchmarks/adhesion_flat.py's CASE.
E_STAR, WORK, RHO, PRESSURE, TOL = 1.0, 1e-5, 1e-3, 5e-3, 1e-6


def _solve(n: int, surfaces: Path, mode: str, target: float) -> dict:
    """One Tamaas solve in this process; ``mode`` in {pressure, gap, bare}."""
    import time

    import tamaas as tm

    tm.set_log_level(tm.LogLevel.error)
    z = np.load(surfaces / f"z{n}.npy")
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E, model.nu = E_STAR, 0.0  # Tamaas' E* = E / (1 - nu^2)
    pkr = tm.PolonskyKeerRey
    if mode == "bare":
        solver = pkr(model, z, TOL)
    else:
        solver = pkr(model, z, TOL, pkr.gap, pkr.gap if mode == "gap" else pkr.pressure)
        adhesion = tm.ExponentialAdhesionFunctional(z)
        adhesion.parameters = {"rho": RHO, "surface_energy": WORK}
        solver.addFunctionalTerm(adhesion)
    solver.max_iter = 1_000_000
    t0 = time.process_time()
    solver.solve(target)
    cpu = time.process_time() - t0
    p = np.array(model.traction).reshape(n, n)
    g = np.array(model.displacement).reshape(n, n) - z
    g -= g.min()  # its gap is zero on the contact
    # on the gap, the contact is where the gap is zero; the pressure solver leaves a gap
    # of round-off there (~1e-12 of the heights), so its contact is where it presses
    touching = p > 0.0 if mode == "bare" else g <= 0.0
    out = {"cpu_s": cpu, "mean_pressure": float(p.mean()),
           "area_fraction": float(np.mean(touching)), "mean_gap": float(g.mean())}
    if mode != "bare":
        t = (WORK / RHO) * np.exp(-g / RHO)
        viol = np.where(g <= 0.0, np.maximum(-(p + t), 0.0), np.abs(p + t))
        out.update(attractive_pressure=float(t.mean()),
                   repulsive_pressure=float(p.mean() + t.mean()),
                   residual=float(viol.max() / (WORK / RHO)))
    return out


def _run(n: int, surfaces: Path, mode: str, target: float, threads: str | None) -> dict:
    """:func:`_solve` in a fresh process, with ``OMP_NUM_THREADS`` set before import."""
    env = dict(os.environ)
    env.pop("OMP_NUM_THREADS", None)
    if threads is not None:
        env["OMP_NUM_THREADS"] = threads
    cmd = [sys.executable, __file__, str(surfaces), "--one", f"{n},{mode},{target!r}"]
    res = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
    return json.loads(res.stdout.strip().splitlines()[-1])


def _quantities(r: dict) -> dict:
    units = {"cpu_s": "s", "mean_pressure": "Pa", "mean_gap": "m", "area_fraction": "1",
             "attractive_pressure": "Pa", "repulsive_pressure": "Pa", "residual": "1"}
    return {k: {"value": v, "unit": units[k]} for k, v in r.items()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("surfaces", type=Path, help="folder with z<N>.npy from adhesion_flat.py")
    ap.add_argument("--sizes", default="128,256,512")
    ap.add_argument("--out", type=Path)
    ap.add_argument("--one", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one:
        n, mode, target = args.one.split(",")
        print(json.dumps(_solve(int(n), args.surfaces, mode, float(target))))
        return
    import tamaas as tm

    case = json.loads((args.surfaces / "case.json").read_text())
    for key, v in (("e_star", E_STAR), ("work_of_adhesion", WORK), ("range", RHO),
                   ("mean_pressure", PRESSURE), ("tolerance", TOL)):
        if case[key]["value"] != v:
            sys.exit(f"case.json's {key} {case[key]['value']} differs from this script's {v}")
    cases = {}
    for n in (int(s) for s in args.sizes.split(",")):
        row = {}
        for label, threads in (("omp1", "1"), ("default", None)):
            adh = _run(n, args.surfaces, "pressure", PRESSURE, threads)
            gap = _run(n, args.surfaces, "gap", adh["mean_gap"], threads)
            bare = _run(n, args.surfaces, "bare", PRESSURE, threads)
            row[label] = {"adhesive_pressure_controlled": _quantities(adh),
                          "adhesive_gap_controlled": _quantities(gap),
                          "non_adhesive": _quantities(bare)}
            print(f"n {n} {label}: adhesive {adh['cpu_s']:.2f} s (gap-controlled "
                  f"{gap['cpu_s']:.2f} s), non-adhesive {bare['cpu_s']:.2f} s; area "
                  f"{adh['area_fraction']:.5f}, mean gap {adh['mean_gap']:.6g}",
                  file=sys.stderr)
        cases[str(n)] = row
    record = {
        "description": "Tamaas on the adhesive rough flat case of benchmarks/adhesion_flat.py",
        "case": case,
        "produced_by": "benchmarks/tamaas_adhesion.py (Tamaas in a separate virtualenv)",
        "tamaas": {"version": tm.__version__, "backend": tm.TamaasInfo.backend,
                   "solver": "PolonskyKeerRey(primal gap) + ExponentialAdhesionFunctional; "
                             "non-adhesive: PolonskyKeerRey(primal pressure)",
                   "tolerance": TOL},
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%MZ"),
        "machine": {"platform": platform.platform(), "processor": _cpu_name(),
                    "cores": os.cpu_count(), "numpy": np.__version__,
                    "note": "shared by other jobs; process_time, not wall time"},
        "results": cases,
    }
    text = json.dumps(record, indent=1)
    if args.out:
        args.out.write_text(text + "\n")
    else:
        print(text)


def _cpu_name() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


if __name__ == "__main__":
    main()
