"""Input checks shared by the profile engine: turn user arrays into clean float64 vectors.

Every public function of :mod:`profiles` validates through here, so that a bad argument
fails with one :class:`~profiles._errors.ProfileError` a user can act on rather than with a
traceback from deep inside numpy.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from profiles._errors import ProfileError


def as_heights(z: Any, name: str = "z") -> np.ndarray:
    """A 1D float64 copy of ``z`` (NaN = not measured; +-inf is treated as NaN)."""
    try:
        arr = np.array(z, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ProfileError(f"{name} must be a 1D array of numbers: {exc}") from None
    if arr.ndim != 1:
        raise ProfileError(f"{name} must be a 1D array, got shape {arr.shape}")
    if arr.size == 0:
        raise ProfileError(f"{name} is empty: a profile needs measured points")
    arr[~np.isfinite(arr)] = np.nan
    return arr


def as_step(dx: Any, name: str = "dx") -> float:
    """A positive finite sampling step in metres."""
    try:
        v = float(dx)
    except (TypeError, ValueError):
        raise ProfileError(f"{name} must be a positive length in metres, got {dx!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise ProfileError(f"{name} must be a positive finite length in metres, got {dx!r}")
    return v


def as_positions(x: Any, n: int, name: str = "x") -> np.ndarray:
    """Strictly increasing finite positions, one per height."""
    try:
        arr = np.array(x, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ProfileError(f"{name} must be a 1D array of positions: {exc}") from None
    if arr.ndim != 1 or arr.size != n:
        raise ProfileError(f"{name} must hold one position per height ({n}), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ProfileError(f"{name} contains NaN or infinite positions")
    if n > 1 and not np.all(np.diff(arr) > 0):
        raise ProfileError(f"{name} must be strictly increasing (sort the profile by position)")
    return arr


def require_valid(z: np.ndarray, minimum: int = 1, what: str = "this evaluation") -> np.ndarray:
    """Boolean mask of measured points; raise if fewer than ``minimum``."""
    valid = np.isfinite(z)
    count = int(np.count_nonzero(valid))
    if count == 0:
        raise ProfileError("the profile has no measured points (all heights are NaN)")
    if count < minimum:
        raise ProfileError(
            f"{what} needs at least {minimum} measured points, the profile has {count}"
        )
    return valid


def cell_widths(x: np.ndarray) -> np.ndarray:
    """Length of profile each point stands for (half-way to its neighbours).

    The two end points get the full adjacent step, so that a uniform profile gets equal
    widths ``dx`` everywhere and weighted means reduce to plain means.
    """
    n = x.size
    if n == 1:
        return np.ones(1)
    d = np.diff(x)
    w = np.empty(n)
    w[1:-1] = 0.5 * (d[:-1] + d[1:])
    w[0] = d[0]
    w[-1] = d[-1]
    return w


def length_text(value: float, digits: int = 4) -> str:
    """A length in metres as text in the most readable of nm, µm, mm and m (messages)."""
    v = float(value)
    for factor, unit in ((1e-9, "nm"), (1e-6, "µm"), (1e-3, "mm")):
        if abs(v) < 999.95 * factor:
            return f"{v / factor:.{digits}g} {unit}"
    return f"{v:.{digits}g} m"
