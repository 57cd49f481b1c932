"""The measured points of a scan: the one place that turns a Topography into valid heights.

Every areal parameter uses the valid (non-NaN) points only, never a grid padded with zeros.
"""

from __future__ import annotations

import numpy as np

from surfmet._errors import SurfmetInputError
from surfmet._model import Topography, require_measurement


def heights_of(topo: Topography) -> np.ndarray:
    """The height grid of ``topo``; one clear error for anything but a Topography."""
    if not isinstance(topo, Topography):
        raise SurfmetInputError(
            f"areal parameters need a Topography, got {type(topo).__name__}; for a profile "
            "use surfmet.roughness or profiles.analyze_profile"
        )
    return require_measurement(topo).heights


def valid_values(z: np.ndarray) -> np.ndarray:
    """The measured heights of ``z`` as a flat array; error if there is none."""
    v = z.ravel()
    if np.isnan(v).any():
        v = v[~np.isnan(v)]
    if v.size == 0:
        raise SurfmetInputError("the scan has no measured point")
    return v


def fixed_order_dot(a: np.ndarray, b: np.ndarray) -> float:
    """Dot product summed in a fixed order (bitwise reproducible across thread counts)."""
    # einsum sums in a fixed order on one thread, unlike BLAS ddot whose blocking follows
    # the thread count: results must be bitwise identical between a serial run and Dask
    # workers (which run single-threaded BLAS).
    return float(np.einsum("i,i->", a, b))


def centred(z: np.ndarray) -> tuple[np.ndarray, np.ndarray, bool]:
    """(heights minus valid mean with NaN kept, valid mask, all-valid flag)."""
    valid = ~np.isnan(z)
    full = bool(valid.all())
    if not full and not valid.any():
        raise SurfmetInputError("the scan has no measured point")
    mean = float(z.mean()) if full else float(z[valid].mean())
    return z - mean, valid, full
