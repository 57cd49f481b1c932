"""``surfmet scales FILE...``: scale-dependent roughness of one surface from several
measurements (contact.engineering's analysis; Sanner et al. 2022)."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, check_output, emit_json, length, log, save_figure
from surfmet.cli._scan_options import (
    add_scan_options,
    print_caveats,
    read_options,
    scan_caveats,
)

EPILOG = """examples:
  surfmet scales surface.zip
  surfmet scales afm.jpk stylus.csv --tip-radius 20nm --json
  surfmet scales surface.zip --per-decade 10 --plot scales.png

FILE is a scan file or a contact.engineering container (a zip with meta.yml), whose
measurements all count. Each measurement contributes where it is reliable: above its
pixel and its tip-radius cut-off (the radius its file states, else --tip-radius), below its
size; the surface's value at a distance is the mean over the measurements contributing
there, one vote each. Distances run on the grid 10^(j/N) m.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "scales",
        help="scale-dependent rms slope and curvature, ACF, variable bandwidth and PSD of "
        "several measurements of one surface",
        description="Scale-dependent statistics averaged over measurements (Sanner et al. "
        "2022, Appl. Surf. Sci. Adv. 7:100190; as contact.engineering computes them).",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("files", nargs="+", metavar="FILE", help="scan files or containers")
    add_measurement_arguments(p, 5)
    p.add_argument("--direction", choices=("x", "y", "both"), default="x",
                   help="axis of a map's derivatives: x (rows, default), y (columns), or "
                   "both (the two axes' slope and curvature variances added, as "
                   "SurfaceTopography hands x and y to the statistic)")
    add_scan_options(p)
    p.add_argument("--plot", metavar="OUT.png", default=None,
                   help="write the figure (one curve per measurement and the average)")
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def add_measurement_arguments(p: argparse.ArgumentParser, per_decade: int) -> None:
    """``--tip-radius`` and ``--per-decade`` (shared by scales, spectrum and flat-contact)."""
    p.add_argument("--tip-radius", type=length, metavar="R", default=None,
                   help="probe tip radius for measurements whose file states none (e.g. 20nm)")
    p.add_argument("--per-decade", type=int, metavar="N", default=per_decade,
                   help=f"points per decade of the distance grid (default {per_decade})")


def read_measurements(files: list[str], **read_options: Any) -> list[Any]:
    """Every measurement of every FILE (containers give all of theirs, unless ``channel=``
    picks one), read with ``read_options`` (:func:`surfmet.read`'s ``height_unit=``,
    ``dx=``, ``dy=``, ``channel=``)."""
    from pathlib import Path

    import surfmet
    from surfmet.io._calibration import state_units
    from surfmet.io.container import _is_container, read_container

    units = {k: v for k, v in read_options.items() if k != "channel"}
    out = []
    for f in files:
        head = Path(f).read_bytes()[:4] if Path(f).is_file() else b""
        if (head == b"PK\x03\x04" and read_options.get("channel") is None
                and _is_container(Path(f).read_bytes())):
            out.extend(state_units(s, f"{f}:{s.metadata.get('member')}", **units)
                       for s in read_container(f))
        else:
            out.append(surfmet.read(f, **read_options))
    return out


def run(args: argparse.Namespace) -> int:
    from surfmet.records._scales import scales_record
    from surfmet.scale_dependent import analyze_scales

    check_output(args.plot, "--plot")
    scans = read_measurements(args.files, **read_options(args))
    log(f"{len(scans)} measurement(s) from {len(args.files)} file(s)")
    a = analyze_scales(scans, tip_radius=args.tip_radius, per_decade=args.per_decade,
                       direction=args.direction)
    rec = {"files": args.files, **scales_record(a), "caveats": scan_caveats(*scans)}
    if args.plot:
        from surfmet.plots.scales import scales_figure

        save_figure(scales_figure(a, args.plot), args.plot)
    if args.json:
        emit_json(rec)
        return 0
    _print(a)
    print_caveats(rec["caveats"])
    return 0


def _print(a: Any) -> None:
    import numpy as np

    from surfmet.scale_dependent import DIRECTION_WORDS
    from surfmet.units import format_length

    print(f"derivatives {DIRECTION_WORDS[a.direction]}")
    for m in a.measurements:
        cut = format_length(m.cutoff) if m.cutoff is not None else (
            "none, every scale reliable" if m.tip_radius else "none")
        print(f"{m.file}  {m.kind}, pixel {format_length(m.pixel)}, size "
              f"{format_length(m.size)}, cut-off {cut} ({m.cutoff_source})")
    votes = a.contributors("slope")
    print(f"{'distance':>12} {'rms slope':>11} {'rms curv. 1/m':>14}  contributors")
    for j, d in enumerate(a.distance):
        if not np.isfinite(a.rms_slope[j]) and not np.isfinite(a.rms_curvature[j]):
            continue
        who = ",".join(str(i + 1) for i in np.flatnonzero(votes[:, j])) or "-"
        print(f"{format_length(d):>12} {a.rms_slope[j]:11.4g} {a.rms_curvature[j]:14.4g}  {who}")
    band = a.psd_band()
    if band:
        print(f"PSD measured over q = {band[0]:.4g}..{band[1]:.4g} rad/m (periodic Hann "
              f"window, {a.psd_per_decade} bins per decade)")


def print_all_scales(r: dict[str, Any]) -> None:
    """Text of an all-scales record: bands, rms values and Persson (when present)."""
    from surfmet.units import format_length, format_quantity

    def band(b: dict[str, Any]) -> str:
        w = b["wavelength"]["value"]
        return "none" if w is None else (f"wavelengths {format_length(w[0])}..{format_length(w[1])}"
                                         f" (q = {b['q']['value'][0]:.4g}..{b['q']['value'][1]:.4g}"
                                         " rad/m)")

    print("all scales: PSD averaged over the measurements (profile PSD -> isotropic)")
    for i, m in enumerate(r["measurements"]):
        print(f"  [{i + 1}] {m['file']}  {m['kind']}, contributes over {band(m['psd_band'])}")
    print(f"  measured band  {band(r['psd']['measured_band'])}")
    h = r["hurst"]
    print(f"  h_rms {format_length(r['h_rms']['value'])}, h'_rms {r['slope_rms']['value']:.5g}, "
          f"curvature rms {format_quantity(r['curvature_rms']['value'], '1/m', 5)}"
          + ("" if h is None else f", Hurst H {h['value']:.4f}") + " (of the band)")
    if r.get("summits"):
        sm = r["summits"]
        print(f"  Nayak alpha {sm['nayak_alpha']:.4g}, summits: density "
              f"{sm['density']['value'] * 1e-6:.5g} 1/mm², radius "
              f"{format_length(sm['radius']['value'])}"
              + (f", plasticity psi {r['plasticity_index']:.4g}" if "plasticity_index" in r
                 else ""))
    if "persson" in r:
        print(f"  {'p (MPa)':>9} {'A/A0':>10} {'kappa':>7} {'gap (µm)':>9} {'K (MPa/µm)':>11}"
              "   Persson, all scales")
        for row in r["persson"]:
            print(f"  {row['pressure']['value'] / 1e6:9.4g} {row['area_fraction']:10.4g} "
                  f"{row['kappa']:7.3f} {row['mean_gap']['value'] * 1e6:9.4g} "
                  f"{row['stiffness']['value'] / 1e12:11.4g}")
    for note in r["notes"]:
        log(f"  note: {note}")
