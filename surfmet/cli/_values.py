"""The command line's shared option forms: several values in one option (lists and ranges
alike, :mod:`surfmet.value_lists`), the scan-on-a-flat ``--periodic`` choice, the plate
given positionally or as ``--plate``, and options a chosen model does not use.

Each is one function here and every command that takes the option calls it, so that an
option reads the same wherever it appears.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import Any

from surfmet import units
from surfmet._errors import SurfmetInputError
from surfmet.value_lists import DEFAULT_POINTS, MAX_POINTS, parse_values, split_items

#: The help text's description of a list-or-range option (its metavar).
VALUES_METAVAR = "V[,V...]|V1:V2[:N]"


def values_help(what: str, example: str) -> str:
    """The help of a list-or-range option, the same words everywhere."""
    return (f"{what}: a list ({example}) or N log-spaced values START:END[:N] (default N "
            f"{DEFAULT_POINTS}, at most {MAX_POINTS} values); items may be mixed")


def _values_type(parse_one: Callable[[str], float], option: str) -> Callable[[str], list[float]]:
    def convert(text: str) -> list[float]:
        try:
            return parse_values(text, parse_one, option)
        except SurfmetInputError as exc:  # argparse names the option already
            raise argparse.ArgumentTypeError(str(exc).removeprefix(f"{option}: ")) from None

    convert.__name__ = option  # argparse names the type in its messages
    return convert


#: argparse type of ``--loads`` (newtons).
loads = _values_type(units.parse_force, "--loads")
#: argparse type of ``--pressures`` (pascals).
pressures = _values_type(units.parse_pressure, "--pressures")


def parse_position(text: str, option: str = "--positions") -> tuple[float, float]:
    """One apex offset ``X:Y`` (lengths) in metres."""
    parts = text.split(":")
    if len(parts) != 2:
        raise SurfmetInputError(f"{option}: a position is X:Y (e.g. 0.2mm:0), got {text!r}")
    return (units.parse_length(parts[0]), units.parse_length(parts[1]))


def parse_positions(text: str, option: str = "--positions") -> list[tuple[float, float]]:
    """``X:Y,X:Y,...``: the list grammar of :func:`surfmet.value_lists.split_items`."""
    return [parse_position(t, option) for t in split_items(text, option)]


def positions(text: str) -> list[tuple[float, float]]:
    """argparse type of ``--positions``."""
    try:
        return parse_positions(text)
    except SurfmetInputError as exc:
        raise argparse.ArgumentTypeError(str(exc).removeprefix("--positions: ")) from None


#: ``--periodic``'s values, the same in every command that takes it.
PERIODIC_CHOICES = ("auto", "yes", "no")


def add_periodic_argument(p: argparse.ArgumentParser, *, default: str = "auto",
                          help: str = "take the scan as periodic (default auto: detect "
                          "from its edges)") -> None:
    """``--periodic {auto,yes,no}``; a bare ``--periodic`` is ``yes`` (the flag form
    ``contact`` used to take)."""
    p.add_argument("--periodic", nargs="?", const="yes", choices=PERIODIC_CHOICES,
                   default=default, help=f"{help}; a bare --periodic is yes")


def periodic_flag(text: str) -> bool | None:
    """``auto`` -> None, ``yes`` -> True, ``no`` -> False."""
    return {"auto": None, "yes": True, "no": False}[text]


def add_interaction_argument(p: Any) -> None:
    """``--interaction`` with the laws' table for choices, one default everywhere
    (:data:`surfmet.mechanics.adhesion.INTERACTION`), and the laws' parameter options
    (:func:`surfmet.cli._laws.add_law_arguments`)."""
    from surfmet.cli._laws import add_law_arguments
    from surfmet.mechanics.adhesion_laws import INTERACTION

    add_law_arguments(p, INTERACTION, f"adhesion law (default {INTERACTION}, in every "
                      "command)")


#: The parsed arguments' notes on the options' forms, printed on stderr once the command
#: has run (an error is then its one line alone).
DEFERRED_NOTES = "deferred_notes"


class _Plate(argparse.Action):
    """The plate's scan, given once: as the positional PLATE (the form of every command
    that reads a scan) or as ``--plate FILE``, its alias, which is noted on stderr."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: Any, option_string: str | None = None) -> None:
        if values is None or values == []:  # an absent optional positional
            return
        if getattr(namespace, self.dest, None) not in (None, []):
            parser.error("the plate is given twice: give PLATE or --plate, once")
        if option_string is not None:  # said after the command's output (surfmet.cli.main)
            command = parser.prog.split()[-1]
            notes = getattr(namespace, DEFERRED_NOTES, None) or []
            notes.append(f"note: --plate is an alias of the positional scan, the form of "
                         f"every command: surfmet {command} {values} ...")
            setattr(namespace, DEFERRED_NOTES, notes)
        if self.nargs == "*" and option_string is not None:
            values = [values]
        setattr(namespace, self.dest, values)


def add_plate_argument(p: argparse.ArgumentParser, help: str, *, several: bool = False,
                       dest: str = "plate") -> None:
    """The plate's scan as the positional ``PLATE`` (``FILE...`` with ``several``), and
    ``--plate FILE`` as its alias (noted on stderr). Absent, ``dest`` is None (or [] with
    ``several``): a command that needs the scan says so (:func:`require_plate`)."""
    p.add_argument(dest, nargs="*" if several else "?", default=argparse.SUPPRESS,
                   action=_Plate, metavar="FILE" if several else "PLATE", help=help)
    p.add_argument("--plate", dest=dest, default=[] if several else None, action=_Plate,
                   metavar="FILE", help="the same as the positional scan (an alias)")


def require_plate(value: Any, command: str, metavar: str = "PLATE") -> None:
    """Refuse a command that needs the scan without one."""
    if value is None or value == []:
        raise SurfmetInputError(f"{command} needs a scan: surfmet {command} {metavar} ...")


def refuse_unused(args: argparse.Namespace, defaults: dict[str, Any], choice: str,
                  uses: dict[str, tuple[str, ...]], option: str = "--model") -> None:
    """Refuse an option given (its value not the parser's default) with an ``option``
    ``choice`` that does not use it: ``uses`` maps each option to the choices that do. A
    value that would be silently ignored is one line, naming where it applies."""
    for name, choices in uses.items():
        dest = name.lstrip("-").replace("-", "_")
        if choice not in choices and getattr(args, dest, None) != defaults.get(dest):
            raise SurfmetInputError(f"{name} is not used by {option} {choice}: it applies to "
                                    f"{option} {' and '.join(choices)}")
