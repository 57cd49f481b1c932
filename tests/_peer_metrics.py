"""SurfaceTopography's definitions of the values its tests assert, for the reader tests.

MANIFEST.tsv quotes numbers from SurfaceTopography (ST) tests. These helpers restate ST's
definitions (``SurfaceTopography/Uniform/ScalarParameters.py`` and ``Derivative.py``) on
surfmet's (ny, nx) arrays, where row j is a line along x. They are independent of the
surfmet code under test, so that a reader that shifts, scales or masks data wrongly fails.
"""

from __future__ import annotations

import warnings

import numpy as np


def st_sq(h: np.ndarray) -> float:
    """``rms_height_from_area``: rms about the mean, over the measured points."""
    v = h[np.isfinite(h)]
    return float(np.sqrt(np.mean((v - v.mean()) ** 2)))


def st_rq(h: np.ndarray) -> float:
    """``rms_height_from_profile``: each line along x loses its own mean, then the square
    deviations of all points are averaged and the root taken (ST's ``Rq``)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # rows without a valid point
        d = h - np.nanmean(h, axis=1, keepdims=True)
    return float(np.sqrt(np.nanmean(d**2)))


def st_rms_gradient(h: np.ndarray, dx: float, dy: float) -> float:
    """``rms_gradient``: first-order forward differences along x and y, evaluated on the
    (ny - 1) x (nx - 1) points where both exist (ST trims the non-periodic edge)."""
    gx = (h[:-1, 1:] - h[:-1, :-1]) / dx
    gy = (h[1:, :-1] - h[:-1, :-1]) / dy
    return float(np.sqrt(np.mean(gx**2 + gy**2)))


def detrend_curvature(h: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """``detrend('curvature')``: subtract the least-squares fit of 1, x, y, x², xy, y²."""
    ny, nx = h.shape
    y, x = np.mgrid[:ny, :nx]
    x = x * dx
    y = y * dy
    ok = np.isfinite(h)
    cols = [np.ones_like(x), x, y, x * x, x * y, y * y]
    # Scale the columns so that the normal equations stay well conditioned.
    a = np.stack([c[ok] / np.abs(c).max() for c in cols], axis=1)
    coef, *_ = np.linalg.lstsq(a, h[ok], rcond=None)
    fit = sum(k * c / np.abs(c).max() for k, c in zip(coef, cols))
    return h - fit
