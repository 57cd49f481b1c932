"""``surfmet fit FILE --shape circle|sphere``: radius of a ball or roller from a scan."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, emit_json
from surfmet.cli._scan_options import add_scan_options, print_caveats, read_scan, scan_caveats

EPILOG = """examples:
  surfmet fit ball.nms --shape sphere
  surfmet fit ball.nms --shape sphere --loss soft_l1 --json
  surfmet fit ball.nms --shape circle --profile row:256
  surfmet fit roller_profile.csv --shape circle

The sphere fit is geometric least squares (algebraic start); the circle fit is the
profile engine's. Uncertainties are standard uncertainties (k = 1) from the fit.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "fit",
        help="fit a sphere (areal) or a circle (profile) and report radius and form",
        description="Least-squares sphere or circle fit: radius, centre, their uncertainty "
        "and the residual (form deviation).",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("file", help="scan file")
    add_scan_options(p)
    p.add_argument("--shape", required=True, choices=("circle", "sphere"))
    p.add_argument("--profile", default=None, metavar="row:K|col:K",
                   help="for --shape circle on an areal scan: the row or column to fit")
    p.add_argument("--loss", default="linear", choices=("linear", "huber", "soft_l1"),
                   help="loss of the geometric fit (robust: huber, soft_l1)")
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet.units import format_length

    scan = read_scan(args.file, args)
    from surfmet.records import fit_record

    rec = {"file": args.file, **fit_record(scan, args.shape, args.profile, args.loss)}
    rec["caveats"] = scan_caveats(scan)
    if args.json:
        emit_json(rec)
        return 0
    print(f"file                {args.file}")
    print(f"shape               {rec['shape']} ({rec['n_points']} points, loss {args.loss})")
    print(f"radius              {format_length(rec['radius']['value'], 8)} "
          f"± {format_length(rec['radius_uncertainty']['value'], 3)} (k = 1)")
    centre = ", ".join(format_length(v, 6) for v in rec["center"]["value"])
    print(f"centre              ({centre})")
    print(f"rms residual        {format_length(rec['rms_residual']['value'])}")
    if "form_pv" in rec:
        what = rec["names"]["form_pv"].split(": ", 1)[-1]
        print(f"form deviation      {format_length(rec['form_pv']['value'])} {what}")
    print(f"residual PV         {format_length(rec['pv_form_deviation']['value'])} all points "
          "(roughness and outliers included)")
    print_caveats(rec["caveats"])
    return 0
