"""Helpers shared by the subcommands: argument types, JSON output, progress bars."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Iterable, Iterator
from typing import Any, TypeVar

from surfmet import units
from surfmet._errors import SurfmetInputError

T = TypeVar("T")


def _argtype(parse: Any, what: str) -> Any:
    def convert(text: str) -> Any:
        try:
            value = parse(text)
        except SurfmetInputError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None
        note = units.bare_number_note(text, value, what)
        if note:  # "20" for a radius: read as metres, as documented, and said so
            log(f"note: {note}")
        return value

    convert.__name__ = what  # argparse names the type in its messages
    return convert


length = _argtype(units.parse_length, "length")
force = _argtype(units.parse_force, "force")
pressure = _argtype(units.parse_pressure, "pressure")
speed = _argtype(units.parse_speed, "speed")


def positive_length(text: str) -> float:
    """argparse type: a strictly positive length in metres."""
    value = length(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"length {text!r} must be positive")
    return value


def add_ball_arguments(parser: Any, *, plate_option: bool = True, required: bool = True) -> None:
    """The ball-on-plate arguments shared by contact, hertz-check, rolling and
    rolling-contact: the plate's scan ``PLATE`` (``--plate`` its alias,
    :func:`surfmet.cli._values.add_plate_argument`; left out without ``plate_option``),
    ``--ball``, ``--radius``, ``--materials``."""
    if plate_option:
        from surfmet.cli._values import add_plate_argument

        add_plate_argument(parser, "scan of the plate (levelled)")
    parser.add_argument("--ball", metavar="FILE",
                        help="scan of the ball (its best-fit sphere is removed)")
    parser.add_argument("--radius", type=positive_length, required=required, metavar="L",
                        help="ball radius, e.g. 20mm")
    parser.add_argument("--materials", required=required, metavar="BALL,PLATE",
                        help="ball and plate materials, e.g. steel,aluminium "
                        "(override values with NAME:E=..:nu=..:H=..)")


def add_spikes_argument(parser: Any) -> None:
    """``--spikes remove|keep``: what every contact command does with the scans' spikes
    (one default, :data:`surfmet.mechanics.scan_preparation.SPIKES`)."""
    from surfmet.mechanics.scan_preparation import SPIKE_CHOICES, SPIKES

    parser.add_argument("--spikes", choices=SPIKE_CHOICES, default=SPIKES,
                        help=f"the scans' spikes (optical outliers): remove them before the "
                        f"contact (default {SPIKES}) or keep them as measured")


def spike_summary(prep: Any) -> str:
    """One line saying what was done with the scans' spikes."""
    if prep is None or prep.pair is None:
        return "no scan"
    if prep.spikes == "keep":
        return "spikes kept (--spikes keep)"
    counts = ", ".join(f"{k} {v}" for k, v in prep.spikes_removed.items())
    return f"spikes removed ({counts})"


def check_output(path: Any, option: str) -> None:
    """Refuse, before any work, an output path that cannot be written
    (:func:`surfmet._atomic.check_writable`)."""
    from surfmet._atomic import check_writable

    check_writable(path, option)


def save_figure(fig: Any, path: str) -> None:
    """Close a written matplotlib figure and say where it went (on stderr)."""
    from surfmet.plots._style import close

    close(fig)
    log(f"figure written to {path}")


def add_json_flag(parser: argparse.ArgumentParser) -> None:
    """The ``--json`` flag every subcommand shares."""
    parser.add_argument(
        "--json", action="store_true", help="machine-readable JSON on stdout (logs go to stderr)"
    )


def emit_json(obj: Any) -> None:
    """Write ``obj`` as JSON on stdout (NaN/inf become null), with the ``"inputs"`` of the
    command being run (:func:`surfmet.cli._inputs.attach`)."""
    from surfmet.cli._inputs import attach

    text = json.dumps(units.jsonable(attach(obj)), indent=2, ensure_ascii=False, allow_nan=False)
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def log(message: str) -> None:
    """A line of human information on stderr."""
    print(message, file=sys.stderr)


def add_quiet_flag(parser: Any) -> None:
    """``--quiet``: no progress on stderr."""
    parser.add_argument("--quiet", "-q", action="store_true",
                        help="no progress on stderr (shown for long runs: a bar on a "
                        "terminal, one line per stage elsewhere)")


def show_progress(args: Any) -> bool:
    """Whether a command shows its progress: always, unless ``--quiet``."""
    return not getattr(args, "quiet", False)


def progress(iterable: Iterable[T], total: int | None = None, desc: str = "",
             show: bool | None = True) -> Iterator[T]:
    """Progress on stderr over a long loop (:func:`surfmet._batch.progress_bar`)."""
    from surfmet._batch import progress_bar

    with progress_bar(total, desc, show) as bar:
        for item in iterable:
            yield item
            bar.update(1)


def print_solve(record: Any, label: str = "solve", warned: Iterable[str] = ()) -> None:
    """The solve record's line (:meth:`contact._record.SolveRecord.text`; ``record`` the
    record or its JSON), and its
    edge-contact warning on a line of its own unless a warning about the domain edge is
    among ``warned`` (printed by the command already); the label padded as in the tables."""
    if isinstance(record, dict):  # a command's JSON "solve" object
        from surfmet.records._solve import solve_from_record

        record = solve_from_record(record)
    indent = " " * (len(label) - len(label.lstrip()))
    print(f"{label:14s} {record.text()}")
    if record.warning and not any("edge of" in w for w in warned):
        print(f"{indent + 'warning':{max(14, len(label))}s} {record.warning}")
