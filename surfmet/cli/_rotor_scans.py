"""``surfmet rotor --plate FILE [--ball FILE]``: the scans that give the rough contact's
extent beside the Hertz radius in the verdict's arm bound
(:mod:`surfmet.mechanics.rotor_rough_bound`)."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet._errors import SurfmetInputError
from surfmet.cli._grid import add_grid_argument, check_grid
from surfmet.cli._scan_options import add_scan_options, read_bodies

__all__ = ["add_scan_arguments", "read_rotor_scans", "rough_bound"]


def add_scan_arguments(p: argparse.ArgumentParser) -> None:
    """``--plate``, ``--ball``, ``--grid`` and the shared scan options."""
    g = p.add_argument_group("scans (the rough contact's extent in the arm bound)")
    g.add_argument("--plate", metavar="FILE", help="scan of the plate: adds the rough "
                   "contact's radius a* at the symmetric ball load (surfmet hertz-check's) "
                   "beside the Hertz radius")
    g.add_argument("--ball", metavar="FILE", help="scan of the ball (with --plate)")
    add_grid_argument(g, "contact grid of the rough contact, cells per side (default "
                      "hertz-check's)")
    add_scan_options(p, ("plate", "ball"))


def read_rotor_scans(args: argparse.Namespace) -> None:
    """Check the options and read the scans before any work (one line on bad input)."""
    if args.ball is not None and args.plate is None:
        raise SurfmetInputError("--ball needs --plate (the rough contact is the ball's on "
                                "the scanned plate)")
    if args.grid is not None and args.plate is None:
        raise SurfmetInputError("--grid is the rough contact's: it needs --plate")
    check_grid(args.grid)
    if args.plate is not None:
        read_bodies(args)


def rough_bound(args: argparse.Namespace, verdict: Any) -> Any:
    """The rough arm bound for the verdict, or None without scans."""
    if args.plate is None:
        return None
    if verdict is None or verdict.arm is None or verdict.rig is None:
        raise SurfmetInputError("--plate needs the rig's arm bound (paper2022, or --rig "
                                "RIG.json)")
    from surfmet.mechanics.rotor_rough_bound import rough_arm_bound

    return rough_arm_bound(verdict.arm, verdict.rig.ball_radius, args.plate, args.ball,
                           grid=args.grid)
