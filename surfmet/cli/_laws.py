"""The commands' interaction laws, read from the one table (:mod:`contact.adhesion.laws`).

``--interaction`` takes the name of any registered law, and every registered law's
parameters are options of the commands that take a law (``--work-of-adhesion`` and
``--range`` for the laws stated by a work and a range; a law of other numbers brings its
own): a new law is usable from the command line without a line here. The law is built
from the options its table entry names (:func:`interaction_from_arguments`); an option it
does not take, or one it needs and was not given, is one line naming them.
"""

from __future__ import annotations

import argparse
import math
import re
from typing import Any

from surfmet._errors import SurfmetInputError

__all__ = ["add_law_arguments", "angle", "interaction_from_arguments"]

#: The angle units a command reads, in radians.
ANGLE_UNITS = {"rad": 1.0, "mrad": 1e-3, "deg": math.pi / 180.0, "°": math.pi / 180.0}
_ANGLE_RE = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-z°]*)\s*$")


def angle(text: str) -> float:
    """argparse type: an angle in radians from ``"30deg"``, ``"30°"``, ``"0.5rad"`` or a
    bare number (radians, SI)."""
    m = _ANGLE_RE.match(str(text))
    if not m or (m.group(2) and m.group(2) not in ANGLE_UNITS):
        raise argparse.ArgumentTypeError(
            f"cannot read the angle {text!r}: write a number with one of "
            f"{', '.join(ANGLE_UNITS)}, e.g. 30deg (a bare number is radians)")
    return float(m.group(1)) * ANGLE_UNITS[m.group(2) or "rad"]


def _types() -> dict[str, Any]:
    """The argparse type of each SI unit a law's parameter may have."""
    from surfmet.cli._common import _argtype, positive_length, pressure
    from surfmet.units import parse_surface_energy

    energy = _argtype(parse_surface_energy, "work")  # J/m^2 = N/m: one parser reads both
    tension = _argtype(parse_surface_energy, "surface tension")
    return {"J/m^2": energy, "N/m": tension, "m": positive_length, "Pa": pressure,
            "rad": angle}


def add_law_arguments(p: Any, default: str, help_head: str) -> None:
    """``--interaction`` with the table's names (default ``default``), and each registered
    law's parameter options that the parser ``p`` (a parser or a group) does not declare
    already."""
    from contact.adhesion.laws import LAWS, law_parameters

    laws = "; ".join(f"{name}: {cls.summary}" for name, cls in LAWS.items())
    p.add_argument("--interaction", choices=tuple(LAWS), default=default,
                   help=f"{help_head} ({laws})")
    types = _types()
    for par in law_parameters().values():
        takers = [name for name, cls in LAWS.items() if par in cls.parameters]
        try:
            p.add_argument(par.option, type=types[par.unit], dest=par.keyword,
                           help=f"{par.help} (--interaction {' or '.join(takers)})")
        except argparse.ArgumentError:  # the command declares it, with its own help
            continue


def interaction_from_arguments(args: argparse.Namespace, *, optional: bool = False) -> Any:
    """The law ``--interaction`` names, of the parameters given as options; with
    ``optional``, None where no law parameter was given at all."""
    from contact._errors import ContactInputError
    from contact.adhesion.laws import build_law, law_parameters

    values = {k: getattr(args, k, None) for k in law_parameters()}
    if optional and all(v is None for v in values.values()):
        return None
    try:
        return build_law(args.interaction, **values)
    except ContactInputError as exc:  # the option's words, as the user typed them
        raise SurfmetInputError(str(exc)) from None
