"""Several values of one quantity in one argument: ``--loads 4N,5N,6N``, ``1N:100N:9``.

One grammar for every option and API argument that takes several values (loads,
pressures, ...): a comma-separated list of items, each item either one value
(``5N``) or a log-spaced range ``START:END[:N]`` (N values from START to END, both
included; :data:`DEFAULT_POINTS` without N). Items may be mixed (``1N:10N:3,50N``). Every
value is a positive quantity read by the quantity's own parser
(:func:`surfmet.units.parse_force`, :func:`surfmet.units.parse_pressure`...), and the
whole argument gives at most :data:`MAX_POINTS` values: each is a solve, and a range
such as ``1MPa:100MPa:100000`` is a typing slip far more often than a wish for a day's
run.

Positions (``X:Y,...``) use ``:`` between their coordinates, so they are lists only
(:func:`split_items` is their list grammar too).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from surfmet._errors import SurfmetInputError

__all__ = ["DEFAULT_POINTS", "MAX_POINTS", "parse_values", "split_items"]

#: Values of a range START:END written without its count N.
DEFAULT_POINTS = 9
#: The most values one argument may give (each is a solve).
MAX_POINTS = 100


def split_items(text: str, what: str) -> list[str]:
    """The comma-separated items of ``text`` (blank items dropped); none is one error
    naming ``what`` (the option, e.g. ``"--loads"``)."""
    items = [t.strip() for t in str(text).split(",") if t.strip()]
    if not items:
        raise SurfmetInputError(f"{what} is empty: give one value or more")
    return items


def _count(text: str, item: str, what: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise SurfmetInputError(f"{what}: the count N in {item!r} (START:END:N) is not a whole "
                                "number") from None
    if n < 2:
        raise SurfmetInputError(f"{what}: the range {item!r} needs N of at least 2")
    if n > MAX_POINTS:
        raise SurfmetInputError(f"{what}: the range {item!r} asks for {n} values, more than "
                                f"{MAX_POINTS} (each is a solve); give a smaller N")
    return n


def _range(item: str, parse_one: Callable[[str], float], what: str) -> list[float]:
    parts = item.split(":")
    if len(parts) not in (2, 3):
        raise SurfmetInputError(f"{what}: cannot read {item!r}: a range is START:END or "
                                "START:END:N (N log-spaced values)")
    lo, hi = parse_one(parts[0]), parse_one(parts[1])
    n = DEFAULT_POINTS if len(parts) == 2 else _count(parts[2], item, what)
    if not (lo > 0 and hi > lo):
        raise SurfmetInputError(f"{what}: the range {item!r} needs 0 < START < END")
    import numpy as np

    # the engine's spacing (contact._rolling.log_loads), END included exactly
    return [float(v) for v in np.geomspace(lo, hi, n)]


def parse_values(text: str, parse_one: Callable[[str], float], what: str) -> list[float]:
    """The values of a list-or-range argument (module notes), in the order written.

    Parameters
    ----------
    text : str
        ``"4N,5N,6N"``, ``"1N:100N"``, ``"1N:100N:5"``, ``"1N:10N:3,50N"``.
    parse_one : callable
        Reads one value with its unit into SI (e.g. :func:`surfmet.units.parse_force`).
    what : str
        The argument as the user wrote it (``"--loads"``), named by every error.

    Raises
    ------
    SurfmetInputError
        An unreadable item, a value that is not positive, a range that is empty or gives
        more than :data:`MAX_POINTS` values, or more than :data:`MAX_POINTS` in all.
    """
    values: list[float] = []
    for item in split_items(text, what):
        if ":" in item:
            values.extend(_range(item, parse_one, what))
            continue
        value = parse_one(item)
        if not (math.isfinite(value) and value > 0):
            raise SurfmetInputError(f"{what}: {item!r} must be positive")
        values.append(value)
    if len(values) > MAX_POINTS:
        raise SurfmetInputError(f"{what} gives {len(values)} values, more than {MAX_POINTS} "
                                "(each is a solve)")
    return values
