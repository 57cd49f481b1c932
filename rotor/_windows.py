"""Model-free windowed accelerations: what the frames alone say about the groups' difference.

The joint model's group tracks (:mod:`rotor._joint`) are polynomials of the track
position; their difference at the release or at the last mark is an end value of a
polynomial, where it is least constrained. Beside it this module reads the acceleration off
the frames with no track model: the track is cut into windows of equal length, and in each
window each launch's marks are fitted by a parabola in time,

    phi(t) = c0 + c1 tau + c2 tau^2,    tau = t - (the window's mean time),

so the window's acceleration is ``eps = 2 c2``: exact for a constant acceleration within
the window, and no track model. The times carry the reading noise, so each row's weight is
``1 / (omega sigma_t)`` (its time error carried to the angle by the speed there, from the
fit itself); the standard error follows from the weighted fit's covariance, scaled up by
the window's own reduced chi-square where that is larger. A group's value in a window is
the mean of its launches, with the larger of the propagated standard error and the
launches' own scatter (``sd / sqrt(n)``), so launch-to-launch variation is never hidden.
The difference of two groups is taken window by window, and a straight line through the
differences (weighted, its standard error scaled by the reduced chi-square where above 1)
is the model-free trend.

A window where the difference is within two standard errors of zero is one where the data
cannot resolve it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["GroupWindows", "WindowedDifference", "launch_windows", "windowed_difference"]

MIN_ROWS = 4
"""Rows a window needs in a launch (three parameters and one degree of freedom)."""


def _window_fit(phi: np.ndarray, t: np.ndarray, sigma: np.ndarray) -> tuple[float, float]:
    """``(eps, stderr)`` of the parabola ``phi(t)`` through one window's marks, each row's
    time error ``sigma`` carried to the angle by the speed there (two passes)."""
    tau = t - t.mean()
    design = np.column_stack([np.ones_like(tau), tau, tau * tau])
    speed = np.full(tau.size, np.ptp(phi) / max(np.ptp(t), 1e-12))
    for _ in range(3):
        wt = 1.0 / (np.maximum(speed, 1e-12) * sigma)
        coef, *_ = np.linalg.lstsq(design * wt[:, None], phi * wt, rcond=None)
        speed = np.abs(coef[1] + 2.0 * coef[2] * tau)
    wd = design * wt[:, None]
    resid = wd @ coef - phi * wt
    scale = max(float(resid @ resid) / (tau.size - 3), 1.0)
    cov = np.linalg.pinv(wd.T @ wd) * scale
    return 2.0 * float(coef[2]), 2.0 * math.sqrt(max(float(cov[2, 2]), 0.0))


def launch_windows(angles: np.ndarray, times: np.ndarray, sigma: np.ndarray,
                   edges: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One launch's windowed accelerations: ``angles`` (rad, track position of each used
    row), ``times`` (s), ``sigma`` (s, each row's reading noise), ``edges`` (rad, the
    windows' bounds). Returns ``(eps, stderr)`` per window (rad/s²; NaN where a window holds
    fewer than :data:`MIN_ROWS` rows)."""
    n_w = edges.size - 1
    eps, se = np.full(n_w, np.nan), np.full(n_w, np.nan)
    for w in range(n_w):
        sel = (angles >= edges[w]) & (angles < edges[w + 1])
        if np.count_nonzero(sel) >= MIN_ROWS:
            eps[w], se[w] = _window_fit(angles[sel], times[sel], sigma[sel])
    return eps, se


@dataclass(frozen=True)
class GroupWindows:
    """A group's windowed acceleration: ``mean`` and ``stderr`` (rad/s²) per window, with
    ``n`` the launches that have a value there."""

    mean: np.ndarray
    stderr: np.ndarray
    n: np.ndarray


def _group(eps: np.ndarray, se: np.ndarray) -> GroupWindows:
    """Mean over launches (rows of ``eps``) per window, with the larger of the propagated
    and the scatter's standard error."""
    ok = np.isfinite(eps)
    n = ok.sum(axis=0)
    mean, stderr = np.full(eps.shape[1], np.nan), np.full(eps.shape[1], np.nan)
    for w in np.flatnonzero(n > 0):
        e, s = eps[ok[:, w], w], se[ok[:, w], w]
        prop = math.sqrt(float(np.sum(s**2))) / e.size
        scatter = float(np.std(e, ddof=1)) / math.sqrt(e.size) if e.size > 1 else 0.0
        mean[w], stderr[w] = float(np.mean(e)), max(prop, scatter)
    return GroupWindows(mean, stderr, n)


@dataclass(frozen=True)
class WindowedDifference:
    """Minuend minus subtrahend, window by window (SI: m, rad/s²).

    ``centres``/``edges``: the windows along the track (m from the release);
    ``difference``/``stderr`` per window; ``minuend``/``subtrahend``: the groups' own
    :class:`GroupWindows`; ``trend``/``trend_stderr`` (rad/s² per m) and ``intercept`` of
    the weighted straight line through the differences (NaN with fewer than 3 windows).

    See Also
    --------
    frame_windows : builds it from a table's joint fit.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import judge_table, paper_rig, table3
    >>> groups = {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]}
    >>> verdict = judge_table(table3(), groups, fps=120.0, step=np.pi / 2, rig=paper_rig(),
    ...                       permutation=False)
    >>> windows = verdict.difference.windows
    >>> windows.centres.round(2).tolist()
    [0.09, 0.28, 0.47, 0.66]
    """

    edges: np.ndarray
    centres: np.ndarray
    difference: np.ndarray
    stderr: np.ndarray
    minuend: GroupWindows
    subtrahend: GroupWindows
    trend: float
    trend_stderr: float
    intercept: float

    @property
    def resolved(self) -> np.ndarray:
        """Windows where the difference exceeds two standard errors."""
        return np.isfinite(self.difference) & (np.abs(self.difference) > 2 * self.stderr)

    @property
    def window_length(self) -> float:
        return float(self.edges[1] - self.edges[0])


def _line(x: np.ndarray, y: np.ndarray, se: np.ndarray) -> tuple[float, float, float]:
    """Weighted straight line ``y = a + b x``: ``(b, stderr of b, a)``."""
    ok = np.isfinite(y) & np.isfinite(se) & (se > 0)
    if np.count_nonzero(ok) < 3:
        return math.nan, math.nan, math.nan
    w = 1.0 / se[ok]
    design = np.column_stack([np.ones(np.count_nonzero(ok)), x[ok]]) * w[:, None]
    coef, *_ = np.linalg.lstsq(design, y[ok] * w, rcond=None)
    resid = design @ coef - y[ok] * w
    scale = max(float(resid @ resid) / (np.count_nonzero(ok) - 2), 1.0)
    cov = np.linalg.inv(design.T @ design) * scale
    return float(coef[1]), math.sqrt(float(cov[1, 1])), float(coef[0])


def windowed_difference(positions: list[np.ndarray], times: list[np.ndarray],
                        sigmas: list[np.ndarray], group_of_launch: np.ndarray,
                        minuend: int, subtrahend: int, radius: float,
                        n_windows: int = 5) -> WindowedDifference:
    """The model-free difference of two groups' accelerations along the track.

    ``positions`` (rad from each launch's release), ``times`` (s) and ``sigmas`` (s) per
    launch, its used rows only; ``group_of_launch``: group index per launch; ``radius`` (m)
    converts angle to track length; ``n_windows`` windows of equal length over the track
    every launch covers."""
    if n_windows < 1:
        raise ValueError("n_windows must be at least 1")
    top = min(float(np.max(p)) for p in positions)
    bottom = max(float(np.min(p)) for p in positions)
    edges = np.linspace(bottom, top * (1 + 1e-12), n_windows + 1)
    eps, se = zip(*(launch_windows(p, t, s, edges) for p, t, s in
                    zip(positions, times, sigmas, strict=True)), strict=True)
    eps, se = np.array(eps), np.array(se)
    g = np.asarray(group_of_launch)
    gm, gs = _group(eps[g == minuend], se[g == minuend]), _group(eps[g == subtrahend],
                                                                  se[g == subtrahend])
    diff = gm.mean - gs.mean
    dse = np.hypot(gm.stderr, gs.stderr)
    x = 0.5 * (edges[1:] + edges[:-1]) * radius
    trend, trend_se, icpt = _line(x, diff, dse)
    return WindowedDifference(edges * radius, x, diff, dse, gm, gs, trend, trend_se, icpt)
