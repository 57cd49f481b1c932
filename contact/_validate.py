"""Argument checks shared by the contact engine (raising its input-error family)."""

from __future__ import annotations

import math
from typing import Any

from contact.errors import ContactInputError


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
    return v
