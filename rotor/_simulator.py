"""Simulator of the paper's rotor experiment, with hidden effects, producing a Table-3 column.

The rotor (mass properties from :mod:`rotor._mechanics`) rolls without sliding on a
plate whose equivalent slope may change along the path, braked by a constant rolling-friction
torque and optionally by a torque growing with speed, with its centre of mass optionally off
the axis.
The equation of motion is the exact Lagrangian of an eccentric rolling body (not the reduced
form the analysis fits): with ``e`` the offset of ``G`` from the axis, ``chi = phi - psi_G``,

    I(phi) phi'' = M g [R S(x) - e S sin(chi) + e C cos(chi)] + M R e cos(chi) phi'^2
                   - M_r - c phi'
    I(phi) = J + M (R^2 + e^2 - 2 R e sin(chi))

where ``x = R (phi - phi0)`` is the distance rolled, ``S(x) = S0 - kappa x`` the equivalent
slope ``sin(alpha) sin(beta)`` (``kappa``: slope change per metre, e.g. a sagging plate),
``C = sqrt(1 - S^2)``, ``M_r = s_r (N1**lam + N2**lam)`` (Eq. 47) and ``c`` a viscous
rolling-resistance coefficient. It is integrated with ``scipy.integrate.solve_ivp`` (DOP853,
mark crossings as events), independently of the quadrature :mod:`rotor._forward` uses.

Frame indices are made as Table 3 was: the camera runs at ``fps``; frame ``n`` shows the
rotor at time ``n/fps`` after the recording started; the reader notes, for each mark, the
first frame that shows it at or past the rod's axis, ``f = ceil(t fps)``, where the moment he
judges as "at the axis" may be off by an angular reading error (``reading_sd``, rad). Misread
rows add a whole number of frames to single entries.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from contact._errors import ContactInputError
from rotor._arrays import readonly
from rotor._mechanics import (
    G_STANDARD,
    MassProperties,
    mass_properties,
    rolling_torque,
)
from rotor._paper import FPS, MARK_STEP

__all__ = [
    "EFFECTS",
    "HiddenEffects",
    "SimulatedRun",
    "effect_signature",
    "random_hidden_effects",
    "simulate_random_run",
    "simulate_rotor",
]

EFFECTS = ("none", "decaying", "unbalance", "decaying+unbalance")


@dataclass(frozen=True)
class HiddenEffects:
    """What a simulated run hides (SI units).

    Attributes
    ----------
    effect : str
        One of :data:`EFFECTS`.
    decay_form : str or None
        ``"position"`` (slope changing along the plate) or ``"speed"`` (viscous resistance).
    slope : float
        Equivalent slope ``S0 = sin(alpha) sin(beta)`` at the start.
    slope_gradient : float
        ``kappa``: decrease of the equivalent slope per metre rolled, 1/m.
    viscous : float
        ``c``: resisting torque per angular speed, N m s.
    com_offset, com_phase : float
        Distance of the centre of mass from the axis (m) and its angular position (rad).
    s_r, lam : float
        Rolling-friction law ``M_r = s_r N**lam`` at each ball.
    start_angle : float
        Angle (rad, <= 0) of the rest position relative to the first mark.
    start_time : float
        Time (s) after the camera started at which the rotor is released.
    misread : tuple of int
        Row numbers ``k`` whose frame index is misread.
    misread_by : tuple of int
        Frames added to each of them.
    reading_sd : float
        Angular scatter (rad) of judging when a mark is at the axis.
    eps0 : float
        Resulting initial angular acceleration without unbalance (rad/s²).
    eta, gamma, amplitude : float
        The same effects in the analysis' parameters: ``eta`` (1/s²), ``gamma`` (1/s),
        unbalance amplitude (rad/s²).
    wave_amplitude, wave_period, wave_phase : float
        A plate wave: the equivalent slope undulates along the track by
        ``B sin(2 pi (phi - phi_start) / P + chi)`` in acceleration terms (``B`` rad/s²,
        ``P`` rad of rotor turn, ``chi`` rad at the release point); 0: a plane plate.

    See Also
    --------
    simulate_random_run : draws one and simulates the run it hides.

    Examples
    --------
    >>> from rotor import simulate_random_run
    >>> hidden = simulate_random_run(3, "unbalance").hidden
    >>> print(hidden.effect, hidden.lam, hidden.misread, f"eps0 = {hidden.eps0:.2f} rad/s²")
    unbalance 1.0 (14,) eps0 = 1.69 rad/s²
    """

    effect: str
    decay_form: str | None
    slope: float
    slope_gradient: float
    viscous: float
    com_offset: float
    com_phase: float
    s_r: float
    lam: float
    start_angle: float
    start_time: float
    misread: tuple[int, ...]
    misread_by: tuple[int, ...]
    reading_sd: float
    eps0: float
    eta: float
    gamma: float
    amplitude: float
    wave_amplitude: float = 0.0
    wave_period: float = 2 * math.pi
    wave_phase: float = 0.0


@dataclass(frozen=True)
class SimulatedRun:
    """A simulated test: Table-3-like frame indices and the truth behind them.

    ``frames[i]`` is the frame index of row ``k[i]`` (mark ``(k - 1) step``);
    ``true_times`` the exact crossing times (s since the camera started);
    ``clean_frames`` the frame indices before misreads.

    Attributes
    ----------
    k : numpy.ndarray of int
        Row numbers.
    frames, clean_frames : numpy.ndarray
        Frame indices as read and before the misreads.
    true_times : numpy.ndarray
        Exact crossing times (s).
    hidden : HiddenEffects
        The truth behind the run.
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).

    See Also
    --------
    simulate_random_run : makes one.

    Examples
    --------
    >>> from rotor import simulate_random_run
    >>> run = simulate_random_run(3, "unbalance")
    >>> row = run.hidden.misread[0]
    >>> print(len(run.frames), row, int(run.frames[row - 1] - run.clean_frames[row - 1]))
    25 14 -7
    """

    k: np.ndarray
    frames: np.ndarray
    clean_frames: np.ndarray
    true_times: np.ndarray
    hidden: HiddenEffects
    fps: float
    step: float


def simulate_rotor(
    hidden: HiddenEffects,
    *,
    n_marks: int = 25,
    fps: float = FPS,
    step: float = MARK_STEP,
    props: MassProperties | None = None,
    g: float = G_STANDARD,
    seed: int | None = 0,
) -> SimulatedRun:
    """Integrate the rotor's motion and read it out as frame indices.

    Parameters
    ----------
    hidden : HiddenEffects
        The physics and the reading errors (see :func:`random_hidden_effects`).
    n_marks : int
        Number of rows (marks ``0, step, ..., (n_marks - 1) step``).
    fps, step : float
        Camera frame rate and mark spacing.
    props : MassProperties
        Rotor; default the paper's symmetric rotor.
    seed : int
        Seed of the angular reading errors.
    """
    if n_marks < 3:
        raise ContactInputError("simulate at least 3 marks")
    if not (fps > 0 and step > 0):
        raise ContactInputError("fps and step must be positive")
    if hidden.start_angle > 0 or hidden.start_angle <= -step:
        raise ContactInputError("start_angle must lie in (-step, 0]")
    p = mass_properties(collar_offset="symmetric") if props is None else props
    m, r, j = p.mass, p.ball_radius, p.axial_inertia
    e, psi = hidden.com_offset, hidden.com_phase
    m_r = rolling_torque(hidden.s_r, hidden.lam, p, 0.0, math.pi / 2, g)
    phi0 = hidden.start_angle

    # the wave's amplitude as a slope: B = M g R S_w / (J + M R^2)
    wave_slope = hidden.wave_amplitude * p.rolling_inertia / (m * g * r)
    k_wave = 2.0 * math.pi / hidden.wave_period

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        phi, w = y
        s = hidden.slope - hidden.slope_gradient * r * (phi - phi0)
        if wave_slope:
            s += wave_slope * math.sin(k_wave * (phi - phi0) + hidden.wave_phase)
        c = math.sqrt(max(1.0 - s * s, 0.0))
        chi = phi - psi
        inertia = j + m * (r * r + e * e - 2.0 * r * e * math.sin(chi))
        torque = (
            m * g * (r * s - e * s * math.sin(chi) + e * c * math.cos(chi))
            + m * r * e * math.cos(chi) * w * w
            - m_r
            - hidden.viscous * w
        )
        return [w, torque / inertia]

    targets = np.arange(n_marks) * step
    start_acc = rhs(0.0, np.array([phi0, 0.0]))[1]
    if start_acc <= 0:
        raise ContactInputError("the rotor does not start: the slope does not beat the friction")
    events = []
    for target in targets:
        def ev(_t, y, target=target):
            return y[0] - target
        ev.terminal = False
        ev.direction = 1
        events.append(ev)
    # integrate long enough to pass the last mark (from rest at the smallest acceleration)
    t_end = 4.0 * math.sqrt(2 * (targets[-1] - phi0) / start_acc) + 10.0
    last = targets[-1]

    def done(_t, y):
        return y[0] - (last + 0.5 * step)
    done.terminal = True
    done.direction = 1

    def stall(_t, y):
        return y[1] + 1e-9 if _t > 1e-3 else 1.0
    stall.terminal = True
    stall.direction = -1

    sol = solve_ivp(rhs, (0.0, t_end), [phi0, 0.0], method="DOP853", rtol=1e-11, atol=1e-12,
                    events=[*events, done, stall], dense_output=False)
    crossings = np.full(n_marks, np.nan)
    for i, te in enumerate(sol.t_events[:n_marks]):
        if len(te):
            crossings[i] = te[0]
    if phi0 == 0.0:
        crossings[0] = 0.0  # released on the first mark
    if np.any(~np.isfinite(crossings)):
        raise ContactInputError("the simulated rotor stalled before the last mark")
    t_true = crossings + hidden.start_time
    omega = np.array([float(ys[0][1]) if len(ys) else 0.0 for ys in sol.y_events[:n_marks]])
    clean, frames = _read_frames(hidden, t_true, omega, start_acc, fps, seed)
    return SimulatedRun(
        k=readonly(np.arange(1, n_marks + 1)),
        frames=readonly(frames),
        clean_frames=readonly(clean),
        true_times=readonly(t_true),
        hidden=hidden,
        fps=float(fps),
        step=float(step),
    )


def _read_frames(hidden: HiddenEffects, t_true: np.ndarray, omega: np.ndarray,
                 start_acc: float, fps: float, seed: int | None) -> tuple[np.ndarray, np.ndarray]:
    """Frame indices as the reader notes them, before and after the misreads: the first
    frame at or past each (angularly misjudged) crossing."""
    n_marks = t_true.size
    rng = np.random.default_rng(seed)
    if hidden.reading_sd > 0:
        # the angular speed at each mark turns an angular reading error into a time error
        delta = hidden.reading_sd * rng.standard_normal(n_marks)
        w_eff = np.sqrt(omega**2 + 2 * start_acc * hidden.reading_sd)
        t_read = t_true + delta / w_eff
        t_read[0] = t_true[0]  # the first row is the time origin
    else:
        t_read = t_true
    clean = np.ceil(t_read * fps - 1e-9).astype(np.int64)
    frames = clean.copy()
    for k, d in zip(hidden.misread, hidden.misread_by):
        if not 2 <= k <= n_marks:
            raise ContactInputError(f"misread row {k} is not in 2..{n_marks}")
        frames[k - 1] += int(d)
    return clean, frames


def random_hidden_effects(
    seed: int | np.random.Generator,
    effect: str | None = None,
    *,
    decay_form: str | None = None,
    n_misread: int | None = None,
    n_marks: int = 25,
    step: float = MARK_STEP,
    reading_sd: float = 0.0,
    props: MassProperties | None = None,
    g: float = G_STANDARD,
    decay_fraction: tuple[float, float] = (0.12, 0.4),
    unbalance_fraction: tuple[float, float] = (0.12, 0.3),
    misread_frames: tuple[int, int] = (5, 12),
    wave_fraction: tuple[float, float] | None = None,
    wave_period_rev: tuple[float, float] = (0.3, 3.0),
) -> HiddenEffects:
    """Draw a random mix of hidden effects of random size and phase.

    Parameters
    ----------
    seed : int or Generator
    effect : str, optional
        Force one of :data:`EFFECTS` (default: drawn at random).
    decay_form : {"position", "speed"}, optional
        Force the decay form (default: drawn).
    n_misread : int, optional
        Number of misread rows (default: 0 to 2 at random; ``none`` runs get 0 unless
        given).
    decay_fraction : (float, float)
        The acceleration lost over the run, as a fraction of ``eps0``.
    unbalance_fraction : (float, float)
        Unbalance amplitude as a fraction of ``eps0``.
    misread_frames : (int, int)
        Range of the misread offsets in frames (sign random).
    wave_fraction : (float, float), optional
        Add a plate wave of this amplitude range (fraction of ``eps0``), of period uniform
        in ``wave_period_rev`` (revolutions) and random phase; drawn after everything else,
        so the other draws do not change.

    Notes
    -----
    Accelerations are drawn like the paper's (``eps0`` 1.6 to 2.6 rad/s², rolling friction
    ``s_r`` 5 to 50 um with ``lam = 1``); the start is a rest position up to 0.3 rad before
    the first mark (exactly on it one time in three), released 0.3 to 2 s into the film.
    """
    rng = np.random.default_rng(seed)
    p = mass_properties(collar_offset="symmetric") if props is None else props
    if effect is None:
        effect = str(rng.choice(EFFECTS))
    if effect not in EFFECTS:
        raise ContactInputError(f"effect must be one of {EFFECTS}, got {effect!r}")
    decays = effect in ("decaying", "decaying+unbalance")
    unbal = effect in ("unbalance", "decaying+unbalance")
    if decays and decay_form is None:
        decay_form = str(rng.choice(("position", "speed")))
    if not decays:
        decay_form = None
    eps0 = float(rng.uniform(1.6, 2.6))
    s_r = float(rng.uniform(5e-6, 50e-6))
    inertia = p.rolling_inertia
    m_r = rolling_torque(s_r, 1.0, p, 0.0, math.pi / 2, g)
    slope = (inertia * eps0 + m_r) / (p.mass * g * p.ball_radius)
    phi_end = (n_marks - 1) * step
    kappa = visc = eta = gamma = 0.0
    if decays:
        frac = float(rng.uniform(*decay_fraction))
        if decay_form == "position":
            eta = frac * eps0 / phi_end
            kappa = eta * inertia / (p.mass * g * p.ball_radius**2)
        else:
            # the speed at the end, from rest with the mean acceleration
            w_end = math.sqrt(2 * eps0 * (1 - frac / 2) * phi_end)
            gamma = frac * eps0 / w_end
            visc = gamma * inertia
    amp = e = psi = 0.0
    if unbal:
        amp = float(rng.uniform(*unbalance_fraction)) * eps0
        e = amp * inertia / (p.mass * g)
        psi = float(rng.uniform(0, 2 * math.pi))
    start_angle = 0.0 if rng.random() < 1 / 3 else -float(rng.uniform(0.0, 0.3))
    start_time = float(rng.uniform(0.3, 2.0))
    if n_misread is None:
        n_misread = 0 if effect == "none" else int(rng.integers(0, 3))
    rows = sorted(int(v) for v in rng.choice(np.arange(3, n_marks + 1), size=n_misread,
                                             replace=False)) if n_misread else []
    # keep misread rows apart so each stays a single-row error
    rows = [k for i, k in enumerate(rows) if i == 0 or k - rows[i - 1] > 1]
    by = tuple(int(rng.integers(misread_frames[0], misread_frames[1] + 1))
               * int(rng.choice((-1, 1))) for _ in rows)
    wave = {}
    if wave_fraction is not None:
        wave = {"wave_amplitude": float(rng.uniform(*wave_fraction)) * eps0,
                "wave_period": 2 * math.pi * float(rng.uniform(*wave_period_rev)),
                "wave_phase": float(rng.uniform(0, 2 * math.pi))}
    return HiddenEffects(
        **wave,
        effect=effect,
        decay_form=decay_form,
        slope=float(slope),
        slope_gradient=float(kappa),
        viscous=float(visc),
        com_offset=float(e),
        com_phase=float(psi),
        s_r=s_r,
        lam=1.0,
        start_angle=start_angle,
        start_time=start_time,
        misread=tuple(rows),
        misread_by=by,
        reading_sd=float(reading_sd),
        eps0=eps0,
        eta=float(eta),
        gamma=float(gamma),
        amplitude=float(amp),
    )


def simulate_random_run(
    seed: int,
    effect: str | None = None,
    *,
    n_marks: int = 25,
    fps: float = FPS,
    step: float = MARK_STEP,
    min_signature: float | None = None,
    max_draws: int = 100,
    **kwargs,
) -> SimulatedRun:
    """:func:`random_hidden_effects` then :func:`simulate_rotor`.

    Misread offsets that would break the column's order are shrunk so that the frames still
    increase. With ``min_signature`` (frames), draws are repeated (from the same seeded
    stream, with the same effect class) until every hidden effect's
    :func:`effect_signature` reaches it, so that the effect is recoverable in principle;
    sizes, phases, start and misreads stay random.

    Parameters
    ----------
    seed : int
        Seed of the random draw (the same seed gives the same run).
    effect : str, optional
        One of :data:`EFFECTS` (``"none"``, ``"decaying"``, ``"unbalance"``,
        ``"decaying+unbalance"``); drawn at random when None.
    n_marks : int
        Rows of the column.
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).
    min_signature : float, optional
        The least signature (frames) every hidden effect must leave.
    max_draws : int
        Draws tried to reach ``min_signature``.
    **kwargs
        Passed to the draw of the hidden effects.

    Returns
    -------
    SimulatedRun
        The frame indices and the truth behind them.

    Raises
    ------
    ContactInputError
        No draw in ``max_draws`` reached ``min_signature``.

    See Also
    --------
    analyse_test : recovers the effects from the frames.

    Examples
    --------
    A run with an unbalanced rotor and one misread row: the analysis finds both, and the
    initial acceleration to within 0.01 rad/s² of the truth:

    >>> from rotor import analyse_test, simulate_random_run
    >>> run = simulate_random_run(3, "unbalance")
    >>> print(run.hidden.effect, run.hidden.misread, f"{run.hidden.eps0:.2f} rad/s²")
    unbalance (14,) 1.69 rad/s²
    >>> report = analyse_test("x1", run.frames)
    >>> print(report.effect, report.outliers, f"{report.eps0:.2f} rad/s²")
    unbalance (14,) 1.69 rad/s²
    """
    rng = np.random.default_rng(seed)
    if effect is None:
        # the class is drawn once, so that redrawing for visibility does not bias it
        effect = str(rng.choice(EFFECTS))
    for _ in range(max_draws):
        run = _one_run(rng, effect, n_marks, fps, step, kwargs)
        if min_signature is None:
            return run
        sig = effect_signature(run)
        if all(v >= min_signature for v in sig.values()):
            return run
    raise ContactInputError(
        f"no draw in {max_draws} gave every effect a signature of {min_signature} frames"
    )


def _one_run(rng: np.random.Generator, effect, n_marks, fps, step, kwargs) -> SimulatedRun:
    from dataclasses import replace

    hidden = random_hidden_effects(rng, effect, n_marks=n_marks, step=step, **kwargs)
    noise_seed = int(rng.integers(2**31))
    run = simulate_rotor(hidden, n_marks=n_marks, fps=fps, step=step, seed=noise_seed)
    if not hidden.misread:
        return run
    clean = np.asarray(run.clean_frames)
    by = []
    for k, d in zip(hidden.misread, hidden.misread_by):
        i = k - 1
        room_up = (clean[i + 1] - clean[i] - 1) if i + 1 < clean.size else abs(d)
        room_dn = clean[i] - clean[i - 1] - 1
        by.append(int(min(d, room_up)) if d > 0 else int(max(d, -room_dn)))
    hidden = replace(hidden, misread_by=tuple(by))
    return simulate_rotor(hidden, n_marks=n_marks, fps=fps, step=step, seed=noise_seed)


def effect_signature(run: SimulatedRun) -> dict[str, float]:
    """How visible each hidden effect is at the camera's frame rate.

    For each effect the run hides, the rms (in frames) of the best fit to the exact,
    noise-free crossing times of the model that lacks that effect (start time and angle
    free): ``"decay"`` against ``const`` (or ``unbalance``), ``"unbalance"`` against
    ``const`` (or the run's decay form). An effect whose signature is well below the frame
    quantisation (0.29 frame rms) cannot be recovered by any analysis of the frame indices:
    a free start absorbs much of an unbalance, for instance, at some phases.
    """
    from rotor._fitting import fit_model
    from rotor._noise import Noise, quantisation_sigma

    h = run.hidden
    t = np.asarray(run.true_times) - float(run.true_times[0])
    phi = (np.asarray(run.k) - 1) * run.step
    flat = Noise(quantisation_sigma(run.fps), 0.0)
    out: dict[str, float] = {}

    def misfit(model: str, inits: list[dict[str, float]]) -> float:
        fit = fit_model(t, phi, model, fps=run.fps, step=run.step, noise=flat, inits=inits)
        return fit.rms * run.fps

    start = [{"eps0": h.eps0, "t0": 0.0, "phi0": max(h.start_angle, -run.step + 1e-6)}]
    decays = h.effect in ("decaying", "decaying+unbalance")
    unbal = h.effect in ("unbalance", "decaying+unbalance")
    if decays:
        out["decay"] = misfit("unbalance" if unbal else "const", start)
    if unbal:
        out["unbalance"] = misfit(str(h.decay_form) if decays else "const",
                                  [{**start[0], "eta": h.eta, "gamma": h.gamma}])
    return out
