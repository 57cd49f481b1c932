"""The evaluation options of ``surfmet roughness`` for the commands that show a scan's
roughness too (``report``, ``show``): the same names, types and defaults, turned into the
same keyword arguments of :func:`surfmet.roughness.roughness`, so that one file with one
set of options gives one set of numbers wherever it is shown."""

from __future__ import annotations

import argparse
from typing import Any


def add_roughness_options(p: argparse.ArgumentParser, *, what: str = "evaluate") -> None:
    """Add ``--level --ls --lc --edge --standard --rk-line --valley-suppression
    --n-sampling --window --profile --spikes`` with ``surfmet roughness``'s meaning and
    defaults (``--level``: plane, a line on profiles, none for an instrument's R-profile;
    a profile's λc, λs, standard and sampling lengths: the ones its file states)."""
    from surfmet.cli.roughness import _cutoff, _positive_int

    g = p.add_argument_group("evaluation (as surfmet roughness)")
    g.add_argument("--level", default=None,
                   help="form removal: none, mean, plane, poly:N, sphere, cylinder (default "
                   "plane, a line on profiles; none for a file holding an instrument's "
                   "R-profile)")
    g.add_argument("--ls", type=_cutoff, default=None,
                   help="S-filter nesting index λs (e.g. 2.5um), or none")
    g.add_argument("--lc", type=_cutoff, default=None,
                   help="L-filter nesting index / cut-off λc (e.g. 0.8mm); profiles: none for "
                   "an already filtered profile, auto for the ISO 4288 rule (default: the "
                   "file's stated λc, else auto)")
    g.add_argument("--edge", choices=("discard", "moment", "renormalise"), default="discard",
                   help="areal filters' edge treatment (as surfmet roughness; default discard)")
    g.add_argument("--standard", choices=("iso21920", "iso4287"), default=None,
                   help="profiles: iso21920 or iso4287 (default: the file's, else iso21920)")
    g.add_argument("--rk-line", choices=("secant", "least-squares", "levels"), default=None,
                   help="profiles: ISO 13565-2 equivalent straight line (default: the file's "
                   "instrument's, else secant)")
    g.add_argument("--valley-suppression", action="store_true",
                   help="profiles: ISO 13565-1 two-stage λc filter")
    g.add_argument("--n-sampling", type=_positive_int, default=None, metavar="N",
                   help="profiles: number of sampling lengths (default: the file's, else 5)")
    g.add_argument("--window", default=None, metavar="X0:X1", help=f"{what} x in X0..X1 only")
    g.add_argument("--profile", default=None, metavar="row:K|col:K",
                   help=f"{what} one row or column of an areal scan (R-parameters)")
    g.add_argument("--spikes", action="store_true", help="remove spikes before levelling")


def roughness_options(args: argparse.Namespace) -> dict[str, Any]:
    """The keyword arguments of :func:`surfmet.roughness.roughness` the options give (the
    ones ``surfmet roughness`` passes)."""
    from surfmet.cli.roughness import _options

    return _options(args)
