"""The joint law of motion of several launches on one track.

Every launch of a table rolls down the same plate from the same launch block, so the part of
the rotor's angular acceleration that comes from the plate (its slope, the slope's trend and
its waviness) is one function of the track position, shared by all launches. What may differ
between launches is a constant: the rolling-friction torque of the collar position (a group
offset, the only place where a dependence of ``M_r`` on the ball loads can show at constant
mass and inertia, Alaci et al. 2022 Eqs. 47-49) and launch-to-launch spread. So launch ``i``
obeys

    phi'' = delta_i + g(s),        s = phi - phi0_i >= 0,     g(0) = 0,

from rest at ``phi0_i`` (rad, <= 0: the release point before the first mark) at time
``t0_i``. The track function ``g`` is a Legendre series in the track position over the span
rolled, ``g(s) = sum_j beta_j [P_j(2 s / S - 1) - P_j(-1)]``, ``j = 1..m``: degree 1 is a
linear trend of the slope, higher degrees its waviness. A group-specific track has one
``beta`` vector per group.

The data are the times at which the marks cross. With ``u = phi'^2 / 2``,
``u(s) = delta s + sum_j beta_j G_j(s)`` in closed form (``G_j`` the integral of the basis),
and ``t = t0 + int_0^s ds' / sqrt(2 u)``, integrated by Gauss-Legendre quadrature in
``sigma = sqrt(s)`` between successive marks (the start singularity is removed). The
Jacobian is analytic: ``dt/dt0 = 1``, ``dt/dphi0 = -1/omega``, and for a coefficient ``c`` of
``u``, ``dt/dc = -int (du/dc) / (2u)^(3/2) ds``.

This forward model shares no code with :mod:`rotor._forward` (a cumulative trapezoid
on a grid) or with the ODE simulator (:mod:`rotor._simulator`) that tests it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre as leg

__all__ = ["TrackLayout", "track_acceleration", "track_basis", "track_times"]

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(8)
_U_FLOOR = 1e-9
"""Floor of ``u / s`` (rad/s²) where a trial model stalls: keeps times finite (a barrier)."""


@dataclass(frozen=True)
class TrackLayout:
    """How a parameter vector maps onto the launches.

    Attributes
    ----------
    span : float
        ``S`` (rad): the track span over which the Legendre series is defined.
    degree : int
        ``m``: number of track coefficients per track.
    group_of_launch : ndarray of int
        Index of each launch's group.
    n_tracks : int
        1 for a shared track, the number of groups for group-specific tracks.
    """

    span: float
    degree: int
    group_of_launch: np.ndarray
    n_tracks: int

    @property
    def n_launches(self) -> int:
        return int(self.group_of_launch.size)

    @property
    def n_params(self) -> int:
        return self.n_tracks * self.degree + 3 * self.n_launches

    def track_of_launch(self) -> np.ndarray:
        """Index of the track each launch rolls on."""
        if self.n_tracks == 1:
            return np.zeros(self.n_launches, dtype=int)
        return self.group_of_launch

    def split(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``beta`` (tracks, m), ``delta``, ``phi0``, ``t0`` (each per launch)."""
        nb = self.n_tracks * self.degree
        n = self.n_launches
        beta = x[:nb].reshape(self.n_tracks, self.degree)
        return beta, x[nb : nb + n], x[nb + n : nb + 2 * n], x[nb + 2 * n :]


def track_basis(s: np.ndarray, span: float, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """Basis values ``B_j(s)`` and their integrals ``G_j(s) = int_0^s B_j`` (``..., m``).

    ``int_{-1}^xi P_j = (P_{j+1} - P_{j-1}) / (2j + 1)`` (Abramowitz & Stegun 22.13.9... the
    recurrence of the Legendre polynomials' derivatives), and ``P_j(-1) = (-1)^j``.
    """
    xi = 2.0 * s / span - 1.0
    p = leg.legvander(xi, degree + 1)
    j = np.arange(1, degree + 1)
    p_start = np.where(j % 2 == 0, 1.0, -1.0)
    vals = p[..., 1 : degree + 1] - p_start
    ints = (0.5 * span * (p[..., 2 : degree + 2] - p[..., 0:degree]) / (2 * j + 1)
            - p_start * s[..., None])
    return vals, ints


def track_acceleration(s: np.ndarray, beta: np.ndarray, span: float) -> np.ndarray:
    """``g(s)`` (rad/s²) of one track's coefficients ``beta`` at track positions ``s`` (rad).

    ``g(s) = sum_j beta_j [P_j(2 s / S - 1) - P_j(-1)]``, ``j = 1..m``: the part of the
    angular acceleration that the plate adds at track position ``s``, zero at the start.

    Parameters
    ----------
    s : numpy.ndarray
        Track positions (rad of rotor turn since the release).
    beta : numpy.ndarray
        The ``m`` Legendre coefficients of the track (rad/s²); degree 1 is a linear trend.
    span : float
        ``S`` (rad): the span over which the series is defined.

    Returns
    -------
    numpy.ndarray
        ``g(s)``, shaped like ``s`` (rad/s²).

    See Also
    --------
    fit_table : fits the coefficients to a table's launches.

    Examples
    --------
    One coefficient is a linear trend, ``beta_1 (2 s / S)``; the second adds a parabola that
    vanishes at both ends:

    >>> import numpy as np
    >>> from rotor import track_acceleration
    >>> s = np.array([0.0, 10.0, 20.0])
    >>> track_acceleration(s, np.array([2.0]), 20.0).tolist()
    [0.0, 2.0, 4.0]
    >>> track_acceleration(s, np.array([2.0, 0.1]), 20.0).round(3).tolist()
    [0.0, 1.85, 4.0]
    """
    vals, _ = track_basis(np.asarray(s, float), span, beta.size)
    return vals @ beta


def track_times(x: np.ndarray, layout: TrackLayout, angles: np.ndarray, mask: np.ndarray,
                jacobian: bool = False) -> tuple[np.ndarray, np.ndarray | None]:
    """Crossing times of every launch at its mark angles.

    Parameters
    ----------
    x : ndarray
        The parameters in the order of :meth:`TrackLayout.split`.
    angles : ndarray (launches, K)
        Mark angles (rad from the first mark, increasing; padded rows repeat the last angle).
    mask : ndarray of bool (launches, K)
        Real (not padded) entries.
    jacobian : bool
        Also return ``dt/dx`` (launches, K, n_params).

    Returns
    -------
    times : ndarray (launches, K), s
    jac : ndarray or None
    """
    beta, delta, phi0, t0 = layout.split(np.asarray(x, float))
    tr = layout.track_of_launch()
    s_marks = np.maximum(angles - phi0[:, None], 0.0)
    sig = np.sqrt(s_marks)
    lo = np.concatenate([np.zeros((sig.shape[0], 1)), sig[:, :-1]], axis=1)
    half = 0.5 * (sig - lo)
    sig_q = 0.5 * (sig + lo)[..., None] + half[..., None] * _GAUSS_X  # (L, K, G)
    s_q = sig_q * sig_q
    _, ints_q = track_basis(s_q, layout.span, layout.degree)
    b = beta[tr]  # (L, m)
    u = delta[:, None, None] * s_q + np.einsum("lkgm,lm->lkg", ints_q, b)
    u = np.maximum(u, _U_FLOOR * s_q + 1e-300)
    two_u = 2.0 * u
    f = 2.0 * sig_q / np.sqrt(two_u)
    wq = half[..., None] * _GAUSS_W
    times = t0[:, None] + np.cumsum(np.sum(f * wq, axis=-1), axis=1)
    if not jacobian:
        return times, None
    # d/dc of the integrand 2 sigma (2u)^(-1/2) is -2 sigma (du/dc) (2u)^(-3/2)
    g3 = -2.0 * sig_q / (two_u * np.sqrt(two_u)) * wq  # (L, K, G)
    n_l, n_k = angles.shape
    jac = np.zeros((n_l, n_k, layout.n_params))
    m = layout.degree
    d_beta = np.cumsum(np.einsum("lkg,lkgm->lkm", g3, ints_q), axis=1)
    d_delta = np.cumsum(np.sum(g3 * s_q, axis=-1), axis=1)
    u_marks = np.maximum(delta[:, None] * s_marks + np.einsum(
        "lkm,lm->lk", track_basis(s_marks, layout.span, m)[1], b), _U_FLOOR * s_marks + 1e-300)
    d_phi0 = -1.0 / np.sqrt(2.0 * u_marks)
    nb = layout.n_tracks * m
    for i in range(n_l):
        jac[i, :, tr[i] * m : (tr[i] + 1) * m] = d_beta[i]
        jac[i, :, nb + i] = d_delta[i]
        jac[i, :, nb + n_l + i] = d_phi0[i]
        jac[i, :, nb + 2 * n_l + i] = 1.0
    jac[~mask] = 0.0
    return times, jac
