"""Adequacy of a fitted law of motion: is what the model leaves white reading noise?

A model explains a column when its residuals are reading noise: of a variance the data
estimate (the noise model of :mod:`rotor._noise`, with the frame quantisation as its
floor) and without order. Three statistics look at the order of the standardised residuals
``z = r / sigma`` taken in angle order:

* the Wald-Wolfowitz runs test on their signs (few runs: systematic);
* their lag-1 autocorrelation (positive: systematic);
* a periodogram of the residual *acceleration* against the rotation angle
  (:func:`wave_scan`): for each trial period ``P`` the share of the residuals that an
  acceleration ``B sin(2 pi phi / P + chi)`` added to the fitted model explains, to first
  order in ``B`` and with the model's own parameters free to move with it (their Jacobian is
  projected out). Its best period, amplitude (rad/s²) and phase characterise what is left.

Each is turned into a nominal one-sided p-value (normal for the runs z and for
``lag1 sqrt(n)``, the F test of two added regressors for the periodogram's best period); the
statistic is ``-log10`` of the smallest. Frame quantisation of a smoothly accelerating
rotor is *not* white (neighbouring rows share the fraction of a frame), so the nominal
p-values are only a scale: the p-value reported is calibrated by simulation, the share of
simulated clean columns over the declared prior (the one of the effect calibration) whose
statistic is at least as large (``adequacy_calibration.json``, written by
``benchmarks/rotor_adequacy.py``). A test is adequate unless that share is at most
:data:`ALPHA` (2 % false alarms per clean column).

References
----------
Wald A., Wolfowitz J. (1940) Ann. Math. Stat. 11:147-162.
Box G.E.P., Pierce D.A. (1970) Distribution of residual autocorrelations in
autoregressive-integrated moving average time series models. JASA 65:1509-1526.
Scargle J.D. (1982) Studies in astronomical time series analysis II. ApJ 263:835-853.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rotor._diagnostics import lag1_autocorrelation, runs_test_z
from rotor._family import MODELS, ModelFit
from rotor._forward import PARAM_NAMES, batch_crossing_times, model_speeds
from rotor._paper import BALL_RADIUS
from rotor._starts import wave_period_range

__all__ = [
    "ALPHA",
    "MIN_ROWS",
    "AdequacyCheck",
    "ResidualWave",
    "WaveScan",
    "adequacy_p_value",
    "check_adequacy",
    "named_wave",
    "residual_wave",
    "scan_peaks",
    "smooth_deletion_z",
    "wave_scan",
]

ALPHA = 0.02
"""Calibrated false-alarm rate per clean column at which a model is judged inadequate."""
MIN_ROWS = 10
"""Fewest rows the check judges: the calibration's prior starts at 10 rows."""
_CALIBRATION_FILE = Path(__file__).resolve().parent / "adequacy_calibration.json"
_CALIBRATION: dict | None = None


@dataclass(frozen=True)
class WaveScan:
    """The residual-acceleration periodogram of one fit (:func:`wave_scan`).

    ``periods`` (rad of rotor turn), and per period: ``share`` of the standardised residuals'
    sum of squares explained, ``amplitude`` ``B`` (rad/s²) and ``phase`` ``chi`` (rad) of the
    acceleration ``B sin(2 pi phi / P + chi)``, ``phi`` counted from the first mark.
    ``span`` is the angle the rows cover (rad), ``n`` the rows and ``p`` the model's free
    parameters.
    """

    periods: np.ndarray
    share: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    span: float
    n: int
    p: int

    @property
    def best(self) -> int:
        return int(np.argmax(self.share)) if self.share.size else -1


@dataclass(frozen=True)
class ResidualWave:
    """What a model leaves, as a wave of the rotation angle (or the fitted plate wave).

    ``period`` in rad of rotor turn, ``revolutions`` and ``track_length`` (m of track rolled
    per period, ``period x rolling radius``); ``amplitude`` (rad/s²); ``phase_rotor``: the
    phase at the first mark; ``phase_track``: the phase at the release point (start angle
    ``phi0`` of the fit), so that launches from the same place on the plate share it when
    the wave is a plate feature. ``unbalance_like``: the period is within one resolution
    (``P^2 / span``) of one turn, where a plate wave and an unbalance look the same.
    """

    period: float
    revolutions: float
    track_length: float
    amplitude: float
    phase_rotor: float
    phase_track: float
    unbalance_like: bool
    share: float


@dataclass(frozen=True)
class AdequacyCheck:
    """The adequacy of one fitted model (:func:`check_adequacy`).

    ``statistic``: ``-log10`` of the smallest nominal p-value of the three; ``p_value``: its
    calibrated probability on clean columns (NaN without a calibration); ``adequate``:
    ``p_value > ALPHA`` (True without a calibration); ``p_floor``: the smallest p-value the
    calibration can give, ``1/(n_clean + 1)``. ``runs_z``, ``lag1``, ``wave_share`` and their
    nominal p-values; ``residual``: the periodogram's best wave. ``judged`` is False for a
    column of fewer than :data:`MIN_ROWS` rows (outside the calibration: ``p_value`` NaN,
    ``adequate`` True).

    Attributes
    ----------
    model : str
        The model checked.
    statistic, p_value, p_floor : float
        The combined statistic, its calibrated p-value and the smallest one the calibration
        can give.
    adequate, judged : bool
        The verdict, and whether the column was long enough to judge.
    runs_z, lag1, wave_share : float
        The three statistics on the standardised residuals.
    nominal : dict of str to float
        Their nominal p-values (``runs``, ``lag1``, ``wave``).
    residual : ResidualWave or None
        The periodogram's best residual wave.
    scan : WaveScan or None
        The periodogram.

    See Also
    --------
    check_adequacy : builds it.

    Examples
    --------
    Clean constant-acceleration frames: the chosen model explains them.

    >>> import numpy as np
    >>> from rotor import analyse_test
    >>> phi = np.arange(25) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> report = analyse_test("s1", np.round(1000 + 120 * t))
    >>> check = report.adequacy
    >>> print(check.model, check.judged, check.adequate, check.p_value > 0.5)
    const True True True
    """

    model: str
    statistic: float
    p_value: float
    adequate: bool
    p_floor: float
    runs_z: float
    lag1: float
    wave_share: float
    nominal: dict[str, float]
    residual: ResidualWave | None
    scan: WaveScan | None
    judged: bool = True


def _normal_sf(x: float) -> float:
    return 0.5 * math.erfc(x / math.sqrt(2.0))


def _base_jacobian(phi: np.ndarray, fit: ModelFit, sigma: np.ndarray) -> np.ndarray:
    """Jacobian of the standardised times at ``phi`` in the fit's free parameters."""
    free = [k for k in MODELS[fit.model].free if k in PARAM_NAMES]
    x0 = np.array([fit.params[k] for k in PARAM_NAMES])
    rows = np.repeat(x0[None, :], len(free) + 1, axis=0)
    steps = []
    for j, k in enumerate(free):
        h = 1e-6 * max(1.0, abs(x0[PARAM_NAMES.index(k)]))
        rows[j + 1, PARAM_NAMES.index(k)] += h
        steps.append(h)
    tt = batch_crossing_times(phi, rows)
    if not free:
        return np.zeros((phi.size, 0))
    return ((tt[1:] - tt[0]) / np.array(steps)[:, None]).T / sigma[:, None]


def _wave_response(phi: np.ndarray, fit: ModelFit, periods: np.ndarray) -> np.ndarray:
    """First-order change of the crossing times at ``phi`` per unit acceleration
    ``sin(k phi)`` and ``cos(k phi)`` for each period: (n, 2 len(periods)).

    With ``u = omega^2/2``, ``du/dphi = eps(phi) - gamma omega``: an added ``da(phi)``
    changes ``u`` by ``du`` with ``du' + (gamma/omega) du = da`` (integrating factor
    ``exp G``, ``G = int gamma/omega dphi``; ``du = int da`` without the speed term) and the
    time by ``dt = -int du / omega^3 dphi``. On ``phi = phi0 + s^2`` the integrands are
    smooth at the start."""
    phi0 = float(fit.params["phi0"])
    s_max = math.sqrt(max(float(np.max(phi)) - phi0, 1e-12))
    s = np.linspace(0.0, s_max, 1201)[1:]
    grid = phi0 + s * s
    omega = np.maximum(model_speeds(grid, fit.params), 1e-9)
    k = 2.0 * math.pi / periods[:, None]
    du_sin = (np.cos(k * phi0) - np.cos(k * grid)) / k
    du_cos = (np.sin(k * grid) - np.sin(k * phi0)) / k
    gamma = float(fit.params.get("gamma", 0.0))
    if gamma:
        dphi = 2.0 * s  # dphi/ds
        big_g = _cumulative(gamma / omega * dphi, s)
        grow = np.exp(big_g)
        du_sin = _cumulative(np.sin(k * grid) * grow * dphi, s) / grow
        du_cos = _cumulative(np.cos(k * grid) * grow * dphi, s) / grow
    weight = 2.0 * s / omega**3
    resp = []
    for du in (du_sin, du_cos):
        y = du * weight
        cum = np.concatenate([np.zeros((y.shape[0], 1)),
                              np.cumsum(0.5 * (y[:, 1:] + y[:, :-1]) * np.diff(s), axis=1)],
                             axis=1)
        # from s = 0 to the first grid point the integrand is ~ its limit there
        cum = cum + y[:, :1] * s[0]
        sq = np.sqrt(np.maximum(phi - phi0, 0.0))
        resp.append(-np.array([np.interp(sq, s, c) for c in cum]))
    out = np.empty((phi.size, 2 * periods.size))
    out[:, 0::2] = resp[0].T
    out[:, 1::2] = resp[1].T
    return out


def _default_periods(ph: np.ndarray, step: float) -> np.ndarray:
    span = float(np.max(ph) - np.min(ph))
    lo, hi = wave_period_range(ph, step)
    n_per = int(min(max(3.0 * span * (1.0 / lo - 1.0 / hi), 12), 120))
    return 1.0 / np.linspace(1.0 / hi, 1.0 / lo, n_per)


def _design(angles: np.ndarray, fit: ModelFit, use: np.ndarray, periods: np.ndarray):
    """Standardised target ``-r/sigma``, the model's Jacobian and the wave responses on the
    rows ``use``."""
    ph = np.asarray(angles, float)[use]
    sig = np.asarray(fit.sigma, float)[use]
    z = -np.asarray(fit.residuals, float)[use] / sig
    return z, _base_jacobian(ph, fit, sig), _wave_response(ph, fit, periods) / sig[:, None]


def _cumulative(y: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Cumulative trapezoid of ``y`` over ``s`` from ``s = 0`` (``y`` taken as its first
    value below the first grid point)."""
    flat = np.ndim(y) == 1
    y = np.atleast_2d(y)
    out = np.concatenate([np.zeros((y.shape[0], 1)),
                          np.cumsum(0.5 * (y[:, 1:] + y[:, :-1]) * np.diff(s), axis=1)], axis=1)
    out = out + y[:, :1] * s[0]
    return out[0] if flat else out


def wave_scan(
    times: np.ndarray,
    angles: np.ndarray,
    fit: ModelFit,
    *,
    step: float,
    rows: np.ndarray | None = None,
    periods: np.ndarray | None = None,
) -> WaveScan:
    """The periodogram of ``fit``'s residual acceleration against the rotation angle.

    ``rows`` (mask) defaults to the fit's rows; other rows enter with their prediction errors.
    ``periods`` (rad) defaults to a grid even in frequency over the resolvable range
    (:func:`rotor._starts.wave_period_range`), three points per resolution element.
    """
    phi = np.asarray(angles, float)
    use = np.asarray(fit.used if rows is None else rows, bool)
    periods = _default_periods(phi[use], step) if periods is None else np.asarray(periods, float)
    z, jac, w = _design(phi, fit, use, periods)
    q = np.linalg.svd(jac, full_matrices=False)[0] if jac.shape[1] else np.zeros((z.size, 0))
    z_perp = z - q @ (q.T @ z)
    total = float(z_perp @ z_perp)
    w_perp = w - q @ (q.T @ w)
    share = np.zeros(periods.size)
    beta = np.zeros((periods.size, 2))
    for j in range(periods.size):
        x = w_perp[:, 2 * j : 2 * j + 2]
        b = x.T @ z_perp
        coef = np.linalg.lstsq(x.T @ x, b, rcond=None)[0]
        beta[j] = coef
        share[j] = float(b @ coef) / total if total > 0 else 0.0
    ph = phi[use]
    return WaveScan(periods=periods, share=np.clip(share, 0.0, 1.0),
                    amplitude=np.hypot(beta[:, 0], beta[:, 1]),
                    phase=np.arctan2(beta[:, 1], beta[:, 0]),
                    span=float(np.max(ph) - np.min(ph)), n=int(z.size), p=int(jac.shape[1]))


def smooth_deletion_z(angles: np.ndarray, fit: ModelFit, period: float) -> np.ndarray:
    """Each row's deletion residual (noise sigmas) under ``fit``'s model plus a wave of
    ``period``, linearised and fitted on every row (rows outside ``fit`` enter with their
    prediction errors): small where a smooth systematic deviation, not a misread, explains
    the row."""
    use = np.ones(np.shape(angles), bool)
    z, jac, w = _design(angles, fit, use, np.array([period]))
    x = np.hstack([jac, w])
    coef, *_ = np.linalg.lstsq(x, z, rcond=None)
    e = z - x @ coef
    h = np.einsum("ij,jk,ik->i", x, np.linalg.pinv(x.T @ x), x)
    return e / np.sqrt(np.maximum(1.0 - h, 1e-9))


def scan_peaks(scan: WaveScan, count: int = 2) -> list[int]:
    """Indices of the ``count`` highest local maxima of the scan's share."""
    s = scan.share
    if s.size == 0:
        return []
    peaks = [j for j in range(s.size) if (j == 0 or s[j] >= s[j - 1])
             and (j == s.size - 1 or s[j] >= s[j + 1])]
    return sorted(peaks, key=lambda j: -s[j])[:count]


def residual_wave(scan: WaveScan, fit: ModelFit, j: int | None = None,
                  rolling_radius: float = BALL_RADIUS) -> ResidualWave | None:
    """The scan's wave at index ``j`` (default its best): what ``fit`` leaves."""
    j = scan.best if j is None else j
    if j < 0:
        return None
    return _as_wave(float(scan.periods[j]), float(scan.amplitude[j]), float(scan.phase[j]),
                    float(scan.share[j]), fit, scan.span, rolling_radius)


def named_wave(fit: ModelFit, span: float,
               rolling_radius: float = BALL_RADIUS) -> ResidualWave | None:
    """The plate wave a wave model fitted (None for the other models); ``span``: the angle
    the column covers (rad), for the resolution.

    Parameters
    ----------
    fit : ModelFit
        A fitted model; only the plate-wave models (``wave``, ``position+wave``,
        ``speed+wave``) have a wave to name.
    span : float
        The angle the column covers (rad).
    rolling_radius : float
        The rolling radius (m) that turns the wave's period into a length of track.

    Returns
    -------
    ResidualWave or None
        The wave's period (rad, turns and m of track), amplitude (rad/s²) and phases; None
        for a model without a wave.

    See Also
    --------
    check_adequacy : finds a residual wave that a model leaves.

    Examples
    --------
    Column ``as1`` of Table 3 needs a plate wave: one of about 4.6 rotor turns, 0.58 m of
    track, 0.13 rad/s² in amplitude:

    >>> from rotor import analyse_test, named_wave, table3
    >>> report = analyse_test("as1", table3()["as1"])
    >>> wave = named_wave(report.fit, float(report.angles[-1]))
    >>> print(report.selected, f"{wave.revolutions:.1f} turns, {wave.track_length:.2f} m,"
    ...       f" {wave.amplitude:.2f} rad/s²")
    position+wave 4.6 turns, 0.58 m, 0.13 rad/s²
    >>> print(named_wave(report.fits["const"], float(report.angles[-1])))
    None
    """
    if "wave_c" not in MODELS[fit.model].free:
        return None
    p = fit.params
    return _as_wave(float(p["wave_period"]), math.hypot(p["wave_c"], p["wave_s"]),
                    math.atan2(p["wave_s"], p["wave_c"]), math.nan, fit, span, rolling_radius)


def _as_wave(period: float, amp: float, phase: float, share: float, fit: ModelFit,
             span: float, rolling_radius: float) -> ResidualWave:
    k = 2.0 * math.pi / period
    track = (phase + k * float(fit.params["phi0"])) % (2.0 * math.pi)
    return ResidualWave(
        period=period, revolutions=period / (2.0 * math.pi), track_length=period * rolling_radius,
        amplitude=amp, phase_rotor=phase % (2.0 * math.pi), phase_track=track,
        unbalance_like=bool(abs(1.0 / period - 1.0 / (2.0 * math.pi)) < 1.0 / max(span, 1e-12)),
        share=share)


def _calibration() -> dict | None:
    global _CALIBRATION
    if _CALIBRATION is None and _CALIBRATION_FILE.exists():
        _CALIBRATION = json.loads(_CALIBRATION_FILE.read_text())
    return _CALIBRATION


def adequacy_p_value(statistic: float) -> tuple[float, float]:
    """Calibrated p-value of an adequacy statistic, ``(k + 1)/(n + 1)`` with ``k`` of the
    ``n`` simulated clean columns at or above it, and the floor ``1/(n + 1)``; NaN, NaN
    without a calibration file."""
    cal = _calibration()
    if cal is None or not math.isfinite(statistic):
        return math.nan, math.nan
    clean = np.asarray(cal["statistic_clean"], float)
    k = int(np.count_nonzero(clean >= statistic))
    return (k + 1) / (clean.size + 1), 1.0 / (clean.size + 1)


def check_adequacy(times: np.ndarray, angles: np.ndarray, fit: ModelFit, *,
                   step: float) -> AdequacyCheck:
    """Is ``fit`` adequate? The three order statistics on its standardised residuals, their
    combination, its calibrated p-value and the best residual wave (module docstring).

    Parameters
    ----------
    times, angles : numpy.ndarray
        The column's crossing times (s) and mark angles (rad).
    fit : ModelFit
        The fitted model to check.
    step : float
        The angle between marks (rad).

    Returns
    -------
    AdequacyCheck
        The statistics, the calibrated p-value and the verdict (adequate when the p-value
        exceeds :data:`ALPHA`).

    See Also
    --------
    analyse_test : checks its chosen model this way.

    Examples
    --------
    A simulated run with an unbalanced rotor: constant acceleration leaves a wave of one
    turn in the residuals, the unbalance model does not:

    >>> import numpy as np
    >>> from rotor import analyse_test, check_adequacy, simulate_random_run
    >>> report = analyse_test("x1", simulate_random_run(3, "unbalance").frames)
    >>> for model in ("const", "unbalance"):
    ...     check = check_adequacy(report.times, report.angles, report.fits[model],
    ...                            step=np.pi / 2)
    ...     print(model, check.adequate)
    const False
    unbalance True
    """
    phi = np.asarray(angles, float)
    used = np.asarray(fit.used, bool)
    order = np.argsort(phi[used], kind="stable")
    z = (np.asarray(fit.residuals, float)[used] / np.asarray(fit.sigma, float)[used])[order]
    rz, l1 = runs_test_z(z), lag1_autocorrelation(z)
    scan = wave_scan(times, angles, fit, step=step)
    j = scan.best
    share = float(scan.share[j]) if j >= 0 else 0.0
    dof = max(scan.n - scan.p - 2, 1)
    nominal = {
        "runs": _normal_sf(-rz) if math.isfinite(rz) else 1.0,
        "lag1": _normal_sf(l1 * math.sqrt(z.size)) if math.isfinite(l1) else 1.0,
        "wave": float((1.0 - share) ** (dof / 2.0)),
    }
    stat = -math.log10(max(min(nominal.values()), 1e-300))
    judged = int(np.count_nonzero(used)) >= MIN_ROWS
    p, floor = adequacy_p_value(stat) if judged else (math.nan, math.nan)
    return AdequacyCheck(
        model=fit.model, statistic=stat, p_value=p,
        adequate=bool(not (p <= ALPHA)) if math.isfinite(p) else True, p_floor=floor,
        runs_z=rz, lag1=l1, wave_share=share, nominal=nominal,
        residual=residual_wave(scan, fit), scan=scan, judged=judged)
