"""Calibrate the rotor verdict (:mod:`rotor._verdict`) by simulation.

Tables of two groups of three launches are simulated by the ODE integrator
(:mod:`rotor._tables`, the stated prior there) and analysed by the joint model
(:mod:`rotor._joint`):

- shared track, no offset: the null of both tests (false alarms of ``difference``);
- shared track, offset uniform in +-0.3 rad/s²: the null of the shared-track test and the
  power of the offset test;
- group-specific tracks: the power of the shared-track test;
- lam = 4/3 at slopes of 0.6-1 degree: how often a verdict claims a difference.

The shared-track test's critical value is the 98 % quantile of its F statistic over the
null tables of even index; its false-alarm rate is then measured on the odd ones.
Writes ``rotor/verdict_calibration.json`` (``--out``). About 10 minutes on 2 cores:

    python benchmarks/rotor_verdict_calibration.py --workers 2
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from multiprocessing import get_context
from pathlib import Path

import numpy as np
from scipy.stats import t as student_t

from rotor import (
    FPS,
    MARK_STEP,
    draw_scenario,
    fit_table,
    group_offset,
    prepare_table,
    shared_track_f,
    simulate_table,
)

GROUPS = {"as": ["as1", "as2", "as3"], "s": ["s1", "s2", "s3"]}
KINDS = {"null0": 120, "offset": 120, "track": 60, "lam43": 30}
T_LEVEL = 0.99  # two-sided 2 %


def one(args: tuple[str, int]) -> dict:
    kind, seed = args
    rng = np.random.default_rng([list(KINDS).index(kind), seed])
    off = float(rng.uniform(-0.3, 0.3)) if kind == "offset" else 0.0
    scn = draw_scenario(rng, offset=off, track_differs=kind == "track",
                        lam=4 / 3 if kind == "lam43" else 1.0)
    cols = simulate_table(scn, rng)
    data = prepare_table(cols, GROUPS, FPS, MARK_STEP)
    shared, gw = fit_table(data)
    o = group_offset(data, shared)
    return {"kind": kind, "seed": seed, "offset": off, "f": shared_track_f(shared, gw),
            "t": o.t_statistic, "dof": o.dof, "estimate": o.value,
            "degree": shared.layout.degree}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scale", type=float, default=1.0, help="fraction of the tables")
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "rotor"
                                         / "verdict_calibration.json"))
    a = ap.parse_args()
    jobs = [(k, i) for k, n in KINDS.items() for i in range(max(int(n * a.scale), 4))]
    t0 = time.time()
    rows = []
    with get_context("spawn").Pool(a.workers) as pool:
        for i, r in enumerate(pool.imap(one, jobs, chunksize=2)):
            rows.append(r)
            if (i + 1) % 10 == 0:
                print(f"{i + 1}/{len(jobs)} tables, {time.time() - t0:.0f} s", file=sys.stderr,
                      flush=True)
    null = [r for r in rows if r["kind"] in ("null0", "offset")]
    f_ref = np.sort([r["f"] for i, r in enumerate(null) if i % 2 == 0])
    f_crit = float(np.quantile(f_ref, 0.98))
    held = [r["f"] for i, r in enumerate(null) if i % 2 == 1]
    t_crit = float(student_t.ppf(0.5 + T_LEVEL / 2, 4))

    def says_difference(r: dict) -> bool:
        return r["f"] <= f_crit and abs(r["t"]) > t_crit

    by = {k: [r for r in rows if r["kind"] == k] for k in KINDS}
    bins = [(0.0, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.3)]
    power_offset = []
    for lo, hi in bins:
        sel = [r for r in by["offset"] if lo <= abs(r["offset"]) < hi]
        if sel:
            power_offset.append({"abs_offset_rad_s2": [lo, hi], "n": len(sel),
                                 "rate": sum(map(says_difference, sel)) / len(sel)})
    out = {
        "what": "calibration of the rotor verdict (rotor._verdict) by simulation",
        "prior": draw_scenario.__doc__.strip().splitlines()[0] + " Prior: rotor._tables "
                 "(paper's rotor; acceleration U(1.5, 2.8) rad/s²; slope U(0.6, 1.0) deg; trend "
                 "eta U(-0.02, 0.06) rad/s² per rad; one wave of amplitude U(0, 0.4) rad/s², "
                 "period U(1.5, 6) rev, any phase; launch spread U(0.01, 0.06) rad/s²; reading "
                 "scatter U(0.02, 0.08) rad; release 0.001-0.1 rad before the first mark; a "
                 "misread row of 3-5 frames in half of the launches; 3 launches per group, "
                 "25 marks)",
        "generated_by": "benchmarks/rotor_verdict_calibration.py",
        "tables": {k: len(v) for k, v in by.items()},
        "seconds": round(time.time() - t0, 1),
        "shared_track_test": {
            "statistic": "F = (chi2_shared - chi2_groupwise)/q / (chi2_groupwise/dof)",
            "critical_f": f_crit, "level": 0.02,
            "null_f_sorted": [round(float(v), 6) for v in f_ref],
            "false_alarm_held_out": float(np.mean(np.asarray(held) > f_crit)),
            "n_held_out": len(held),
            "power_group_specific_tracks": float(np.mean([r["f"] > f_crit for r in by["track"]])),
        },
        "offset_test": {
            "rule": "difference when the shared track is adequate and |offset|/stderr > "
                    "t(0.99, launches - groups)",
            "t_level": T_LEVEL,
            "false_alarm_zero_offset": sum(map(says_difference, by["null0"])) / len(by["null0"]),
            "n_zero_offset": len(by["null0"]),
            "power_by_offset": power_offset,
            "difference_rate_lambda_4_3": sum(map(says_difference, by["lam43"])) / len(by["lam43"]),
        },
        "rows": rows,
    }
    Path(a.out).write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps({k: v for k, v in out.items() if k != "rows"} | {
        "shared_track_test": {k: v for k, v in out["shared_track_test"].items()
                              if k != "null_f_sorted"}}, indent=1))


if __name__ == "__main__":
    main()
