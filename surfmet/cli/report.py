"""``surfmet report FILE... -o report.html``: one self-contained HTML report."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import (
    add_json_flag,
    add_quiet_flag,
    check_output,
    emit_json,
    force,
    log,
    positive_length,
    show_progress,
)
from surfmet.cli._roughness_options import add_roughness_options, roughness_options
from surfmet.cli._scan_options import add_scan_options, read_bodies, read_options

EPILOG = """examples:
  surfmet report plate.x3p -o report.html
  surfmet report scans/*.nms -o lab.html --level poly:2 --lc 0.25mm --ls 2.5um
  surfmet report trace.csv -o trace.html                 (a profile: R-parameters)
  surfmet report plate.nms -o hertz.html --radius 10mm --load 4.7N \\
      --materials steel,aluminium --ball ball.nms
  surfmet report scans/*.x3p -o quick.html --no-3d --json

The page holds, per scan: the instrument metadata, the parameter table with units and
the filters used, the 3D view, height map, Abbott-Firestone curve and PSD (profile plots
for a profile), and with --radius, --load and --materials the Hertz check. Pictures are
embedded (data URIs): the single file opens offline. A container's measurements each get
a section (CONTAINER:MEMBER, as surfmet roughness names its records). A scan that fails
gets its error in the page (the others are reported all the same) and the exit status
is 1.

Every number is the one the commands give for the same file and options: the parameters
are surfmet roughness's (the evaluation options below are its options, with its defaults:
a profile keeps the λc, λs, standard and sampling lengths its file states), the PSD is
surfmet spectrum's and the Hertz check surfmet hertz-check's. --json prints, per scan, the
records those commands emit (info, roughness, spectrum, hertz_check).
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "report",
        help="self-contained HTML report: metadata, parameters, pictures, Hertz check",
        description="Evaluate scans and write one HTML file with everything embedded.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("files", nargs="+", metavar="FILE", help="scan file(s)")
    p.add_argument("-o", "--output", required=True, metavar="HTML", help="report to write")
    p.add_argument("--title", default="surfmet report", help="page title")
    add_roughness_options(p)
    p.add_argument("--no-3d", dest="no_3d", action="store_true",
                   help="leave out the 3D views (faster)")
    p.add_argument("--rotor", metavar="TABLE", help="put the rotor verdict on a frame table "
                   "first (as 'surfmet rotor TABLE'; 'paper2022' for the paper's Table 3)")
    p.add_argument("--rig", metavar="RIG.json", help="the rotor's rig, with --rotor")
    hz = p.add_argument_group("Hertz check (all three to enable)")
    hz.add_argument("--radius", type=positive_length, metavar="L", help="ball radius, e.g. 10mm")
    hz.add_argument("--load", type=force, metavar="F", help="normal load, e.g. 4.7N")
    hz.add_argument("--materials", metavar="BALL,PLATE", help="e.g. steel,aluminium")
    hz.add_argument("--ball", metavar="FILE", help="scan of the ball (optional)")
    add_scan_options(p, ("ball",))
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet._errors import SurfmetInputError

    check_output(args.output, "-o")
    read_bodies(args, ("ball",))  # the ball as the user states it (--ball-pixel...)
    from surfmet._report_hertz import HertzOptions, hertz_check_available
    from surfmet.report import write_report

    options = roughness_options(args)
    given = [n for n in ("radius", "load", "materials") if getattr(args, n) is not None]
    hertz = None
    if given or args.ball:
        missing = [f"--{n}" for n in ("radius", "load", "materials") if getattr(args, n) is None]
        if missing:
            raise SurfmetInputError(f"the Hertz check needs --radius, --load and --materials; "
                                    f"missing {', '.join(missing)}")
        if not args.load > 0:
            raise SurfmetInputError(f"--load must be positive, got {args.load} N")
        if not hertz_check_available():
            raise SurfmetInputError(
                "the Hertz check is not available in this installation "
                "(surfmet.mechanics.hertz_check "
                "is missing); leave out --radius/--load/--materials")
        hertz = HertzOptions(radius=args.radius, load=args.load, materials=args.materials,
                             ball=args.ball)
    rotor = _rotor_verdict(args)
    sections = write_report(args.files, args.output, options, title=args.title,
                            include_3d=not args.no_3d, hertz=hertz,
                            progress=show_progress(args), rotor=rotor,
                            read_options=read_options(args))
    failed = [s for s in sections if s.status != "ok"]
    for s in failed:
        msg = s.error or ""
        log(f"surfmet: error: {msg if msg.startswith(s.file) else s.file + ': ' + msg}")
    for s in sections:
        if s.hertz_error:
            log(f"surfmet: error: {s.file}: Hertz check: {s.hertz_error}")
    if args.json:
        rec: dict[str, Any] = {"output": args.output,
                               "scans": [s.summary() for s in sections]}
        if rotor is not None:  # the verdict record surfmet rotor --json emits
            from surfmet.records._rotor_verdict import verdict_record

            rec["rotor"] = {"verdict": verdict_record(rotor)}
        emit_json(rec)
    else:
        log(f"wrote {args.output} ({len(sections) - len(failed)} of {len(sections)} scans)")
    return 1 if failed or any(s.hertz_error for s in sections) else 0


def _rotor_verdict(args: argparse.Namespace) -> Any:
    """The verdict ``surfmet rotor`` gives on ``--rotor`` (with ``--rig``), or None."""
    from surfmet._errors import SurfmetInputError

    if args.rotor is None:
        if args.rig:
            raise SurfmetInputError("--rig goes with --rotor TABLE")
        return None
    from rotor import FPS, MARK_STEP
    from surfmet._frames import read_frames_table
    from surfmet.cli.rotor import PAPER_ALIAS, _paper_path
    from surfmet.mechanics.rotor_verdict import judge, load_rig, paper_verdict

    if args.rotor == PAPER_ALIAS and not args.rig:
        return paper_verdict()
    ks, cols = read_frames_table(_paper_path() if args.rotor == PAPER_ALIAS else args.rotor)
    rig = load_rig(args.rig) if args.rig else None
    if rig is None:
        log("note: no --rig: the rotor verdict's lambda outputs and confounds are left out")
    return judge(cols, ks, fps=FPS, step=MARK_STEP, rig=rig)
