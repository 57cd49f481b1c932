"""``surfmet spectrum FILE...``: PSD, Hurst exponent, cut-offs, rms values, GW summits; with
several measurements of one surface, their averaged PSD as Persson's theory takes it."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    add_json_flag,
    add_spikes_argument,
    check_output,
    emit_json,
    log,
    pressure,
    save_figure,
)
from surfmet.cli._scan_options import add_scan_options, read_options
from surfmet.cli._values import add_periodic_argument, periodic_flag
from surfmet.cli.scales import add_measurement_arguments

__all__ = ["add_parser", "add_periodic_argument", "periodic_flag"]

EPILOG = """examples:
  surfmet spectrum plate.x3p
  surfmet spectrum plate.x3p --json --plot psd.png
  surfmet spectrum synthetic.npz --periodic yes
  surfmet spectrum plate.x3p --materials steel,aluminium --hardness 0.9GPa

A periodic scan (opposite edges match, or --periodic yes) keeps its mean-removed heights
and is transformed unwindowed; any other scan loses its plane and is Hann-windowed.
Slope, curvature, Nayak's alpha and the summit parameters depend on the scan's
resolution (they grow as the pixel shrinks); h_rms and the Hurst exponent hardly do.

Several FILEs (or a contact.engineering container) are measurements of one surface:
  surfmet spectrum afm.jpk stylus.csv --tip-radius 20nm --json
their profile PSD is averaged as `surfmet scales` does, turned into the isotropic PSD, and
the rms values of the band where it is measured are given with that band, per measurement
and in all, with the band's summit statistics and, with --materials, its plasticity index
(--periodic applies to one scan only).
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "spectrum",
        help="isotropic PSD, Hurst exponent, cut-offs, rms values and GW summit parameters",
        description="Spectral description of an areal scan (Jacobs et al. 2017; Nayak 1971; "
        "McCool 1986).",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("files", nargs="+", metavar="FILE",
                   help="areal scan file; or several measurements of one surface")
    add_periodic_argument(p)
    add_spikes_argument(p)
    p.add_argument("--materials", metavar="A,B", default=None,
                   help="scan and counter-body materials for the plasticity index")
    p.add_argument("--hardness", type=pressure, metavar="P", default=None,
                   help="hardness of the softer body (default: the materials' table value)")
    p.add_argument("--plot", metavar="OUT.png", default=None, help="write the PSD plot")
    add_measurement_arguments(p, 10)
    add_scan_options(p)
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet.cli.scales import read_measurements
    from surfmet.mechanics.spectrum import scan_spectrum
    from surfmet.records._spectrum import spectrum_command_record

    check_output(args.plot, "--plot")
    scans = read_measurements(args.files, **read_options(args))
    if len(scans) > 1:
        return _run_several(args, scans)
    # the facade resolves the materials (surfmet.mechanics.material_spec.scan_pair)
    s, level, preparation = scan_spectrum(scans[0], periodic=periodic_flag(args.periodic),
                                          spikes=args.spikes, materials=args.materials or None,
                                          hardness=args.hardness)
    rec = spectrum_command_record(args.files[0], s, level, preparation)
    if args.plot:
        from surfmet.plots.spectrum import spectrum_figure

        save_figure(spectrum_figure(s, args.plot), args.plot)
    if args.json:
        emit_json(rec)
        return 0
    _print(rec, s)
    return 0


def _run_several(args: argparse.Namespace, scans: list[Any]) -> int:
    """The averaged PSD of several measurements and the rms values of its band."""
    from surfmet.cli.scales import print_all_scales
    from surfmet.mechanics.all_scales import all_scales
    from surfmet.records._all_scales import all_scales_record

    log(f"{len(scans)} measurements from {len(args.files)} file(s)")
    # the facade resolves the materials (with --hardness), before the analysis
    run = all_scales(scans, tip_radius=args.tip_radius, per_decade=args.per_decade,
                     materials=args.materials or None, hardness=args.hardness)
    pair, s = run.pair, run.spectrum
    e_star, hard = (None, None) if pair is None else (pair.e_star, pair.hardness)
    names = [] if pair is None else pair.names
    rec = {"files": args.files, **({"materials": names} if names else {}),
           **all_scales_record(s, e_star=e_star, hardness=hard)}
    if args.periodic != "auto":
        rec["notes"].append("--periodic applies to one scan: the averaged PSD is Hann-windowed")
    if args.plot:
        from surfmet.plots.spectrum import all_scales_figure

        save_figure(all_scales_figure(s, args.plot), args.plot)
    if args.json:
        emit_json(rec)
        return 0
    print_all_scales(rec)
    return 0


def _print(rec: dict[str, Any], s: Any) -> None:
    from surfmet.units import format_length, format_quantity

    def wl(q: float | None) -> str:
        import math

        return "none" if not q else f"{format_length(2 * math.pi / q)} (q = {q:.4g} rad/m)"

    print(f"file  {rec['file']}")
    prep = rec["scan_preparation"]
    for note in prep["notes"]:
        print(f"  scan: {note}")
    print(f"  {'periodic, unwindowed' if s.periodic else 'not periodic, Hann window'}"
          f" (levelling: {rec['levelling']})")
    lo, hi = s.hurst.q_range
    print(f"  Hurst H          {s.hurst.hurst:.4f}  fitted on q = {lo:.4g}..{hi:.4g} rad/m")
    print(f"  roll-off         {wl(s.roll_off)}")
    print(f"  short cut-off    {wl(s.short_cutoff)}")
    if s.noise_floor:
        print(f"  noise floor from {wl(s.noise_floor)} (not fitted)")
    print(f"  h_rms            {format_length(s.h_rms)} (spectrum), "
          f"{format_length(s.h_rms_real)} (real space)")
    print(f"  h'_rms *         {s.slope_rms:.5g} (spectrum), {s.slope_rms_real:.5g} (real space)")
    # in the unit the all-scales summary and Spc use (the one formatter's 1/µm)
    print(f"  curvature rms *  {format_quantity(s.curvature_rms, '1/m', 5)} (spectrum), "
          f"{format_quantity(s.curvature_rms_real, '1/m', 5)} (real space)")
    sm = s.summits
    print(f"  Nayak alpha *    {sm.alpha:.4g}")
    print(f"  summits *        density {format_quantity(sm.density, '1/m^2', 5)}, radius "
          f"{format_length(sm.radius)}, sigma_s {format_length(sm.sigma_s)}")
    if s.plasticity is not None:
        print(f"  plasticity psi * {s.plasticity:.4g}")
    for note in rec["notes"]:
        print(f"  note: {note}")
    for caveat in rec["caveats"]:
        print(f"  CAVEAT: {caveat}")
    log("  * depends on the scan's resolution (grows as the pixel shrinks)")
