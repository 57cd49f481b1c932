"""Sampling positions: recognise rounded uniform grids, resample truly irregular profiles.

Profile filters (ISO 16610-21) and the local-slope formula of ISO 4287 assume equally
spaced points. Instrument exports are often *printed* with rounded positions: a Dektak CSV
sampled every 0.15625 µm writes x with one decimal (0.0, 0.2, 0.3, 0.5 ...), which looks
non-uniform although the scan is uniform. :func:`regularize` tells the two cases apart:

* positions that are ``x0 + i*dx`` rounded to a fixed resolution ``q`` (all steps take one
  of two values ``q`` apart and every point lies within ``q/2`` of the fitted grid) are
  taken as that uniform grid: no interpolation, the heights are kept as measured;
* genuinely irregular positions are resampled by linear interpolation onto a uniform grid
  with the median step, covering the same extent. A new point whose neighbours include a
  non-measured point stays non-measured, so NaN holes neither grow nor get filled.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from profiles._arrays import as_heights, as_positions

# Relative tolerance on "equal" steps (floating-point noise of unit conversion).
_STEP_RTOL = 1e-7


@dataclass(frozen=True, eq=False)
class RegularProfile:
    """A profile on a uniform grid.

    Attributes
    ----------
    z : ndarray
        Heights on the uniform grid (NaN = not measured).
    x : ndarray
        Uniform positions ``x0 + i*dx`` in metres.
    dx : float
        The step in metres.
    method : str
        ``"uniform"`` (positions were uniform), ``"uniform-rounded"`` (uniform grid whose
        printed positions were rounded; heights untouched) or ``"resampled"`` (linear
        interpolation).
    info : dict
        What was found: the position resolution, largest deviation from the grid, number
        of points before and after.

    See Also
    --------
    regularize : makes it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import regularize
    >>> x = np.round(np.arange(20) * 0.15625, 1) * 1e-6   # a 0.15625 µm grid printed to 0.1 µm
    >>> reg = regularize(np.zeros(20), x)
    >>> reg.method, reg.z.size
    ('uniform-rounded', 20)
    """

    z: np.ndarray
    x: np.ndarray
    dx: float
    method: str
    info: dict[str, Any] = field(default_factory=dict)


def rounded_grid(x: np.ndarray) -> tuple[float, float, float, float] | None:
    """Fit ``x`` as a uniform grid rounded to a fixed resolution.

    Returns
    -------
    (x0, dx, q, max_dev) or None
        Grid origin, step, the rounding resolution ``q`` (0 for an exactly uniform grid)
        and the largest deviation of a position from the grid; ``None`` if ``x`` is not a
        (possibly rounded) uniform grid.
    """
    n = x.size
    if n < 3:
        return None
    steps = np.diff(x)
    scale = float(np.max(np.abs(steps)))
    lo, hi = float(steps.min()), float(steps.max())
    i = np.arange(n, dtype=np.float64)
    # least-squares grid through the points
    dx, x0 = np.polyfit(i, x, 1)
    dev = float(np.max(np.abs(x - (x0 + dx * i))))
    if hi - lo <= _STEP_RTOL * scale:
        return float(x0), float(dx), 0.0, dev
    # Rounding to a resolution q makes the steps take exactly two values, q apart,
    # bracketing the true step; the points then lie within q/2 of the grid.
    close_lo = np.abs(steps - lo) <= _STEP_RTOL * scale
    close_hi = np.abs(steps - hi) <= _STEP_RTOL * scale
    if not np.all(close_lo | close_hi):
        return None
    q = hi - lo
    if not (lo <= dx <= hi) or q >= dx:
        return None
    # 0.5 q plus a small allowance for the least-squares estimate of the grid itself
    if dev > 0.5 * q * 1.05 + _STEP_RTOL * scale:
        return None
    return float(x0), float(dx), float(q), dev


def regularize(z: Any, x: Any) -> RegularProfile:
    """Put a profile given at positions ``x`` on a uniform grid (see module docstring).

    Parameters
    ----------
    z : array_like
        Heights in metres, NaN where not measured.
    x : array_like
        Strictly increasing positions in metres.

    Returns
    -------
    RegularProfile

    See Also
    --------
    RegularProfile : the result.

    Examples
    --------
    Positions printed with one decimal hide a uniform grid: the heights are kept as they
    are. Truly irregular positions are resampled by linear interpolation:

    >>> import numpy as np
    >>> from profiles import regularize
    >>> x = np.round(np.arange(20) * 0.15625, 1) * 1e-6
    >>> print(regularize(np.zeros(20), x).method)
    uniform-rounded
    >>> x = np.arange(50) ** 1.5 * 1e-7
    >>> reg = regularize(np.sin(x * 1e4), x)
    >>> print(reg.method, f"{reg.dx * 1e6:.3f} µm")
    resampled 0.742 µm
    """
    z = as_heights(z)
    x = as_positions(x, z.size)
    n = z.size
    if n == 1:
        return RegularProfile(z, x, 1.0, "uniform", {"n_points": 1})
    grid = rounded_grid(x)
    if grid is not None:
        x0, dx, q, dev = grid
        method = "uniform" if q == 0.0 else "uniform-rounded"
        xu = x0 + dx * np.arange(n)
        info = {
            "n_points": n,
            "position_resolution": q,
            "max_position_deviation": dev,
        }
        return RegularProfile(z, xu, float(dx), method, info)
    steps = np.diff(x)
    dx = float(np.median(steps))
    span = float(x[-1] - x[0])
    m = int(np.floor(span / dx * (1 + 1e-12))) + 1
    xu = x[0] + dx * np.arange(m)
    xu[-1] = min(xu[-1], x[-1])
    valid = np.isfinite(z)
    zu = np.interp(xu, x, np.where(valid, z, 0.0))
    # a new point is measured only if both bracketing originals are measured
    right = np.clip(np.searchsorted(x, xu, side="left"), 0, n - 1)
    left = np.clip(right - 1, 0, n - 1)
    exact = x[right] == xu
    ok = np.where(exact, valid[right], valid[left] & valid[right])
    zu[~ok] = np.nan
    info = {
        "n_points": n,
        "n_resampled": m,
        "min_step": float(steps.min()),
        "max_step": float(steps.max()),
        "interpolation": "linear",
    }
    return RegularProfile(zu, xu, dx, "resampled", info)
