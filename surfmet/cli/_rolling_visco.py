"""``surfmet rolling --model viscoelastic|all``: viscoelastic rolling resistance over a load
sweep, and the rolling-friction mechanisms side by side at the paper rotor's ball loads."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import print_solve


def add_visco_arguments(p: argparse.ArgumentParser) -> None:
    """--speed, --loss, --viscoelastic (used by --model viscoelastic and all)."""
    p.add_argument("--speed", default="0.1", metavar="V",
                   help="rolling speed for the viscoelastic model, e.g. 0.1m/s or 100mm/s "
                   "(a bare number is m/s; default 0.1 m/s, the rotor's mid-run speed)")
    p.add_argument("--loss", default=None, metavar="ETA_BALL,ETA_PLATE",
                   help="loss factors tan(delta); each body's SLS puts its loss peak at the "
                   "contact frequency V/a (an upper bound). Default for --model all: the "
                   "materials' typical values (contact.viscoelastic._loss)")
    p.add_argument("--mu", type=float, default=0.3, metavar="M",
                   help="friction coefficient assumed for the micro-slip mechanism of "
                   "--model microslip and all (default 0.3, dry steel on aluminium)")
    p.add_argument("--no-microslip", action="store_true",
                   help="--model all without micro-slip (one 3D frictional solve per load)")
    from surfmet.cli._common import _argtype
    from surfmet.units import parse_surface_energy

    energy = _argtype(parse_surface_energy, "work")
    p.add_argument("--work-of-adhesion", type=energy, default=None, metavar="W",
                   help="--model all: work of adhesion of the adhesion-hysteresis mechanism "
                   "(default for steel on aluminium in air 0.1 J/m², contact.adhesion.rolling)")
    p.add_argument("--adhesion-hysteresis", type=energy, default=None, metavar="DW",
                   help="--model all: w_sep - w_app (default W itself, the upper bound)")
    p.add_argument("--viscoelastic", action="append", default=None,
                   metavar="BODY:Eg=..:Er=..:tau=..",
                   help="a standard linear solid for ball or plate (creep time tau, CONTACT's "
                   "convention; repeat for both bodies)")


def _loss(text: str | None) -> tuple[float, float] | None:
    from surfmet._errors import SurfmetInputError

    if text is None:
        return None
    try:
        a, b = (float(v) for v in text.split(","))
    except ValueError:
        raise SurfmetInputError(f"--loss needs two numbers ETA_BALL,ETA_PLATE, got {text!r}") \
            from None
    return a, b


def run_visco(args: argparse.Namespace) -> int:
    """Dispatch of --model viscoelastic / all."""
    from surfmet.cli._common import emit_json, log, progress
    from surfmet.cli._rolling_contact_visco import speed_value

    n = len(args.loads)
    speed = speed_value(args.speed)
    if args.model == "all":
        from surfmet._errors import SurfmetInputError
        from surfmet.mechanics.viscoelastic_rolling import rolling_mechanisms

        if not (args.mu > 0 and args.mu < float("inf")):
            raise SurfmetInputError("--mu must be a positive number")
        if args.plate or args.ball:
            # the comparison is of the smooth pair; a scan given here would be ignored
            raise SurfmetInputError(
                "--model all sets the mechanisms side by side on the smooth pair and takes no "
                "scans; run --model plastic or hysteresis with PLATE and --ball for the scans")
        rep = rolling_mechanisms(radius=args.radius, materials=args.materials,
                                 loads=args.loads, speed=speed, loss=_loss(args.loss),
                                 hardness=args.hardness, grid=args.grid or 128,
                                 mu=None if args.no_microslip else args.mu,
                                 adhesion=(args.work_of_adhesion, args.adhesion_hysteresis))
        if args.json:
            from surfmet.records._rolling_mechanisms import mechanisms_record

            emit_json(mechanisms_record(rep))
            return 0
        _print_all(rep)
        return 0
    from surfmet.mechanics.viscoelastic_rolling import viscoelastic_rolling

    if not args.viscoelastic and args.loss is None:
        from surfmet._errors import SurfmetInputError

        raise SurfmetInputError("--model viscoelastic needs --viscoelastic BODY:Eg=..:Er=..:"
                                "tau=.. or --loss ETA_BALL,ETA_PLATE")
    rep = viscoelastic_rolling(
        args.plate, args.ball, radius=args.radius, materials=args.materials,
        loads=args.loads, speed=speed, viscoelastic=args.viscoelastic,
        loss=_loss(args.loss), grid=args.grid or 128, spikes=args.spikes,
        progress=lambda it: progress(it, total=n, desc="rolling (viscoelastic)"))
    for note in rep.notes:
        log(f"note: {note}")
    if args.json:
        from surfmet.records._rolling import visco_rolling_record

        emit_json(visco_rolling_record(rep))
        return 0
    _print_sweep(rep.sweep, speed)
    return 0


def _print_sweep(s: Any, speed: float) -> None:
    print(f"model          viscoelastic (steady rolling at {speed:g} m/s)")
    if s.fit is not None:
        lo_ci, hi_ci = s.lambda_ci
        print(f"lambda_eff     {s.lambda_eff:.4f}   {100 * s.fit.confidence:.0f} % CI "
              f"[{lo_ci:.4f}, {hi_ci:.4f}]")
    else:
        print("lambda_eff     not fitted")
    print(f"{'load (N)':>12}{'M_r (N m)':>14}{'mu_r':>12}{'local λ':>10}")
    for w, m, f, lam in zip(s.loads, s.moments, s.forces, s.local_lambda):
        print(f"{w:12.4g}{m:14.4g}{f / w:12.4g}{lam:10.4f}")
    if s.solve is not None:
        print_solve(s.solve)


def _print_all(rep: Any) -> None:
    from surfmet.mechanics.viscoelastic_rolling import reaches_offset
    from surfmet.units import format_quantity

    c = rep.comparison
    ns, n1, n2 = c.rotor_loads
    a = c.assumptions
    print(f"rotor ball loads   symmetric {ns:.3f} N; asymmetric {n2:.3f} N and {n1:.3f} N; "
          f"J + M R² = {c.rolling_inertia:.4g} kg m²")
    print(f"assumed            speed {a['speed']:g} m/s, loss factor ball {a['loss_ball']:g}, "
          f"plate {a['loss_plate']:g} (alpha_h = {a['alpha_h']:.3g}), H = "
          f"{format_quantity(a['hardness'], 'Pa', 3)}, smooth pair")
    for m in c.mechanisms:
        print(f"  {m.name:19s} {m.assumption}")
    v = rep.verdict
    o = v.offset
    print(f"VERDICT            {v.sentence}")
    from surfmet.mechanics.rotor_verdict import label_swap_text

    if label_swap_text(v):
        print(f"labels             {label_swap_text(v)}")
    print(f"group offset       {o.minuend} - {o.subtrahend} = {o.value:+.4f} rad/s²,, "
          f"{o.level:.0%} CI [{o.ci_low:+.4f}, {o.ci_high:+.4f}] (joint model of Table 3, "
          "surfmet rotor paper2022)")
    print(f"{'mechanism':>19}{'M_r(Ns)':>12}{'M_r(N1)':>12}{'M_r(N2)':>12}{'2nd diff':>12}"
          f"{'lambda':>9}{'95 % CI':>19}{'eps_s-eps_a':>13}  reaches the offset?")
    print(f"{'':19}{'N m':>12}{'N m':>12}{'N m':>12}{'N m':>12}")
    for m in c.mechanisms:
        lo_ci, hi_ci = m.sweep.lambda_ci
        ms, m1, m2 = m.rotor_moments
        fit = (f"{m.sweep.lambda_eff:9.4f}   [{lo_ci:.4f}, {hi_ci:.4f}]"
               if m.sweep.fit is not None else f"{'not fitted':>28}")
        print(f"{m.name:>19}{ms:12.4g}{m1:12.4g}{m2:12.4g}{m1 + m2 - 2 * ms:12.3g}{fit}"
              f"{m.delta_eps:13.3g}  {'yes' if reaches_offset(m.delta_eps, o) else 'no'}")
    name, factor = c.dominant()
    print(f"dominant           {name}, {factor:.3g}x the next mechanism")
    from contact.viscoelastic._mechanisms import BOUNDS_ONLY

    top_ranked = next(m for m in c.mechanisms if m.name == name).torque_symmetric
    for m in c.mechanisms:
        if m.name in BOUNDS_ONLY and top_ranked > 0:
            print(f"                   {m.name} (an upper bound, not ranked) reaches "
                  f"{m.torque_symmetric / top_ranked:.3g}x the dominant one")
    top = max(c.mechanisms, key=lambda m: abs(m.delta_eps))
    if top.delta_eps:
        print(f"                   the largest implied difference ({top.name}) is "
              f"{abs(o.value / top.delta_eps):.3g}x smaller than the verdict's offset")
    for m in c.mechanisms:
        if m.sweep.solve is not None:
            print_solve(m.sweep.solve, f"solve {m.name}")
    for note in rep.notes:
        print(f"note: {note}")
