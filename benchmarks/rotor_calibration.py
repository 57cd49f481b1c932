"""Calibrate the rotor law-of-motion selection by simulation (issue 10).

Columns are made here, independently of the analysis' forward model: the equation of motion

    phi'' = eps0 - eta (phi - phi0) - gamma phi' + A sin(phi + psi)

is integrated from rest at ``phi0 = -x step`` (``x`` uniform in [0, 1): anywhere in the mark
step before the first mark) with ``scipy.integrate.solve_ivp`` (events at the marks), the
release time uniform within a frame, read as ``floor(t fps)``; 0-2 rows get a misread of
5-12 frames (sign random, the column kept increasing).

Measured:

* clean columns (no effect, 0-2 misread rows) over a grid of cells fps x step, with eps0
  0.5-5 rad/s², 10-60 rows and the start drawn inside each cell: the false-effect rate
  (overall and per cell), rows falsely flagged as misread per 100 columns, misread rows
  missed, the eps0 bias and the coverage of its standard error;
* the false-alarm probability of the evidence ``dBIC = BIC(best no-effect model) - BIC(best
  effect model)`` on those clean columns, written as package data
  (``rotor/effect_calibration.json``) that the analysis uses to qualify its verdicts;
* detection power against effect size (fraction of eps0 lost over the run by position or
  speed decay; unbalance amplitude over eps0, random phase) in a few conditions, and the
  smallest size found 90 % of the time;
* the whole-CLI time of ``surfmet rotor paper2022``.

Writes ``docs/rotor_calibration.md`` and ``docs/rotor_calibration.png``.
Run: ``PYTHONPATH=. python3 benchmarks/rotor_calibration.py [--quick]``.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from rotor import analyse_test  # noqa: E402

FPS_CELLS = (30.0, 240.0, 1000.0)
STEP_CELLS = (15.0, 90.0, 360.0)
POWER_CONDITIONS = ((60.0, 90.0, 16), (240.0, 45.0, 40))
SIZES = (0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4)
THRESHOLDS = (0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0, 20.0, 30.0)


def mark_frames(rng, rhs, phi0, marks, step, eps0, fps):
    """Frame indices at which a rotor released at rest at ``phi0`` (``rhs``: its equation of
    motion for ``solve_ivp``) passes ``marks``, the release time uniform within a frame;
    None when it stalls before the last mark."""
    events = []
    for m in marks:
        def ev(_t, y, m=m):
            return y[0] - m
        ev.direction = 1.0
        events.append(ev)
    # a generous horizon: the slowest admissible run
    t_end = 4.0 * math.sqrt(2.0 * (marks[-1] + step) / (eps0 * 0.2)) + 1.0
    sol = solve_ivp(rhs, (0.0, t_end), [phi0, 0.0], events=events, rtol=1e-10,
                    atol=1e-12, max_step=t_end / 200)
    t = np.array([e[0] if e.size else np.nan for e in sol.t_events])
    if not np.all(np.isfinite(t)):
        return None
    t = t + float(rng.uniform(0.0, 1.0)) / fps
    return np.floor(t * fps)


def simulate(rng, *, fps, step_deg, n, eps0, eta=0.0, gamma=0.0, amp=0.0, psi=0.0,
             n_misread=0):
    """Frame indices of one column (see the module docstring), and the misread rows."""
    step = math.radians(step_deg)
    x = float(rng.uniform(0.0, 1.0))
    phi0 = -x * step
    marks = np.arange(n) * step

    def rhs(_t, y):
        phi, w = y
        return [w, eps0 - eta * (phi - phi0) - gamma * w + amp * math.sin(phi + psi)]

    f = mark_frames(rng, rhs, phi0, marks, step, eps0, fps)
    if f is None:
        return None, ()
    bad = []
    if n_misread:
        rows = rng.choice(np.arange(2, n), size=n_misread, replace=False)
        for r in sorted(int(v) for v in rows):
            if any(abs(r - b) <= 1 for b in bad):
                continue
            by = int(rng.integers(5, 13)) * int(rng.choice((-1, 1)))
            lo = f[r - 1] + 1
            hi = f[r + 1] - 1 if r + 1 < n else np.inf
            new = min(max(f[r] + by, lo), hi)
            if abs(new - f[r]) >= 5:
                f[r] = new
                bad.append(r)
    return f, tuple(r + 1 for r in bad)


def clean_columns(rng, per_cell):
    """The clean columns of the sweep: ``per_cell`` per cell fps x step, with 10-60 rows,
    eps0 0.5-5 rad/s² and 0-2 misread rows drawn in each; yields (fps, step_deg, n, eps0,
    frames, misread rows)."""
    for fps in FPS_CELLS:
        for sd in STEP_CELLS:
            for _ in range(per_cell):
                n = int(rng.integers(10, 61))
                eps0 = float(rng.uniform(0.5, 5.0))
                f, bad = simulate(rng, fps=fps, step_deg=sd, n=n, eps0=eps0,
                                  n_misread=int(rng.integers(0, 3)))
                yield fps, sd, n, eps0, f, bad


def evidence(rep) -> float:
    """BIC of the best no-effect model minus that of the best effect model."""
    return float(rep.effect_evidence)


def clean_sweep(rng, per_cell, progress):
    rows = []
    for fps, sd, n, eps0, f, bad in clean_columns(rng, per_cell):
        rep = analyse_test("c1", f, fps=fps, step=math.radians(sd))
        rows.append({"fps": fps, "step_deg": sd, "n": n, "eps0": eps0,
                     "effect": rep.effect, "selected": rep.selected,
                     "false_flags": len(set(rep.outliers) - set(bad)),
                     "missed": len(set(bad) - set(rep.outliers)),
                     "n_misread": len(bad), "eps0_fit": rep.eps0,
                     "eps0_se": rep.eps0_stderr, "evidence": evidence(rep)})
        progress()
    return rows


def power_sweep(rng, per_size, progress):
    rows = []
    for fps, sd, n in POWER_CONDITIONS:
        phi_end = (n - 1) * math.radians(sd)
        for kind in ("position", "speed", "unbalance"):
            for size in SIZES:
                for _ in range(per_size):
                    eps0 = float(rng.uniform(0.5, 5.0))
                    kw = {}
                    if kind == "position":
                        kw["eta"] = size * eps0 / phi_end
                    elif kind == "speed":
                        kw["gamma"] = size * eps0 / math.sqrt(2 * eps0 * (1 - size / 2)
                                                              * phi_end)
                    else:
                        kw["amp"] = size * eps0
                        kw["psi"] = float(rng.uniform(0, 2 * math.pi))
                    f, _bad = simulate(rng, fps=fps, step_deg=sd, n=n, eps0=eps0, **kw)
                    if f is None:
                        continue
                    rep = analyse_test("p1", f, fps=fps, step=math.radians(sd))
                    want = "unbalance" if kind == "unbalance" else "decaying"
                    rows.append({"fps": fps, "step_deg": sd, "n": n, "kind": kind,
                                 "size": size, "found": want in rep.effect,
                                 "effect": rep.effect})
                    progress()
    return rows


def false_alarm_table(clean):
    ev = np.array([r["evidence"] for r in clean])
    n = ev.size
    # (k + 1)/(n + 1): an upper-leaning estimate that is never 0 from a finite sweep
    return {"delta_bic": list(THRESHOLDS),
            "false_alarm": [float((np.sum(ev >= d) + 1) / (n + 1)) for d in THRESHOLDS],
            "n_columns": int(n),
            "definition": "P(BIC(best no-effect model) - BIC(best effect model) >= delta_bic)"
                          " on simulated clean columns (benchmarks/rotor_calibration.py)"}


NOTES = ["## Notes", "",
         "- Sizes are reduced to fit ~10 min on one core: 9 cells (fps x step) of 40 clean "
         "columns (rows, eps0, start and misreads drawn within each cell) and 2 power "
         "conditions x 3 effects x 7 sizes x 10 columns. A per-cell rate from 40 columns "
         "resolves 2.5 % steps: 0 of 40 is consistent with a true rate up to ~7 % (95 %).",
         "- The largest eps0 error in the clean sweep is a 10-row column with 2 of its rows "
         "misread, one the last: too few rows remain to tell a misread last row from decay, "
         "so neither misread was found and a decay was named.",
         "- The false-alarm probabilities are (k + 1)/(n + 1) estimates from the clean sweep; "
         "the analysis reports the value at the largest tabulated dBIC not above its own "
         "(conservative between grid points) and flags the evidence as weak when it is above "
         "1 % or the dBIC to the next simpler model is below 10.",
         "- Adequacy (issue 17): whether the chosen model explains a column is calibrated "
         "separately by `benchmarks/rotor_adequacy.py` (`docs/rotor_adequacy.md`, "
         "`rotor/adequacy_calibration.json`). Reduced sizes there too: 20 clean "
         "columns per cell (173 usable of 180 draws; 7 skipped because their frames repeat at "
         "30 fps with 15 deg marks), so the p-value floor is 1/174 = 0.0057 and the 2 % "
         "threshold rests on the 3-4 largest clean statistics; power from 6 plate-wave columns "
         "per amplitude, period band and condition.", ""
]


def cli_time():
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "surfmet", "rotor", "paper2022"], check=True,
                   capture_output=True, cwd=ROOT,
                   env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--per-cell", type=int, default=40)
    ap.add_argument("--per-size", type=int, default=10)
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("--quick", action="store_true", help="4 per cell, 2 per size")
    a = ap.parse_args()
    if a.quick:
        a.per_cell, a.per_size = 4, 2
    rng = np.random.default_rng(a.seed)
    total = len(FPS_CELLS) * len(STEP_CELLS) * a.per_cell \
        + len(POWER_CONDITIONS) * 3 * len(SIZES) * a.per_size
    done = [0]
    t_start = time.perf_counter()

    def progress():
        done[0] += 1
        if done[0] % 20 == 0:
            print(f"{done[0]}/{total} columns, {time.perf_counter() - t_start:.0f} s",
                  flush=True)

    clean = clean_sweep(rng, a.per_cell, progress)
    t_clean = time.perf_counter() - t_start
    power = power_sweep(rng, a.per_size, progress)
    t_all = time.perf_counter() - t_start
    t_cli = cli_time()
    cal = false_alarm_table(clean)
    (ROOT / "rotor" / "effect_calibration.json").write_text(
        json.dumps(cal, indent=1) + "\n")
    report(clean, power, cal, a, t_clean, t_all, t_cli)


def report(clean, power, cal, a, t_clean, t_all, t_cli):
    out = ["# Rotor law of motion: calibration by simulation", "",
           "Made by `benchmarks/rotor_calibration.py` (seed "
           f"{a.seed}, {a.per_cell} clean columns per cell, {a.per_size} columns per effect "
           "size and condition); columns are integrated independently of the analysis' "
           "forward model (see the script's docstring). Start angle uniform in [0, step) "
           "before the first mark, eps0 uniform 0.5-5 rad/s², 10-60 rows, 0-2 misread rows "
           "(5-12 frames) per clean column, frames = floor(t fps).", ""]
    n = len(clean)
    fe = sum(r["effect"] != "none" for r in clean)
    ff = sum(r["false_flags"] for r in clean)
    nm = sum(r["n_misread"] for r in clean)
    miss = sum(r["missed"] for r in clean)
    rel = np.array([r["eps0_fit"] / r["eps0"] - 1 for r in clean])
    cov = np.array([abs(r["eps0_fit"] - r["eps0"]) <= r["eps0_se"] for r in clean])
    out += ["## Clean columns", "",
            f"- columns: {n}; false effects: {fe} ({100 * fe / n:.2f} %)",
            f"- rows falsely flagged as misread: {ff} ({100 * ff / n:.2f} per 100 columns); "
            f"true misread rows: {nm}, missed: {miss}",
            f"- eps0 relative error: mean {100 * rel.mean():+.3f} %, rms "
            f"{100 * math.sqrt(np.mean(rel**2)):.3f} %, max |.| {100 * np.abs(rel).max():.2f} %",
            f"- standard error covers the truth in {100 * cov.mean():.1f} % of columns "
            "(nominal 68.3 %)", f"- time: {t_clean:.0f} s for {n} columns "
            f"({t_clean / n:.2f} s each)", "",
            "| fps | step (deg) | columns | false effects | falsely flagged rows | "
            "eps0 bias (%) | SE coverage (%) |", "|---|---|---|---|---|---|---|"]
    for fps in FPS_CELLS:
        for sd in STEP_CELLS:
            c = [r for r in clean if r["fps"] == fps and r["step_deg"] == sd]
            rr = np.array([r["eps0_fit"] / r["eps0"] - 1 for r in c])
            cc = np.mean([abs(r["eps0_fit"] - r["eps0"]) <= r["eps0_se"] for r in c])
            out.append(f"| {fps:g} | {sd:g} | {len(c)} | "
                       f"{sum(r['effect'] != 'none' for r in c)} | "
                       f"{sum(r['false_flags'] for r in c)} | {100 * rr.mean():+.3f} | "
                       f"{100 * cc:.0f} |")
    out += ["", "## False-alarm probability against the evidence", "",
            "dBIC = BIC(best no-effect model) - BIC(best effect model) on the clean columns; "
            "probability (k + 1)/(n + 1) of a clean column reaching it. Written to "
            "`rotor/effect_calibration.json`.", "", "| dBIC >= | false-alarm probability |",
            "|---|---|"]
    out += [f"| {d:g} | {p:.4f} |" for d, p in zip(cal["delta_bic"], cal["false_alarm"])]
    out += ["", "## Detection power", "",
            "Size: fraction of eps0 lost over the run (decay), amplitude/eps0 (unbalance, "
            "random phase). Found: the effect class contains the effect.", "",
            "| fps | step | rows | effect | " + " | ".join(f"{s:g}" for s in SIZES)
            + " | smallest size found >= 90 % |", "|---" * (5 + len(SIZES)) + "|"]
    fig_rows = []
    for fps, sd, nn in POWER_CONDITIONS:
        for kind in ("position", "speed", "unbalance"):
            rates = []
            for s in SIZES:
                c = [r["found"] for r in power if r["fps"] == fps and r["kind"] == kind
                     and r["size"] == s]
                rates.append(float(np.mean(c)) if c else math.nan)
            ok = [s for s, q in zip(SIZES, rates) if q >= 0.9
                  and all(q2 >= 0.9 for s2, q2 in zip(SIZES, rates) if s2 >= s)]
            thr = f"{min(ok):g}" if ok else "> " + f"{SIZES[-1]:g}"
            out.append(f"| {fps:g} | {sd:g} | {nn} | {kind} | "
                       + " | ".join(f"{100 * q:.0f} %" for q in rates) + f" | {thr} |")
            fig_rows.append((f"{fps:g} fps, {sd:g} deg, {nn} rows, {kind}", rates))
    out += ["", "## Speed", "",
            f"- whole sweep: {t_all:.0f} s on one core",
            f"- `surfmet rotor paper2022` (whole CLI, 6 columns x 25 rows): {t_cli:.2f} s", ""]
    out += NOTES
    (ROOT / "docs" / "rotor_calibration.md").write_text("\n".join(out))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for label, rates in fig_rows:
            ax.semilogx(SIZES, rates, marker="o", label=label)
        ax.axhline(0.9, color="k", lw=0.8, ls="--")
        ax.set_xlabel("effect size (fraction of eps0)")
        ax.set_ylabel("detection rate")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(ROOT / "docs" / "rotor_calibration.png", dpi=120)
    except ImportError:  # pragma: no cover
        pass
    print("\n".join(out))


if __name__ == "__main__":
    main()
