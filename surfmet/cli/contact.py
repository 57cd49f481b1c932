"""``surfmet contact``: normal contact of a (rough) ball on a (rough) plate by FFT-BEM."""

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
    force,
    log,
    positive_length,
    pressure,
    print_solve,
    show_progress,
    spike_summary,
)
from surfmet.cli._grid import add_grid_argument, add_on_edge_argument, check_grid, pixel_source
from surfmet.cli._resolution_study import add_resolution_study_flag
from surfmet.cli._scan_options import add_scan_options, read_bodies
from surfmet.cli._values import add_periodic_argument

EPILOG = """examples:
  surfmet contact plate.x3p --ball ball.x3p --radius 20mm --load 10N \\
      --materials steel,aluminium --plastic --resolution-study
  surfmet contact --radius 20mm --load 10N --materials steel,aluminium
  surfmet contact plate.nms --ball ball.nms --radius 20mm --load 10N \\
      --materials steel,aluminium --json
  surfmet contact plate.x3p --radius 20mm --load 10N --materials steel,aluminium \\
      --plastic --out result.npz
  surfmet contact --radius 20mm --load 10N --materials steel:E=200GPa:nu=0.29,al:H=1GPa

Materials: steel, aluminium, glass, copper, brass, titanium, fused_silica,
tungsten_carbide, silicon_nitride, alumina, pmma, mild_steel (override any value with
NAME:E=...:nu=...:H=...). Without a scan the smooth (Hertz) case is solved.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "contact",
        help="normal contact of a rough ball on a rough plate (FFT boundary elements)",
        description="Solve the frictionless normal contact of a ball on a plate with the "
        "FFT boundary-element method, using the scans' roughness when given, and compare "
        "with Hertz.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_ball_arguments(p)
    p.add_argument("--load", type=force, required=True, metavar="F", help="normal load, e.g. 10N")
    plast = p.add_mutually_exclusive_group()
    plast.add_argument("--hardness", type=pressure, metavar="P",
                       help="cap the pressure at this hardness (elastic-perfectly-plastic)")
    plast.add_argument("--plastic", action="store_true",
                       help="cap the pressure at the softer material's table hardness")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    add_grid_argument(p, "cells per side (default: the scans' own pixel, native resolution, "
                      "when it fits in memory; 256 for a smooth ball)")
    p.add_argument("--size", type=positive_length, metavar="L",
                   help="domain side (default: automatic from Hertz and the roughness)")
    add_periodic_argument(p, default="no", help="periodic domain: yes, or no (default: a "
                          "free boundary; auto is no, a ball's contact being local)")
    add_on_edge_argument(p, "contact reaching the domain edge: enlarge the domain (default), "
                         "warn and return the truncated result, or fail")
    p.add_argument("--tol", type=float, default=1e-6, help="solver tolerance (default 1e-6)")
    p.add_argument("--max-iter", type=int, default=2000, help="iteration limit (default 2000)")
    add_resolution_study_flag(p)
    p.add_argument("--out", metavar="FILE.npz", help="save the fields (pressure, gap, ...)")
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    read_bodies(args)  # the scans as the user states them (--height-unit, --pixel...)
    import json

    import numpy as np

    from surfmet.mechanics.ball_contact import ball_contact
    from surfmet.units import jsonable

    args.periodic = args.periodic == "yes"
    if args.resolution_study:
        from surfmet.cli._resolution_study import run_study

        return run_study(args, "contact")
    check_grid(args.grid)
    check_output(args.out, "--out")
    from surfmet._batch import progress_bar

    # a smooth ball on a small grid is done before a line would help
    big = (args.grid or 0) >= 512 or bool(args.plate or args.ball)
    with progress_bar(None, "contact, iterations",
                      show_progress(args) if big else False) as bar:

        def callback(it: int, residual: float) -> None:
            bar.update(1)
            bar.set_postfix_str(f"residual {residual:.1e}", refresh=False)

        sol = ball_contact(
            args.plate, args.ball, radius=args.radius, load=args.load,
            materials=args.materials, hardness=args.hardness, plastic=args.plastic,
            grid=args.grid, size=args.size, periodic=args.periodic, on_edge=args.on_edge,
            tol=args.tol, max_iter=args.max_iter, callback=callback,
            spikes=args.spikes)
    res, pair = sol.result, sol.pair
    if sol.preparation is not None and not args.json:
        for note in sol.preparation.notes:
            log(f"note: {note}")
    if args.json:  # in text the warnings are part of the table below
        for w in sol.warnings:
            log(f"warning: {w}")

    from surfmet.records._contact import ball_contact_record

    rec = ball_contact_record(sol)
    rec["grid"]["pixel_source"] = pixel_source(res.dx, pair, args.grid)
    if args.out:
        from surfmet._atomic import atomic_open

        with atomic_open(args.out, "wb") as fh:  # a file object: numpy adds no suffix
            np.savez_compressed(fh, **res.arrays(), dx=res.dx, dy=res.dy,
                                summary=json.dumps(jsonable(rec)))
    if args.json:
        emit_json(rec)
        return 0
    _print(sol, args)
    return 0


def _print(sol: Any, args: argparse.Namespace) -> None:
    """The text table of a solved contact."""
    from surfmet.units import format_length, format_quantity, readable_quantities

    res, pair = sol.result, sol.pair
    ball_m, plate_m = sol.ball_material, sol.plate_material
    hz = res.hertz
    print(f"materials      {ball_m.name} on {plate_m.name}, E* = "
          f"{format_quantity(res.e_star, 'Pa')}")
    if sol.preparation is not None:
        print(f"scans          {spike_summary(sol.preparation)}")
    print(f"grid           {res.shape[1]} x {res.shape[0]} cells, pixel "
          f"{format_length(res.dx)} ({pixel_source(res.dx, pair, args.grid)}), side "
          f"{format_length(res.shape[1] * res.dx)}{' (periodic)' if res.periodic else ''}")
    print(f"load           {format_quantity(res.load, 'N', 6)}")
    print(f"max pressure   {format_quantity(res.pmax, 'Pa', 6)}   (Hertz p0 "
          f"{format_quantity(hz.p0, 'Pa', 6)})")
    print(f"contact radius {format_length(res.contact_radius)} = sqrt(A/pi), real area   "
          f"(95 % of the load within {format_length(res.radius_95)})")
    print(f"effective a*   {format_length(res.effective_radius)} = sqrt(5/2 <r^2>_p)   "
          f"(Hertz a {format_length(hz.a)})")
    print(f"approach       {format_length(res.approach)}   (Hertz delta "
          f"{format_length(hz.delta)})")
    print(f"area fraction  {res.area_fraction:.4g}   clusters {res.n_clusters}")
    if res.hardness is not None:
        print(f"plastic area   {format_quantity(res.plastic_area, 'm^2', 6)}   ({res.regime}; "
              f"hardness {format_quantity(res.hardness, 'Pa', 5)})")
    print_solve(res.solve, "solver", warned=sol.warnings)
    for note in res.notes:
        print(f"note           {readable_quantities(note)}")
    for w in sol.warnings:
        print(f"warning        {readable_quantities(w)}")
    if args.out:
        print(f"fields saved   {args.out}")

