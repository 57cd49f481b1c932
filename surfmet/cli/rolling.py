"""``surfmet rolling``: rolling-resistance moment over a load sweep and its exponent lambda."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    add_ball_arguments,
    add_json_flag,
    add_quiet_flag,
    add_spikes_argument,
    check_output,
    emit_json,
    log,
    pressure,
    print_solve,
    progress,
    save_figure,
    show_progress,
)
from surfmet.cli._grid import add_grid_argument, check_grid, pixel_source
from surfmet.cli._resolution_study import add_resolution_study_flag
from surfmet.cli._rolling_visco import add_visco_arguments, run_visco
from surfmet.cli._scan_options import add_scan_options, read_bodies
from surfmet.cli._values import VALUES_METAVAR, loads, positions, refuse_unused, values_help

EPILOG = """examples:
  surfmet rolling plate.x3p --radius 20mm --materials steel,aluminium \\
      --loads 1N:100N:5 --resolution-study
  surfmet rolling --radius 20mm --materials steel,aluminium --loads 1N:100N:9
  surfmet rolling plate.x3p --ball ball.x3p --radius 20mm \\
      --materials steel,aluminium --loads 1N:100N:9 --json
  surfmet rolling plate.x3p --radius 20mm --materials steel,aluminium \\
      --loads 1N:100N:9 --model plastic --plot lambda.png

M_r = s_r N^lambda is computed from the contact solution at each load (log-spaced,
warm-started): the hysteresis model (Johnson, Contact Mechanics 9.2: the work done on the
material entering the contact, times alpha_h) or the plastic model (the plastic work of
the first pass at the softer body's hardness). lambda_eff is the least-squares slope of
log M_r against log N with its confidence interval; the local exponent shows how it
drifts with the load. A smooth ball gives lambda = 4/3.
"""

#: The options of one dissipation model: given with another model they are refused
#: (they would be ignored).
MODEL_OPTIONS: dict[str, tuple[str, ...]] = {
    "--speed": ("viscoelastic", "all"),
    "--loss": ("viscoelastic", "all"),
    "--viscoelastic": ("viscoelastic",),
    "--work-of-adhesion": ("all",),
    "--adhesion-hysteresis": ("all",),
    "--no-microslip": ("all",),
    "--mu": ("microslip", "all"),
    "--traction-ratio": ("microslip",),
    "--alpha-h": ("hysteresis",),
    "--hardness": ("plastic", "all"),
    "--lossy": ("hysteresis", "plastic"),
    "--kinematics": ("hysteresis", "plastic"),
}
#: The parser's defaults (filled by add_parser), against which a given option is told.
_DEFAULTS: dict[str, Any] = {}


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "rolling",
        help="rolling-resistance exponent lambda (M_r = s_r N^lambda) from contact solutions",
        description="Rolling-resistance moment of a ball on a (rough) plate over a load "
        "sweep, under the hysteresis or the plastic dissipation model, and the fitted "
        "exponent lambda with its confidence interval.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_ball_arguments(p)
    p.add_argument("--loads", type=loads, required=True, metavar=VALUES_METAVAR,
                   help=values_help("loads", "4N,5N,6N") + "; three or more to fit lambda")
    p.add_argument("--model", choices=("hysteresis", "plastic", "microslip", "viscoelastic",
                                       "all"),
                   default="hysteresis", help="dissipation model (default hysteresis; "
                   "microslip: frictional slip of dissimilar bodies, contact.tangential; "
                   "all: the mechanisms side by side at the rotor's ball loads, with "
                   "the rotor's --radius 20mm; --loads sets only the lambda fit)")
    p.add_argument("--traction-ratio", type=float, default=0.0, metavar="T",
                   help="microslip: tangential force over normal force opposing the rolling "
                   "(e.g. the rotor's acceleration; default 0, free rolling)")
    add_visco_arguments(p)
    p.add_argument("--alpha-h", type=float, default=1.0, metavar="A",
                   help="hysteresis loss fraction (default 1: M_r is the work put in)")
    p.add_argument("--lossy", choices=("both", "plate", "ball"), default="both",
                   help="body that dissipates (its share of the displacement; default both)")
    p.add_argument("--kinematics", choices=("rolling", "frozen"), default="rolling",
                   help="rolling: asperities travel with the material (default); frozen: "
                   "the snapshot's -du/dx, asperity slopes included")
    p.add_argument("--hardness", type=pressure, metavar="P",
                   help="hardness of the softer body for the plastic model (default: table)")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    add_grid_argument(p, "contact grid, cells per side (default: the scans' own pixel, "
                      "native resolution, when it fits in memory)")
    add_resolution_study_flag(p)
    p.add_argument("--positions", type=positions, default=None, metavar="X:Y,...",
                   help="track positions: apex offsets from the middle of the scans; the "
                   "exponent is fitted to the mean moment over them")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="local processes over the track positions (default: one per CPU)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the track positions on a Dask cluster, e.g. tcp://host:8786")
    p.add_argument("--plot", metavar="FILE", help="write M_r(N) and the local exponent")
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    _DEFAULTS.update({a.dest: a.default for a in p._actions})
    return p


def run(args: argparse.Namespace) -> int:
    read_bodies(args)  # the scans as the user states them (--height-unit, --pixel...)
    import math

    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.rolling_resistance import rolling_resistance
    from surfmet.units import format_length, format_quantity

    args.loads = sorted(set(args.loads))  # a sweep runs up the loads (warm starts)
    refuse_unused(args, _DEFAULTS, args.model, MODEL_OPTIONS)
    if args.model in ("viscoelastic", "all"):
        return run_visco(args)
    n = len(args.loads)
    if n < 3:
        raise SurfmetInputError("--loads needs at least 3 loads to fit an exponent with a "
                                "confidence interval")
    if not (math.isfinite(args.alpha_h) and args.alpha_h > 0):
        raise SurfmetInputError("--alpha-h must be positive")
    check_grid(args.grid)
    check_output(args.plot, "--plot")
    if args.hardness is not None and args.model != "plastic":
        raise SurfmetInputError("--hardness applies to --model plastic")
    if args.resolution_study:
        from surfmet.cli._resolution_study import run_study

        return run_study(args, "rolling")
    if args.positions is not None or args.workers is not None or args.scheduler is not None:
        return _run_tracks(args, args.loads)
    rep = rolling_resistance(
        args.plate, args.ball, radius=args.radius, materials=args.materials,
        loads=args.loads, model=args.model, hardness=args.hardness,
        alpha_h=args.alpha_h, lossy=args.lossy, kinematics=args.kinematics,
        spikes=args.spikes, grid=args.grid,
        progress=lambda it: progress(it, total=n, desc=f"rolling ({args.model}), loads",
                                     show=show_progress(args)),
        mu=args.mu, traction_ratio=args.traction_ratio,
    )
    for note in rep.notes:
        log(f"note: {note}")
    if args.plot:
        save_figure(rep.figure(args.plot), args.plot)
    s = rep.sweep
    pair = rep.scans.pair if rep.scans is not None else None
    source = pixel_source(s.settings["dx"], pair, args.grid)
    if args.json:
        from surfmet.records._rolling import rolling_record

        emit_json(rolling_record(rep))
        return 0
    lo_ci, hi_ci = s.lambda_ci
    print(f"model          {s.model}"
          + (f" ({s.settings['kinematics']} kinematics, alpha_h = {args.alpha_h:g})"
             if s.model == "hysteresis" else
             f" (mu = {args.mu:g}, traction ratio {args.traction_ratio:g})"
             if s.model == "microslip" else
             f" (first pass, hardness {format_quantity(s.settings['hardness'], 'Pa')})"))
    if s.fit is not None:
        print(f"lambda_eff     {s.lambda_eff:.4f}   "
              f"{100 * s.fit.confidence:.0f} % CI [{lo_ci:.4f}, {hi_ci:.4f}]  "
              f"(s_r = {s.fit.prefactor:.4g} N^(1-λ) m)")
    else:
        print("lambda_eff     not fitted (fewer than 3 loads dissipate)")
    print(f"grid           {s.settings['grid']} x {s.settings['grid']} cells, pixel "
          f"{format_length(s.settings['dx'])} ({source})")
    print(f"{'load (N)':>12}{'M_r (N m)':>14}{'local λ':>10}")
    for w, m, lam in zip(s.loads, s.moments, s.local_lambda):
        print(f"{w:12.4g}{m:14.4g}{lam:10.4f}")
    if s.solve is not None:
        print_solve(s.solve)
    return 0


def _run_tracks(args: argparse.Namespace, loads: Any) -> int:
    """Several track positions through
    :func:`surfmet.mechanics.rolling_resistance.rolling_tracks`."""
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.rolling_resistance import rolling_tracks

    if args.workers is not None and args.workers < 1:
        raise SurfmetInputError("--workers must be at least 1")
    positions = args.positions or [None]
    if args.plot:
        raise SurfmetInputError("--plot draws one track; leave out --positions/--workers/"
                                "--scheduler to use it")
    rep = rolling_tracks(
        args.plate, args.ball, positions=positions, workers=args.workers,
        scheduler=args.scheduler, radius=args.radius, materials=args.materials,
        progress=show_progress(args), loads=tuple(float(w) for w in loads),
        model=args.model, hardness=args.hardness,
        alpha_h=args.alpha_h, lossy=args.lossy, kinematics=args.kinematics,
        spikes=args.spikes, grid=args.grid)
    failed = [t for t in rep.tracks if t.get("error")]
    if args.json:
        from surfmet.records._rolling import tracks_record

        emit_json({**tracks_record(rep), "model": args.model})
        return 1 if failed else 0
    if rep.fit is not None:
        lo_ci, hi_ci = rep.fit.ci
        print(f"lambda_eff     {rep.lambda_eff:.4f}   {100 * rep.fit.confidence:.0f} % CI "
              f"[{lo_ci:.4f}, {hi_ci:.4f}]  (mean moment over {len(rep.tracks) - len(failed)}"
              f" track positions)")
    else:
        print("lambda_eff     not fitted (fewer than 3 loads dissipate)")
    for t in rep.tracks:
        where = "middle" if t["offset"] is None else (
            f"{t['offset'][0] * 1e6:.1f} µm, {t['offset'][1] * 1e6:.1f} µm")
        print(f"  track {where:>24}: " + (f"error: {t['error']}" if t.get("error")
                                          else f"lambda {t['lambda']:.4f}"))
    print(f"{'load (N)':>12}{'mean M_r (N m)':>16}")
    for w, m in zip(rep.loads, rep.mean_moments):
        print(f"{w:12.4g}{m:16.4g}")
    return 1 if failed else 0
