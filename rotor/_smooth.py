"""The last resort beyond the family: an unexplained smooth deviation of the acceleration.

When neither the core family nor the plate wave (:mod:`rotor._extension`) leaves an
adequate residual, the selected model's acceleration is given a free-form smooth addition

    da(phi) = sum_{j=2}^{K+1} c_j P_j(x),   x = 2 (phi - phi_first) / span - 1,

Legendre polynomials of the rotation angle over the marks (degrees 0 and 1 are left out:
they are a change of ``eps0`` and a position decay, members of the family). The addition is
linearised about the fit (first-order response of the crossing times, as the residual
periodogram of :mod:`rotor._adequacy`, with the model's own parameters free to move
with it), so a candidate costs one least-squares solve. Its BIC is the model's BIC less the
drop of the chi-square plus ``K ln n``; the number of modes ``K`` is the BIC choice, and the
smooth term is selected only when it beats the model by more than the selection margin (the
nested rule of :func:`rotor._selection.select_model`). It is tried only on columns the
calibrated adequacy check rejects, so a clean column is given one at most at the check's
false-alarm rate. What it reports is no effect with a cause: an "unexplained smooth
deviation" of a stated amplitude (largest ``|da|`` over the marks, rad/s²).

References
----------
Schwarz G. (1978) Estimating the dimension of a model. Ann. Stat. 6:461-464.
Abramowitz M., Stegun I.A. (1964) Handbook of mathematical functions, ch. 22 (Legendre
polynomials).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotor._adequacy import _base_jacobian, _cumulative
from rotor._diagnostics import lag1_autocorrelation, runs_test_z
from rotor._family import ModelFit
from rotor._forward import PARAM_NAMES, crossing_times

__all__ = ["MAX_MODES", "SmoothDeviation", "fit_smooth_deviation", "smooth_response"]

MAX_MODES = 10
"""Most Legendre modes (degrees 2 to 11) the smooth term may use."""


@dataclass(frozen=True)
class SmoothDeviation:
    """The selected smooth term (:func:`fit_smooth_deviation`).

    ``model``: the model it is added to; ``modes``: ``K``; ``coefficients`` (rad/s²) of
    ``P_2 .. P_{K+1}``; ``amplitude``: largest ``|da|`` over the marks (rad/s²) and
    ``at_angle`` (rad from the first mark) where it is reached; ``rms`` of ``da`` over the
    marks (rad/s²); ``delta_bic``: the model's BIC minus the smooth term's (> margin);
    ``runs_z`` and ``lag1`` of what is left after it (standardised, in angle order).
    """

    model: str
    modes: int
    coefficients: tuple[float, ...]
    amplitude: float
    at_angle: float
    rms: float
    delta_bic: float
    runs_z: float
    lag1: float


def _legendre(x: np.ndarray, degrees: range) -> np.ndarray:
    """Rows ``P_d(x)`` for ``d`` in ``degrees`` (Bonnet's recursion)."""
    p_prev, p = np.ones_like(x), x.copy()
    out = {0: p_prev, 1: p}
    for d in range(1, max(degrees)):
        p_prev, p = p, ((2 * d + 1) * x * p - d * p_prev) / (d + 1)
        out[d + 1] = p
    return np.array([out[d] for d in degrees])


def smooth_response(phi: np.ndarray, fit: ModelFit, lo: float, span: float,
                    modes: int) -> np.ndarray:
    """First-order change of the crossing times at ``phi`` per unit acceleration
    ``P_j(x)``, ``j = 2 .. modes + 1``: (n, modes). ``lo`` and ``span``: the first mark's
    angle and the angle the marks cover (rad), which map ``phi`` onto ``x``.

    With ``u = omega^2/2``: ``du' + (gamma/omega) du = da`` and ``dt = -int du/omega^3 dphi``,
    integrated on ``phi = phi0 + s^2`` (smooth at the release)."""
    phi0 = float(fit.params["phi0"])
    s_max = math.sqrt(max(float(np.max(phi)) - phi0, 1e-12))
    s = np.linspace(0.0, s_max, 1201)[1:]
    grid = phi0 + s * s
    # omega = dphi/dt from t(s), smooth in s at the release (a difference in phi is not)
    t = crossing_times(grid, **{k: fit.params[k] for k in PARAM_NAMES})
    dphi = 2.0 * s
    omega = np.maximum(dphi / np.maximum(np.gradient(t, s, edge_order=2), 1e-300), 1e-9)
    basis = _legendre(2.0 * (grid - lo) / span - 1.0, range(2, modes + 2))
    gamma = float(fit.params.get("gamma", 0.0))
    grow = np.exp(_cumulative(gamma / omega * dphi, s)) if gamma else np.ones_like(s)
    du = _cumulative(basis * grow * dphi, s) / grow
    dt = -_cumulative(du * (dphi / omega**3), s)
    sq = np.sqrt(np.maximum(phi - phi0, 0.0))
    return np.array([np.interp(sq, s, c) for c in dt]).T


def fit_smooth_deviation(angles: np.ndarray, fit: ModelFit, *, margin: float,
                         max_modes: int = MAX_MODES) -> SmoothDeviation | None:
    """The smooth term added to ``fit``, with the number of modes by BIC, if it beats ``fit``
    by more than ``margin`` (module docstring); else None."""
    phi = np.asarray(angles, float)
    use = np.asarray(fit.used, bool)
    ph = phi[use]
    sig = np.asarray(fit.sigma, float)[use]
    n = int(ph.size)
    jac = _base_jacobian(ph, fit, sig)
    top = min(max_modes, n - jac.shape[1] - 4)
    if top < 1:
        return None
    lo, span = float(np.min(ph)), float(np.ptp(ph))
    z = -np.asarray(fit.residuals, float)[use] / sig
    q = np.linalg.svd(jac, full_matrices=False)[0] if jac.shape[1] else np.zeros((n, 0))
    z_perp = z - q @ (q.T @ z)
    w = smooth_response(ph, fit, lo, span, top) / sig[:, None]
    w_perp = w - q @ (q.T @ w)
    chi0 = float(z_perp @ z_perp)
    best = (math.inf, 0, np.zeros(0))
    for k in range(1, top + 1):
        coef = np.linalg.lstsq(w_perp[:, :k], z_perp, rcond=None)[0]
        e = z_perp - w_perp[:, :k] @ coef
        bic = fit.bic - (chi0 - float(e @ e)) + k * math.log(n)
        if bic < best[0]:
            best = (bic, k, coef)
    bic, k, coef = best
    if not fit.bic - bic > margin:
        return None
    e = z_perp - w_perp[:, :k] @ coef
    order = np.argsort(ph, kind="stable")
    marks = np.linspace(lo, lo + span, 401)
    da = coef @ _legendre(2.0 * (marks - lo) / span - 1.0, range(2, k + 2))
    j = int(np.argmax(np.abs(da)))
    return SmoothDeviation(
        model=fit.model, modes=k, coefficients=tuple(float(c) for c in coef),
        amplitude=float(abs(da[j])), at_angle=float(marks[j] - lo),
        rms=float(np.sqrt(np.mean(da**2))), delta_bic=float(fit.bic - bic),
        runs_z=runs_test_z(e[order]), lag1=lag1_autocorrelation(e[order]))
