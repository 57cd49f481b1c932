"""The evaluation options of ``surfmet roughness`` for the commands that show a scan's
roughness too (``report``, ``show``): the same names, types and defaults, turned into the
same keyword arguments of :func:`surfmet.roughness.roughness`, so that one file with one
set of options gives one set of numbers wherever it is shown."""

from __future__ import annotations

import argparse
from typing import Any

from surfmet.cli._common import positive_length

#: ``--element-start`` choices: the pairings of :data:`profiles._elements.ELEMENT_STARTS`
#: (the command line names them without importing the engine)
ELEMENT_STARTS = ("peak", "first-crossing")


def positive_int(text: str) -> int:
    """An integer of at least 1 (argparse type)."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {n}")
    return n


def cutoff(text: str) -> str | float:
    """A nesting index: a length, or none / off / auto (argparse type)."""
    if text.strip().lower() in ("none", "off", "auto"):
        return text.strip().lower()
    return positive_length(text)


def add_roughness_options(p: argparse.ArgumentParser, *, what: str = "evaluate",
                          group: bool = True) -> None:
    """Add ``--level --ls --lc --edge --standard --rk-line --element-start
    --valley-suppression --n-sampling --window --profile --spikes`` with ``surfmet
    roughness``'s meaning and defaults (``--level``: plane, a line on profiles, none for an
    instrument's R-profile; a profile's λc, λs, standard, sampling lengths, Rk construction
    and element pairing: the ones its file states)."""
    g: Any = p.add_argument_group("evaluation (as surfmet roughness)") if group else p
    g.add_argument("--level", default=None,
                   help="form removal: none, mean, plane, poly:N, sphere, cylinder (default "
                   "plane, a line on profiles; none for a file holding an instrument's "
                   "R-profile)")
    g.add_argument("--ls", type=cutoff, default=None,
                   help="S-filter nesting index λs (e.g. 2.5um), or none")
    g.add_argument("--lc", type=cutoff, default=None,
                   help="L-filter nesting index / cut-off λc (e.g. 0.8mm); profiles: none for "
                   "an already filtered profile, auto for the ISO 4288 rule (default: the "
                   "file's stated λc, else auto)")
    g.add_argument("--edge", choices=("discard", "moment", "renormalise"), default="discard",
                   help="areal filters: the band of half a nesting index along each border "
                   "where the Gaussian weights run past the scan (end effects) is left out "
                   "(discard, the default) or kept with a moment or renormalised correction "
                   "(biased near λc); the output states which")
    g.add_argument("--standard", choices=("iso21920", "iso4287"), default=None,
                   help="profiles: iso21920 (ISO 21920-2, over the evaluation length; the "
                   "default unless the file states another) or iso4287 (ISO 4287:1997, "
                   "per sampling length, averaged)")
    g.add_argument("--rk-line", choices=("secant", "least-squares", "levels"), default=None,
                   help="profiles: ISO 13565-2 equivalent straight line: the least-gradient "
                   "40%% secant (default, unless the file states its instrument's), its "
                   "least-squares fit, or 'levels' (the curve tabulated at 1%% of Rt, as a "
                   "Mitutoyo SurfTest prints)")
    g.add_argument("--element-start", choices=ELEMENT_STARTS, default=None,
                   help="profiles: RSm and Rc profile elements paired peak first (default, "
                   "unless the file states its instrument's and its standard is in force) "
                   "or from the first mean-line crossing of each sampling length (of the "
                   "evaluation length with iso21920; 'first-crossing', as a Mitutoyo "
                   "SurfTest)")
    g.add_argument("--valley-suppression", action="store_true",
                   help="profiles: ISO 13565-1 two-stage λc filter for stratified surfaces")
    g.add_argument("--n-sampling", type=positive_int, default=None, metavar="N",
                   help="profiles: number of sampling lengths (default: the file's, else 5)")
    g.add_argument("--window", default=None, metavar="X0:X1", help=f"{what} x in X0..X1 only")
    g.add_argument("--profile", default=None, metavar="row:K|col:K",
                   help=f"{what} one row or column of an areal scan (R-parameters)")
    g.add_argument("--spikes", action="store_true", help="remove spikes before levelling")


def roughness_options(args: argparse.Namespace) -> dict[str, Any]:
    """The keyword arguments of :func:`surfmet.roughness.roughness` the options give (the
    ones ``surfmet roughness`` passes)."""
    return {"level": args.level, "ls": args.ls, "lc": args.lc, "window": args.window,
            "profile": args.profile, "spikes": args.spikes, "standard": args.standard,
            "n_sampling": args.n_sampling, "rk_line": args.rk_line,
            "element_start": args.element_start,
            "valley_suppression": args.valley_suppression, "edge": args.edge}
