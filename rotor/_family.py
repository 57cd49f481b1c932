"""The model family of the rotor's law of motion and the record of one fitted model.

``rest``
    constant acceleration from rest at the first mark (the paper's assumption; 1 parameter);
``parabola``
    the paper's general parabola ``phi = c2 t^2 + c1 t + c0`` fitted on the angles;
``const``
    constant acceleration from rest at an unknown start time ``t0`` and angle ``phi0``
    (the start prior: :func:`rotor._starts.parameter_bounds`);
``position``, ``speed``, ``position+speed``
    decaying acceleration: ``eps0 - eta (phi - phi0)`` (the driving slope changes along the
    plate) and/or ``eps0 - gamma omega`` (resistance growing with speed);
``unbalance`` and ``*+unbalance``
    a torque ``A sin(phi + psi)`` from a centre of mass off the axis, alone or combined;
``wave``, ``position+wave``, ``speed+wave`` (the extension, :data:`EXTENSION`)
    a driving slope undulating along the track, ``B sin(2 pi phi / P + chi)`` of free period
    ``P`` (a plate that is not plane). They are fitted only when the in-family choice does
    not explain the data (:mod:`rotor._extension`). A period of one turn has the
    unbalance's form: the two cannot be told apart from one launch, and each wave model has
    its unbalance counterpart as a parent, so it must beat it by the selection margin. After
    a decaying choice only the decay with a wave is fitted (``wave`` alone is then not tried).

Every model but ``parabola`` is the equation of :mod:`rotor._forward` with some
parameters fixed at zero; the models are nested through their ``parents``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rotor._noise import Noise

__all__ = [
    "CORE",
    "EXTENSION",
    "MODELS",
    "ORDER",
    "PARAM_UNITS",
    "SELECTABLE",
    "ModelFit",
    "ModelSpec",
    "ancestors",
    "is_nested",
    "with_derived_params",
]


PARAM_UNITS = {
    "eps0": "rad/s^2",
    "eta": "1/s^2",
    "gamma": "1/s",
    "a_c": "rad/s^2",
    "a_s": "rad/s^2",
    "t0": "s",
    "phi0": "rad",
    "c2": "rad/s^2",
    "c1": "rad/s",
    "c0": "rad",
    "amplitude": "rad/s^2",
    "phase": "rad",
    "wave_c": "rad/s^2",
    "wave_s": "rad/s^2",
    "wave_period": "rad",
    "wave_amplitude": "rad/s^2",
    "wave_phase": "rad",
}


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
        ModelSpec("wave", ("eps0", "wave_c", "wave_s", "wave_period", "t0", "phi0"), "wave",
                  None, ("unbalance",),
                  "constant acceleration plus a plate wave B sin(2 pi phi/P + chi) of free "
                  "period P"),
        ModelSpec("position+wave", ("eps0", "eta", "wave_c", "wave_s", "wave_period", "t0",
                                    "phi0"), "decaying+wave", "position",
                  ("position+unbalance",), "position decay and a plate wave"),
        ModelSpec("speed+wave", ("eps0", "gamma", "wave_c", "wave_s", "wave_period", "t0",
                                 "phi0"), "decaying+wave", "speed",
                  ("speed+unbalance",), "speed decay and a plate wave"),
    )
}
EXTENSION = ("wave", "position+wave", "speed+wave")
"""The plate-wave models: fitted on demand, never by default."""
CORE = tuple(name for name in MODELS if name not in EXTENSION)
"""The models fitted for every test."""
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

    See Also
    --------
    analyse_test : fits every model of the family to a column.

    Examples
    --------
    A rotor released from rest at -0.25 rad and accelerating at 2 rad/s² passes the first
    mark at 1 rad/s; the constant-acceleration fit recovers its start (``t0`` is
    ``-1/2`` s, ``phi0`` is ``-1/4`` rad):

    >>> import numpy as np
    >>> from rotor import analyse_test
    >>> phi = np.arange(25) * np.pi / 2
    >>> t = (-1.0 + np.sqrt(1.0 + 2 * 2.0 * phi)) / 2.0
    >>> report = analyse_test("s1", np.round(1000 + 120 * t))
    >>> fit = report.fits["const"]
    >>> print(fit.model, fit.n, fit.p, f"eps0 = {fit.params['eps0']:.2f} rad/s²")
    const 25 3 eps0 = 2.00 rad/s²
    >>> print(f"t0 = {fit.params['t0']:.2f} s, phi0 = {fit.params['phi0']:.2f} rad")
    t0 = -0.50 s, phi0 = -0.25 rad
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


def with_derived_params(params: dict[str, float]) -> dict[str, float]:
    out = dict(params)
    amp = math.hypot(params.get("a_c", 0.0), params.get("a_s", 0.0))
    out["amplitude"] = amp
    out["phase"] = math.atan2(params.get("a_s", 0.0), params.get("a_c", 0.0)) if amp else 0.0
    wc, ws = params.get("wave_c", 0.0), params.get("wave_s", 0.0)
    if wc or ws:
        out["wave_amplitude"] = math.hypot(wc, ws)
        out["wave_phase"] = math.atan2(ws, wc)
    return out


def ancestors(names: Sequence[str]) -> set[str]:
    todo = set(names)
    stack = list(names)
    while stack:
        for parent in MODELS[stack.pop()].parents:
            if parent not in todo:
                todo.add(parent)
                stack.append(parent)
    return todo


def is_nested(simple: str, rich: str) -> bool:
    return simple != rich and simple in ancestors([rich])
