"""``surfmet rotor FILE``: the rotor's law of motion from frame indices (Table 3 of the paper).

FILE is tab- or space-separated text: a header ``k`` then one column per test, one row per
mark (row ``k`` = the frame at which the rotor had turned ``(k - 1)`` mark steps). Empty
cells, ``nan`` or ``-`` mark missing readings. Columns whose names differ only in trailing
digits (``as1``, ``as2``...) form a group. ``paper2022`` names the paper's Table 3 as shipped
with surfmet.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path
from typing import Any

from rotor import FPS, MARK_STEP, TABLE3_FILENAME
from surfmet._errors import SurfmetInputError
from surfmet.cli._common import add_json_flag, add_quiet_flag, check_output, emit_json, log
from surfmet.cli._rotor_scans import add_scan_arguments, read_rotor_scans, rough_bound
from surfmet.mechanics._rotor_adequacy import adequacy_sentences
from surfmet.mechanics.rotor_verdict import (
    table_verdict,
    verdict_figure,
    verdict_lines,
    verdict_plot_path,
)
from surfmet.records._rotor_analysis import analysis_record
from surfmet.records._rotor_verdict import verdict_record
from surfmet.units import display_unit

PAPER_ALIAS = "paper2022"

EPILOG = """examples:
  surfmet rotor paper2022
  surfmet rotor table3_frames.tsv --plot residuals.png
  surfmet rotor runs.tsv --fps 240 --step-deg 45 --json
  surfmet rotor paper2022 --cv exact --json > rotor.json
  surfmet rotor paper2022 --plate plate.x3p --ball ball.x3p --grid 64   (rough arm bound)

Models (fitted on the times, weighted by a reading-noise model with the frame quantisation
as its floor): rest (the paper's: constant acceleration from rest at the first mark),
parabola (the paper's general parabola on the angles), const (constant acceleration, free
start), position / speed (decaying acceleration), unbalance, and their combinations.
The BIC picks one per test; misread rows are found robustly and left out."""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "rotor",
        help="law of motion of the rolling rotor from frame indices (Table 3)",
        description="Fit the rotor's law of motion to frame indices per mark: the paper's "
        "parabolas, constant acceleration with a free start, decaying acceleration "
        "(position- or speed-dependent), unbalance; select by BIC, find misread rows, "
        "compare the groups of tests.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("file", help=f"TSV of frame indices (header 'k' then columns), or "
                   f"{PAPER_ALIAS!r} for the paper's Table 3")
    p.add_argument("--fps", type=float, default=FPS, help=f"camera frame rate (default {FPS:g})")
    p.add_argument("--step-deg", type=float, default=math.degrees(MARK_STEP),
                   help=f"rotation between successive rows, degrees (default "
                   f"{math.degrees(MARK_STEP):g})")
    p.add_argument("--cv", choices=("approx", "exact"), default="approx",
                   help="leave-one-point-out errors from leverages (fast) or refits")
    p.add_argument("--threshold", type=float, default=4.0,
                   help="misread threshold in noise sigmas (default 4)")
    p.add_argument("--plot", metavar="PATH", help="write the residual figure to PATH (.png/.pdf) "
                   "and the verdict's figure beside it (PATH_verdict.png)")
    p.add_argument("--rig", metavar="RIG.json",
                   help="the rig (SI): ball_radius_m, mass_kg, axial_inertia_kg_m2, fps, "
                   "step_deg, optional slope_rad, e_star_Pa, plate (words), materials "
                   "[BALL, PLATE], groups {NAME: {ball_loads_N: [N1, N2], "
                   "columns: [...]}}; gives the verdict's lambda outputs and confounds (the "
                   "arm bound and the lateral creep take the rig's E* and materials, else "
                   "the paper's steel on aluminium) "
                   f"({PAPER_ALIAS} carries the paper's rig)")
    add_scan_arguments(p)
    add_quiet_flag(p)
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def _paper_path() -> Path:
    return Path(__file__).resolve().parents[1] / "data" / TABLE3_FILENAME


def _fmt_p(p: float) -> str:
    return "-" if not math.isfinite(p) else f"{p:.3g}"


def _print_tests(an: Any) -> None:
    from rotor import false_alarm_floor

    fps = an.fps
    print("per test (rms in frames; BIC; leave-one-out rms in frames)")
    print(f"  {'test':6s} {'model':26s} {'effect':19s} {'misread k':12s} "
          f"{'eps0 rad/s²':>16s} {'rest':>6s} {'const':>6s} {'chosen':>7s}")
    for t in an.tests:
        sel = t.fit
        # a short column may leave a model out (too few rows once misreads are set aside)
        rest, const = (f"{t.fits[m].rms * fps:6.2f}" if m in t.fits else f"{'-':>6s}"
                       for m in ("rest", "const"))
        out = ",".join(str(k) for k in t.outliers) or "-"
        print(f"  {t.name:6s} {t.selected:26s} {t.effect:19s} {out:12s} "
              f"{t.eps0:9.3f} ± {t.eps0_stderr:5.3f} {rest} {const} {sel.rms * fps:7.2f}")
    print()
    floor = false_alarm_floor()
    print("  evidence: dBIC to the next simpler model; dBIC no-effect - effect and the calibrated"
          " false-alarm probability at it")
    for t in an.tests:
        weak = "   WEAK evidence" if t.weak_evidence else ""
        pfa = f"{t.false_alarm:.4f}"
        if math.isfinite(t.false_alarm) and t.false_alarm <= floor:
            pfa = f"<= {floor:.4f} (the calibration's resolution floor)"
        print(f"  {t.name:6s} dBIC {t.delta_bic:8.1f}   effect dBIC {t.effect_evidence:8.1f}   "
              f"P(false alarm) {pfa}{weak}")
    print()
    print("  BIC / leave-one-out rms (frames) per model and test")
    names = list(dict.fromkeys(m for t in an.tests for m in t.fits))
    width = max(len(m) for m in names)
    print("  " + f"{'model':{width}s}" + "".join(f"{t.name:>16s}" for t in an.tests))
    for m in names:
        print("  " + f"{m:{width}s}" + "".join(
            (f"{t.fits[m].bic:8.1f}/{t.fits[m].loo_rms * fps:5.2f}" if m in t.fits
             else "-").rjust(16) for t in an.tests))


def _print_adequacy(an: Any) -> None:
    from rotor import ALPHA

    print()
    print(f"adequacy of the chosen model (runs test, lag-1 correlation and residual "
          f"periodogram; inadequate at a calibrated p <= {ALPHA:g})")
    for t in an.tests:
        a = t.adequacy
        if a is None:
            continue
        for line in adequacy_sentences(t):
            print(f"  {t.name:6s} {line}")


def _print_groups(an: Any) -> None:
    from rotor import PARAM_UNITS

    fps = an.fps
    print()
    print(f"study model (smallest BIC over all tests): {an.study_model}")
    for g in an.groups:
        c2, c1, c0 = g.paper_parabola
        print(f"group {g.name!r} ({', '.join(g.tests)})")
        print(f"  paper's parabola through the mean times: phi = {c2:.4f} t² {c1:+.4f} t "
              f"{c0:+.4f}   (rms {g.paper_rms:.3f} rad)")
        for m in dict.fromkeys(("paper", "rest", "const", an.study_model)):
            if m not in g.eps:
                continue  # a short column leaves the model out
            mean, u, vals = g.eps[m]
            label = "paper (2 c2)" if m == "paper" else m
            print(f"  eps0 {label:26s} {mean:7.3f} ± {u:5.3f} rad/s²   "
                  f"[{', '.join(f'{v:.3f}' for v in vals)}]")
        for k, (mean, u, _vals) in g.params.items():
            print(f"  {k:31s} {mean:9.4f} ± {u:6.4f} {display_unit(PARAM_UNITS.get(k, ''))}")
        loto = ", ".join(f"{m} {v * fps:.2f}" for m, v in g.loto_rms.items()
                         if m in ("rest", "const", an.study_model) and math.isfinite(v))
        print(f"  leave-one-test-out rms (frames): {loto}")
        al = g.residual_alignment
        if al is not None:
            print(f"  leftover wave of {al.revolutions:.2f} rev ({al.track_length * 1e3:.0f} mm "
                  f"of track): phases agree at the same track position: coherence "
                  f"{al.coherence_track:.2f} (Rayleigh p {_fmt_p(al.p_track)}); at the same "
                  f"rotor angle: {al.coherence_rotor:.2f} (p {_fmt_p(al.p_rotor)}); "
                  f"lines up by: {al.verdict}")
    if an.comparisons:
        print()
        print("group comparison (b - a); p: Welch's t test on the per-test values "
              "('-': one value per group)")
        for c in an.comparisons:
            print(f"  {c.b} - {c.a} {c.quantity:9s} [{c.model:20s}] {c.difference:+8.4f} ± "
                  f"{c.uncertainty:.4f}  z {c.z:+6.2f}  p {_fmt_p(c.p_value)}")


def _print_summary(an: Any, source: str) -> None:
    fps = an.fps
    print(f"file          {source}")
    print(f"frame rate    {fps:g} /s (quantisation sigma {an.noise_floor * 1e3:.2f} ms = "
          f"{an.noise_floor * fps:.3f} frame)")
    print(f"mark step     {math.degrees(an.step):g} deg")
    print()
    _print_tests(an)
    _print_adequacy(an)
    _print_groups(an)


def run(args: argparse.Namespace) -> int:
    from rotor import analyse_table

    check_output(args.plot, "--plot")
    if not (math.isfinite(args.fps) and args.fps > 0):
        raise SurfmetInputError(f"--fps must be positive, got {args.fps}")
    if not (math.isfinite(args.step_deg) and args.step_deg > 0):
        raise SurfmetInputError(f"--step-deg must be positive, got {args.step_deg}")
    read_rotor_scans(args)
    source = str(_paper_path()) if args.file == PAPER_ALIAS else args.file
    from surfmet._frames import read_frames_table

    ks, cols = read_frames_table(source)
    if args.plot:
        check_output(verdict_plot_path(args.plot), "--plot (verdict figure)")
    verdict, notes = table_verdict(ks, cols, paper=args.file == PAPER_ALIAS, fps=args.fps,
                                   step=math.radians(args.step_deg), rig_path=args.rig)
    for note in notes:
        log(f"note: {note}")
    rough = rough_bound(args, verdict)
    # progress on stderr, unless asked for quiet, or JSON goes to a pipe and stderr is not a
    # terminal (it may be the same pipe)
    show = not getattr(args, "quiet", False) and (not args.json or sys.stderr.isatty())

    def progress(name: str, i: int, n: int) -> None:
        log(f"rotor: test {name} ({i + 1}/{n}) ...")

    if show:
        log(f"analysing {len(cols)} test(s) of {len(ks)} rows ...")
    an = analyse_table(cols, ks, fps=args.fps, step=math.radians(args.step_deg), cv=args.cv,
                       threshold=args.threshold, progress=progress if show else None)
    if args.plot:
        from surfmet.plots.rotor import residual_figure

        residual_figure(an, path=args.plot)
        log(f"residual figure written to {args.plot}")
        if verdict is not None:
            vpath = verdict_plot_path(args.plot)
            verdict_figure(verdict, vpath)
            log(f"verdict figure written to {vpath}")
    if args.json:
        emit_json({"verdict": None if verdict is None else verdict_record(verdict, an, rough),
                   **analysis_record(an, source)})
    else:
        if verdict is not None:
            print("\n".join(verdict_lines(verdict, an, rough)))
            print()
        _print_summary(an, source)
    return 0
