"""``surfmet show FILE -o view.png``: a picture of a scan (3D, 2D height map, or profile)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from surfmet.cli._common import add_json_flag, check_output, emit_json, log
from surfmet.cli._roughness_options import add_roughness_options, roughness_options
from surfmet.cli._scan_options import add_scan_options, print_caveats, read_scan, scan_caveats

EPILOG = """examples:
  surfmet show plate.x3p -o plate.png
  surfmet show plate.x3p -o plate_map.png --2d
  surfmet show plate.x3p -o plate.png --exaggeration 500 --size 1600x1200
  surfmet show ball.nms -o ball.png --level sphere
  surfmet show trace.csv -o trace.png            (a profile: primary, waviness, roughness)
  surfmet show plate.x3p -o plate.pdf --2d --json

The 3D view is rendered off-screen with pyvista (no display needed) and saved as PNG;
heights are exaggerated by a round factor written in the picture. --2d draws a matplotlib
height map (colour bar in µm, scale bar), saved in any format matplotlib knows (png, pdf,
svg).

The picture is of the surface surfmet roughness evaluates, with the same options and
defaults (below): the same form removal (default plane, a line on profiles, none for an
instrument's R-profile), the same S/L filters and, for a profile, the λc, λs, standard and
sampling lengths its file states; nothing is levelled or filtered a second time. --json
states what was drawn and its numbers: the surfmet roughness record of the drawn surface
(the profile view's legend shows its Ra and Rq).
"""


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"size {text!r} must be WIDTHxHEIGHT, e.g. 1200x900"
                                         ) from None
    if not (64 <= w <= 8192 and 64 <= h <= 8192):
        raise argparse.ArgumentTypeError(f"size {text!r}: each side must be 64..8192 pixels")
    return w, h


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "show",
        help="render a scan: 3D view (pyvista) or 2D height map / profile plot (matplotlib)",
        description="Render a scan to an image file: a shaded 3D surface coloured by height, "
        "a 2D height map with colour bar and scale (--2d), or, for a profile, the primary, "
        "waviness and roughness profiles.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("file", help="scan file")
    add_scan_options(p)
    p.add_argument("-o", "--output", required=True, metavar="IMAGE", help="image to write")
    p.add_argument("--2d", dest="two_d", action="store_true",
                   help="matplotlib height map instead of the 3D view")
    p.add_argument("--format", help="force a reader (see 'surfmet formats')")
    p.add_argument("--exaggeration", type=float, default=None, metavar="X",
                   help="vertical exaggeration of the 3D view (default: automatic)")
    p.add_argument("--cmap", default="viridis", help="matplotlib colormap (default viridis)")
    p.add_argument("--size", type=_size, default=(1200, 900), metavar="WxH",
                   help="3D image size in pixels (default 1200x900)")
    p.add_argument("--max-points", type=int, default=300_000, metavar="N",
                   help="decimate larger scans to about N points for the 3D view")
    add_roughness_options(p, what="draw")
    add_json_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet._errors import SurfmetInputError
    from surfmet.roughness import roughness

    out = Path(args.output)
    check_output(out, "-o")
    _check_picture(args)
    scan = read_scan(args.file, args)
    profile_view = scan.kind == "profile" or args.profile is not None
    if not (profile_view or args.two_d) and out.suffix.lower() != ".png":
        raise SurfmetInputError(f"the 3D view is written as PNG; name the output "
                                f"*.png (got {out.name}), or use --2d for pdf/svg")
    # the surface surfmet roughness evaluates, with its options: one file, one answer
    res = roughness(scan, **roughness_options(args))
    drawn = _measurement_drawn(scan)
    rec: dict[str, Any] = {"file": args.file, "output": str(out),
                           "caveats": scan_caveats(scan)}
    if drawn:
        rec["measurement"] = drawn
    if res.kind == "profile":
        if not args.two_d:
            log("surfmet: a profile has no 3D view; drawing its profiles")
        rec.update(view="profile", shown=["Ra", "Rq"])
        _draw_profile(res, out, Path(args.file).name)
    elif args.two_d:
        from surfmet.plots._style import close
        from surfmet.plots.areal import height_map

        fig = height_map(res.surface, cmap=args.cmap)
        _save(fig, out)
        close(fig)
        rec.update(view="2d", shown=[])
    else:
        from surfmet._render import render_3d

        img = render_3d(res.surface, out, exaggeration=args.exaggeration, cmap=args.cmap,
                        window_size=args.size, max_points=args.max_points)
        rec.update(view="3d", size=[int(img.shape[1]), int(img.shape[0])], shown=[])
    # named as the roughness command names the record of the same surface
    from surfmet.records._roughness import roughness_record

    rec["roughness"] = {"file": drawn["name"] if drawn else args.file, "status": "ok",
                        **roughness_record(res)}
    if args.json:
        emit_json(rec)
    else:
        log(f"wrote {out}")
        if drawn:
            log(f"note: drew measurement {drawn['index'] + 1} of {drawn['of']} of the "
                f"container ({drawn['name']}); --channel N|NAME draws another")
        print_caveats(rec["caveats"], sys.stderr)
    return 0


def _measurement_drawn(scan: Any) -> dict[str, Any] | None:
    """Which measurement of a container the view draws (None for a lone scan): its name
    ``CONTAINER:MEMBER`` (that of its roughness record), index and the container's count."""
    md = scan.metadata
    if "container" not in md or "member" not in md:
        return None
    return {"name": f"{md['container']}:{md['member']}", "index": int(md["measurement"]),
            "of": len(md.get("channels") or ()) or 1}


def _check_picture(args: argparse.Namespace) -> None:
    """Refuse, before the scan is read, a colormap matplotlib does not have and an output
    name whose suffix names no format it writes (the 3D view: PNG only), in the words the
    user gave."""
    import matplotlib as mpl
    from matplotlib.backend_bases import FigureCanvasBase

    from surfmet._errors import SurfmetInputError

    if args.cmap not in mpl.colormaps:
        names = sorted(n for n in mpl.colormaps if not n.endswith("_r"))
        raise SurfmetInputError(f"--cmap {args.cmap!r} is not a colormap; one of "
                                f"{', '.join(names)} (each also reversed, as NAME_r)")
    suffix = Path(args.output).suffix.lower().lstrip(".")
    formats = sorted(FigureCanvasBase.get_supported_filetypes())
    if not suffix or suffix not in formats:
        what = "has no suffix" if not suffix else f"ends in .{suffix}, not an image format"
        raise SurfmetInputError(
            f"-o {args.output}: {what}; name the picture with one of .{', .'.join(formats)} "
            "(the 3D view: .png)")


def _draw_profile(res: Any, out: Path, name: str) -> None:
    """The primary / waviness / roughness figure of the analysis behind ``res``."""
    from surfmet.plots._style import close
    from surfmet.plots.profile import profile_figure

    fig = profile_figure(res.analysis, title=name)
    _save(fig, out)
    close(fig)


def _save(fig: Any, out: Path) -> None:
    from surfmet._errors import SurfmetInputError
    from surfmet.plots._style import save

    try:
        save(fig, out, dpi=120)
    except ValueError as exc:  # matplotlib: unknown extension
        raise SurfmetInputError(f"cannot write {out.name}: {exc}") from None
