"""``surfmet fit FILE --shape circle|sphere``: radius of a ball or roller from a scan."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, emit_json

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
    p.add_argument("--shape", required=True, choices=("circle", "sphere"))
    p.add_argument("--profile", default=None, metavar="row:K|col:K",
                   help="for --shape circle on an areal scan: the row or column to fit")
    p.add_argument("--loss", default="linear", choices=("linear", "huber", "soft_l1"),
                   help="loss of the geometric fit (robust: huber, soft_l1)")
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def fit_record(scan: Any, shape: str, profile: str | None = None, loss: str = "linear"
               ) -> dict[str, Any]:
    """The fit as a JSON-ready dict (value/unit pairs)."""
    from surfmet.errors import SurfmetInputError
    from surfmet.model import Profile, Topography
    from surfmet.units import quantity

    if shape == "sphere":
        if not isinstance(scan, Topography):
            raise SurfmetInputError("a sphere fit needs an areal scan; for a profile use "
                                    "--shape circle")
        if profile is not None:
            raise SurfmetInputError("--profile applies to --shape circle only")
        from surfmet.fitting import fit_sphere

        f = fit_sphere(scan, loss=loss)
        return {
            "shape": "sphere",
            "radius": quantity(f.radius, "m"),
            "center": quantity(list(f.center), "m"),
            "rms_residual": quantity(f.rms_residual, "m"),
            "radius_uncertainty": quantity(f.radius_uncertainty, "m"),
            "center_uncertainty": quantity(list(f.center_uncertainty), "m"),
            "pv_form_deviation": quantity(f.pv_form_deviation, "m"),
            "n_points": f.n_points,
            "convex": f.convex,
            "loss": loss,
        }
    import numpy as np

    import profiles

    if isinstance(scan, Topography):
        if profile is None:
            raise SurfmetInputError("a circle fit of an areal scan needs --profile row:K "
                                    "or col:K")
        from surfmet.extract import extract_profile

        prof = extract_profile(scan, profile)
    elif isinstance(scan, Profile):
        if profile is not None:
            raise SurfmetInputError("--profile applies to areal scans; this file is a profile")
        prof = scan
    else:  # pragma: no cover
        raise SurfmetInputError(f"cannot fit {type(scan).__name__}")
    f = profiles.fit_circle(np.asarray(prof.positions), np.asarray(prof.z), loss=loss)
    return {
        "shape": "circle",
        "profile": prof.metadata.get("profile"),
        "radius": quantity(f.radius, "m"),
        "center": quantity(list(f.center), "m"),
        "rms_residual": quantity(f.rms_residual, "m"),
        "radius_uncertainty": quantity(f.radius_uncertainty, "m"),
        "center_uncertainty": quantity(list(f.center_uncertainty), "m"),
        "pv_form_deviation": quantity(f.pv_form_deviation, "m"),
        "n_points": f.n_points,
        "loss": loss,
    }


def run(args: argparse.Namespace) -> int:
    import surfmet
    from surfmet.units import format_length

    scan = surfmet.read(args.file)
    rec = {"file": args.file, **fit_record(scan, args.shape, args.profile, args.loss)}
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
    print(f"PV form deviation   {format_length(rec['pv_form_deviation']['value'])}")
    return 0
