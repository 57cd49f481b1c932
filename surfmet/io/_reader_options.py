"""The options a read takes besides the bytes: those every format takes (the units a file
may not state, :data:`GENERIC_OPTIONS`), ``channel`` (only where a format holds several),
and the reader's own, checked against its signature before it runs, so that a misspelt
option is the user's mistake in one line, not a ``TypeError`` passed off as a damaged file.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

from surfmet._errors import SurfmetInputError

# The functions take a format's name and its decoder, not the registry's FormatSpec, so that
# this module needs nothing from the registry that calls it.
Decoder = Callable[..., Any]

__all__ = ["GENERIC_OPTIONS", "accepts", "check_options", "take_generic_options"]

#: The options every read takes, whatever the format: the units a file may not state.
GENERIC_OPTIONS = ("height_unit", "dx", "dy")


def accepts(decode: Decoder, option: str) -> bool:
    """Whether the decoder takes ``option`` (by name or through ``**options``)."""
    params = inspect.signature(decode).parameters
    return option in params or any(p.kind is inspect.Parameter.VAR_KEYWORD
                                   for p in params.values())


def take_generic_options(fmt: str, decode: Decoder, options: dict[str, Any], name: str
                         ) -> dict[str, Any]:
    """Take out of ``options`` the units the user states that the reader does not take
    itself (:func:`surfmet.io._calibration.state_units` applies them after the read), and
    refuse ``channel`` for a format that holds a single one."""
    if options.get("channel") is not None and not accepts(decode, "channel"):
        raise SurfmetInputError(f"{name}: a {fmt} file holds a single channel: no "
                                f"channel can be chosen (got {options['channel']!r})")
    if options.get("channel", 0) is None:
        options.pop("channel")
    stated = {}
    for key in GENERIC_OPTIONS:
        if key in options and not accepts(decode, key):
            value = options.pop(key)
            if value is not None:
                stated[key] = value
    return stated


def check_options(fmt: str, decode: Decoder, options: dict[str, Any]) -> None:
    # A misspelt option is the user's mistake, not damage in the file: say so before the
    # decoder runs, rather than letting a TypeError pass for a corrupted file.
    if not options:
        return
    params = inspect.signature(decode).parameters
    if any(p.kind is inspect.Parameter.VAR_KEYWORD for p in params.values()):
        return
    accepted = [n for n, p in list(params.items())[2:] if p.kind is not p.VAR_POSITIONAL]
    unknown = sorted(set(options) - set(accepted))
    if unknown:
        raise SurfmetInputError(
            f"the {fmt} reader takes no option(s) {unknown}; it accepts "
            f"{accepted or 'no options'}"
        )
