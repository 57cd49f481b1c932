"""Small array helpers of the rotor study."""

from __future__ import annotations

import numpy as np

from contact._validate import frozen

__all__ = ["on_rows", "readonly"]


def readonly(a: np.ndarray) -> np.ndarray:
    """A read-only copy of ``a``: the frozen records hold arrays nobody can change."""
    return frozen(a, copy=True)


def on_rows(values: np.ndarray, used: np.ndarray) -> np.ndarray:
    """``values`` given for the rows of the mask ``used`` spread over all rows, NaN elsewhere."""
    out = np.full(used.shape, np.nan)
    out[used] = values
    return out
