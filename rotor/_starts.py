"""The start-state prior of the law-of-motion fits, their bounds and starting points.

The prior is physical: the start angle lies anywhere in the mark step before the first mark
(else that mark would have been read) and the start time follows from it (from rest, up to
``1/(sqrt 2 - 1)`` = 2.41 first-step durations before the first mark). The fit is global over
the start state: a closed-form profile over the start angle (:func:`start_profile`) gives
its starting points.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

__all__ = [
    "from_rest_estimate",
    "full_parameters",
    "inside_bounds",
    "parameter_bounds",
    "start_profile",
    "wave_period_range",
]


def parameter_bounds(t: np.ndarray, phi: np.ndarray, step: float, eps_ref: float) -> dict:
    """Parameter bounds from the physical prior. The start angle lies anywhere in the mark
    step before the first mark (else that earlier mark would have been read); the start
    time follows from it: released from rest a fraction ``x`` of a step before the first
    mark, the rotor needs ``sqrt(x)/(sqrt(1 + x) - sqrt(x))`` first-step durations to reach
    it (2.41 as ``x -> 1``), so the start time is bounded by three first-step durations
    (plus two frames of reading slack) before the first mark, not one. The unbalance
    components stay below the from-rest acceleration (a larger one would stall the rotor
    at every turn), and so do the plate wave's; its period lies in
    :func:`wave_period_range`."""
    order = np.argsort(phi)
    t_step = float(t[order[1]] - t[order[0]]) if t.size > 1 else 1.0
    t_first = float(t[order[0]])
    a_max = max(eps_ref, 1e-6)
    return {
        "eps0": (1e-9, np.inf),
        "eta": (0.0, np.inf),
        "gamma": (0.0, 50.0),
        "a_c": (-a_max, a_max),
        "a_s": (-a_max, a_max),
        "t0": (t_first - 3.0 * t_step - 2.0 * abs(t_step) / max(t.size, 1), t_first + t_step),
        "phi0": (float(phi[order[0]]) - step, float(phi[order[0]])),
        "wave_c": (-a_max, a_max),
        "wave_s": (-a_max, a_max),
        "wave_period": wave_period_range(phi, step),
    }


def wave_period_range(phi: np.ndarray, step: float) -> tuple[float, float]:
    """The plate-wave periods (rad of rotor turn) a column can resolve: from just above two
    mark steps (shorter waves alias onto longer ones between the marks) to the angle the
    column spans (a longer one is a trend, which the decay models describe)."""
    span = float(np.max(phi) - np.min(phi)) if np.size(phi) else 0.0
    lo = 2.05 * step
    return lo, max(span, 2.0 * lo)


def start_profile(t: np.ndarray, phi: np.ndarray, step: float,
                  n_grid: int = 64, keep: int = 2) -> list[dict[str, float]]:
    """Global starts for the constant-acceleration fit: a profile over the start angle.

    For a start ``phi0 = phi_first - x step`` the from-rest law ``t = t0 + c sqrt(phi -
    phi0)`` (``c = sqrt(2/eps0)``) is linear in ``(t0, c)``, so each ``x`` on a grid over
    [0, 1) gets its least-squares ``(t0, eps0)`` in closed form; the ``keep`` best grid
    points, each refined by golden-section search on ``x``, are returned as starting points
    (the fit's cost is multimodal in the start state, so one local start is not enough).
    """
    i0 = int(np.argmin(phi))
    pf = float(phi[i0])

    def sse(x: float) -> tuple[float, float, float]:
        root = np.sqrt(np.maximum(phi - (pf - x * step), 0.0))
        a = np.vstack([np.ones_like(root), root]).T
        coef, *_ = np.linalg.lstsq(a, t, rcond=None)
        r = a @ coef - t
        return float(r @ r), float(coef[0]), float(coef[1])

    xs = (np.arange(n_grid) + 0.5) / n_grid
    costs = np.array([sse(x)[0] for x in xs])
    out = []
    for j in np.argsort(costs)[:keep]:
        lo, hi = max(xs[j] - 1.0 / n_grid, 0.0), min(xs[j] + 1.0 / n_grid, 1.0 - 1e-9)
        g = (math.sqrt(5.0) - 1.0) / 2.0
        for _ in range(30):
            a1, b1 = hi - g * (hi - lo), lo + g * (hi - lo)
            if sse(a1)[0] < sse(b1)[0]:
                hi = b1
            else:
                lo = a1
        x = 0.5 * (lo + hi)
        _, t0, c = sse(x)
        if c > 0:
            out.append({"eps0": 2.0 / (c * c), "t0": t0, "phi0": pf - x * step})
    return out


def inside_bounds(x: float, lo: float, hi: float) -> float:
    w = 1e-9 * max(1.0, abs(x))
    if math.isfinite(lo):
        x = max(x, lo + w)
    if math.isfinite(hi):
        x = min(x, hi - w)
    return float(x)


def full_parameters(free: Sequence[str], x: Sequence[float], fixed: Mapping[str, float]) -> dict:
    p = {"eps0": 1.0, "eta": 0.0, "gamma": 0.0, "a_c": 0.0, "a_s": 0.0, "t0": 0.0, "phi0": 0.0,
         "wave_c": 0.0, "wave_s": 0.0, "wave_period": 2 * math.pi}
    p.update(fixed)
    p.update(zip(free, (float(v) for v in x)))
    return p


def from_rest_estimate(t: np.ndarray, phi: np.ndarray) -> float:
    # from rest at the first row: t = x sqrt(phi) is linear in x = sqrt(2/eps)
    i0 = int(np.argmin(phi))
    rt = t - t[i0]
    rp = np.maximum(phi - phi[i0], 0.0)
    x = float(np.sum(rt * np.sqrt(rp)) / max(float(np.sum(rp)), 1e-300))
    return 2.0 / x**2 if x > 0 else 1.0
