"""An independent generator of clean rotor columns (not :mod:`contact.rotor_sim`).

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
