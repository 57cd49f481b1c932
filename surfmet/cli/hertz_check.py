"""``surfmet hertz-check PLATE``: does Hertz hold for this scan at this load?"""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    _argtype,
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
    save_figure,
)
from surfmet.cli._grid import add_grid_argument, add_on_edge_argument, check_grid, pixel_source
from surfmet.cli._resolution_study import add_resolution_study_flag
from surfmet.cli._scan_options import add_scan_options, read_bodies

EPILOG = """examples:
  surfmet hertz-check plate.x3p --ball ball.x3p --radius 20mm --load 10N \\
      --materials steel,aluminium --resolution-study --json
  surfmet hertz-check plate.x3p --radius 20mm --load 10N --materials steel,aluminium
  surfmet hertz-check plate.nms --ball ball.nms --radius 20mm --load 4.7N \\
      --materials steel,aluminium --json
  surfmet hertz-check plate.x3p --radius 20mm --load 10N --materials steel,al:H=0.9GPa \\
      --plot hertz.png

The verdict combines the Greenwood-Johnson-Matsubara parameter alpha = sigma R / a0^2
(sigma: combined rms roughness after levelling the plate and removing the ball's
sphere; Hertz holds for alpha < 0.05) with a boundary-element solution on the scans
compared with Hertz: averaged pressure profile, effective contact radius, approach, and
yield at the softer material's hardness. Spikes are removed from the scans first.
The verdict names the simplest model within tolerance of the boundary elements: hertz,
greenwood_tripp (GW asperities from the scans' spectra under the Hertz body), its
elastic-plastic variant capped at the hardness, or the BEM itself (JSON: models, verdict).

With --work-of-adhesion W (and --range Z0, default 0.3 nm) it states Tabor's parameter
(R w^2 / (E*^2 Z0^3))^(1/3) of the contact (R the ball's radius) and of a typical asperity
(the spectral summit radius), Pastewka & Robbins' (2014, PNAS 111:3298, eq. 10)
stickiness parameter of the roughness (sticky below 1), the smooth-ball pull-offs
against the load, and whether adhesion changes the contact (JSON: adhesion). Without W
the section is left out (no default work of adhesion is assumed).
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    from surfmet.units import parse_surface_energy

    p = sub.add_parser(
        "hertz-check",
        help="does Hertz hold for this rough contact? (GJM alpha and boundary elements)",
        description="Compare the rough contact of a ball on a scanned plate (and ball) with "
        "Hertz theory, and say whether Hertz holds, with the reasons.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_ball_arguments(p)
    p.add_argument("--load", type=force, required=True, metavar="F",
                   help="normal load, e.g. 10N")
    p.add_argument("--hardness", type=pressure, metavar="P",
                   help="hardness of the softer body (default: the materials' table value)")
    p.add_argument("--elastic", action="store_true",
                   help="elastic solution only (do not check yield)")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    add_grid_argument(p, "contact grid, cells per side (default: the scans' own pixel, "
                      "native resolution, when it fits in memory)")
    add_on_edge_argument(p, "contact reaching the domain edge: enlarge (default), warn, fail")
    add_resolution_study_flag(p)
    g = p.add_argument_group("adhesion (Tabor and Pastewka-Robbins parameters)")
    g.add_argument("--work-of-adhesion", type=_argtype(parse_surface_energy, "work"),
                   metavar="W", help="work of adhesion, e.g. 0.1J/m2: adds the adhesion "
                   "assessment (left out without it)")
    g.add_argument("--range", type=positive_length, metavar="Z0", dest="range_",
                   help="interaction range (default 0.3 nm, an interatomic spacing)")
    p.add_argument("--plot", metavar="FILE",
                   help="write the pressure map and the radial profile against Hertz")
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet.cli._values import require_plate

    read_bodies(args)  # the scans as the user states them (--height-unit, --pixel...)
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.hertz_check import hertz_check
    from surfmet.units import format_length, format_quantity, readable_quantities

    require_plate(args.plate, "hertz-check")
    check_grid(args.grid)
    check_output(args.plot, "--plot")
    if args.elastic and args.hardness is not None:
        raise SurfmetInputError("--elastic and --hardness exclude each other")
    if args.resolution_study:
        from surfmet.cli._resolution_study import run_study

        return run_study(args, "hertz-check")
    check = hertz_check(args.plate, radius=args.radius, load=args.load,
                        materials=args.materials, ball=args.ball, hardness=args.hardness,
                        plastic=not args.elastic, spikes=args.spikes, grid=args.grid,
                        on_edge=args.on_edge, work_of_adhesion=args.work_of_adhesion,
                        adhesion_range=args.range_)
    res = check.result
    source = pixel_source(res.dx, check.scans.pair, args.grid)
    for note in check.notes:
        log(f"note: {note}")
    if args.plot:
        save_figure(check.figure(args.plot), args.plot)
    if args.json:
        from surfmet.records._hertz import hertz_check_record

        emit_json(hertz_check_record(check))
        return 0
    c = check.comparison
    hz = c.hertz
    print(f"{c.headline} "
          f"(α = {c.alpha:.3g}, σ = {format_length(c.sigma)})")
    for reason in c.reasons:
        print(f"  - {reason}")
    for w in check.warnings:
        print(f"warning: {readable_quantities(w)}")
    print()
    print(f"{'':16}{'Hertz':>14}{'BEM':>14}")
    rows = [
        ("peak pressure", format_quantity(hz.p0, "Pa"), format_quantity(c.pmax, "Pa")),
        ("radius a, a*", format_length(hz.a), format_length(c.effective_radius)),
        ("approach", format_length(hz.delta), format_length(c.approach)),
        ("area / πa0²", "1", f"{c.area_fraction:.3g}"),
        ("yielded / πa0²", "0", f"{c.plastic_fraction:.3g}"),
    ]
    for name, a, b in rows:
        print(f"{name:16}{a:>14}{b:>14}")
    if check.hierarchy is not None:
        h = check.hierarchy
        print()
        print(f"model: {h.verdict} ({h.reasons[0]})")
        print(f"{'':26}{'a*':>12}{'a* error':>10}{'profile error':>15}")
        for name, m in h.models.items():
            print(f"{name:26}{format_length(m.a_star):>12}{100 * m.radius_error:>9.3g}%"
                  f"{100 * m.profile_error:>13.3g}%")
    if check.adhesion is not None:
        _print_adhesion(check.adhesion)
    print(f"grid {res.shape[1]} x {res.shape[0]} cells, pixel {format_length(res.dx)} "
          f"({source}); "
          f"load {check.load:.4g} N, R = {format_length(check.radius)}, "
          f"{check.ball_material.name} on {check.plate_material.name}")
    from surfmet.records._hertz import hertz_check_solve

    print_solve(hertz_check_solve(check))
    return 0


def _print_adhesion(a: Any) -> None:
    """The adhesion assessment in text."""
    from surfmet.units import format_length

    print()
    print(f"adhesion: w = {a.work:.4g} J/m², range {format_length(a.range)}: "
          f"{'changes' if a.changes_contact else 'does not change'} the contact")
    print(f"  Tabor parameter  contact {a.tabor_contact:.3g}"
          + ("" if a.tabor_asperity is None else
             f", asperity {a.tabor_asperity:.3g} (summit radius "
             f"{format_length(a.summit_radius)})"))
    print(f"  {a.reason}")
