"""``surfmet flat-contact FILE...``: the scan on a flat, BEM against Persson, GW and BGT;
with several measurements of one surface, Persson's theory from their averaged PSD too."""

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
from surfmet.cli._scan_options import add_scan_options, read_options
from surfmet.cli._values import (
    VALUES_METAVAR,
    add_interaction_argument,
    add_plate_argument,
    pressures,
    require_plate,
    values_help,
)
from surfmet.cli.scales import add_measurement_arguments, print_all_scales, read_measurements
from surfmet.cli.spectrum import add_periodic_argument, periodic_flag

EPILOG = """examples:
  surfmet flat-contact plate.x3p --materials steel,aluminium --pressures 1MPa:100MPa:5
  surfmet flat-contact plate.x3p --materials aluminium --pressures 10MPa,50MPa --json
  surfmet flat-contact synthetic.npz --e-star 1GPa --pressures 1MPa:30MPa:4 --plot fc.png
  surfmet flat-contact plate.x3p --materials steel,aluminium --hardness 0.9GPa \\
      --pressures 20MPa --periodic no

  surfmet flat-contact afm.jpk stylus.csv --e-star 70GPa --pressures 10MPa --tip-radius 20nm
  surfmet flat-contact surface.zip --materials steel,aluminium --pressures 1MPa:100MPa:3

--materials A presses the scan (material A) on a rigid flat; A,B on an elastic flat of B.
The BEM is periodic when the scan is (opposite edges match, or --periodic yes) and has a
free boundary otherwise; the output says which. Errors are model/BEM - 1.

With --work-of-adhesion W --range RHO the scan is also pressed with adhesion
(--interaction dugdale, the default, tension w/h0 up to the gap h0 = RHO, its step
smoothed on the pixel; or exponential, t(g) = (w/rho) exp(-g/rho)) at each pressure,
beside the non-adhesive BEM: the contact area fraction (gap zero), the mean gap and the
attractive pressure (the law's tension averaged over the nominal area, touching points
included; the nominal pressure is the repulsive mean minus it). The adhesive solve is
periodic and elastic: a non-periodic scan needs --periodic yes, and --hardness is
refused. With several FILEs it runs on the BEM's map.
  surfmet flat-contact synthetic.npz --e-star 1GPa --pressures 0.1MPa:1MPa:3 \
      --work-of-adhesion 50mJ/m2 --range 5nm

Several FILEs (or a contact.engineering container) are measurements of one surface: their
profile PSD is averaged as `surfmet scales` does (each where it is reliable), turned into
the isotropic PSD and Persson's theory is evaluated on it over the band where it is
measured (stated). The BEM needs one height map: it runs on the first areal map named
(as for one file, with GW and BGT on that map's spectrum), and is left out when there is
none.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "flat-contact",
        help="a scan pressed on a flat: boundary elements vs Persson, GW and BGT",
        description="Nominally flat contact of a rough scan: area, mean gap, stiffness and "
        "clusters from the BEM, and the error of each rough-contact theory against it.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_plate_argument(p, "areal scan of the rough surface; or several measurements of it",
                       several=True, dest="files")
    mod = p.add_mutually_exclusive_group(required=True)
    mod.add_argument("--materials", metavar="A[,B]", help="scan material [, flat material]")
    mod.add_argument("--e-star", type=pressure, metavar="E", help="composite modulus E*")
    p.add_argument("--pressures", type=pressures, required=True, metavar=VALUES_METAVAR,
                   help=values_help("nominal pressures", "1MPa,5MPa"))
    p.add_argument("--hardness", type=pressure, metavar="H", default=None,
                   help="cap the BEM pressure at H (elastic-perfectly-plastic)")
    add_periodic_argument(p)
    add_spikes_argument(p)
    p.add_argument("--stiffness", choices=("curve", "solve"), default="curve",
                   help="BEM stiffness from the slope of the computed ln p(ū) curve (default, "
                   "no extra solve) or from one more solve at p(1+1%%) per pressure")
    p.add_argument("--plot", metavar="OUT.png", default=None,
                   help="plot A/A0 and the mean gap against p for all four")
    add_adhesion_arguments(p)
    add_measurement_arguments(p, 10)
    add_scan_options(p)
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def add_adhesion_arguments(p: argparse.ArgumentParser) -> None:
    """--work-of-adhesion, --range and --interaction of an adhesive flat contact."""
    from surfmet.units import parse_surface_energy

    g = p.add_argument_group("adhesion (a periodic scan, elastic)")
    g.add_argument("--work-of-adhesion", type=_argtype(parse_surface_energy, "work"),
                   metavar="W", help="also press with adhesion of this work, e.g. 50mJ/m2")
    g.add_argument("--range", type=positive_length, metavar="RHO", dest="range_",
                   help="interaction range (rho of the exponential law, h0 = w/sigma0 of "
                   "the Dugdale law), e.g. 2nm; needed with --work-of-adhesion")
    add_interaction_argument(g)


def adhesion_law(args: argparse.Namespace) -> Any:
    """The adhesion law the arguments ask for (:mod:`surfmet.cli._laws`: the law
    ``--interaction`` names, of its parameters), or None where no law parameter is given."""
    from surfmet._errors import SurfmetInputError
    from surfmet.cli._laws import interaction_from_arguments

    work = getattr(args, "work_of_adhesion", None)
    if work is not None and not work > 0:
        raise SurfmetInputError(f"--work-of-adhesion must be positive, got {work!r} J/m²")
    return interaction_from_arguments(args, optional=True)


def run(args: argparse.Namespace) -> int:
    from surfmet._batch import progress_bar
    from surfmet._errors import SurfmetInputError
    from surfmet.mechanics.flat_contact import flat_contact, plot
    from surfmet.records import flat_contact_record

    require_plate(args.files, "flat-contact", "FILE")
    pressures = sorted(set(args.pressures))
    law = adhesion_law(args)
    check_output(args.plot, "--plot")
    if args.e_star is not None and not args.e_star > 0:
        raise SurfmetInputError(f"--e-star must be positive, got {args.e_star!r}")
    scans = read_measurements(args.files, **read_options(args))
    if len(scans) > 1:
        return _run_several(args, scans, pressures, law)
    bar = progress_bar(len(pressures), "flat-contact, pressures", show_progress(args))
    # the facade resolves --materials or --e-star (surfmet.mechanics.material_spec.scan_pair);
    # the BEM stays elastic unless --hardness is given
    rep = flat_contact(scans[0], materials=args.materials, e_star=args.e_star,
                       pressures=pressures, hardness=args.hardness,
                       periodic=periodic_flag(args.periodic), stiffness=args.stiffness,
                       progress=lambda done, total: bar.update(1), spikes=args.spikes,
                       adhesion=law)
    bar.close()
    names = [] if rep.materials is None else rep.materials.names
    rec = {"file": args.files[0], **({"materials": names} if names else {}),
           **flat_contact_record(rep)}
    if args.plot:
        save_figure(plot(rep, args.plot), args.plot)
    if args.json:
        emit_json(rec)
        return 0
    _print(rec)
    return 0


def _run_several(args: argparse.Namespace, scans: list[Any], pressures: Any, law: Any) -> int:
    """Persson from the averaged PSD of all measurements; the BEM on the first map."""
    from surfmet._batch import progress_bar
    from surfmet._model import Topography
    from surfmet.mechanics.all_scales import all_scales
    from surfmet.mechanics.flat_contact import flat_contact, plot
    from surfmet.records import flat_contact_record
    from surfmet.records._all_scales import all_scales_record

    log(f"{len(scans)} measurements from {len(args.files)} file(s)")
    # the facade resolves --materials or --e-star once, before the analysis
    run = all_scales(scans, tip_radius=args.tip_radius, per_decade=args.per_decade,
                     materials=args.materials, e_star=args.e_star, hardness=args.hardness,
                     pressures=pressures)
    pair, a, s, curve = run.pair, run.analysis, run.spectrum, run.curve
    e_star, names = pair.e_star, pair.names
    first = next((k for k, m in enumerate(scans) if isinstance(m, Topography)), None)
    rep = None
    rec: dict[str, Any] = {"files": args.files, **({"materials": names} if names else {}),
                           "all_scales": all_scales_record(s, curve, e_star)}
    if first is None:
        rec["bem_scan"] = None
        rec["all_scales"]["notes"].append("no BEM: none of the measurements is a height map")
    else:
        bar = progress_bar(len(pressures), "flat-contact, pressures", show_progress(args))
        rep = flat_contact(scans[first], materials=pair, pressures=pressures,
                           hardness=args.hardness,
                           periodic=periodic_flag(args.periodic), stiffness=args.stiffness,
                           progress=lambda done, total: bar.update(1), spikes=args.spikes,
                           adhesion=law)
        bar.close()
        rec["bem_scan"] = {"file": a.measurements[first].file, **flat_contact_record(rep)}
        rec["all_scales"]["notes"].append(
            f"the BEM, GW and BGT see only {a.measurements[first].file} (its own band); "
            "Persson in all_scales sees every measurement's band")
    if args.plot:
        save_figure(plot(rep, args.plot, all_scales=curve), args.plot)
    if args.json:
        emit_json(rec)
        return 0
    if rep is not None:
        print(f"BEM on {rec['bem_scan']['file']}:")
        _print({"file": rec["bem_scan"]["file"], **rec["bem_scan"]})
    print_all_scales(rec["all_scales"])
    return 0


def _print(rec: dict[str, Any]) -> None:
    from surfmet.units import format_quantity

    print(f"file  {rec['file']}")
    prep = rec["scan_preparation"]
    spikes = ("spikes kept (--spikes keep)" if prep["spikes"] == "keep" else
              f"spikes removed ({prep['spikes_removed']['scan']})")
    print(f"  scan: {spikes}, {100 * prep['filled_fraction']['value']:.3g} % of the points "
          "filled")
    g = rec["grid"]
    print(f"  {rec['boundary']} boundary, levelling {rec['levelling']}, "
          f"{g['nx']} x {g['ny']} cells, "
          f"E* = {format_quantity(rec['e_star']['value'], 'Pa')}, "
          f"h'_rms = {rec['spectrum']['slope_rms']['spectrum']['value']:.4g}")
    print(f"  {'p (MPa)':>9} {'model':>8} {'A/A0':>10} {'kappa':>7} {'gap (µm)':>9} "
          f"{'K (MPa/µm)':>11} {'err A':>8} {'err gap':>8}")
    for r in rec["results"]:
        pm = r["pressure"]["value"] / 1e6
        b = r["bem"]
        gap, k = b["mean_gap"]["value"], b["stiffness"]["value"]
        print(f"  {pm:9.4g} {'BEM':>8} {b['area_fraction']:10.4g} {b['kappa']:7.3f} "
              f"{'-' if gap is None else f'{gap * 1e6:.4g}':>9} "
              f"{'-' if k is None else f'{k / 1e12:.4g}':>11}"
              f"   clusters {b['n_clusters']}, corrected A/A0 {b['corrected_area_fraction']:.4g}")
        for name in ("persson", "gw", "bgt"):
            m = r[name]
            gap = m["mean_gap"]["value"]
            k = m["stiffness"]["value"]
            ea, eg = m["relative_error"]["area_fraction"], m["relative_error"]["mean_gap"]
            print(f"  {'':9} {name:>8} {m['area_fraction']:10.4g} {m['kappa']:7.3f} "
                  f"{'-' if gap is None else f'{gap * 1e6:.4g}':>9} "
                  f"{'-' if k is None else f'{k / 1e12:.4g}':>11} "
                  f"{'-' if ea is None else f'{100 * ea:+.1f}%':>8} "
                  f"{'-' if eg is None else f'{100 * eg:+.1f}%':>8}")
    print_solve(rec["solve"], "  solve", warned=rec["notes"])  # the edge: once, a note
    if "adhesion" in rec:
        _print_adhesion(rec)
    for note in rec["notes"]:
        log(f"  note: {note}")
    for caveat in rec["caveats"]:
        print(f"  CAVEAT: {caveat}")


def _print_adhesion(rec: dict[str, Any]) -> None:
    """The adhesive solve beside the non-adhesive one, per pressure."""
    from surfmet.units import format_length, format_quantity, readable_quantities

    ad = rec["adhesion"]
    print(f"  adhesion: {ad['interaction']} law, w = "
          f"{format_quantity(ad['work_of_adhesion']['value'], 'J/m^2')}, range "
          f"{format_length(ad['range']['value'])}, peak tension "
          f"{format_quantity(ad['peak_tension']['value'], 'Pa')} (periodic solve)")
    if ad["step_smoothing"]["value"] > 0.0:
        scale = ("the pixel's scale, capped at the range"
                 if ad["step_smoothing"]["value"] >= ad["range"]["value"] else "the pixel's scale")
        print(f"  {ad['interaction'].capitalize()} step smoothed over "
              f"{format_length(ad['step_smoothing']['value'], 3)} of "
              f"gap ({scale}: removes the pixels' pinning of the zone's end)")
    # the gaps in µm, as the non-adhesive table's 'gap (µm)'
    print(f"  {'p (MPa)':>9} {'A/A0 bare':>10} {'A/A0 adh':>10} {'gap bare (µm)':>14} "
          f"{'gap adh (µm)':>13} {'attractive (MPa)':>17}")
    for r in rec["results"]:
        a, b = r["adhesive"], r["bem"]
        print(f"  {r['pressure']['value'] / 1e6:9.4g} {b['area_fraction']:10.4g} "
              f"{a['contact_area_fraction']['value']:10.4g} "
              f"{b['mean_gap']['value'] * 1e6:14.4g} {a['mean_gap']['value'] * 1e6:13.4g} "
              f"{a['attractive_pressure']['value'] / 1e6:17.4g}")
    print_solve(ad["solve"], "  solve")
    for w in ad["warnings"]:
        print(f"  WARNING: {readable_quantities(w)}")
