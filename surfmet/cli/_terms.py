"""API names in messages, put in the command line's terms at its edge.

The engines and the Python API word their errors for a caller of the API
(``on_edge='warn'``, ``pass channel=``, ``n_sampling``). A user of the command line never
wrote those names: :func:`cli_terms` replaces each by the option that sets the same thing
in the command that failed, and, where that command has no such option, by words that do
not point at one (advice to pass an option the command lacks is dropped).
"""

from __future__ import annotations

import re
from collections.abc import Collection, Sequence
from typing import Any

__all__ = ["cli_terms"]

#: (pattern, the command's wording, the option it needs, the wording without that option).
_TERMS: tuple[tuple[str, str, str, str], ...] = (
    (r"\s*\(or accept a truncated result: on_edge='warn'\)", r" (or accept a truncated "
     r"result: --on-edge warn)", "--on-edge", ""),
    (r"on_edge='(\w+)'", r"--on-edge \1", "--on-edge", r"\1"),
    (r"pass format= one of: ", "give --format, one of: ", "--format", "known formats: "),
    (r"pass channel=", "give --channel", "--channel", "name the channel"),
    (r"pass height_unit=", "give --height-unit", "--height-unit", "the height unit is needed"),
    (r"\bheight_unit=", "--height-unit", "--height-unit", "the height unit"),
    (r"\(pass verify_checksum=False to read (\w+) anyway\)",
     r"(the Python API reads \1 anyway with verify_checksum=False)", "", ""),
    (r"fewer sampling lengths \(n_sampling\)", "fewer sampling lengths (--n-sampling)",
     "--n-sampling", "fewer sampling lengths"),
    (r"n_sampling must be", "--n-sampling must be", "--n-sampling", "the sampling lengths must be"),
    (r"no λc filter \(lc=None\)", "no λc filter (--lc none)", "--lc", "no λc filter"),
    (r"end_treatment='(\w+)'", r"--edge \1", "--edge", r"\1 end treatment"),
    (r"edge='(\w+)'", r"--edge \1", "--edge", r"\1 end treatment"),
    (r"\bplastic=True\b", "--plastic", "--plastic", "plastic"),
)


def cli_terms(text: str, options: Collection[str]) -> str:
    """``text`` with the API's names replaced by the options in ``options`` (the failing
    command's option strings, e.g. ``{"--on-edge", "--grid"}``), see the module notes."""
    for pattern, wording, option, without in _TERMS:
        if re.search(pattern, text):
            has = not option or option in options
            text = re.sub(pattern, wording if has else without, text)
    return text


def command_options(parser: Any, argv: Sequence[str]) -> set[str]:
    """The option strings of the subcommand ``argv`` names (none when it names none)."""
    import argparse

    for action in getattr(parser, "_actions", ()):
        if isinstance(action, argparse._SubParsersAction) and argv:
            sub = action.choices.get(argv[0])
            if sub is not None:
                return set(sub._option_string_actions)
    return set()
