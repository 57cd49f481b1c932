"""``surfmet demo [--out DIR]``: the whole story of the paper on the scans shipped with surfmet."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import add_json_flag, add_quiet_flag, emit_json, show_progress

EPILOG = """examples:
  surfmet demo
  surfmet demo --out demo_out
  surfmet demo --out demo_out --json > demo.json
  surfmet demo --out /tmp/quick --quick

Reads the bundled stand-ins for the paper's plate and ball scans (synthetic, with the
statistics of its Table 2, written as X3P by surfmet), reports their roughness and the
ball's radius, checks Hertz at 10 N (verdict and reasons), solves the contact at the
rotor's load, runs a short rolling-resistance sweep and analyses the rotor's law of motion
from the paper's Table 3 (shipped with surfmet). Figures and summary.json go to DIR
(default ./surfmet_demo). A non-empty DIR is used only if it holds a previous demo output.
"""


def add_parser(sub: Any) -> argparse.ArgumentParser:
    p = sub.add_parser(
        "demo",
        help="the whole story (roughness, radius, Hertz check, contact, rolling, rotor) "
        "on the bundled paper scans",
        description="Run surfmet end to end on the scans and the rotor table shipped with it "
        "(Alaci et al. 2022): a readable story on stdout, progress on stderr, figures and "
        "summary.json in DIR.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--out", default="surfmet_demo", metavar="DIR",
                   help="output folder (default ./surfmet_demo); created if absent")
    p.add_argument("--quick", action="store_true",
                   help="leave out the per-test law-of-motion models of Table 3 (most of "
                   "the run's time) and four of the figures; every number printed is the "
                   "full run's")
    add_json_flag(p)
    add_quiet_flag(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from surfmet.demo import prepare_output, run_demo, story

    prepare_output(args.out)  # refuse a foreign folder before any work
    summary = run_demo(args.out, quick=args.quick, progress=show_progress(args))
    if args.json:
        emit_json(summary)
    else:
        print(story(summary))
    return 0
