"""``surfmet rolling-contact ... --viscoelastic BODY:Eg=..:Er=..:tau=.. --speed V``: the
steady viscoelastic rolling solve behind the rolling-contact command (normal problem; with
--mu also the tangential tractions: 3D with a dissimilar pair's coupling taken one way,
plane strain for quasi-identical bodies).

The record and the text are those of the elastic command (the same names, grid line and
sign convention, :func:`surfmet.cli._rolling_contact_text.print_summary`), plus the
viscoelastic ones: the pressure's offset ahead of the axis and the leading and trailing
contact edges. Free rolling of a dissimilar roller (plane strain, no coupled solve) is
reported as not solved, with the reason
(:mod:`surfmet.mechanics.viscoelastic_rolling_contact`).
"""

from __future__ import annotations

import argparse
from typing import Any

from surfmet._errors import SurfmetInputError


def add_visco_options(p: argparse.ArgumentParser) -> None:
    """The --viscoelastic option (repeatable: one per body)."""
    p.add_argument("--viscoelastic", action="append", default=None,
                   metavar="BODY:Eg=..:Er=..:tau=..",
                   help="steady rolling on a standard linear solid: BODY ball or plate, "
                   "glassy and relaxed moduli (Pa units), creep time tau_c (s, ms; CONTACT's "
                   "convention: the stress-relaxation time is tau_c Er/Eg); needs --speed; "
                   "repeat for both bodies. Reports the rolling-resistance coefficient, "
                   "pmax, approach and the contact edges; with --mu also the tractions "
                   "(creepage, fx, stick and slip; a dissimilar ball's coupling one way; "
                   "free rolling of a dissimilar roller, with --line, is not solved), "
                   "e.g. --viscoelastic plate:Eg=3GPa:Er=1GPa:tau=1ms")


def load_value(text: Any, line: bool) -> float:
    """A load in N, or with ``line`` a load per length in N/m (``100N/mm``)."""
    from surfmet.mechanics.rolling_contact import parse_line_load
    from surfmet.units import parse_force

    if isinstance(text, (int, float)):
        return float(text)
    return parse_line_load(text) if line else parse_force(str(text))


def speed_value(value: Any) -> float:
    """V in m/s, positive, from a speed with or without its unit (``1m/s``, ``50mm/s``,
    ``0.1``; :func:`surfmet.units.parse_speed`)."""
    from surfmet.units import parse_speed

    v = value if isinstance(value, float) else parse_speed(str(value))
    if not v > 0:
        raise SurfmetInputError(f"--speed must be positive (m/s), got {value!r}")
    return v


def run_viscoelastic(args: argparse.Namespace) -> int:
    """Solve and report (text or --json), in the elastic command's layout
    (:func:`surfmet.cli._rolling_contact_text.print_summary`)."""
    from surfmet.cli._common import emit_json
    from surfmet.mechanics.viscoelastic_rolling_contact import viscoelastic_rolling_contact
    from surfmet.records._rolling_contact import visco_rolling_contact_record

    if getattr(args, "speed", None) is None:
        raise SurfmetInputError("--viscoelastic needs --speed V (m/s)")
    line = bool(getattr(args, "line", False))
    vc = viscoelastic_rolling_contact(
        radius=args.radius, load=load_value(args.load, line), materials=args.materials,
        viscoelastic=args.viscoelastic, speed=speed_value(args.speed), line=line,
        grid=getattr(args, "grid", None), plate=getattr(args, "plate", None),
        ball=getattr(args, "ball", None), mu=getattr(args, "mu", None),
        creepage=getattr(args, "creepage", None))
    rec = visco_rolling_contact_record(vc)
    if args.json:
        emit_json(rec)
        return 0
    from surfmet.cli._rolling_contact_text import print_summary

    print_summary(rec)
    return 0
