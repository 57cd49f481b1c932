"""An independent generator of clean rotor columns (not :mod:`rotor._simulator`).

A rotor released from rest with constant angular acceleration ``eps0``, a fraction ``x`` of
a mark step before the first mark (``x`` uniform in [0, 1)), at a release time uniform
within one frame; mark ``j`` is crossed at ``t_j = t_r + sqrt(2 (x + j) step / eps0)``
(closed form, nothing else), read as ``floor`` or ``round`` of ``t_j fps``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CleanColumn:
    frames: np.ndarray
    eps0: float
    fps: float
    step: float
    x: float


def clean_column(rng: np.random.Generator, *, fps: float | None = None,
                 step_deg: float | None = None, n: int | None = None,
                 eps0: float | None = None, x: float | None = None,
                 reading: str | None = None) -> CleanColumn:
    """One clean column drawn from the declared range (any argument fixes that draw)."""
    fps = float(rng.uniform(30.0, 1000.0)) if fps is None else float(fps)
    step_deg = float(rng.uniform(15.0, 360.0)) if step_deg is None else float(step_deg)
    n = int(rng.integers(10, 61)) if n is None else int(n)
    eps0 = float(rng.uniform(0.5, 5.0)) if eps0 is None else float(eps0)
    x = float(rng.uniform(0.0, 1.0)) if x is None else float(x)
    reading = str(rng.choice(["floor", "round"])) if reading is None else reading
    step = math.radians(step_deg)
    t_r = float(rng.uniform(0.0, 1.0)) / fps
    t = t_r + np.sqrt(2.0 * (x + np.arange(n)) * step / eps0)
    f = np.floor(t * fps) if reading == "floor" else np.floor(t * fps + 0.5)
    return CleanColumn(f, eps0, fps, step, x)


def effect_column(rng: np.random.Generator, *, fps: float, step_deg: float, n: int,
                  kind: str, size: float) -> CleanColumn:
    """A column with one effect, integrated with ``solve_ivp`` (events at the marks).

    ``kind``: ``position`` (``eps = eps0 - eta (phi - phi0)``) or ``speed`` (``- gamma
    omega``), ``size`` the fraction of eps0 lost over the run; ``unbalance``: ``A sin(phi +
    psi)`` with ``A = size eps0`` and a random phase. Release and reading as
    :func:`clean_column` (``floor``).
    """
    from scipy.integrate import solve_ivp

    eps0 = float(rng.uniform(0.5, 5.0))
    x = float(rng.uniform(0.0, 1.0))
    step = math.radians(step_deg)
    phi0 = -x * step
    phi_end = (n - 1) * step
    eta = gamma = amp = psi = 0.0
    if kind == "position":
        eta = size * eps0 / phi_end
    elif kind == "speed":
        gamma = size * eps0 / math.sqrt(2 * eps0 * (1 - size / 2) * phi_end)
    elif kind == "unbalance":
        amp, psi = size * eps0, float(rng.uniform(0.0, 2 * math.pi))
    else:
        raise ValueError(kind)

    def rhs(_t, y):
        return [y[1], eps0 - eta * (y[0] - phi0) - gamma * y[1] + amp * math.sin(y[0] + psi)]

    events = []
    for m in np.arange(n) * step:
        def ev(_t, y, m=m):
            return y[0] - m
        ev.direction = 1.0
        events.append(ev)
    t_end = 10.0 * math.sqrt(2.0 * (phi_end + step) / eps0) + 1.0
    sol = solve_ivp(rhs, (0.0, t_end), [phi0, 0.0], events=events, rtol=1e-10, atol=1e-12,
                    max_step=t_end / 200)
    t = np.array([e[0] for e in sol.t_events]) + float(rng.uniform(0.0, 1.0)) / fps
    return CleanColumn(np.floor(t * fps), eps0, fps, step, x)
