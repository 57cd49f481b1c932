"""Argument checks and array helpers shared by the contact engine (input-error family)."""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np

from contact._errors import ContactInputError


def positive(value: Any, what: str, unit: str = "") -> float:
    """``float(value)`` if it is a finite number > 0, else :class:`ContactInputError`.

    ``what`` names the quantity and ``unit`` its SI unit, for the message.
    """
    where = f" in {unit}" if unit else ""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ContactInputError(f"{what} must be a number{where}, got {value!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise ContactInputError(f"{what} must be positive and finite{where}, got {value!r}")
    if v < sys.float_info.min:  # subnormal: its powers and inverses underflow or overflow
        raise ContactInputError(f"{what} {v:.3g}{' ' + unit if unit else ''} is too small to "
                                f"compute with (below {sys.float_info.min:.3g}): not a "
                                "physical value")
    return v


def frozen(a: Any, *, copy: bool = False, dtype: Any = None) -> np.ndarray:
    """``a`` as a C-contiguous, read-only array.

    Without ``copy`` it is a copy only where ``a`` is not contiguous (or not of ``dtype``),
    so a caller's contiguous array becomes read-only too; ``copy=True`` always copies and
    leaves the caller's array writeable. Results are frozen dataclasses; freezing their
    arrays too keeps a caller from changing a field behind the derived scalars' back.
    """
    out = np.array(a, dtype=dtype, copy=True, order="C") if copy else \
        np.ascontiguousarray(a, dtype=dtype)
    out.setflags(write=False)
    return out
