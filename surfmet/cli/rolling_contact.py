"""``surfmet rolling-contact``: steady rolling with friction (stick, slip, creepage)."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    add_ball_arguments,
    add_json_flag,
    add_quiet_flag,
    add_spikes_argument,
    emit_json,
    log,
    positive_length,
    speed,
    spike_summary,
)
from surfmet.cli._rolling_contact_text import print_summary
from surfmet.cli._rolling_contact_visco import add_visco_options, run_viscoelastic
from surfmet.cli._scan_options import add_scan_options, read_bodies

EPILOG = """examples:
  surfmet rolling-contact --radius 20mm --load 5N --materials steel,aluminium --mu 0.3
  surfmet rolling-contact --radius 20mm --load 5N --materials steel,aluminium --mu 0.3 \\
      --creepage 1e-4 --json
  surfmet rolling-contact --radius 25mm --load 100N/mm --line --materials aluminium,steel \\
      --mu 0.05
  surfmet rolling-contact plate.x3p --ball ball.x3p --radius 20mm --load 5N \\
      --materials steel,aluminium --mu 0.3 --grid 96

Sign convention: body 1 = ball, body 2 = plate; the contact moves in +x (leading edge at
+x); creepage = (rigid slip velocity of the ball relative to the plate) / rolling speed;
forces are those on the ball, so a positive creepage gives a negative fx. Without
--creepage the case is free rolling (fx = 0) and the creepage it takes is reported.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "rolling-contact",
        help="steady rolling with friction: stick/slip areas, creepage, frictional power",
        description="Solve steady rolling of a ball (or a roller, --line) on a plate with "
        "Coulomb friction by boundary elements: pressure, tractions, stick and slip "
        "areas, the normal-tangential coupling of dissimilar materials.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_ball_arguments(p)
    p.add_argument("--load", required=True, metavar="F",
                   help="normal load, e.g. 5N (with --line: per length, e.g. 100N/mm)")
    p.add_argument("--mu", type=float, required=True, metavar="M",
                   help="coefficient of friction (> 0)")
    p.add_argument("--creepage", type=float, metavar="X",
                   help="longitudinal creepage xi (default: free rolling, fx = 0)")
    p.add_argument("--line", action="store_true",
                   help="plane strain line contact (a roller), load per unit length")
    p.add_argument("--speed", type=speed, metavar="V",
                   help="rolling speed, e.g. 1m/s or 50mm/s (a bare number is m/s; adds "
                   "the frictional power in W)")
    p.add_argument("--grid", type=int, metavar="N",
                   help="elements per side (default 64; 256 with --line)")
    p.add_argument("--size", type=positive_length, metavar="L",
                   help="domain side (default: automatic from Hertz and the scans' "
                   "roughness, as for `surfmet contact`, enlarged if the contact outgrows it)")
    add_scan_options(p, ("plate", "ball"))
    add_spikes_argument(p)
    add_visco_options(p)
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    read_bodies(args)  # the scans as the user states them (--height-unit, --pixel...)
    import math

    from surfmet import units
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.rolling_contact import parse_line_load, solve_rolling_contact
    from surfmet.records._rolling_contact import rolling_contact_record

    if args.creepage is not None and not math.isfinite(args.creepage):
        raise SurfmetInputError("--creepage must be a finite number")
    if not (math.isfinite(args.mu) and args.mu > 0):
        raise SurfmetInputError("--mu must be a positive number")
    if args.viscoelastic:
        if args.size is not None:
            raise SurfmetInputError("--size sets the elastic solver's domain; the "
                                    "viscoelastic model sizes its own")
        return run_viscoelastic(args)
    load = parse_line_load(args.load) if args.line else units.parse_force(args.load)
    if not load > 0:
        raise SurfmetInputError("--load must be positive")
    roughness = None
    if args.plate or args.ball:
        from surfmet.mechanics.scan_preparation import prepare_scans

        if args.line:
            raise SurfmetInputError("--line takes no scans (a roller's profile is not read)")
        # the one scan preparation every contact command shares (spikes, levelling, pairing)
        prep = prepare_scans(args.plate, args.ball, spikes=args.spikes)
        for note in prep.notes:
            log(f"note: {note}")
        log(f"note: {spike_summary(prep)}")
        pair = prep.pair
        roughness = (pair.roughness, pair.dx, pair.dy)
    rc = solve_rolling_contact(args.radius, load, args.materials, args.mu,
                               creepage=args.creepage, line=args.line, speed=args.speed,
                               grid=args.grid, roughness=roughness, size=args.size)
    rec = rolling_contact_record(rc)
    if args.json:
        emit_json(rec)
        return 0
    print_summary(rec)
    return 0
