"""The forward model of the rotor's law of motion: the times at which the marks cross.

The equation of motion of the whole model family (:mod:`rotor._family`),

    phi'' = eps0 - eta (phi - phi0) - gamma phi' + a_c sin(phi) + a_s cos(phi)
            + wave_c sin(k phi) + wave_s cos(k phi),      k = 2 pi / wave_period

from rest at ``phi0`` at time ``t0``, solved for the time at given angles (the data are
times at known angles), for one parameter set or a batch of them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from functools import lru_cache

import numpy as np

__all__ = ["PARAM_NAMES", "STALL", "batch_crossing_times", "crossing_times", "model_speeds"]

PARAM_NAMES = ("eps0", "eta", "gamma", "a_c", "a_s", "t0", "phi0", "wave_c", "wave_s",
               "wave_period")
"""The parameters of the equation of motion, in the column order of a parameter batch."""
STALL = 1e-6
"""Floor of the specific kinetic energy per angle turned (rad/s²) where a model stalls, and
of the start acceleration: keeps the times finite (a barrier for the fits)."""


def crossing_times(
    phi: np.ndarray,
    eps0: float,
    eta: float = 0.0,
    gamma: float = 0.0,
    a_c: float = 0.0,
    a_s: float = 0.0,
    t0: float = 0.0,
    phi0: float = 0.0,
    wave_c: float = 0.0,
    wave_s: float = 0.0,
    wave_period: float = 2 * math.pi,
    *,
    n_grid: int = 700,
    max_sweeps: int = 200,
) -> np.ndarray:
    """Times (s) at which a rotor starting from rest reaches the angles ``phi`` (rad).

    The equation of motion is

        phi'' = eps0 - eta (phi - phi0) - gamma phi' + a_c sin(phi) + a_s cos(phi)

        + wave_c sin(k phi) + wave_s cos(k phi),      k = 2 pi / wave_period

    from rest at ``phi0`` at time ``t0``; ``A sin(phi + psi)`` with ``a_c = A cos(psi)``,
    ``a_s = A sin(psi)`` is the unbalance torque per inertia; the ``wave`` terms are a
    driving slope that undulates along the track with a period of ``wave_period`` (rad of
    rotor turn; a period of one turn is the unbalance's form).

    Parameters
    ----------
    phi : numpy.ndarray
        Angles (rad), in any order.
    eps0 : float
        Constant angular acceleration (rad/s²).
    eta : float
        Stiffness of a linear change of the acceleration with the angle (1/s²).
    gamma : float
        Speed-proportional (viscous) drag (1/s).
    a_c, a_s : float
        The unbalance torque per inertia (rad/s²).
    t0, phi0 : float
        Start time (s) and angle (rad) of the motion from rest.
    wave_c, wave_s, wave_period : float
        Amplitudes (rad/s²) and period (rad) of a track undulation.
    n_grid, max_sweeps : int
        Integration grid size and the Picard iteration's sweep limit.

    Returns
    -------
    numpy.ndarray
        The crossing times (s), shaped like ``phi``.

    See Also
    --------
    analyse_test : fits this model's family to a column of frame indices.

    Notes
    -----
    The data give times at known angles, so ``t(phi)`` is computed directly. With
    ``u = phi'^2/2``, ``du/dphi = eps(phi) - gamma sqrt(2u)``: without the speed term ``u`` is a
    closed form, with it a Picard iteration converges (its Lipschitz constant in the variable
    below is ``~2 gamma/sqrt(2 eps)``). The start singularity is removed by
    ``phi = phi0 + s^2``, where ``u ~ eps_start s^2`` and ``dt/ds = 2s/sqrt(2u)`` is smooth;
    the time is one cumulative trapezoid, accurate to ~1e-3 frame at 120 fps. Where the model
    stalls (``u <= 0``) the times become very large but finite: a barrier for the fits.
    Angles below ``phi0`` get ``t0``.

    Examples
    --------
    At constant acceleration from rest the times are ``sqrt(2 phi / eps0)``; a viscous drag
    makes the rotor later at every mark:

    >>> import numpy as np
    >>> from rotor import crossing_times
    >>> phi = np.arange(5) * np.pi / 2
    >>> crossing_times(phi, 2.0).round(4).tolist()
    [0.0, 1.2533, 1.7725, 2.1708, 2.5066]
    >>> np.sqrt(2 * phi / 2.0).round(4).tolist()
    [0.0, 1.2533, 1.7725, 2.1708, 2.5066]
    >>> crossing_times(phi, 2.0, gamma=0.1).round(3).tolist()
    [0.0, 1.28, 1.826, 2.252, 2.616]
    """
    phi = np.asarray(phi, dtype=float)
    p = np.array([[eps0, eta, gamma, a_c, a_s, t0, phi0, wave_c, wave_s, wave_period]],
                 dtype=float)
    return batch_crossing_times(phi.ravel(), p, n_grid, max_sweeps)[0].reshape(phi.shape)


def batch_crossing_times(phi: np.ndarray, p: np.ndarray, n_grid: int = 700,
                         max_sweeps: int = 200) -> np.ndarray:
    """:func:`crossing_times` for a batch of parameter rows ``p`` (B, 10), in the order of
    ``PARAM_NAMES``, at the angles ``phi`` (n,): returns (B, n). One vectorised pass, so a
    finite-difference Jacobian costs about one evaluation's overhead instead of p + 1."""
    eps0, eta, gamma, a_c, a_s, t0, phi0 = (p[:, j : j + 1] for j in range(7))
    wave_c, wave_s, wave_period = (p[:, j : j + 1] for j in range(7, 10))
    bsz = p.shape[0]
    if phi.size == 0:
        return np.zeros((bsz, 0))
    order = np.argsort(phi, kind="stable")
    rel = np.maximum(phi[order][None, :] - phi0, 0.0)  # (B, n)
    knots = np.zeros((bsz, phi.size + 1))
    np.sqrt(rel, out=knots[:, 1:])
    span = knots[0, -1]
    if span <= 0:
        out = np.broadcast_to(t0, (bsz, phi.size)).copy()
        return out
    # a grid of nearly uniform spacing in s on which the marks are nodes: each interval
    # between successive marks gets points in proportion to its length (at least 4); the
    # counts come from the first parameter row and serve the whole batch
    lens = np.diff(knots, axis=1)
    m = np.maximum(np.rint(n_grid * lens[0] / span).astype(np.int64), 4)
    ends, idx, step_no = _grid_layout(m.tobytes())
    h = lens / m  # (B, n)
    s = np.empty((bsz, int(ends[-1]) + 1))
    s[:, :-1] = knots[:, idx] + h[:, idx] * step_no
    s[:, -1] = knots[:, -1]
    hh = h[:, idx]

    def cumtrapz(y: np.ndarray) -> np.ndarray:
        out = np.empty_like(y)
        out[:, 0] = 0.0
        np.cumsum(0.5 * (y[:, 1:] + y[:, :-1]) * hh, axis=1, out=out[:, 1:])
        return out

    x = s * s
    u = eps0 * x
    if np.any(eta):
        u -= 0.5 * eta * x * x
    if np.any(a_c) or np.any(a_s):
        ang = phi0 + x
        u -= a_c * (np.cos(ang) - np.cos(phi0))
        u += a_s * (np.sin(ang) - np.sin(phi0))
    wavy = bool(np.any(wave_c) or np.any(wave_s))
    if wavy:
        k = 2.0 * np.pi / wave_period
        kang = k * (phi0 + x)
        u -= wave_c * (np.cos(kang) - np.cos(k * phi0)) / k
        u += wave_s * (np.sin(kang) - np.sin(k * phi0)) / k
    if np.any(gamma):
        u = _picard_speed_term(u, gamma, s, hh, max_sweeps)
    np.maximum(u, STALL * x, out=u)
    eps_start = eps0 + a_c * np.sin(phi0) + a_s * np.cos(phi0)
    if wavy:
        eps_start = eps_start + wave_c * np.sin(k * phi0) + wave_s * np.cos(k * phi0)
    eps_start = np.maximum(eps_start, STALL)
    g0 = 2.0 / np.sqrt(2.0 * eps_start)
    with np.errstate(divide="ignore", invalid="ignore"):
        g = 2.0 * s / np.sqrt(2.0 * u)
    # s = 0 (the start, repeated when the first mark is the start): the limit 2/sqrt(2 eps)
    g = np.where(s > 0, g, g0)
    t = cumtrapz(g)
    out = np.empty((bsz, phi.size))
    out[:, order] = t0 + t[:, ends]
    return out


@lru_cache(maxsize=64)
def _grid_layout(m_bytes: bytes) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For ``m`` grid points per mark interval: the end index of each interval, the
    interval of each grid point and its number within the interval (cached: the counts
    repeat from one evaluation to the next)."""
    m = np.frombuffer(m_bytes, dtype=np.int64)
    ends = np.cumsum(m)
    idx = np.repeat(np.arange(m.size), m)
    step_no = np.arange(int(ends[-1])) - np.repeat(ends - m, m)
    for a in (ends, idx, step_no):
        a.flags.writeable = False
    return ends, idx, step_no


def _picard_speed_term(u_pos: np.ndarray, gamma: np.ndarray, s: np.ndarray, hh: np.ndarray,
                       max_sweeps: int) -> np.ndarray:
    """``u = u_pos - gamma int 2 s sqrt(2 u) ds`` by Picard iteration to 1e-11 of ``u``'s
    scale (the speed term of :func:`crossing_times`), with the buffers reused."""
    scale = max(float(np.max(np.abs(u_pos))), 1e-300)
    two_s = 2.0 * s
    u = u_pos
    w = np.empty_like(u_pos)
    mid = np.empty((u_pos.shape[0], u_pos.shape[1] - 1))
    new = np.empty_like(u_pos)
    new[:, 0] = 0.0
    for _ in range(max_sweeps):
        np.maximum(u, 0.0, out=w)
        w *= 2.0
        np.sqrt(w, out=w)
        np.multiply(two_s, w, out=w)
        # the cumulative trapezoid of w, as in crossing_times
        np.add(w[:, 1:], w[:, :-1], out=mid)
        mid *= 0.5
        mid *= hh
        np.cumsum(mid, axis=1, out=new[:, 1:])
        new *= gamma
        np.subtract(u_pos, new, out=new)
        np.subtract(new, u, out=w)
        np.abs(w, out=w)
        done = float(np.max(w)) <= 1e-11 * scale
        u, new = new, (np.empty_like(u_pos) if u is u_pos else u)
        new[:, 0] = 0.0
        if done:
            break
    return u


def model_speeds(phi: np.ndarray, params: Mapping[str, float]) -> np.ndarray:
    """Model angular speed (rad/s) at the angles ``phi``."""
    d = 1e-4
    both = crossing_times(np.concatenate([phi, phi + d]), **{k: params[k] for k in PARAM_NAMES})
    n = phi.size
    dt = both[n:] - both[:n]
    return np.where(dt > 0, d / np.maximum(dt, 1e-300), 0.0)
