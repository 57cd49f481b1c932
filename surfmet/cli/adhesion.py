"""``surfmet adhesion``: approach and retraction of an adhesive sphere (or cylinder) on a
flat."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    _argtype,
    add_json_flag,
    add_quiet_flag,
    add_spikes_argument,
    check_output,
    emit_json,
    log,
    positive_length,
    pressure,
    print_solve,
    save_figure,
    show_progress,
)
from surfmet.cli._scan_options import add_scan_options, print_caveats, read_bodies, scan_caveats
from surfmet.cli._values import add_interaction_argument, add_plate_argument

EPILOG = """examples:
  surfmet adhesion --radius 10um --e-star 1GPa --work-of-adhesion 50mJ/m2 --range 2nm
  surfmet adhesion --radius 5um --materials pmma,glass --work-of-adhesion 0.05J/m^2 \\
      --range 1nm --interaction exponential --json
  surfmet adhesion --radius 10um --e-star 1GPa --work-of-adhesion 0.05J/m2 --range 5nm \\
      --grid 192 --plot cycle.png
  surfmet adhesion --radius 10um --e-star 1GPa --work-of-adhesion 50mJ/m2 --range 2nm \\
      plate.x3p --size 2um
  surfmet adhesion --line --radius 10um --e-star 1GPa --work-of-adhesion 50mJ/m2 \\
      --range 3nm --json

A smooth sphere (no PLATE, --ball, --grid or --size) is solved by default on
axisymmetric rings (--model auto; JSON "discretisation"): a free half-space, rings
narrow enough to put {rings:g} across the cohesive zone (or 200 across the contact where
the zone is wider), so the pull-off is Maugis' within 2 % from lambda 0.05 to 10 and the
approach is Maugis' delta, from the distant surface. --model 3d (or --grid, --size, a
scan) takes the periodic 3D grid instead: the sphere is a paraboloid in the middle of a
periodic cell (--size, default four times the larger of the JKR contact radius at zero
load and the interaction zone), the approach from the deformed mean plane. --range is
h0 = w / sigma0 for the Dugdale (Maugis) law, rho for the exponential law
t(g) = (w / rho) exp(-g / rho). The pull-off force is the largest tension on the way out
(displacement control). A grid that leaves the cohesive zone pi E* w / (4 sigma0^2) fewer
than {zone:g} pixels wide is warned about (JSON grid.process_zone_pixels): the pull-off then
comes out too large, by the measured excess the warning states. On the 3D grid without
--grid the Dugdale law's grid is the one (at least 128 cells) that makes the zone {zone:g}
pixels wide; where the memory does not allow it, the largest grid that fits is used and a
warning says by how much the pull-off is then off (JSON grid.why; measured convergence
in docs/adhesion.md).
Measured against Maugis-Dugdale on this command's sphere, Dugdale step smoothed on the
grid (benchmarks/adhesion_zone_threshold.py): within 2.1 % from 2 pixels up (Maugis
lambda 1 to 5), up to +3.8 % between 1.5 and 2, +4.6 % to +14 % below
1.1. The exponential law and --line have no smoothed step: their warning starts at {plain:g}.

PLATE and --ball add the scans' roughness: the plate levelled, the ball's best-fit
sphere removed, both paired and sampled onto the solver's grid around the middle of the
scans, which must cover the periodic cell (--size).

--line: a cylinder of radius --radius in plane strain (its axis along the scan's y), on
a periodic line of --grid cells (default 2048) across --size (default 16 times the larger
of the JKR half-width at zero load and the interaction's reach). Forces are per unit
length (N/m), energies J/m; the pull-off is compared with JKR's 3 (pi w^2 E* R / 16)^(1/3)
and with the rigid cylinder's. With PLATE the roughness is the scan's middle row.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    from contact._zone_resolution import MIN_ZONE_PIXELS, MIN_ZONE_PIXELS_PLAIN, ZONE_RINGS
    from surfmet.units import parse_surface_energy

    p = sub.add_parser(
        "adhesion",
        help="pull-off, jumps and hysteresis of an adhesive sphere on a flat",
        description="Approach an elastic sphere to a flat and retract it under displacement "
        "control, with a Dugdale (Maugis) or exponential adhesion law solved on axisymmetric "
        "rings (a smooth sphere) or an FFT "
        "boundary-element grid: pull-off force, jump-in and jump-out, energy lost in the "
        "cycle, and the Maugis and Tabor parameters.",
        epilog=EPILOG.format(zone=MIN_ZONE_PIXELS, plain=MIN_ZONE_PIXELS_PLAIN,
                             rings=ZONE_RINGS),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--radius", type=positive_length, required=True, metavar="R",
                   help="sphere radius, e.g. 10um")
    mod = p.add_mutually_exclusive_group(required=True)
    mod.add_argument("--materials", metavar="A,B", help="sphere and flat materials")
    mod.add_argument("--e-star", type=pressure, metavar="E", help="composite modulus E*")
    p.add_argument("--work-of-adhesion", type=_argtype(parse_surface_energy, "work"),
                   metavar="W", help="work of adhesion, e.g. 50mJ/m2 (the laws stated by "
                   "a work and a range)")
    p.add_argument("--range", type=positive_length, metavar="RHO",
                   dest="range_", help="interaction range, e.g. 2nm (the laws stated by a "
                   "work and a range)")
    add_interaction_argument(p)
    p.add_argument("--grid", type=int, default=None, metavar="N",
                   help="cells per side of the 3D grid (implies --model 3d; default: with "
                   "the Dugdale law the grid, at least "
                   "128, that gives the cohesive zone 2 pixels, within memory; 128 with the "
                   "exponential law; with --line, across the period, default 2048)")
    p.add_argument("--model", choices=("auto", "axisymmetric", "3d"), default="auto",
                   help="the sphere's discretisation (default auto: a smooth sphere without "
                   "--grid or --size on axisymmetric rings that resolve the cohesive zone at "
                   "any Maugis lambda; scans, --grid or --size: the periodic 3D grid)")
    p.add_argument("--line", action="store_true",
                   help="a cylinder of radius --radius (plane strain), per unit length")
    p.add_argument("--size", type=positive_length, metavar="L", help="side of the periodic cell")
    p.add_argument("--steps", type=int, default=40, metavar="K",
                   help="approach steps on each leg (default 40)")
    add_plate_argument(p, "scan of the plate (levelled; its roughness enters the gap)")
    p.add_argument("--ball", metavar="FILE",
                   help="scan of the ball (its best-fit sphere is removed)")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    p.add_argument("--plot", metavar="OUT.png", help="plot the load-approach cycle")
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet._batch import progress_bar
    from surfmet.cli._laws import interaction_from_arguments
    from surfmet.mechanics.adhesion import adhesion, plot
    from surfmet.mechanics.adhesion_line import line_adhesion, line_plot, refuse_ball
    from surfmet.records._adhesion import adhesion_record, line_record
    from surfmet.units import readable_quantities

    law = interaction_from_arguments(args)  # its options checked before any scan is read
    if args.line:
        refuse_ball(args.ball)  # before the scans are read
    read_bodies(args)  # the scans as the user states them (--height-unit, --pixel...)

    check_output(args.plot, "--plot")
    with progress_bar(2 * args.steps, "adhesion, steps", show_progress(args)) as bar:
        run_ = (line_adhesion if args.line else adhesion)(
            args.radius, materials=args.materials, e_star=args.e_star, interaction=law,
            grid=args.grid, size=args.size, steps=args.steps, plate=args.plate,
            ball=args.ball, spikes=args.spikes, progress=lambda done, total: bar.update(1),
            **({} if args.line else {"model": args.model}))
    if args.plot:
        save_figure((line_plot if args.line else plot)(run_, args.plot), args.plot)
    if args.json:
        for w in run_.result.warnings:
            log(f"warning: {readable_quantities(w)}")
        emit_json((line_record if args.line else adhesion_record)(run_))
        return 0
    if run_.line:
        _print_line(run_)
    else:
        _print(run_)
    print_caveats(scan_caveats(args.plate, args.ball))
    return 0


#: A cycle cannot gain energy: a negative loss is the trapezoidal rule's error over the
#: approach steps (jumps inside a step), larger than the loss itself.
_NEGATIVE = (" (negative: below the integration error of the approach steps; use more "
             "--steps or a finer --grid)")


def _print_line(run_: Any) -> None:
    """The text summary of a line-contact cycle."""
    from surfmet.units import format_length, format_quantity, readable_quantities

    res = run_.result
    cyc, law = res.cycle, res.law
    print(f"cylinder        R = {format_length(res.radius)}, E* = "
          f"{format_quantity(res.e_star, 'Pa')} "
          "(plane strain, per unit length)")
    print(f"interaction     w = {format_quantity(law.work, 'J/m^2')}, range "
          f"{format_length(law.range)}, peak tension {format_quantity(law.peak, 'Pa')}")
    print(f"Maugis lambda   {res.maugis_parameter:.4g}   (Tabor mu {res.tabor_parameter:.4g})")
    print(f"grid            {res.cells} cells, pixel {format_length(res.dx)}, "
          f"period {format_length(res.size)}")
    print(f"pull-off force  {_pull_off(cyc, 'N/m', 1.0)} (JKR {res.jkr_pull_off:.5g} N/m, "
          f"rigid cylinder {res.rigid_pull_off:.5g} N/m)")
    _print_cycle(cyc, "N/m", 1.0, "J/m")
    if run_.scans is not None:
        print(f"scans           plate {run_.scans.plate_name}; roughness rms on the profile "
              f"{format_length(run_.scans.roughness_rms)}")
    for w in res.warnings:
        print(f"warning         {readable_quantities(w)}")


def _print(run_: Any) -> None:
    """The text summary of a cycle."""
    from surfmet.units import format_length, format_quantity, readable_quantities

    ball = run_.result
    cyc, law = ball.cycle, ball.law
    print(f"sphere          R = {format_length(ball.radius)}, E* = "
          f"{format_quantity(ball.e_star, 'Pa')}")
    print(f"interaction     w = {format_quantity(law.work, 'J/m^2')}, range "
          f"{format_length(law.range)}, peak tension {format_quantity(law.peak, 'Pa')}")
    print(f"Maugis lambda   {ball.maugis_parameter:.4g}   (Tabor mu {ball.tabor_parameter:.4g})")
    if law.smoothing > 0.0:
        where = "rings'" if run_.axisymmetric else "grid's"
        scale = (f"the {where} scale, capped at the range" if law.smoothing >= law.range
                 else f"the {where} scale")
        step = f"{law.name.capitalize()} step"
        print(f"{step:15s} smoothed over {format_length(law.smoothing)} of gap "
              f"({scale}: removes the pixels' pinning of the zone's end)")
    if run_.axisymmetric:
        kind = "graded rings, the finest" if ball.graded else "rings of"
        print(f"rings           {ball.rings} {kind} {format_length(ball.dr)} to radius "
              f"{format_length(ball.outer_radius)} (axisymmetric, free half-space; the "
              f"cohesive zone {ball.process_zone / ball.dr:.3g} rings wide)")
    else:
        print(f"grid            {ball.grid} x {ball.grid} cells, "
              f"pixel {format_length(ball.dx)}, periodic cell {format_length(ball.size)}")
    print(f"                {run_.grid_why}")
    in_w_r = cyc.pull_off_force / (3.141592653589793 * law.work * ball.radius)
    print(f"pull-off force  {_pull_off(cyc, 'µN', 1e6)}"
          + (f" = {in_w_r:.4g} pi w R (JKR 1.5, DMT 2)" if in_w_r > 0 else
             " (JKR 1.5 pi w R, DMT 2 pi w R)"))
    _print_cycle(cyc, "µN", 1e6, "J")
    if run_.scans is not None:
        print(f"scans           plate {run_.scans.plate_name or '-'}, ball "
              f"{run_.scans.ball_name or '-'}; roughness rms on the grid "
              f"{format_length(run_.scans.roughness_rms)}")
    for w in ball.warnings:
        print(f"warning         {readable_quantities(w)}")


def _how(jump: Any) -> str:
    """How a jump reads: abrupt (nothing added), smooth, or smooth over a step too wide
    to resolve a snap (contact.adhesion.cycle.find_jump)."""
    if jump.abrupt:
        return ""
    if jump.resolved:
        return " (smooth)"
    return (" (no faster than a continuous branch over this step, which is wider than the "
            "interaction range: a snap inside it is not resolved; use more --steps)")


def _pull_off(cyc: Any, unit: str, scale: float) -> str:
    """The pull-off force in ``unit``, or 0 named as a retraction that never pulled."""
    if cyc.pull_off_force > 0.0:
        return f"{cyc.pull_off_force * scale:.5g} {unit}"
    least = float(min(cyc.retraction_leg.load)) * scale
    return (f"0 {unit}: the retraction never pulled (its least load, {least:.4g} {unit}, "
            "is not tensile)")


def _loads_shown(before: float, after: float) -> tuple[float, float]:
    """The loads across a jump as printed: one that is round-off beside the other (the
    load before contact, ~1e-29 of the pull-off) shows as 0, not as 2.1e-29."""
    big = max(abs(before), abs(after))
    return (0.0 if abs(before) < 1e-9 * big else before,
            0.0 if abs(after) < 1e-9 * big else after)


def _print_cycle(cyc: Any, force_unit: str, scale: float, energy_unit: str) -> None:
    """The jumps, the energy lost and the solve record of a cycle, sphere or line alike
    (loads times ``scale`` in ``force_unit``)."""
    from surfmet.units import format_length

    for name, jump in (("jump-in", cyc.jump_in), ("jump-out", cyc.jump_out)):
        if jump is None:
            print(f"{name:15s} none within the approach range")
        else:
            before, after = _loads_shown(jump.load_before * scale, jump.load_after * scale)
            print(f"{name:15s} at approach {format_length(jump.approach)} (+- "
                  f"{format_length(jump.step / 2)}), load {before:.4g} -> "
                  f"{after:.4g} {force_unit}"
                  f"{_how(jump)}")
    lost, resolution = cyc.hysteresis_energy, cyc.hysteresis_resolution
    if lost == 0.0 and resolution > 0.0:
        print(f"hysteresis      0 {energy_unit} lost in the cycle (within {resolution:.2g} "
              f"{energy_unit} of zero: the solves' tolerance times the work on the legs)")
    else:
        print(f"hysteresis      {lost:.4g} {energy_unit} lost in the cycle"
              f"{_NEGATIVE if lost < 0 else ''}")
    print_solve(cyc.solve, "solve          ")
