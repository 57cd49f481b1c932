"""Calibrate the rotor verdict's lane test (:func:`rotor.lane_f`) by simulation
with launch-level lanes in the null.

Tables of two groups of three launches are simulated by the ODE integrator
(:mod:`rotor._tables`); in the ``lane*`` kinds every launch rolls on a lane of its own
(the stated prior :data:`rotor.LANE_PRIOR`: the plate's wave shifted per
launch by a phase uniform in +-(0.3 to pi) rad, its amplitude scaled by 1 +- (0 to 0.5),
its trend changed by a normal (0 to 0.01) rad/s² per rad, on a wave of 0.1-0.4 rad/s²):

- ``null0``/``lane0``: no group effect, without and with lanes;
- ``offset``/``laneoff``: an offset uniform in +-0.3 rad/s², without and with lanes;
- ``track``/``lanetrack``: group-specific tracks (another trend and wave), without and with
  lanes: the lane test's power;
- ``lam43``: lam = 4/3 at slopes of 0.6-1 degree, with lanes.

Every kind's tables are split by index: the lane test's critical p is the 2 % quantile of
its nominal p over the even-index tables of the four kinds with a shared group track; every
rate published is measured on the odd-index (held-out) tables only. The verdict's rule with
lanes: ``undetermined`` when the shared-track F exceeds its critical value (3.75, no one
track explains the launches) and the lane statistic's nominal p (under F(q_g, q_l), which
depends on the track's degree) is below its calibrated critical p; else
``difference`` when ``|offset| / stderr > t(0.99, 4)``; else ``no_difference``.

Writes ``rotor/lane_calibration.json`` (``--out``):

    python benchmarks/rotor_lane_calibration.py --workers 2
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from multiprocessing import get_context
from pathlib import Path

import numpy as np
from scipy.stats import f as f_dist
from scipy.stats import t as student_t

from rotor import (
    FPS,
    LANE_PRIOR,
    MARK_STEP,
    draw_scenario,
    fit_table,
    group_offset,
    lane_f,
    launchwise_fit,
    prepare_table,
    shared_track_f,
    simulate_table,
)

GROUPS = {"as": ["as1", "as2", "as3"], "s": ["s1", "s2", "s3"]}
KINDS = {"null0": 100, "lane0": 120, "offset": 60, "laneoff": 120, "track": 40,
         "lanetrack": 40, "lam43": 30}
NULL_KINDS = ("null0", "lane0", "offset", "laneoff")
T_LEVEL = 0.99  # two-sided 2 %
LEVEL = 0.02


def one(args: tuple[str, int]) -> dict:
    kind, seed = args
    rng = np.random.default_rng([100 + list(KINDS).index(kind), seed])
    off = float(rng.uniform(-0.3, 0.3)) if kind in ("offset", "laneoff") else 0.0
    lanes = LANE_PRIOR if kind.startswith("lane") or kind == "lam43" else None
    scn = draw_scenario(rng, offset=off, track_differs=kind in ("track", "lanetrack"),
                        lam=4 / 3 if kind == "lam43" else 1.0, lanes=lanes)
    data = prepare_table(simulate_table(scn, rng), GROUPS, FPS, MARK_STEP)
    shared, gw = fit_table(data)
    lw = launchwise_fit(data, shared)
    o = group_offset(data, shared)
    return {"kind": kind, "seed": seed, "offset": off, "f": shared_track_f(shared, gw),
            "lane_f": lane_f(shared, gw, lw), "t": o.t_statistic, "dof": o.dof,
            "estimate": o.value, "ci_low": o.ci_low, "ci_high": o.ci_high,
            "degree": shared.layout.degree}


F_CRIT = 3.745485512870677
"""The shared-track test's critical F (``rotor/verdict_calibration.json``)."""


def nominal_p(r: dict) -> float:
    """The lane statistic's p under F(q_g, q_l): q_g = the track's degree (two groups),
    q_l = 4 degree (six launches, two groups); NaN stays NaN (read as groups differing)."""
    m = r["degree"]
    return float(f_dist.sf(r["lane_f"], m, 4 * m)) if np.isfinite(r["lane_f"]) else np.nan


def _code(r: dict, p_crit: float, t_crit: float) -> str:
    """The verdict's rule: undetermined when no shared track explains the launches and the
    groups' tracks differ more than the launches' within a group do."""
    if r["f"] > F_CRIT and not nominal_p(r) >= p_crit:
        return "undetermined"
    return "difference" if abs(r["t"]) > t_crit else "no_difference"


def _rates(rows: list[dict], p_crit: float, t_crit: float) -> dict:
    codes = [_code(r, p_crit, t_crit) for r in rows]
    n = len(codes)
    return {"n": n, **{c: codes.count(c) / n if n else None
                       for c in ("difference", "undetermined", "no_difference")}}


def _power(rows: list[dict], p_crit: float, t_crit: float) -> list[dict]:
    out = []
    for lo, hi in [(0.0, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.3)]:
        sel = [r for r in rows if lo <= abs(r["offset"]) < hi]
        if sel:
            said = [r for r in sel if _code(r, p_crit, t_crit) == "difference"]
            cover = [r["ci_low"] <= r["offset"] <= r["ci_high"] for r in said]
            out.append({"abs_offset_rad_s2": [lo, hi], "n": len(sel),
                        "difference_rate": len(said) / len(sel),
                        "true_offset_in_ci_when_difference": (sum(cover) / len(cover)
                                                              if cover else None)})
    return out


def summarise(rows: list[dict]) -> dict:
    """Critical value from the even-index null tables; every rate on the held-out ones."""
    by = {k: [r for r in rows if r["kind"] == k] for k in KINDS}
    ref = np.sort([nominal_p(r) for k in NULL_KINDS for r in by[k] if r["seed"] % 2 == 0])
    ref = np.where(np.isnan(ref), 0.0, ref)
    p_crit = float(np.quantile(ref, LEVEL))
    t_crit = float(student_t.ppf(0.5 + T_LEVEL / 2, 4))
    held = {k: [r for r in v if r["seed"] % 2 == 1] for k, v in by.items()}
    old = {k: float(np.mean([r["f"] > F_CRIT for r in v])) for k, v in held.items()}
    return {
        "lane_test": {
            "statistic": "F_lane = [(chi2_shared - chi2_groupwise)/q_g] / "
                         "[(chi2_groupwise - chi2_launchwise)/q_l], q_g = degree (two "
                         "groups), q_l = (launches - groups) degree; its nominal p under "
                         "F(q_g, q_l) is the calibrated quantity",
            "critical_p": p_crit, "level": LEVEL, "n_reference": int(ref.size),
            "null_p_sorted": [float(f"{v:.6g}") for v in ref]},
        "t_critical": t_crit,
        "held_out": {k: _rates(v, p_crit, t_crit) for k, v in held.items()},
        "power_by_offset_no_lanes": _power(held["offset"], p_crit, t_crit),
        "power_by_offset_lanes": _power(held["laneoff"], p_crit, t_crit),
        "old_rule_undetermined_rate": old,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scale", type=float, default=1.0, help="fraction of the tables")
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "rotor"
                                         / "lane_calibration.json"))
    ap.add_argument("--extend", metavar="JSON",
                    help="keep a previous run's rows and simulate only the tables it lacks")
    ap.add_argument("--resummarise", metavar="JSON",
                    help="recompute the summary from a previous run's rows, simulating nothing")
    a = ap.parse_args()
    if a.resummarise:
        prev = json.loads(Path(a.resummarise).read_text())
        out = {k: v for k, v in prev.items() if k != "rows"} | summarise(prev["rows"])
        _write(out | {"rows": prev["rows"]}, a.out)
        return
    jobs = [(k, i) for k, n in KINDS.items() for i in range(max(int(n * a.scale), 4))]
    rows, seconds = [], 0.0
    if a.extend:
        prev = json.loads(Path(a.extend).read_text())
        rows, seconds = prev["rows"], float(prev["seconds"])
        done = {(r["kind"], r["seed"]) for r in rows}
        jobs = [j for j in jobs if j not in done]
    t0 = time.time() - seconds
    with get_context("spawn").Pool(a.workers) as pool:
        for i, r in enumerate(pool.imap(one, jobs, chunksize=2)):
            rows.append(r)
            if (i + 1) % 20 == 0:
                print(f"{i + 1}/{len(jobs)} tables, {time.time() - t0:.0f} s", file=sys.stderr,
                      flush=True)
    out = {
        "what": "calibration of the rotor verdict's lane test by simulation, launch-level "
                "lanes in the null",
        "prior": "rotor.draw_scenario (the paper's rotor; acceleration "
                 "U(1.5, 2.8) rad/s²; slope U(0.6, 1.0) deg; trend eta U(-0.02, 0.06) rad/s² "
                 "per rad; one wave of period U(1.5, 6) rev, any phase, amplitude U(0, 0.4) "
                 "rad/s² without lanes; launch spread U(0.01, 0.06) rad/s²; reading scatter "
                 "U(0.02, 0.08) rad; a misread row in half the launches) with lanes from "
                 "rotor.LANE_PRIOR: per table a phase half-width U(0.3, pi) "
                 "rad, an amplitude half-width U(0, 0.5), a trend sd U(0, 0.01) rad/s² per "
                 "rad, on a wave of amplitude U(0.1, 0.4) rad/s²; per launch its lane's wave "
                 "shifted, scaled and its trend changed by draws within them",
        "split": "critical value from the even-index tables of null0, lane0, offset and "
                 "laneoff; every rate from the odd-index (held-out) tables",
        "generated_by": "benchmarks/rotor_lane_calibration.py",
        "tables": {k: sum(r["kind"] == k for r in rows) for k in KINDS},
        "seconds": round(time.time() - t0, 1),
        **summarise(rows),
        "rows": rows,
    }
    _write(out, a.out)


def _write(out: dict, path: str) -> None:
    out["rule"] = ("undetermined when F > 3.75 (the shared-track test) and the lane test's "
                   "nominal p < lane_test.critical_p; else difference when |offset| / "
                   "stderr > t(0.99, 4); else no_difference")
    Path(path).write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps({k: v for k, v in out.items() if k not in ("rows",)} | {
        "lane_test": {k: v for k, v in out["lane_test"].items() if k != "null_p_sorted"}},
        indent=1))


if __name__ == "__main__":
    main()
