"""The paper's parabolas: ``phi = c2 t^2 + c1 t + c0`` fitted on the angles, per test (a
member of the model family, reported beside the others) and through a group's mean times
(the paper's own fit).

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Materials 15(7):2518, Section 4.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from contact._errors import ContactInputError
from rotor._arrays import readonly
from rotor._diagnostics import (
    lag1_autocorrelation,
    minus_two_log_likelihood,
    runs_test_z,
)
from rotor._family import ModelFit
from rotor._noise import Noise, estimate_noise, quantisation_sigma
from rotor._paper import FPS, MARK_STEP

__all__ = ["fit_parabola", "paper_parabola"]


def fit_parabola(t, phi, used, fps, step) -> ModelFit:
    tu, pu = t[used], phi[used]
    n = int(used.sum())
    a = np.vstack([tu**2, tu, np.ones_like(tu)]).T
    coef, *_ = np.linalg.lstsq(a, pu, rcond=None)
    ang_used = a @ coef - pu
    dof = max(n - 3, 1)
    cov = float(ang_used @ ang_used) / dof * np.linalg.inv(a.T @ a)
    full = np.vstack([t**2, t, np.ones_like(t)]).T

    def inv(c: np.ndarray, ph: np.ndarray) -> np.ndarray:
        # the rising branch of the parabola; NaN where it never reaches the angle
        q2, q1, q0 = c
        if q2 <= 0:
            return np.full(ph.shape, np.nan)
        disc = q1 * q1 - 4 * q2 * (q0 - ph)
        return np.where(disc >= 0, (-q1 + np.sqrt(np.maximum(disc, 0))) / (2 * q2), np.nan)

    res = inv(coef, phi) - t
    idx = np.flatnonzero(used)
    press = np.empty(n)
    for j, i in enumerate(idx):
        keep = used.copy()
        keep[i] = False
        aa = np.vstack([t[keep] ** 2, t[keep], np.ones(int(keep.sum()))]).T
        cj, *_ = np.linalg.lstsq(aa, phi[keep], rcond=None)
        press[j] = float(inv(cj, phi[i : i + 1])[0] - t[i])
    ru = res[used]
    sq = quantisation_sigma(fps)
    finite = bool(np.all(np.isfinite(ru)))
    params = {"c2": float(coef[0]), "c1": float(coef[1]), "c0": float(coef[2])}
    if finite:
        omega = np.abs(2 * coef[0] * t + coef[1])
        noise = estimate_noise(ru, omega[used], 2 * coef[0], sq)
        sig = noise.sigma(omega, 2 * coef[0], int(np.argmin(phi)))
        chi2 = float(np.sum((ru / sig[used]) ** 2))
        bic = minus_two_log_likelihood(ru, sig[used]) + 5 * math.log(n)
        rss = float(ru @ ru)
    else:
        noise, sig, chi2, bic, rss = Noise(math.nan, math.nan), np.full(t.shape, np.nan), \
            math.inf, math.inf, math.inf
    return ModelFit(
        model="parabola",
        params=params,
        stderr={k: float(math.sqrt(cov[i, i])) for i, k in enumerate(("c2", "c1", "c0"))},
        residuals=readonly(res),
        sigma=readonly(sig),
        used=readonly(used),
        n=n,
        p=3,
        rss=rss,
        rms=math.sqrt(rss / n),
        chi2=chi2,
        noise=noise,
        bic=bic,
        loo_rms=float(np.sqrt(np.mean(press**2))) if np.all(np.isfinite(press)) else math.inf,
        chi2_quant=rss / (sq**2 * dof),
        runs_z=runs_test_z(ru) if finite else math.nan,
        lag1=lag1_autocorrelation(ru) if finite else math.nan,
        success=finite,
        press=readonly(press),
        angle_residuals=readonly(full @ coef - phi),
        angle_rms=float(math.sqrt(np.mean(ang_used**2))),
        loo_kind="exact",
    )


def paper_parabola(
    columns: Sequence[np.ndarray], fps: float = FPS, step: float = MARK_STEP
) -> tuple[np.ndarray, np.ndarray, float]:
    """The paper's fit: least-squares parabola ``phi = c2 t^2 + c1 t + c0`` through the mean
    time of the tests at each row (``t = (f_k - f_1)/fps``; rows where every test has a
    reading).

    Parameters
    ----------
    columns : sequence of numpy.ndarray
        The frame indices of each test, one array per test, rows aligned (NaN: no reading).
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).

    Returns
    -------
    coef : numpy.ndarray
        ``[c2, c1, c0]`` (rad/s², rad/s, rad); the acceleration is ``2 c2``.
    stderr : numpy.ndarray
        Their standard errors.
    rms : float
        The rms angle residual (rad).

    Raises
    ------
    ContactInputError
        Fewer than 4 rows.

    See Also
    --------
    analyse_table : the law of motion of each test, with its noise model.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518.

    Examples
    --------
    The asymmetric group's columns of Table 3 give the parabola the paper prints as its
    ``phi_s`` (0.821, 1.134, -0.527): the text's labels are swapped.

    >>> from rotor import paper_parabola, table3
    >>> table = table3()
    >>> coef, stderr, rms = paper_parabola([table["as1"], table["as2"], table["as3"]])
    >>> coef.round(3).tolist(), f"rms {rms:.2f} rad"
    ([0.821, 1.134, -0.527], 'rms 0.23 rad')
    """
    arr = np.vstack([np.asarray(c, float) for c in columns])
    if arr.shape[1] < 4:
        raise ContactInputError("the paper's parabola needs at least 4 rows")
    times = (arr - arr[:, :1]) / fps
    ok = np.all(np.isfinite(times), axis=0)
    tm = times[:, ok].mean(axis=0)
    phi = np.flatnonzero(ok) * step
    coef, cov = np.polyfit(tm, phi, 2, cov=True)
    res = np.polyval(coef, tm) - phi
    return coef, np.sqrt(np.diag(cov)), float(np.sqrt(np.mean(res**2)))
