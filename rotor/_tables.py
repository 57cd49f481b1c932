"""Whole tables of launches simulated by the ODE integrator (:mod:`rotor._simulator`):
the calibration and the tests of the joint model's verdict.

A table is two groups of launches (the paper's asymmetric collar, ``as``, against the end of
the rod and the symmetric one, ``s``) on a plate whose slope is a trend plus one wave; each
launch has its own release point, release time, reading scatter and misread rows, and its own
rolling-friction coefficient (the launch-to-launch spread). The stated prior of the
calibration (:func:`draw_scenario`) is the paper's rig with accelerations of 1.5-2.8 rad/s²,
slopes of 0.6-1.0 degrees and the scatter Table 3 shows. Another rig is a :class:`Scenario`
with ``rotors`` of its own (:func:`loaded_rotor`: any load contrast) and a friction arm of
its own (``draw_scenario(arm=...)``: the slope then follows from the arm), as a soft plate's
large contact allows.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from contact._errors import ContactInputError
from rotor._mechanics import G_STANDARD, MassProperties, mass_properties
from rotor._paper import FPS, MARK_STEP
from rotor._simulator import HiddenEffects, simulate_rotor

__all__ = ["LANE_PRIOR", "LanePrior", "PlateTrack", "Scenario", "draw_lanes", "draw_scenario",
           "group_loads", "lane_track", "loaded_rotor", "simulate_table"]

GROUPS = {"as": "end", "s": "symmetric"}
"""The paper's two collar positions, as :func:`~rotor._mechanics.mass_properties`
names them."""


@dataclass(frozen=True)
class PlateTrack:
    """Equivalent slope along the track: ``S0 - kappa x`` plus a wave of ``wave_amplitude``
    (rad/s² of acceleration), ``wave_period`` (rad of rotor turn) and ``wave_phase``."""

    slope: float
    slope_gradient: float = 0.0
    wave_amplitude: float = 0.0
    wave_period: float = 4 * math.pi
    wave_phase: float = 0.0


@dataclass(frozen=True)
class LanePrior:
    """Lane-to-lane variation: each launch rolls on a lane of its own, as a rotor released a
    few mm aside sees the plate. Its lane's wave is the table's wave shifted by a phase
    uniform in ``+-phase_spread`` (rad) with its amplitude scaled by a factor uniform in
    ``1 +- amplitude_spread``, and its slope trend changed by a normal ``trend_sd`` (rad/s² of
    acceleration per rad of turn). ``phase_spread``, ``amplitude_spread`` and ``trend_sd`` are
    themselves drawn per table, uniform in the given ranges."""

    phase_spread: tuple[float, float] = (0.3, math.pi)
    amplitude_spread: tuple[float, float] = (0.0, 0.5)
    trend_sd: tuple[float, float] = (0.0, 0.01)
    wave_amplitude: tuple[float, float] = (0.1, 0.4)


LANE_PRIOR = LanePrior()
"""The calibration's stated prior for lane-to-lane variation (``benchmarks/
rotor_verdict_calibration.py``): up to half a wave period of phase, half the amplitude and
0.01 rad/s² per rad of trend between lanes, on a wave of 0.1-0.4 rad/s²."""


@dataclass(frozen=True)
class Lanes:
    """One table's draw from a :class:`LanePrior`: the half-widths and sd applied to each
    launch."""

    phase_spread: float
    amplitude_spread: float
    trend_sd: float


@dataclass(frozen=True)
class Scenario:
    """One simulated table's truth: per group its track and rolling-friction law
    (``s_r``, ``lam``), the launch spread ``launch_sd`` (rad/s²), the reading scatter
    ``reading_sd`` (rad) and the launches per group; ``lanes``: each launch on a lane of
    its own (None: every launch of a group on the group's track); ``rotors``: each group's
    rotor (None: the paper's, with its collar as :data:`GROUPS` says).

    See Also
    --------
    draw_scenario : draws one from the calibration's prior.
    simulate_table : the frame columns it gives.

    Examples
    --------
    An offset of 0.3 rad/s² is a difference of ``s_r`` of ``0.3 (J + M R²) / (M g)``
    between the groups, 1.75e-5 m at ``lambda = 1``:

    >>> import numpy as np
    >>> from rotor import draw_scenario
    >>> scn = draw_scenario(np.random.default_rng(1), offset=0.3)
    >>> print(scn.lam, scn.launches, f"{scn.s_r['as'] - scn.s_r['s']:.2e} m")
    1.0 3 1.75e-05 m
    """

    tracks: dict[str, PlateTrack]
    s_r: dict[str, float]
    lam: float
    launch_sd: float
    reading_sd: float
    launches: int = 3
    n_marks: int = 25
    misreads: bool = True
    lanes: Lanes | None = None
    rotors: Mapping[str, MassProperties] | None = None


def _props(group: str, rotors: Mapping[str, MassProperties] | None = None) -> MassProperties:
    if rotors is not None:
        return rotors[group]
    return mass_properties(collar_offset=GROUPS[group])


def group_loads(group: str, g: float = G_STANDARD,
                rotors: Mapping[str, MassProperties] | None = None) -> tuple[float, float]:
    """Ball loads (N) of a group's rotor on a level plate (the paper's unless ``rotors``)."""
    p = _props(group, rotors)
    mg = p.mass * g
    return mg * p.d2 / (p.d1 + p.d2), mg * p.d1 / (p.d1 + p.d2)


def loaded_rotor(share: float, props: MassProperties | None = None) -> MassProperties:
    """``props`` (default: the paper's symmetric rotor) with its centre of mass moved along
    the axis so that ball 1 carries ``share`` of the weight on a level plate; mass, inertia
    and ball radius kept. A rig the paper's collar cannot make (it reaches a share of 0.575
    at the rod's end): 6.7/2.6 N, for instance, is ``share = 6.7 / 9.3``."""
    p = mass_properties(collar_offset="symmetric") if props is None else props
    if not (isinstance(share, (int, float)) and 0.0 < share < 1.0):
        raise ContactInputError(f"a ball's share of the weight must lie in (0, 1), got {share!r}")
    span = p.d1 + p.d2
    d2 = share * span  # N1 = M g d2 / (d1 + d2)
    return replace(p, d1=span - d2, d2=d2, com_offset=d2 - 0.5 * span)


def draw_lanes(rng: np.random.Generator, prior: LanePrior = LANE_PRIOR) -> Lanes:
    """One table's lane-to-lane variation from ``prior``."""
    return Lanes(rng.uniform(*prior.phase_spread), rng.uniform(*prior.amplitude_spread),
                 rng.uniform(*prior.trend_sd))


def lane_track(track: PlateTrack, lanes: Lanes, rng: np.random.Generator) -> PlateTrack:
    """A launch's own lane: ``track`` with its wave shifted and scaled and its trend
    changed as ``lanes`` says."""
    p = _props("s")
    to_kappa = p.rolling_inertia / (p.mass * G_STANDARD * p.ball_radius**2)
    return replace(
        track, wave_phase=track.wave_phase + rng.uniform(-lanes.phase_spread,
                                                         lanes.phase_spread),
        wave_amplitude=track.wave_amplitude * rng.uniform(1 - lanes.amplitude_spread,
                                                          1 + lanes.amplitude_spread),
        slope_gradient=track.slope_gradient + lanes.trend_sd * rng.standard_normal() * to_kappa)


def draw_scenario(rng: np.random.Generator, *, offset: float = 0.0, track_differs: bool = False,
                  lam: float = 1.0, slope_deg: tuple[float, float] = (0.6, 1.0),
                  lanes: LanePrior | None = None,
                  rotors: Mapping[str, MassProperties] | None = None,
                  arm: float | None = None) -> Scenario:
    """A table from the calibration's prior.

    The symmetric group's acceleration exceeds the asymmetric one's by ``offset`` rad/s²
    (through its rolling-friction coefficient); ``track_differs`` gives the groups tracks of
    their own (another trend and another wave); ``lam`` the exponent of ``M_r = s_r N**lam``;
    ``lanes``: each launch on a lane of its own, drawn from this prior (its wave amplitude
    range replaces the plate's); ``rotors``: each group's rotor (``{"as": ..., "s": ...}``,
    default the paper's); ``arm``: the friction arm ``M_r / N`` (m) at the symmetric group's
    ball load, ``s_r = arm / N_s**(lam - 1)`` for both groups, the start slope then following
    from the drawn acceleration (``slope_deg`` is drawn but unused, so that the other draws
    do not change).

    Parameters
    ----------
    rng : numpy.random.Generator
        The random stream.
    offset : float
        Symmetric minus asymmetric group's acceleration (rad/s²).
    track_differs : bool
        Give each group a track of its own.
    lam : float
        The exponent of ``M_r = s_r N**lam``.
    slope_deg : tuple of float
        Range of the start slope (degrees).
    lanes : LanePrior, optional
        Put each launch on a lane of its own.
    rotors : Mapping of str to MassProperties, optional
        Each group's rotor.
    arm : float, optional
        The friction arm ``M_r / N`` (m) at the symmetric group's ball load.

    Returns
    -------
    Scenario
        The table's truth.

    Raises
    ------
    ContactInputError
        A friction arm that is not a positive length.

    See Also
    --------
    simulate_table : the frame columns of a scenario.

    Examples
    --------
    >>> import numpy as np
    >>> from rotor import draw_scenario
    >>> scn = draw_scenario(np.random.default_rng(1), offset=0.3, lam=4 / 3)
    >>> sorted(scn.tracks), round(scn.lam, 3), scn.launches
    (['as', 's'], 1.333, 3)
    """
    p = _props("s", rotors)
    j = p.rolling_inertia
    mgr = p.mass * G_STANDARD * p.ball_radius
    slope = math.sin(math.radians(rng.uniform(*slope_deg)))
    eps = rng.uniform(1.5, 2.8)
    n_s = group_loads("s", rotors=rotors)
    if arm is None:
        torque = mgr * slope - eps * j
    else:
        if not (arm > 0 and math.isfinite(arm)):
            raise ContactInputError(f"the friction arm must be a positive length, got {arm!r}")
        # both balls' torque s_r (N1**lam + N2**lam) with s_r N_s**(lam - 1) = arm
        torque = arm * (n_s[0] ** lam + n_s[1] ** lam) / (0.5 * (n_s[0] + n_s[1])) ** (lam - 1)
        slope = (torque + eps * j) / mgr
    s_r_s = torque / (n_s[0] ** lam + n_s[1] ** lam)
    # the groups' load sums are equal (M g), so at lam = 1 one s_r gives one torque
    s_r = {"s": s_r_s - offset * j / (n_s[0] ** lam + n_s[1] ** lam), "as": s_r_s}
    # eta (rad/s² per rad of turn) = M g R^2 kappa / (J + M R^2)
    to_kappa = j / (p.mass * G_STANDARD * p.ball_radius**2)

    wave = (0.0, 0.4) if lanes is None else lanes.wave_amplitude

    def track() -> PlateTrack:
        return PlateTrack(slope, rng.uniform(-0.02, 0.06) * to_kappa, rng.uniform(*wave),
                          rng.uniform(1.5, 6.0) * 2 * math.pi, rng.uniform(0, 2 * math.pi))

    shared = track()
    tracks = {"as": shared, "s": track() if track_differs else shared}
    return Scenario(tracks, s_r, lam, rng.uniform(0.01, 0.06), rng.uniform(0.02, 0.08),
                    lanes=None if lanes is None else draw_lanes(rng, lanes),
                    rotors=None if rotors is None else dict(rotors))


def simulate_table(scn: Scenario, rng: np.random.Generator, fps: float = FPS,
                   step: float = MARK_STEP) -> dict[str, np.ndarray]:
    """Frame columns ``as1..`` and ``s1..`` of one simulated table.

    Parameters
    ----------
    scn : Scenario
        The table's truth (:func:`draw_scenario`).
    rng : numpy.random.Generator
        The random stream (launch spread, misreads, starts, reading noise).
    fps, step : float
        Frame rate (1/s) and the angle between marks (rad).

    Returns
    -------
    dict of str to numpy.ndarray
        ``as1..`` and ``s1..``: frame indices of each launch, like Table 3's columns.

    See Also
    --------
    judge_table : the verdict on such a table.

    Examples
    --------
    A table whose symmetric group is faster by 0.3 rad/s²: the verdict finds the
    difference, and its interval holds the truth:

    >>> import numpy as np
    >>> from rotor import draw_scenario, judge_table, simulate_table
    >>> rng = np.random.default_rng(1)
    >>> table = simulate_table(draw_scenario(rng, offset=0.3), rng)
    >>> sorted(table), len(table["s1"])
    (['as1', 'as2', 'as3', 's1', 's2', 's3'], 25)
    >>> verdict = judge_table(table, {"s": ["s1", "s2", "s3"], "as": ["as1", "as2", "as3"]},
    ...                       fps=120.0, step=np.pi / 2, permutation=False)
    >>> off = verdict.offset
    >>> print(verdict.code, f"{off.value:.1f} rad/s²", off.ci_low < -0.3 < off.ci_high)
    difference -0.3 rad/s² True
    """
    cols: dict[str, np.ndarray] = {}
    for group in ("as", "s"):
        p = _props(group, scn.rotors)
        n = group_loads(group, rotors=scn.rotors)
        tr = scn.tracks[group]
        for i in range(1, scn.launches + 1):
            if scn.lanes is not None:
                tr = lane_track(scn.tracks[group], scn.lanes, rng)
            d_eps = scn.launch_sd * rng.standard_normal()
            s_r = scn.s_r[group] + d_eps * p.rolling_inertia / (n[0] ** scn.lam + n[1] ** scn.lam)
            mis: tuple[int, ...] = ()
            by: tuple[int, ...] = ()
            if scn.misreads and rng.random() < 0.5:
                mis = (int(rng.integers(4, scn.n_marks + 1)),)
                by = (int(rng.choice([-1, 1]) * rng.integers(3, 6)),)
            hidden = HiddenEffects(
                effect="decaying", decay_form="position", slope=tr.slope,
                slope_gradient=tr.slope_gradient, viscous=0.0, com_offset=0.0, com_phase=0.0,
                s_r=s_r, lam=scn.lam, start_angle=-rng.uniform(0.001, 0.1),
                start_time=rng.uniform(0.0, 0.5), misread=mis, misread_by=by,
                reading_sd=scn.reading_sd, eps0=math.nan, eta=math.nan, gamma=0.0,
                amplitude=0.0, wave_amplitude=tr.wave_amplitude, wave_period=tr.wave_period,
                wave_phase=tr.wave_phase)
            run = simulate_rotor(hidden, n_marks=scn.n_marks, fps=fps, step=step, props=p,
                                 seed=int(rng.integers(2**31)))
            cols[f"{group}{i}"] = np.asarray(run.frames, dtype=float)
    return cols
