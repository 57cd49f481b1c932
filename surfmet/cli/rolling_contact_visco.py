"""``surfmet rolling-contact ... --viscoelastic BODY:Eg=..:Er=..:tau=.. --speed V``: the
steady viscoelastic rolling solve behind the rolling-contact command (normal problem; with
--mu also the tangential tractions, plane strain or 3D).

Reports the rolling-resistance coefficient (the pressure's moment about the axis over
N R), pmax, the approach, and the leading and trailing contact edges (the contact moves
towards +x; the leading edge is where material enters).
"""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.errors import SurfmetInputError


def add_visco_options(p: argparse.ArgumentParser) -> None:
    """The --viscoelastic option (repeatable: one per body)."""
    p.add_argument("--viscoelastic", action="append", default=None,
                   metavar="BODY:Eg=..:Er=..:tau=..",
                   help="steady rolling on a standard linear solid: BODY ball or plate, "
                   "glassy and relaxed moduli (Pa units), creep time tau_c (s, ms; CONTACT's "
                   "convention: the stress-relaxation time is tau_c Er/Eg); needs --speed; "
                   "repeat for both bodies. Reports the rolling-resistance coefficient, "
                   "pmax, approach and the contact edges; with --mu also the tractions "
                   "(quasi-identical bodies; creepage, fx, stick and slip), "
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
    """Solve and report (text or --json)."""
    from surfmet.cli._common import emit_json, print_solve
    from surfmet.mechanics.viscoelastic_rolling import viscoelastic_rolling_contact

    if getattr(args, "speed", None) is None:
        raise SurfmetInputError("--viscoelastic needs --speed V (m/s)")
    line = bool(getattr(args, "line", False))
    res, tr = viscoelastic_rolling_contact(
        radius=args.radius, load=load_value(args.load, line), materials=args.materials,
        viscoelastic=args.viscoelastic, speed=speed_value(args.speed), line=line,
        grid=getattr(args, "grid", None), plate=getattr(args, "plate", None),
        ball=getattr(args, "ball", None), mu=getattr(args, "mu", None),
        creepage=getattr(args, "creepage", None))
    out = res.to_json()
    if tr is not None:
        out.update(_traction_json(res, tr, line))
        out["traction_solve"] = tr.solve.to_json()
    out["model"] = ("viscoelastic steady rolling, normal problem"
                    + (f" and tangential tractions ({'plane strain' if line else '3D'}, "
                       "quasi-identical bodies)" if tr is not None else " (frictionless)"))
    out["direction"] = "the contact moves towards +x; the leading edge is at larger x"
    if args.json:
        emit_json(out)
        return 0
    per = " per unit length" if line else ""
    print(f"viscoelastic steady rolling at {res.speed:g} m/s, load {res.load:.6g} "
          f"{'N/m' if line else 'N'}{per}")
    print(f"rolling-resistance coefficient  {res.rolling_resistance:.6g}  "
          f"(pressure resultant {res.pressure_offset * 1e6:.4g} µm ahead of the axis)")
    print(f"pmax                            {res.pmax / 1e6:.6g} MPa")
    print(f"approach                        {res.approach * 1e6:.6g} µm"
          + ("  (2D: against a 1 m datum)" if line else ""))
    print(f"leading edge                    {res.leading * 1e6:.6g} µm")
    print(f"trailing edge                   {res.trailing * 1e6:.6g} µm")
    if tr is not None:
        t = _traction_json(res, tr, line)
        print(f"creepage                        {t['creepage']['value']:.6g}")
        print(f"fx                              {t['fx']['value']:.6g} {t['fx']['unit']}")
        if line:
            print(f"stick, slip length              {t['stick_length']['value'] * 1e6:.5g} "
                  f"µm, {t['slip_length']['value'] * 1e6:.5g} µm")
        else:
            print(f"stick, slip area                {t['stick_area']['value'] * 1e12:.5g} "
                  f"µm², {t['slip_area']['value'] * 1e12:.5g} µm²")
    print_solve(res.solve, "normal solve                   ")
    if tr is not None:
        print_solve(tr.solve, "traction solve                 ")
    return 0


def _traction_json(res: Any, tr: Any, line: bool) -> dict[str, Any]:
    """Creepage, force and stick/slip extent of the tractions, with units."""
    sign = {"sign_convention": "creepage (v1 - v2)/V and fx on body 1 (the ball)"}
    if line:
        dx = float(res.x[1] - res.x[0])
        return {"creepage": {"value": tr.creepage, "unit": ""},
                "fx": {"value": tr.force, "unit": "N/m"},
                "stick_length": {"value": float(tr.stick.sum()) * dx, "unit": "m"},
                "slip_length": {"value": float(tr.slip.sum()) * dx, "unit": "m"}, **sign}
    return {"creepage": {"value": tr.creepage.xi, "unit": ""},
            "fx": {"value": tr.fx, "unit": "N"}, "fy": {"value": tr.fy, "unit": "N"},
            "stick_area": {"value": tr.stick_area, "unit": "m^2"},
            "slip_area": {"value": tr.slip_area, "unit": "m^2"}, **sign}

