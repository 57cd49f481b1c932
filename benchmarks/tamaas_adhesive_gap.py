"""Tamaas' mean gaps on issue 38's adhesive rough flat case (run in a peer virtualenv).

The provenance of ``tests/data/tamaas_adhesive_gap.json``. It never runs in the test suite
and nothing in the package imports Tamaas; it needs Tamaas and numpy only::

    python3 -m venv /tmp/w6venv && /tmp/w6venv/bin/pip install tamaas numpy
    /tmp/w6venv/bin/python benchmarks/tamaas_adhesive_gap.py \
        --out tests/data/tamaas_adhesive_gap.json

The surface is tests/adhesive_gap_case.py's (numpy alone), at amplitudes 1 (adhesion
dominant: a quarter of the area touches at 20 kPa) and 4. Tamaas 2.9's PolonskyKeerRey on
the gap with the mean pressure imposed and its ExponentialAdhesionFunctional (energy
-w exp(-g/rho), so t = (w/rho) exp(-g/rho), surfmet's exponential law), tolerance 1e-8,
E = E*, nu = 0. From its fields: the gap g = displacement - z (its minimum is zero: Tamaas
returns the gap of the contact), the area where g = 0, the mean gap over all cells and over
the free cells, the law's traction averaged over all cells; CPU time by process_time.
"""

from __future__ import annotations

import argparse
import datetime
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
import adhesive_gap_case as case

PRESSURES, AMPLITUDES, TOL = (2e4, 5e4, 1e5, 2e5), (1.0, 4.0), 1e-8


def _solve(z: np.ndarray, pressure: float) -> dict:
    import tamaas as tm

    n = z.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [case.BOX] * 2, [n, n])
    model.E, model.nu = case.E_STAR, 0.0
    pkr = tm.PolonskyKeerRey
    solver = pkr(model, z, TOL, pkr.gap, pkr.pressure)
    law = tm.ExponentialAdhesionFunctional(z)
    law.parameters = {"rho": case.RANGE, "surface_energy": case.WORK}
    solver.addFunctionalTerm(law)
    solver.max_iter = 100_000
    t0 = time.process_time()
    solver.solve(pressure)
    cpu = time.process_time() - t0
    p = np.array(model.traction).reshape(n, n)
    g = np.array(model.displacement).reshape(n, n) - z
    g_min = float(g.min())
    g = g - g_min
    free = g > 0.0
    t = (case.WORK / case.RANGE) * np.exp(-g / case.RANGE)
    units = {"cpu_s": "s", "mean_pressure": "Pa", "area_fraction": "1", "mean_gap": "m",
             "mean_gap_out_of_contact": "m", "attractive_pressure": "Pa",
             "gap_minimum_before_shift": "m"}
    vals = {"pressure": pressure, "cpu_s": cpu, "mean_pressure": float(p.mean()),
            "area_fraction": float(np.mean(~free)), "mean_gap": float(g.mean()),
            "mean_gap_out_of_contact": float(g[free].mean()),
            "attractive_pressure": float(t.mean()), "gap_minimum_before_shift": g_min}
    return {k: ({"value": v, "unit": units[k]} if k in units else {"value": v, "unit": "Pa"})
            for k, v in vals.items()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path)
    args = ap.parse_args()
    import tamaas as tm

    tm.set_log_level(tm.LogLevel.error)
    results = {}
    for amp in AMPLITUDES:
        z = case.surface(amp)
        rows = [_solve(z, p) for p in PRESSURES]
        results[f"{amp:g}"] = {"fingerprint": {"rms": float(np.sqrt(np.mean(z * z))),
                                               "max": float(z.max()), "z00": float(z[0, 0])},
                               "points": rows}
        for r in rows:
            print(amp, {k: v["value"] for k, v in r.items()}, file=sys.stderr)
    record = {
        "description": "Tamaas on issue 38's adhesive rough flat case (tests/adhesive_gap_case.py)",
        "produced_by": "benchmarks/tamaas_adhesive_gap.py, Tamaas in a separate virtualenv",
        "tamaas": {"version": tm.__version__, "solver": "PolonskyKeerRey(primal gap, mean "
                   "pressure imposed) + ExponentialAdhesionFunctional", "tolerance": TOL},
        "numpy": np.__version__,
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%MZ"),
        "case": {"n": case.N, "box": {"value": case.BOX, "unit": "m"},
                 "e_star": {"value": case.E_STAR, "unit": "Pa"},
                 "work_of_adhesion": {"value": case.WORK, "unit": "J/m^2"},
                 "range": {"value": case.RANGE, "unit": "m"}},
        "results": results,
    }
    text = json.dumps(record, indent=1)
    if args.out:
        args.out.write_text(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    main()
