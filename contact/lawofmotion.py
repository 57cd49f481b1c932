"""Law of motion of a rolling rotor from frame indices: model family, fits, selection, misreads.

The data are like Table 3 of Alaci et al. (2022): for each launch ("test"), the frame index at
which the rotor has turned each further mark step (a quarter turn), filmed at ``fps``. Row
``k`` is at angle ``(k - k_first) step``; times are ``(f_k - f_first)/fps``. The paper assumes
constant angular acceleration from rest at the first mark and fits parabolas ``phi(t)``.

Model family (all but ``parabola`` are fitted by weighted least squares on the *times*, the
quantity that was measured):

``rest``
    constant acceleration from rest at the first mark (the paper's assumption; 1 parameter);
``parabola``
    the paper's general parabola ``phi = c2 t^2 + c1 t + c0`` fitted on the angles;
``const``
    constant acceleration from rest at an unknown start time ``t0`` and angle ``phi0``.
    The prior is physical: the start angle lies anywhere in the mark step before the first
    mark (else that mark would have been read) and the start time follows from it (from
    rest, up to ``1/(sqrt 2 - 1)`` = 2.41 first-step durations before the first mark). The
    fit is global over the start state: a closed-form profile over the start angle
    (:func:`_start_profile`) gives its starting points, and every richer model starts
    from its parents' optima (the unbalance models also from four phases);
``position``, ``speed``, ``position+speed``
    decaying acceleration: ``eps0 - eta (phi - phi0)`` (the driving slope changes along the
    plate) and/or ``eps0 - gamma omega`` (resistance growing with speed);
``unbalance`` and ``*+unbalance``
    a torque ``A sin(phi + psi)`` from a centre of mass off the axis, alone or combined.

Noise model. A row's time error has two parts: the frame grain and other timing scatter,
``sigma_t >= 1/(fps sqrt(12))``, and the scatter ``sigma_a`` (rad) in judging when a mark is at
the rod's axis, which costs ``sigma_a/omega`` in time and so weighs on the slow early rows
(on Table 3 the residuals are homoscedastic in angle, not in time). The first row is the time
origin (the launch) and has ``sigma_t`` only. Each model's noise is its maximum-likelihood
estimate from leverage-corrected residuals ``r/sqrt(1 - h)``, so that a model spending its
parameters on the few slow rows does not also shrink ``sigma_a`` there.

Selection: BIC (``-2 ln L + (p + 2) ln n``) with a margin: a model nested in the minimum-BIC one
wins unless the richer is better by more than ``margin`` (default 6, "strong" evidence in Kass
& Raftery's scale). The selection is calibrated by simulation over the declared range (frame
rate 30-1000 fps, mark step 15-360 deg, 10-60 rows, eps0 0.5-5 rad/s², start anywhere in the
step, 0-2 misread rows): ``benchmarks/rotor_calibration.py`` measures the false-effect rate
(``docs/rotor_calibration.md``) and writes the false-alarm probability against the evidence
(``rotor_calibration.json``) that qualifies each verdict (:func:`false_alarm_probability`).
Leave-one-point-out (approximate, from the leverages, or exact refits) and leave-one-test-out
prediction errors are reported beside, with a runs test and the lag-1
autocorrelation of the residuals to tell systematic misfit from noise.

Misread rows (a frame number mistyped or misjudged) are found by a forward-backward search on
externally studentised deletion residuals under a flexible model, with a Student-t noise
estimate that a few gross errors do not inflate (:func:`find_misread_rows`), then judged again
under the chosen model. The first row is never flagged: a misread first row is a start
offset, which the models fit anyway.

Quantisation convention: a mark crossing at true time ``t`` is read on the first frame that
shows it at or past the rod's axis, ``f = ceil(t fps)``; the half-frame bias this has against
rounding is common to all rows and absorbed by the start time. The error is uniform over one
frame: standard deviation ``1/(fps sqrt(12))`` = 2.4 ms at 120 fps.

References
----------
Alaci S., Ciornei F.-C., Romanu I.-C. (2022) Materials 15(7):2518, Eqs. (47)-(49), Table 3.
Schwarz G. (1978) Estimating the dimension of a model. Ann. Stat. 6:461-464.
Kass R.E., Raftery A.E. (1995) Bayes factors. J. Am. Stat. Assoc. 90:773-795.
Wald A., Wolfowitz J. (1940) On a test whether two samples are from the same population.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import least_squares

from contact.errors import ContactInputError

__all__ = [
    "BIC_MARGIN",
    "FPS",
    "MODELS",
    "PARAM_UNITS",
    "SELECTABLE",
    "STEP",
    "GroupComparison",
    "GroupReport",
    "LawOfMotionAnalysis",
    "MisreadSearch",
    "ModelFit",
    "ModelSpec",
    "Noise",
    "TestReport",
    "analyse_table",
    "analyse_test",
    "crossing_times",
    "false_alarm_probability",
    "find_misread_rows",
    "fit_all_models",
    "fit_model",
    "group_of",
    "leave_one_test_out",
    "loo_exact",
    "paper_parabola",
    "quantisation_sigma",
    "select_model",
    "verdict_evidence",
]

FPS = 120.0
STEP = math.pi / 2
BIC_MARGIN = 6.0
PARAM_NAMES = ("eps0", "eta", "gamma", "a_c", "a_s", "t0", "phi0")
PARAM_UNITS = {
    "eps0": "rad/s²",
    "eta": "1/s²",
    "gamma": "1/s",
    "a_c": "rad/s²",
    "a_s": "rad/s²",
    "t0": "s",
    "phi0": "rad",
    "c2": "rad/s²",
    "c1": "rad/s",
    "c0": "rad",
    "amplitude": "rad/s²",
    "phase": "rad",
}
_STALL = 1e-6


def quantisation_sigma(fps: float = FPS) -> float:
    """Standard deviation of the frame-quantisation error, ``1/(fps sqrt(12))``, s."""
    return 1.0 / (fps * math.sqrt(12.0))


# --------------------------------------------------------------------------------------------
# the forward model: crossing times
# --------------------------------------------------------------------------------------------


def crossing_times(
    phi: np.ndarray,
    eps0: float,
    eta: float = 0.0,
    gamma: float = 0.0,
    a_c: float = 0.0,
    a_s: float = 0.0,
    t0: float = 0.0,
    phi0: float = 0.0,
    *,
    n_grid: int = 700,
    max_sweeps: int = 200,
) -> np.ndarray:
    """Times (s) at which a rotor starting from rest reaches the angles ``phi`` (rad).

    The equation of motion is

        phi'' = eps0 - eta (phi - phi0) - gamma phi' + a_c sin(phi) + a_s cos(phi)

    from rest at ``phi0`` at time ``t0``; ``A sin(phi + psi)`` with ``a_c = A cos(psi)``,
    ``a_s = A sin(psi)`` is the unbalance torque per inertia.

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
    """
    phi = np.asarray(phi, dtype=float)
    p = np.array([[eps0, eta, gamma, a_c, a_s, t0, phi0]], dtype=float)
    return _times_batch(phi.ravel(), p, n_grid, max_sweeps)[0].reshape(phi.shape)


def _times_batch(phi: np.ndarray, p: np.ndarray, n_grid: int = 700,
                 max_sweeps: int = 200) -> np.ndarray:
    """:func:`crossing_times` for a batch of parameter rows ``p`` (B, 7), in the order of
    ``PARAM_NAMES``, at the angles ``phi`` (n,): returns (B, n). One vectorised pass, so a
    finite-difference Jacobian costs about one evaluation's overhead instead of p + 1."""
    eps0, eta, gamma, a_c, a_s, t0, phi0 = (p[:, j : j + 1] for j in range(7))
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
    ends = np.cumsum(m)
    idx = np.repeat(np.arange(phi.size), m)
    step_no = np.arange(int(ends[-1])) - np.repeat(ends - m, m)
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
    if np.any(gamma):
        u_pos = u
        scale = max(float(np.max(np.abs(u_pos))), 1e-300)
        two_s = 2.0 * s
        for _ in range(max_sweeps):
            w = np.sqrt(2.0 * np.maximum(u, 0.0))
            new = u_pos - gamma * cumtrapz(two_s * w)
            done = float(np.max(np.abs(new - u))) <= 1e-11 * scale
            u = new
            if done:
                break
    np.maximum(u, _STALL * x, out=u)
    eps_start = np.maximum(eps0 + a_c * np.sin(phi0) + a_s * np.cos(phi0), _STALL)
    g0 = 2.0 / np.sqrt(2.0 * eps_start)
    with np.errstate(divide="ignore", invalid="ignore"):
        g = 2.0 * s / np.sqrt(2.0 * u)
    # s = 0 (the start, repeated when the first mark is the start): the limit 2/sqrt(2 eps)
    g = np.where(s > 0, g, g0)
    t = cumtrapz(g)
    out = np.empty((bsz, phi.size))
    out[:, order] = t0 + t[:, ends]
    return out


# --------------------------------------------------------------------------------------------
# noise model
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Noise:
    """Reading noise of one test: ``sigma_i^2 = sigma_t^2 + (sigma_a / omega_i)^2``.

    ``sigma_t`` (s, at least the quantisation sigma) is scatter in time; ``sigma_a`` (rad) is
    scatter in judging when a mark overlaps the rod's axis, which costs more time where the
    rotor turns slowly. ``omega_i`` is the model's angular speed at the row, kept above
    ``sqrt(2 eps0 sigma_a)`` (the speed after turning ``sigma_a`` from rest).
    """

    sigma_t: float
    sigma_a: float

    def sigma(self, omega: np.ndarray, eps0: float, origin: int | None = None) -> np.ndarray:
        """Per-row sigma (s); the row ``origin`` (the first mark, the time origin, read
        as the launch) gets the time scatter only."""
        w2 = np.asarray(omega, float) ** 2 + 2.0 * max(eps0, _STALL) * self.sigma_a
        out = np.sqrt(self.sigma_t**2 + self.sigma_a**2 / np.maximum(w2, 1e-300))
        if origin is not None:
            out[origin] = self.sigma_t
        return out


def _speeds(phi: np.ndarray, params: Mapping[str, float]) -> np.ndarray:
    """Model angular speed (rad/s) at the angles ``phi``."""
    d = 1e-4
    both = crossing_times(np.concatenate([phi, phi + d]), **{k: params[k] for k in PARAM_NAMES})
    n = phi.size
    dt = both[n:] - both[:n]
    return np.where(dt > 0, d / np.maximum(dt, 1e-300), 0.0)


_T_NU = 4.0
_T_CONSISTENCY = 1.2033643751050191
"""For Gaussian data the Student-t (nu = 4) maximum-likelihood scale is 0.831 sigma; this
factor makes the robust noise estimate consistent with the Gaussian one."""


def _estimate_noise(r: np.ndarray, omega: np.ndarray, eps0: float, sigma_q: float,
                    start: Noise | None = None, robust: bool = False) -> Noise:
    """Maximum-likelihood ``(sigma_t >= sigma_q, sigma_a >= 0)`` for residuals ``r`` (s).

    ``robust``: Student-t likelihood (nu = 4), so that a few gross errors (misread rows) do
    not inflate the scale; the result is rescaled to be consistent with the Gaussian one.
    Two parameters only, so a coarse-to-fine grid (vectorised) is cheap and cannot stall.
    """
    r2 = np.asarray(r, float) ** 2
    if r2.size == 0:
        return Noise(sigma_q, 0.0)
    sa0 = start.sigma_a if start is not None else 0.0
    v = 1.0 / np.maximum(np.asarray(omega, float) ** 2
                         + 2.0 * max(eps0, _STALL) * max(sa0, 0.01), 1e-300)
    q2 = sigma_q**2
    vs = float(np.mean(v))
    vn = v / vs
    c2 = _T_CONSISTENCY**2 if robust else 1.0

    def nll(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        var = (q2 * (1.0 + a[:, None, None]) + q2 * b[None, :, None] * vn) / c2
        if robust:
            terms = np.log(var) + (_T_NU + 1) * np.log1p(r2 / (_T_NU * var))
        else:
            terms = np.log(var) + r2 / var
        return terms.sum(axis=-1)

    top = math.log10(max(float(r2.max()) / q2, 1.0)) + 1.0
    a = np.concatenate(([0.0], np.logspace(-3, top, 31)))
    b = np.concatenate(([0.0], np.logspace(-3, top, 31)))
    for _ in range(3):
        grid = nll(a, b)
        i, j = np.unravel_index(int(np.argmin(grid)), grid.shape)
        a_best, b_best = float(a[i]), float(b[j])
        a = np.linspace(a[max(i - 1, 0)], a[min(i + 1, a.size - 1)], 15)
        b = np.linspace(b[max(j - 1, 0)], b[min(j + 1, b.size - 1)], 15)
    return Noise(float(math.sqrt(q2 * (1.0 + a_best))), float(math.sqrt(q2 * b_best / vs)))


# --------------------------------------------------------------------------------------------
# the model family
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ModelSpec:
    """One model of the family: its free parameters, effect class and nested parents."""

    name: str
    free: tuple[str, ...]
    effect: str
    decay_form: str | None
    parents: tuple[str, ...]
    description: str


MODELS: dict[str, ModelSpec] = {
    spec.name: spec
    for spec in (
        ModelSpec("rest", ("eps0",), "none", None, (),
                  "constant acceleration from rest at the first mark (the paper's assumption)"),
        ModelSpec("parabola", ("c2", "c1", "c0"), "none", None, (),
                  "general parabola phi(t) fitted on the angles (the paper's fit)"),
        ModelSpec("const", ("eps0", "t0", "phi0"), "none", None, ("rest",),
                  "constant acceleration from rest at an unknown start time and angle"),
        ModelSpec("position", ("eps0", "eta", "t0", "phi0"), "decaying", "position", ("const",),
                  "acceleration decaying with angle (driving slope changing along the plate)"),
        ModelSpec("speed", ("eps0", "gamma", "t0", "phi0"), "decaying", "speed", ("const",),
                  "acceleration decaying with speed (resistance growing with speed)"),
        ModelSpec("unbalance", ("eps0", "a_c", "a_s", "t0", "phi0"), "unbalance", None,
                  ("const",), "constant acceleration plus an unbalance torque A sin(phi+psi)"),
        ModelSpec("position+speed", ("eps0", "eta", "gamma", "t0", "phi0"), "decaying",
                  "position+speed", ("position", "speed"), "both decay forms"),
        ModelSpec("position+unbalance", ("eps0", "eta", "a_c", "a_s", "t0", "phi0"),
                  "decaying+unbalance", "position", ("position", "unbalance"),
                  "position decay and unbalance"),
        ModelSpec("speed+unbalance", ("eps0", "gamma", "a_c", "a_s", "t0", "phi0"),
                  "decaying+unbalance", "speed", ("speed", "unbalance"),
                  "speed decay and unbalance"),
        ModelSpec("position+speed+unbalance",
                  ("eps0", "eta", "gamma", "a_c", "a_s", "t0", "phi0"), "decaying+unbalance",
                  "position+speed",
                  ("position+speed", "position+unbalance", "speed+unbalance"),
                  "both decay forms and unbalance"),
    )
}
ORDER = tuple(MODELS)
"""Fitting order: every model after its parents."""
SELECTABLE = tuple(name for name in MODELS if name != "parabola")
"""Models that take part in the selection. ``parabola`` is reported, not selected: it is the
``const`` curve fitted on the wrong axis and without the physical start."""


@dataclass(frozen=True)
class ModelFit:
    """One model fitted to one test.

    Attributes
    ----------
    model : str
    params : dict
        Every parameter of the equation of motion (free ones fitted, the others at their fixed
        value), SI: ``eps0`` rad/s², ``eta`` 1/s², ``gamma`` 1/s, ``a_c``/``a_s`` rad/s², ``t0``
        s (relative to the first row), ``phi0`` rad; derived ``amplitude`` (rad/s²) and
        ``phase`` (rad) of the unbalance ``A sin(phi + psi)``. For ``parabola``: ``c2, c1, c0``.
    stderr : dict
        Standard errors of the free parameters (NaN at an active bound).
    residuals : ndarray
        Model minus measured time (s) at every row; for rows left out, the prediction error.
    sigma : ndarray
        The noise model's standard deviation (s) at every row.
    used : ndarray of bool
    n, p : int
        Rows used, free parameters.
    rss, rms : float
        Unweighted residual sum of squares (s²) and rms (s) over the used rows.
    chi2 : float
        Weighted residual sum of squares ``sum (r/sigma)^2``.
    noise : Noise
        Maximum-likelihood reading noise for this model.
    bic : float
        ``-2 ln L + (p + 2) ln n`` (the 2 noise parameters are counted for every model).
    loo_rms : float
        Leave-one-point-out prediction rms (s): from the leverages (``loo_kind`` "approx") or
        from refits ("exact").
    chi2_quant : float
        ``rss / (sigma_q^2 (n - p))``: about 1 when the residuals are at the quantisation floor.
    runs_z : float
        Wald-Wolfowitz runs test on the residual signs (strongly negative: systematic).
    lag1 : float
        Lag-1 autocorrelation of the residuals.
    angle_residuals, angle_rms :
        ``parabola`` only: its residuals on the angles (rad), as the paper fitted.
    """

    model: str
    params: dict[str, float]
    stderr: dict[str, float]
    residuals: np.ndarray
    sigma: np.ndarray
    used: np.ndarray
    n: int
    p: int
    rss: float
    rms: float
    chi2: float
    noise: Noise
    bic: float
    loo_rms: float
    chi2_quant: float
    runs_z: float
    lag1: float
    success: bool
    press: np.ndarray | None = None
    leverage: np.ndarray | None = None
    angle_residuals: np.ndarray | None = None
    angle_rms: float | None = None
    loo_kind: str = "approx"

    @property
    def spec(self) -> ModelSpec:
        return MODELS[self.model]

    @property
    def effect(self) -> str:
        return self.spec.effect

    @property
    def eps0(self) -> float:
        """Initial angular acceleration (smooth part, at the start of motion), rad/s²."""
        if self.model == "parabola":
            return 2.0 * self.params["c2"]
        return self.params["eps0"]

    @property
    def eps0_stderr(self) -> float:
        if self.model == "parabola":
            return 2.0 * self.stderr["c2"]
        return self.stderr.get("eps0", math.nan)


def _freeze(a: np.ndarray) -> np.ndarray:
    a = np.array(a, copy=True)
    a.flags.writeable = False
    return a


def _m2ll(r: np.ndarray, sigma: np.ndarray) -> float:
    return float(np.sum(np.log(2 * math.pi * sigma**2) + (r / sigma) ** 2))


def _runs_z(r: np.ndarray) -> float:
    signs = r[r != 0] > 0
    n1 = int(signs.sum())
    n2 = int(signs.size - n1)
    n = n1 + n2
    if n1 == 0 or n2 == 0 or n < 3:
        return math.nan
    runs = 1 + int(np.count_nonzero(signs[1:] != signs[:-1]))
    mu = 2.0 * n1 * n2 / n + 1.0
    var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0))
    return (runs - mu) / math.sqrt(var) if var > 0 else math.nan


def _lag1(r: np.ndarray) -> float:
    den = float(np.sum(r * r))
    return float(np.sum(r[1:] * r[:-1]) / den) if den > 0 else math.nan


def _derived(params: dict[str, float]) -> dict[str, float]:
    out = dict(params)
    amp = math.hypot(params.get("a_c", 0.0), params.get("a_s", 0.0))
    out["amplitude"] = amp
    out["phase"] = math.atan2(params.get("a_s", 0.0), params.get("a_c", 0.0)) if amp else 0.0
    return out


def _bounds(t: np.ndarray, phi: np.ndarray, step: float, eps_ref: float) -> dict:
    """Parameter bounds from the physical prior. The start angle lies anywhere in the mark
    step before the first mark (else that earlier mark would have been read); the start
    time follows from it: released from rest a fraction ``x`` of a step before the first
    mark, the rotor needs ``sqrt(x)/(sqrt(1 + x) - sqrt(x))`` first-step durations to reach
    it (2.41 as ``x -> 1``), so the start time is bounded by three first-step durations
    (plus two frames of reading slack) before the first mark, not one. The unbalance
    components stay below the from-rest acceleration (a larger one would stall the rotor
    at every turn)."""
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
    }


def _start_profile(t: np.ndarray, phi: np.ndarray, step: float,
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


def _interior(x: float, lo: float, hi: float) -> float:
    w = 1e-9 * max(1.0, abs(x))
    if math.isfinite(lo):
        x = max(x, lo + w)
    if math.isfinite(hi):
        x = min(x, hi - w)
    return float(x)


def _full_params(free: Sequence[str], x: Sequence[float], fixed: Mapping[str, float]) -> dict:
    p = {"eps0": 1.0, "eta": 0.0, "gamma": 0.0, "a_c": 0.0, "a_s": 0.0, "t0": 0.0, "phi0": 0.0}
    p.update(fixed)
    p.update(zip(free, (float(v) for v in x)))
    return p


def _rest_estimate(t: np.ndarray, phi: np.ndarray) -> float:
    # from rest at the first row: t = x sqrt(phi) is linear in x = sqrt(2/eps)
    i0 = int(np.argmin(phi))
    rt = t - t[i0]
    rp = np.maximum(phi - phi[i0], 0.0)
    x = float(np.sum(rt * np.sqrt(rp)) / max(float(np.sum(rp)), 1e-300))
    return 2.0 / x**2 if x > 0 else 1.0


def _parabola_fit(t, phi, used, fps, step) -> ModelFit:
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
        noise = _estimate_noise(ru, omega[used], 2 * coef[0], sq)
        sig = noise.sigma(omega, 2 * coef[0], int(np.argmin(phi)))
        chi2 = float(np.sum((ru / sig[used]) ** 2))
        bic = _m2ll(ru, sig[used]) + 5 * math.log(n)
        rss = float(ru @ ru)
    else:
        noise, sig, chi2, bic, rss = Noise(math.nan, math.nan), np.full(t.shape, np.nan), \
            math.inf, math.inf, math.inf
    return ModelFit(
        model="parabola",
        params=params,
        stderr={k: float(math.sqrt(cov[i, i])) for i, k in enumerate(("c2", "c1", "c0"))},
        residuals=_freeze(res),
        sigma=_freeze(sig),
        used=_freeze(used),
        n=n,
        p=3,
        rss=rss,
        rms=math.sqrt(rss / n),
        chi2=chi2,
        noise=noise,
        bic=bic,
        loo_rms=float(np.sqrt(np.mean(press**2))) if np.all(np.isfinite(press)) else math.inf,
        chi2_quant=rss / (sq**2 * dof),
        runs_z=_runs_z(ru) if finite else math.nan,
        lag1=_lag1(ru) if finite else math.nan,
        success=finite,
        press=_freeze(press),
        angle_residuals=_freeze(full @ coef - phi),
        angle_rms=float(math.sqrt(np.mean(ang_used**2))),
        loo_kind="exact",
    )


def fit_model(
    times: np.ndarray,
    angles: np.ndarray,
    model: str,
    *,
    fps: float = FPS,
    step: float = STEP,
    used: np.ndarray | None = None,
    inits: Sequence[Mapping[str, float]] = (),
    noise: Noise | None = None,
    noise_start: Noise | None = None,
    loss: str = "linear",
    irls: int = 1,
    max_starts: int = 2,
    max_nfev: int | None = None,
) -> ModelFit:
    """Fit one model of the family on the times, weighted by the reading-noise model.

    Parameters
    ----------
    times, angles : ndarray
        Times (s, 0 at the first row) and angles (rad, 0 at the first row) of one test.
    model : str
        A key of :data:`MODELS`.
    fps, step : float
        Frame rate (quantisation floor) and mark step (bound on the start angle).
    used : ndarray of bool, optional
        Rows in the fit (default all); the others get prediction errors.
    inits : sequence of dict
        Starting points; the best fit over them is kept (missing parameters start at 0,
        ``eps0`` at the from-rest estimate).
    noise : Noise, optional
        Fixed reading noise. Default: estimated by maximum likelihood, alternating with the
        weighted fit ``irls`` times (iteratively reweighted least squares), from
        ``noise_start`` (default: quantisation only).
    loss : str
        ``least_squares`` loss on the standardised residuals (``soft_l1`` for robust fits).
    irls : int
        Reweighting rounds when the noise is estimated.
    max_starts : int
        The fit starts from this many of ``inits``, those that fit best as they are.
    max_nfev : int, optional
        Iteration budget of each least-squares run (default ``15 * n_params``): a model
        that cannot describe the data wanders for hundreds of iterations in a nearly flat
        valley without a better fit at the end.
    """
    if model not in MODELS:
        raise ContactInputError(f"unknown model {model!r}; known: {', '.join(MODELS)}")
    t = np.asarray(times, dtype=float)
    phi = np.asarray(angles, dtype=float)
    if t.shape != phi.shape or t.ndim != 1:
        raise ContactInputError("times and angles must be 1-D arrays of the same length")
    used = np.ones(t.shape, bool) if used is None else np.asarray(used, bool)
    n = int(used.sum())
    spec = MODELS[model]
    if n <= len(spec.free) + 2:
        raise ContactInputError(
            f"model {model!r} has {len(spec.free)} parameters; {n} rows are too few to fit it"
        )
    if model == "parabola":
        return _parabola_fit(t, phi, used, fps, step)
    free = spec.free
    sq = quantisation_sigma(fps)
    tu, pu = t[used], phi[used]
    i0 = int(np.argmin(phi))
    fixed = {"t0": float(t[i0]), "phi0": float(phi[i0])} if model == "rest" else {}
    eps_rest = _rest_estimate(tu, pu)
    bd = _bounds(tu, pu, step, eps_rest)
    lo = np.array([bd[k][0] for k in free])
    hi = np.array([bd[k][1] for k in free])

    starts = []
    for start in list(inits) or [{}]:
        base = {"eps0": eps_rest, "t0": float(t[i0]), "phi0": float(phi[i0]) - 1e-6}
        base.update({k: v for k, v in start.items() if k in free})
        starts.append(np.array([_interior(base.get(k, 0.0), lo[j], hi[j])
                                for j, k in enumerate(free)]))

    cur_noise = noise if noise is not None else (noise_start or Noise(sq, 0.0))
    if max_nfev is None:
        max_nfev = 15 * len(free)

    cols = [PARAM_NAMES.index(k) for k in free]
    base_row = np.array([_full_params(free, np.zeros(len(free)), fixed)[k]
                         for k in PARAM_NAMES])

    def rows(xs: np.ndarray) -> np.ndarray:
        pr = np.repeat(base_row[None, :], xs.shape[0], axis=0)
        pr[:, cols] = xs
        return pr

    def solve(x0s: list[np.ndarray], sig_u: np.ndarray):
        def fun(x: np.ndarray) -> np.ndarray:
            return (_times_batch(pu, rows(x[None, :]))[0] - tu) / sig_u

        def jac(x: np.ndarray) -> np.ndarray:
            # forward differences, stepping inwards at an upper bound, in one batch
            hstep = 1e-7 * np.maximum(1.0, np.abs(x))
            hstep = np.where(x + hstep > hi, -hstep, hstep)
            xs = np.repeat(x[None, :], len(x) + 1, axis=0)
            xs[1:] += np.diag(hstep)
            tt = _times_batch(pu, rows(xs))
            return ((tt[1:] - tt[0]) / hstep[:, None]).T / sig_u[:, None]

        best = None
        for x0 in x0s:
            # tolerances well below the noise: 1e-7 of the cost is ~1e-5 sigma in time
            r = least_squares(fun, x0, jac=jac, bounds=(lo, hi), x_scale="jac", loss=loss,
                              method="trf", max_nfev=max_nfev, ftol=1e-7, xtol=1e-7)
            if best is None or r.cost < best.cost:
                best = r
        return best

    # weights from the best starting point's speeds
    def sigmas(x: np.ndarray, nz: Noise) -> np.ndarray:
        p = _full_params(free, x, fixed)
        return nz.sigma(_speeds(phi, p), p["eps0"], i0)

    def cost0(x0: np.ndarray) -> float:
        r = crossing_times(pu, **_full_params(free, x0, fixed)) - tu
        return float(np.sum((r / sigmas(x0, cur_noise)[used]) ** 2))

    x0s = sorted(starts, key=cost0)[:max_starts]
    rounds = max(irls, 1) if noise is None else 1
    best = None
    sig = sigmas(x0s[0], cur_noise)
    for it in range(rounds + 1):
        best = solve([best.x] if best is not None else x0s, sig[used])
        if it == rounds:
            break
        if noise is None:
            # the noise from leverage-corrected residuals r/sqrt(1 - h): a model that spends
            # its parameters on the few slow early rows does not also shrink sigma_a there
            p = _full_params(free, best.x, fixed)
            r = crossing_times(pu, **p) - tu
            jf = np.asarray(best.jac)[:, np.asarray(best.active_mask) == 0]
            lev = (np.einsum("ij,jk,ik->i", jf, np.linalg.pinv(jf.T @ jf), jf)
                   if jf.shape[1] else np.zeros(r.size))
            keep = np.flatnonzero(used) != i0
            rc = r / np.sqrt(np.maximum(1.0 - lev, 1e-6))
            cur_noise = _estimate_noise(rc[keep], _speeds(pu, p)[keep], p["eps0"], sq,
                                        cur_noise)
        new_sig = sigmas(best.x, cur_noise)
        # the weights depend on the fitted speeds; refit only if they moved
        if noise is not None and np.max(np.abs(new_sig / sig - 1.0)) < 0.02:
            break
        sig = new_sig
    return _finish_fit(model, t, phi, used, free, fixed, best, cur_noise, fps, sq)


def _finish_fit(model, t, phi, used, free, fixed, r, noise, fps, sq) -> ModelFit:
    params = _full_params(free, r.x, fixed)
    res = crossing_times(phi, **params) - t
    sig = noise.sigma(_speeds(phi, params), params["eps0"], int(np.argmin(phi)))
    ru = res[used]
    su = sig[used]
    n = int(used.sum())
    p = len(free)
    chi2 = float(np.sum((ru / su) ** 2))
    jac = np.asarray(r.jac, dtype=float)  # of the standardised residuals
    active = np.asarray(r.active_mask) != 0
    jf = jac[:, ~active]
    stderr = {k: math.nan for k in free}
    lev = np.zeros(n)
    if jf.shape[1]:
        jtj_inv = np.linalg.pinv(jf.T @ jf)
        cov = max(chi2 / max(n - p, 1), 1.0) * jtj_inv
        for j, k in enumerate(np.array(free)[~active]):
            stderr[str(k)] = float(math.sqrt(max(cov[j, j], 0.0)))
        lev = np.einsum("ij,jk,ik->i", jf, jtj_inv, jf)
    press = ru / np.maximum(1.0 - lev, 1e-6)
    # the first row is the time origin of every model: it is not predicted
    not_first = np.flatnonzero(used) != int(np.argmin(phi))
    rss = float(ru @ ru)
    return ModelFit(
        model=model,
        params=_derived(params),
        stderr=stderr,
        residuals=_freeze(res),
        sigma=_freeze(sig),
        used=_freeze(used),
        n=n,
        p=p,
        rss=rss,
        rms=math.sqrt(rss / n),
        chi2=chi2,
        noise=noise,
        bic=_m2ll(ru, su) + (p + 2) * math.log(n),
        loo_rms=float(np.sqrt(np.mean(press[not_first] ** 2))),
        chi2_quant=rss / (sq**2 * max(n - p, 1)),
        runs_z=_runs_z(ru),
        lag1=_lag1(ru),
        success=bool(r.success),
        press=_freeze(press),
        leverage=_freeze(_spread(lev, used)),
    )


def _spread(values: np.ndarray, used: np.ndarray) -> np.ndarray:
    out = np.full(used.shape, np.nan)
    out[used] = values
    return out


def _inits_from(fits: Mapping[str, ModelFit], spec: ModelSpec) -> list[dict[str, float]]:
    inits = []
    for parent in spec.parents:
        if parent in fits and fits[parent].success:
            pp = dict(fits[parent].params)
            if parent == "rest":
                pp["phi0"] = pp["phi0"] - 1e-6
            inits.append({k: v for k, v in pp.items() if k in spec.free})
    return inits


def _best_noise(fits: Mapping[str, ModelFit], spec: ModelSpec) -> Noise | None:
    cands = [fits[p] for p in spec.parents if p in fits]
    return min(cands, key=lambda f: f.bic).noise if cands else None


def _ancestors(names: Sequence[str]) -> set[str]:
    todo = set(names)
    stack = list(names)
    while stack:
        for parent in MODELS[stack.pop()].parents:
            if parent not in todo:
                todo.add(parent)
                stack.append(parent)
    return todo


def fit_all_models(
    times: np.ndarray,
    angles: np.ndarray,
    *,
    fps: float = FPS,
    step: float = STEP,
    used: np.ndarray | None = None,
    models: Sequence[str] | None = None,
    noise: Noise | None = None,
    loss: str = "linear",
) -> dict[str, ModelFit]:
    """Fit models in nesting order, each started from its parents' optima (so a richer model
    does not end worse than a parent it contains). ``models`` defaults to all; their
    ancestors are fitted too but only the requested ones are returned."""
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    n_used = int(t.size if used is None else np.count_nonzero(used))
    # by default every model the rows can support (a short column leaves the richest out)
    wanted = list(models or [m for m in MODELS if n_used > len(MODELS[m].free) + 2])
    todo = _ancestors(wanted)
    fits: dict[str, ModelFit] = {}
    for name in ORDER:
        if name not in todo:
            continue
        spec = MODELS[name]
        inits = _inits_from(fits, spec)
        if name == "const":
            u = np.ones(t.shape, bool) if used is None else np.asarray(used, bool)
            inits.extend(_start_profile(t[u], phi[u], step))
        if name == "const" and "parabola" in fits:
            c2, c1, c0 = (fits["parabola"].params[k] for k in ("c2", "c1", "c0"))
            if c2 > 0:
                inits.append({"eps0": 2 * c2, "t0": -c1 / (2 * c2),
                              "phi0": c0 - c1 * c1 / (4 * c2)})
        n_starts = 2
        if "a_c" in spec.free and inits:
            # the unbalance phase makes the cost multimodal: also start from four phases
            base = min(inits, key=lambda d: 0.0 if "a_c" in d else 1.0)
            amp = 0.25 * float(base.get("eps0", 1.0))
            for q in range(4):
                inits.append({**base, "a_c": amp * math.cos(q * math.pi / 2),
                              "a_s": amp * math.sin(q * math.pi / 2)})
            n_starts = 3
        fits[name] = fit_model(t, phi, name, fps=fps, step=step, used=used, inits=inits,
                               noise=noise, noise_start=_best_noise(fits, spec), loss=loss,
                               max_starts=n_starts)
    return {k: fits[k] for k in ORDER if k in wanted}


def _nested(simple: str, rich: str) -> bool:
    return simple != rich and simple in _ancestors([rich])


def select_model(fits: Mapping[str, ModelFit], margin: float = BIC_MARGIN) -> str:
    """The BIC choice among :data:`SELECTABLE`; a model nested in it wins instead unless the
    richer one is better by more than ``margin``."""
    bics = {m: fits[m].bic for m in SELECTABLE if m in fits and math.isfinite(fits[m].bic)}
    if not bics:
        raise ContactInputError("no model could be fitted")
    return _select(bics, margin)


def _select(bics: Mapping[str, float], margin: float) -> str:
    best = min(bics, key=bics.get)
    changed = True
    while changed:
        changed = False
        for m in sorted(bics, key=lambda k: (len(MODELS[k].free), bics[k])):
            if _nested(m, best) and bics[m] < bics[best] + margin:
                best, changed = m, True
                break
    return best


def loo_exact(times: np.ndarray, angles: np.ndarray, fit: ModelFit, *, fps: float = FPS,
              step: float = STEP) -> float:
    """Exact leave-one-point-out prediction rms (s): refit without each used row (from the
    full fit, with its noise model) and predict the row."""
    if fit.model == "parabola":
        return fit.loo_rms
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    idx = np.flatnonzero(fit.used)
    init = {k: fit.params[k] for k in MODELS[fit.model].free}
    first = int(np.argmin(phi))
    errs = []
    for i in idx:
        if i == first:
            continue  # the first row is the time origin of every model
        keep = np.array(fit.used, copy=True)
        keep[i] = False
        f = fit_model(t, phi, fit.model, fps=fps, step=step, used=keep, inits=[init],
                      noise=fit.noise)
        errs.append(float(f.residuals[i]))
    return float(np.sqrt(np.mean(np.square(errs))))


def _leverages_with(t: np.ndarray, phi: np.ndarray, fit: ModelFit, rows: np.ndarray,
                    fps: float) -> np.ndarray:
    """Leverages of ``rows`` (mask) at ``fit``'s parameters and noise, NaN elsewhere."""
    spec = MODELS[fit.model]
    first = int(np.argmin(phi))
    fixed = {"t0": float(t[first]), "phi0": float(phi[first])} if fit.model == "rest" else {}
    free = list(spec.free)
    x = np.array([fit.params[k] for k in free])
    sig = np.asarray(fit.sigma)[rows]
    base = crossing_times(phi[rows], **_full_params(free, x, fixed))
    cols = []
    for j in range(len(free)):
        h = 1e-6 * max(1.0, abs(x[j]))
        xp = x.copy()
        xp[j] += h
        cols.append((crossing_times(phi[rows], **_full_params(free, xp, fixed)) - base) / h)
    jac = np.array(cols).T / sig[:, None]
    lev = np.einsum("ij,jk,ik->i", jac, np.linalg.pinv(jac.T @ jac), jac)
    return _spread(lev, rows)


# --------------------------------------------------------------------------------------------
# misread rows
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MisreadSearch:
    """Outcome of :func:`find_misread_rows`.

    ``outliers``: rows judged misread. ``z``: each row's leave-one-out error in units of its
    noise sigma (prediction error for the rows left out). ``deletion_residuals``: the same
    errors in seconds. ``noise``: the reading noise of the clean rows.
    """

    outliers: np.ndarray
    z: np.ndarray
    deletion_residuals: np.ndarray
    noise: Noise
    reference: str


def _robust_noise(fit: ModelFit, phi: np.ndarray, fps: float) -> Noise:
    """Reading noise from a fit's leverage-corrected residuals (each ``r/sqrt(1 - h)`` has the
    noise variance), Student-t likelihood: a misread row still in the fit does not inflate it,
    and removing one of the few slow rows that inform ``sigma_a`` does not swing it."""
    first = int(np.argmin(phi))
    ui = np.flatnonzero(np.asarray(fit.used))
    ui = ui[ui != first]
    lev = np.asarray(fit.leverage)[ui]
    r = np.asarray(fit.residuals)[ui] / np.sqrt(np.maximum(1 - lev, 1e-6))
    return _estimate_noise(r, _speeds(phi[ui], fit.params), fit.params["eps0"],
                           quantisation_sigma(fps), fit.noise, robust=True)


def find_misread_rows(
    times: np.ndarray,
    angles: np.ndarray,
    *,
    fps: float = FPS,
    step: float = STEP,
    threshold: float = 4.0,
    min_frames: float = 1.5,
    reference: str = "position+unbalance",
    initial: np.ndarray | None = None,
    max_fraction: float = 0.2,
    n_candidates: int = 4,
    start: ModelFit | None = None,
) -> MisreadSearch:
    """Find rows whose frame number was misread or mistyped.

    A forward-backward search on externally studentised deletion residuals under
    ``reference``, a flexible model (so that a smooth trend is not taken for misreads):

    1. Fit the rows not yet flagged; rank them by their leverage-corrected residual in
       noise sigmas, and refit without each of the ``n_candidates`` worst (exact deletion,
       so that a model bent towards a misread row does not mask it).
    2. The candidate whose prediction error is largest in units of the noise sigma of the
       fit without it is flagged if that exceeds ``threshold`` and ``min_frames`` frames (a
       frame or two off cannot be told from reading scatter); then repeat.
    3. Backward: a flagged row whose prediction error under the final fit is within the
       threshold is put back.

    At most ``max_fraction`` of the rows are flagged. ``initial`` starts from a given verdict,
    ``start`` from a fit of ``reference`` already made on the rows not in ``initial``.
    The first row is never flagged: a misread first row is a start offset, which the models
    fit anyway.
    """
    t = np.asarray(times, float)
    phi = np.asarray(angles, float)
    n = t.size
    first = int(np.argmin(phi))
    thr_abs = min_frames / fps
    max_out = max(int(max_fraction * n), 1)
    flagged = np.zeros(n, bool) if initial is None else np.asarray(initial, bool).copy()
    flagged[first] = False
    # a short column cannot spare rows for a flexible reference: fall back to a simpler
    # one, and never flag so many rows that the reference has too few left to be fitted
    for simpler in ("position", "const"):
        if n - max_out > len(MODELS[reference].free) + 2:
            break
        if reference != simpler and simpler in _ancestors([reference]):
            reference = simpler
    max_out = max(min(max_out, n - len(MODELS[reference].free) - 3), 0)
    free = MODELS[reference].free

    if start is not None and start.model == reference and np.array_equal(start.used, ~flagged):
        fit = start
    else:
        fit = fit_all_models(t, phi, fps=fps, step=step, used=~flagged,
                             models=[reference])[reference]

    def refit(used: np.ndarray, base: ModelFit) -> ModelFit:
        return fit_model(t, phi, reference, fps=fps, step=step, used=used,
                         inits=[{k: base.params[k] for k in free}], noise_start=base.noise,
                         irls=1)

    def robust_noise(f: ModelFit) -> Noise:
        return _robust_noise(f, phi, fps)

    def verdict(f: ModelFit, i: int, lev: float, nz: Noise) -> tuple[float, float]:
        # externally studentised: the prediction error of a row a fit without it makes has
        # variance sigma_i^2 / (1 - h_ii), h_ii the row's leverage in the fit with it
        d = float(f.residuals[i])
        sig = float(nz.sigma(_speeds(phi[i : i + 1], f.params), f.params["eps0"])[0])
        return d * math.sqrt(max(1.0 - lev, 1e-6)) / sig, d

    def leverage_in(f: ModelFit, i: int) -> float:
        h = float(np.asarray(f.leverage)[i])
        if math.isfinite(h):
            return h
        # row i outside f: its leverage in a fit that includes it, at f's parameters
        back = f.used.copy()
        back[i] = True
        g = _leverages_with(t, phi, f, back, fps)
        return float(g[i])

    for _ in range(2 * max_out + 2):
        changed = False
        # backward: put back flagged rows the current fit predicts well
        nz = robust_noise(fit)
        for i in np.flatnonzero(flagged):
            z, d = verdict(fit, i, leverage_in(fit, i), nz)
            if abs(z) <= threshold or abs(d) <= thr_abs:
                flagged[i] = False
                fit = refit(~flagged, fit)
                changed = True
                break
        if changed:
            continue
        if flagged.sum() >= max_out:
            break
        # forward: exact deletion of the worst candidates
        used_idx = np.flatnonzero(~flagged)
        approx = np.zeros(n)
        lev_u = np.asarray(fit.leverage)[used_idx]
        sig_u = nz.sigma(_speeds(phi[used_idx], fit.params), fit.params["eps0"])
        approx[used_idx] = (np.abs(np.asarray(fit.press)) * np.sqrt(np.maximum(1 - lev_u, 1e-6))
                            / sig_u)
        approx[first] = 0.0
        cands = [int(i) for i in np.argsort(-approx)[:n_candidates] if approx[i] > 0]
        best, best_z, best_fit = -1, 0.0, None
        for i in cands:
            used = ~flagged
            used[i] = False
            f = refit(used, fit)
            z, d = verdict(f, i, float(np.asarray(fit.leverage)[i]), robust_noise(f))
            if abs(d) > thr_abs and abs(z) > abs(best_z):
                best, best_z, best_fit = i, z, f
        if best >= 0 and abs(best_z) > threshold:
            flagged[best] = True
            fit = best_fit
            continue
        break

    # final per-row verdicts: prediction errors for flagged rows, leverage-corrected
    # residuals for the others, in noise sigmas
    dele = np.array(fit.residuals, dtype=float)
    dele[np.asarray(fit.used)] = np.asarray(fit.press)
    dele[first] = 0.0
    nz = robust_noise(fit)
    z = np.zeros(n)
    for i in range(n):
        if i == first:
            continue
        if flagged[i]:
            z[i] = verdict(fit, i, leverage_in(fit, i), nz)[0]
        else:
            h = float(np.asarray(fit.leverage)[i])
            sig = float(nz.sigma(_speeds(phi[i : i + 1], fit.params), fit.params["eps0"])[0])
            z[i] = dele[i] * math.sqrt(max(1.0 - h, 1e-6)) / sig
    return MisreadSearch(_freeze(flagged), _freeze(z), _freeze(dele), nz, reference)


# --------------------------------------------------------------------------------------------
# one test
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class TestReport:
    """The law-of-motion analysis of one test (one column).

    Attributes
    ----------
    name, group : str
    k : ndarray of int
        Row numbers present in the column.
    frames : ndarray
        Frame indices as given.
    times, angles : ndarray
        ``(f - f_first)/fps`` (s) and ``(k - k_first) step`` (rad).
    fits : dict of ModelFit
        Every model, fitted on the rows judged sound.
    selected : str
        The BIC choice (:func:`select_model`).
    effect : str
        ``none``, ``decaying``, ``unbalance`` or ``decaying+unbalance``.
    decay_form : str or None
        ``position``, ``speed`` or ``position+speed`` when the acceleration decays.
    outliers : tuple of int
        Row numbers ``k`` judged misread (left out of the fits).
    eps0, eps0_stderr : float
        Initial angular acceleration of the selected model and its standard error, rad/s².
    z : ndarray
        Each row's leave-one-out error in noise sigmas under the misread search's model.
    omega_first : float
        The selected model's angular speed at the first mark, rad/s (0: starts there).
    delta_bic : float
        BIC of the best model nested in the selected one minus the selected model's (the
        evidence over the next simpler model; NaN for ``rest``, which has none).
    effect_evidence : float
        BIC of the best no-effect model minus that of the best effect model.
    false_alarm : float
        Calibrated probability that a clean column (no effect) reaches ``effect_evidence``
        (:func:`false_alarm_probability`).
    weak_evidence : bool
        An effect is named but on weak evidence: ``false_alarm`` above 1 % or ``delta_bic``
        below 10 ("very strong" starts there on Kass & Raftery's scale).
    """

    __test__ = False  # not a pytest class

    name: str
    group: str
    k: np.ndarray
    frames: np.ndarray
    times: np.ndarray
    angles: np.ndarray
    fits: dict[str, ModelFit]
    selected: str
    effect: str
    decay_form: str | None
    outliers: tuple[int, ...]
    eps0: float
    eps0_stderr: float
    z: np.ndarray
    omega_first: float
    fps: float
    step: float
    delta_bic: float = math.nan
    effect_evidence: float = math.nan
    false_alarm: float = math.nan
    weak_evidence: bool = False

    @property
    def fit(self) -> ModelFit:
        return self.fits[self.selected]

    @property
    def used(self) -> np.ndarray:
        return self.fit.used


_CALIBRATION: dict | None = None
WEAK_FALSE_ALARM = 0.01
WEAK_DELTA_BIC = 10.0


def false_alarm_probability(delta_bic: float) -> float:
    """Calibrated probability that a column without any effect shows ``delta_bic`` or more
    evidence for one (BIC of the best no-effect model minus that of the best effect model).

    From ``contact/rotor_calibration.json``, written by ``benchmarks/rotor_calibration.py``
    (simulated clean columns over the declared range of frame rate, mark step, rows,
    eps0, start angle and misread rows); the value at the largest tabulated ``delta_bic``
    not above the argument (conservative between grid points), 1 below the table.
    """
    global _CALIBRATION
    if _CALIBRATION is None:
        import json
        from pathlib import Path

        _CALIBRATION = json.loads(
            (Path(__file__).resolve().parent / "rotor_calibration.json").read_text())
    if not math.isfinite(delta_bic):
        return math.nan
    d = np.asarray(_CALIBRATION["delta_bic"], float)
    pfa = np.asarray(_CALIBRATION["false_alarm"], float)
    i = int(np.searchsorted(d, delta_bic, side="right")) - 1
    return 1.0 if i < 0 else float(pfa[i])


def verdict_evidence(fits: Mapping[str, ModelFit], selected: str) -> tuple[float, float]:
    """``(delta_bic, effect_evidence)`` of a verdict (see :class:`TestReport`)."""
    simpler = [fits[m].bic for m in _ancestors([selected]) - {selected}
               if m in fits and m in SELECTABLE and math.isfinite(fits[m].bic)]
    delta = min(simpler) - fits[selected].bic if simpler else math.nan
    none = [fits[m].bic for m in SELECTABLE if m in fits and MODELS[m].effect == "none"]
    eff = [fits[m].bic for m in SELECTABLE if m in fits and MODELS[m].effect != "none"]
    evidence = min(none) - min(eff) if none and eff else math.nan
    return float(delta), float(evidence)


def group_of(name: str) -> str:
    """Group of a column: its name without trailing digits (``as2`` -> ``as``)."""
    g = re.sub(r"\d+$", "", name)
    return g or name


def _omega_at(fit: ModelFit, phi_first: float) -> float:
    if fit.model == "parabola":
        return math.nan
    return float(_speeds(np.array([phi_first]), fit.params)[0])


def _prepare(name: str, frames: Sequence[float], k: Sequence[int] | None, fps: float,
             step: float):
    if not (math.isfinite(fps) and fps > 0):
        raise ContactInputError(f"fps must be positive, got {fps!r}")
    if not (math.isfinite(step) and step > 0):
        raise ContactInputError(f"the mark step must be positive, got {step!r}")
    f = np.asarray(frames, dtype=float)
    kk = np.arange(1, f.size + 1) if k is None else np.asarray(k)
    if f.ndim != 1 or kk.shape != f.shape:
        raise ContactInputError(f"column {name!r}: frames and row numbers differ in length")
    ok = np.isfinite(f)
    f, kk = f[ok], kk[ok].astype(int)
    if f.size < 6:
        raise ContactInputError(
            f"column {name!r} has {f.size} readings; the law-of-motion analysis needs >= 6"
        )
    if np.any(np.diff(kk) <= 0):
        raise ContactInputError(f"column {name!r}: row numbers must increase")
    times = (f - f[0]) / fps
    angles = (kk - kk[0]) * step
    bad = np.flatnonzero(np.diff(f) <= 0)
    if bad.size:
        raise ContactInputError(
            f"column {name!r}: frame indices must increase down the column, but row "
            f"{kk[bad[0] + 1]} ({f[bad[0] + 1]:g}) is not after row {kk[bad[0]]} "
            f"({f[bad[0]]:g})"
        )
    return f, kk, times, angles


def analyse_test(
    name: str,
    frames: Sequence[float],
    k: Sequence[int] | None = None,
    *,
    fps: float = FPS,
    step: float = STEP,
    margin: float = BIC_MARGIN,
    cv: str = "approx",
    threshold: float = 4.0,
    min_frames: float = 1.5,
    noise: Noise | None = None,
) -> TestReport:
    """Analyse one column of frame indices: misread rows, every model, the BIC choice.

    Parameters
    ----------
    name : str
        Column name (its group is the name without trailing digits).
    frames : sequence
        Frame index at each row; NaN for a missing reading.
    k : sequence of int, optional
        Row numbers (default 1, 2, ...). Row ``k`` is at angle ``(k - k_first) step``.
    fps, step : float
        Frame rate (1/s) and mark step (rad).
    margin : float
        BIC margin a richer model must win by (:func:`select_model`).
    cv : {"approx", "exact"}
        Leave-one-point-out errors from the leverages, or from refits (slower).
    threshold, min_frames : float
        Misread threshold in noise sigmas, and its floor in frames.
    noise : Noise, optional
        Reading noise to weight every fit with (default: each model estimates its own).
    """
    if cv not in ("approx", "exact"):
        raise ContactInputError(f"cv must be 'approx' or 'exact', got {cv!r}")
    f, kk, times, angles = _prepare(name, frames, k, fps, step)
    search = find_misread_rows(times, angles, fps=fps, step=step, threshold=threshold,
                               min_frames=min_frames)
    outl = np.array(search.outliers)
    # noise=None: every model estimates its own reading noise (from leverage-corrected
    # residuals, see fit_model), so the BIC compares profile likelihoods
    fits = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise)
    chosen = select_model(fits, margin)
    # judge the rows again under the chosen model; refit once if the verdict moves
    if chosen != search.reference:
        again = find_misread_rows(times, angles, fps=fps, step=step, threshold=threshold,
                                  min_frames=min_frames, reference=chosen, initial=outl,
                                  start=fits[chosen])
        if not np.array_equal(again.outliers, outl):
            outl = np.array(again.outliers)
            fits = fit_all_models(times, angles, fps=fps, step=step, used=~outl, noise=noise)
            chosen = select_model(fits, margin)
        search = again
    if cv == "exact":
        fits = {m: (fit if m == "parabola" else replace(
            fit, loo_rms=loo_exact(times, angles, fit, fps=fps, step=step), loo_kind="exact"))
            for m, fit in fits.items()}
    sel = fits[chosen]
    delta, evidence = verdict_evidence(fits, chosen)
    pfa = false_alarm_probability(evidence)
    weak = MODELS[chosen].effect != "none" and (
        pfa > WEAK_FALSE_ALARM or not delta >= WEAK_DELTA_BIC)
    return TestReport(
        name=name,
        group=group_of(name),
        k=_freeze(kk),
        frames=_freeze(f),
        times=_freeze(times),
        angles=_freeze(angles),
        fits=fits,
        selected=chosen,
        effect=MODELS[chosen].effect,
        decay_form=MODELS[chosen].decay_form,
        outliers=tuple(int(v) for v in kk[outl]),
        eps0=sel.eps0,
        eps0_stderr=sel.eps0_stderr,
        z=search.z,
        omega_first=_omega_at(sel, float(angles[0])),
        fps=float(fps),
        step=float(step),
        delta_bic=delta,
        effect_evidence=evidence,
        false_alarm=pfa,
        weak_evidence=bool(weak),
    )


# --------------------------------------------------------------------------------------------
# groups of tests
# --------------------------------------------------------------------------------------------


def paper_parabola(
    columns: Sequence[np.ndarray], fps: float = FPS, step: float = STEP
) -> tuple[np.ndarray, np.ndarray, float]:
    """The paper's fit: least-squares parabola ``phi = c2 t^2 + c1 t + c0`` through the mean
    time of the tests at each row (``t = (f_k - f_1)/fps``; rows where every test has a
    reading). Returns ``[c2, c1, c0]`` (rad/s², rad/s, rad), their standard errors, and the
    rms angle residual (rad)."""
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


@dataclass(frozen=True)
class GroupReport:
    """A group of tests (same collar position).

    Attributes
    ----------
    name : str
    tests : tuple of str
    paper_parabola, paper_parabola_stderr : ndarray
        ``[c2, c1, c0]`` (rad/s², rad/s, rad) of the paper's fit through the mean times.
    paper_rms : float
        Its rms angle residual, rad.
    eps : dict
        Per model (and ``"paper"``: ``2 c2``), ``(mean, uncertainty, per-test values)`` of
        the initial acceleration, rad/s². The uncertainty is the larger of the between-test
        standard error of the mean and the fits' pooled standard error.
    params : dict
        The same for ``eta`` (1/s²), ``gamma`` (1/s) and ``amplitude`` (rad/s²) of the study
        model, where it has them.
    loto_rms : dict
        Leave-one-test-out prediction rms (s) per model (:func:`leave_one_test_out`).
    """

    name: str
    tests: tuple[str, ...]
    paper_parabola: np.ndarray
    paper_parabola_stderr: np.ndarray
    paper_rms: float
    eps: dict[str, tuple[float, float, tuple[float, ...]]]
    params: dict[str, tuple[float, float, tuple[float, ...]]]
    loto_rms: dict[str, float]


@dataclass(frozen=True)
class GroupComparison:
    """Difference ``b - a`` of two groups' initial accelerations (or of another parameter)
    under one model. ``p_value``: Welch's two-sided t test on the per-test values (NaN for
    ``paper``, one value per group; its ``z`` uses the parabolas' standard errors)."""

    a: str
    b: str
    model: str
    quantity: str
    difference: float
    uncertainty: float
    z: float
    p_value: float
    ratio: float


@dataclass(frozen=True)
class LawOfMotionAnalysis:
    """Everything :func:`analyse_table` finds.

    ``study_model`` is the model with the smallest BIC summed over all tests
    (``total_bic``), used to compare groups like with like.
    """

    tests: tuple[TestReport, ...]
    groups: tuple[GroupReport, ...]
    comparisons: tuple[GroupComparison, ...]
    study_model: str
    total_bic: dict[str, float]
    fps: float
    step: float
    noise_floor: float

    def test(self, name: str) -> TestReport:
        for t in self.tests:
            if t.name == name:
                return t
        raise KeyError(name)

    def group(self, name: str) -> GroupReport:
        for g in self.groups:
            if g.name == name:
                return g
        raise KeyError(name)


def _mean_u(values: Sequence[float], errors: Sequence[float]) -> tuple[float, float]:
    v = np.asarray(values, float)
    e = np.asarray(errors, float)
    n = v.size
    mean = float(v.mean())
    sem = float(v.std(ddof=1) / math.sqrt(n)) if n > 1 else math.nan
    fit_u = float(math.sqrt(np.nansum(e**2)) / n) if np.any(np.isfinite(e)) else math.nan
    cands = [x for x in (sem, fit_u) if math.isfinite(x)]
    return mean, (max(cands) if cands else math.nan)


def leave_one_test_out(reports: Sequence[TestReport], model: str) -> float:
    """Leave-one-test-out prediction rms (s) of ``model`` within a group.

    Each test is predicted with the physical parameters (``eps0``, ``eta``, ``gamma``,
    ``a_c``, ``a_s``) averaged over the group's other tests; only its own start (``t0``,
    ``phi0``), which differs from launch to launch, is fitted to it (weighted by its noise
    model). Misread rows are left out. NaN for fewer than two tests and for ``parabola``.
    """
    if len(reports) < 2 or model == "parabola":
        return math.nan
    phys = ("eps0", "eta", "gamma", "a_c", "a_s")
    errs: list[np.ndarray] = []
    for i, rep in enumerate(reports):
        others = [r for j, r in enumerate(reports) if j != i]
        avg = {k: float(np.mean([o.fits[model].params[k] for o in others])) for k in phys}
        own = rep.fits[model]
        used = np.array(own.used)
        t, phi = rep.times[used], rep.angles[used]
        if model == "rest":
            errs.append(crossing_times(phi, **avg, t0=float(t[0]), phi0=float(phi[0])) - t)
            continue
        sig = np.array(own.sigma)[used]
        bd = _bounds(t, phi, rep.step, _rest_estimate(t, phi))
        lo = [bd["t0"][0], bd["phi0"][0]]
        hi = [bd["t0"][1], bd["phi0"][1]]
        x0 = [_interior(own.params["t0"], lo[0], hi[0]),
              _interior(own.params["phi0"], lo[1], hi[1])]

        def fun(x: np.ndarray, t=t, phi=phi, avg=avg, sig=sig) -> np.ndarray:
            return (crossing_times(phi, **avg, t0=x[0], phi0=x[1]) - t) / sig

        r = least_squares(fun, x0, bounds=(lo, hi), x_scale="jac")
        errs.append(r.fun * sig)
    allr = np.concatenate(errs)
    return float(np.sqrt(np.mean(allr**2)))


def analyse_table(
    columns: Mapping[str, Sequence[float]],
    k: Sequence[int] | None = None,
    *,
    fps: float = FPS,
    step: float = STEP,
    margin: float = BIC_MARGIN,
    cv: str = "approx",
    threshold: float = 4.0,
    min_frames: float = 1.5,
) -> LawOfMotionAnalysis:
    """Analyse a table of tests (column name -> frame index per row).

    Per test: :func:`analyse_test`. Per group (name without trailing digits): the paper's
    parabola through the mean times, each model's initial acceleration with its uncertainty,
    leave-one-test-out errors. The study model has the smallest BIC summed over all tests
    (with the same nested-margin rule), one model for every test so that groups compare like
    with like. Groups are compared pairwise under ``paper``, ``rest``, ``const`` and the study
    model, and on the study model's decay and unbalance parameters.
    """
    if not columns:
        raise ContactInputError("no test columns to analyse")
    reports = tuple(
        analyse_test(name, columns[name], k, fps=fps, step=step, margin=margin, cv=cv,
                     threshold=threshold, min_frames=min_frames)
        for name in columns
    )
    # short columns leave their richest models out: compare the models every test has
    common = [m for m in SELECTABLE if all(m in r.fits for r in reports)]
    total = {m: float(sum(r.fits[m].bic for r in reports)) for m in common}
    study = _select(total, margin)

    groups: list[GroupReport] = []
    for gname in dict.fromkeys(r.group for r in reports):
        members = [r for r in reports if r.group == gname]
        cols = [np.asarray(columns[r.name], float) for r in members]
        if len({c.size for c in cols}) == 1:
            coef, se, prms = paper_parabola(cols, fps, step)
        else:
            coef, se, prms = np.full(3, np.nan), np.full(3, np.nan), math.nan
        eps: dict[str, tuple[float, float, tuple[float, ...]]] = {
            "paper": (float(2 * coef[0]), float(2 * se[0]), (float(2 * coef[0]),))
        }
        for m in MODELS:
            if not all(m in r.fits for r in members):
                continue
            vals = [r.fits[m].eps0 for r in members]
            mu, u = _mean_u(vals, [r.fits[m].eps0_stderr for r in members])
            eps[m] = (mu, u, tuple(float(v) for v in vals))
        params: dict[str, tuple[float, float, tuple[float, ...]]] = {}
        free = MODELS[study].free
        for key, needs in (("eta", "eta"), ("gamma", "gamma"), ("amplitude", "a_c")):
            if needs in free:
                vals = [r.fits[study].params[key] for r in members]
                errs = [r.fits[study].stderr.get(key, math.nan) for r in members]
                mu, u = _mean_u(vals, errs)
                params[key] = (mu, u, tuple(float(v) for v in vals))
        groups.append(GroupReport(
            name=gname,
            tests=tuple(r.name for r in members),
            paper_parabola=_freeze(coef),
            paper_parabola_stderr=_freeze(se),
            paper_rms=prms,
            eps=eps,
            params=params,
            loto_rms={m: leave_one_test_out(members, m) for m in common},
        ))

    from scipy import stats

    comps: list[GroupComparison] = []

    def compare(ga, gb, model, quantity, a, b) -> None:
        (ma, ua, va), (mb, ub, vb) = a, b
        diff = mb - ma
        u = math.hypot(ua, ub)
        p = math.nan
        if len(va) > 1 and len(vb) > 1:
            p = float(stats.ttest_ind(vb, va, equal_var=False).pvalue)
        comps.append(GroupComparison(ga.name, gb.name, model, quantity, diff, u,
                                     diff / u if u > 0 else math.nan, p,
                                     mb / ma if ma else math.nan))

    for i in range(len(groups)):
        for j in range(i + 1, len(groups)):
            ga, gb = groups[i], groups[j]
            for m in dict.fromkeys(("paper", "rest", "const", study)):
                compare(ga, gb, m, "eps0", ga.eps[m], gb.eps[m])
            for key in ga.params:
                compare(ga, gb, study, key, ga.params[key], gb.params[key])
    return LawOfMotionAnalysis(
        tests=reports,
        groups=tuple(groups),
        comparisons=tuple(comps),
        study_model=study,
        total_bic=total,
        fps=float(fps),
        step=float(step),
        noise_floor=quantisation_sigma(fps),
    )
