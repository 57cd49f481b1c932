"""The timer every benchmark uses: the best of a few runs.

The minimum, not the mean: on a shared machine other work only ever adds time, so the
fastest run is the least disturbed estimate of the code's own cost.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any


def min_time_and_result(fn: Callable[[], Any], repeats: int = 5) -> tuple[float, Any]:
    """Call ``fn`` ``repeats`` times; return the shortest wall time (s) and the last result."""
    best, out = float("inf"), None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def min_time(fn: Callable[[], Any], repeats: int = 5) -> float:
    """Call ``fn`` ``repeats`` times; return the shortest wall time in seconds."""
    return min_time_and_result(fn, repeats)[0]
