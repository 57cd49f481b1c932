"""Does what the models leave repeat across a group's launches, at the same place on the plate
or at the same angle of the rotor?

A plate that is not plane slows and speeds the rotor at the same *track positions* in every
launch from the same release point; an unbalance or a ball's form error does it at the same
*rotor angles*. For a group where some test's model is inadequate (or a plate wave was
named), every test's in-family residual is fitted with a wave of the group's median period
(the named wave's, else the residual periodogram's best;
:func:`rotor._adequacy.wave_scan` at that one period), and the phases are compared in
both coordinates: the rotor angle from the first mark, and the angle rolled since the fitted
release ``phi0`` (``track = R x angle``). Their concentration is measured by the mean
resultant length and Rayleigh's test (Zar's approximation of its p-value), which with three
launches can reach p = 0.034 only when they agree closely.

Assumptions, stated because the frame table cannot show them: the launches of a group start
from the same release point on the plate, and row 1 of every launch is the same mark of the
rotor.

References
----------
Zar J.H. (2010) Biostatistical Analysis, 5th ed., Section 27.4 (Rayleigh's test).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rotor._adequacy import named_wave, wave_scan
from rotor._analysis import TestReport
from rotor._family import EXTENSION
from rotor._paper import BALL_RADIUS

__all__ = ["ResidualAlignment", "rayleigh_p", "residual_alignment"]


@dataclass(frozen=True)
class ResidualAlignment:
    """The group's leftover wave: ``period`` (rad of rotor turn), ``revolutions``,
    ``track_length`` (m), per test ``amplitude`` (rad/s²), ``phase_rotor`` and
    ``phase_track`` (rad); the mean resultant lengths ``coherence_*`` (1: the same phase in
    every launch) and Rayleigh p-values ``p_*``; ``verdict``: ``"track position"``,
    ``"rotor angle"``, ``"both"`` (the launches also start at nearly the same angle, so the
    two cannot be told apart) or ``"neither"``."""

    period: float
    revolutions: float
    track_length: float
    tests: tuple[str, ...]
    amplitude: tuple[float, ...]
    phase_rotor: tuple[float, ...]
    phase_track: tuple[float, ...]
    coherence_rotor: float
    coherence_track: float
    p_rotor: float
    p_track: float
    verdict: str


def rayleigh_p(phases: Sequence[float]) -> tuple[float, float]:
    """Mean resultant length of ``phases`` and Rayleigh's p-value (Zar's approximation)."""
    th = np.asarray(phases, float)
    n = th.size
    if n < 2:
        return math.nan, math.nan
    rbar = float(abs(np.mean(np.exp(1j * th))))
    rn = n * rbar
    p = math.exp(math.sqrt(1.0 + 4.0 * n + 4.0 * (n * n - rn * rn)) - (1.0 + 2.0 * n))
    return rbar, min(p, 1.0)


def residual_alignment(members: Sequence[TestReport], alpha: float = 0.05,
                       rolling_radius: float = BALL_RADIUS) -> ResidualAlignment | None:
    """The alignment of a group's leftover wave (module docstring); None when every test's
    model is adequate and no wave was named, or the group has one test."""
    odd = [r for r in members if r.adequacy is not None and r.adequacy.residual is not None
           and (not r.adequacy.adequate or r.selected in EXTENSION)]
    if not odd or len(members) < 2:
        return None
    periods = []
    for r in odd:
        named = named_wave(r.fit, float(np.ptp(r.angles)))
        periods.append(named.period if named is not None else r.adequacy.residual.period)
    period = float(np.median(periods))
    k = 2.0 * math.pi / period
    amps, rot, track = [], [], []
    for r in members:
        fit = r.fits[r.family_choice or r.selected]
        scan = wave_scan(r.times, r.angles, fit, step=r.step, periods=np.array([period]))
        amps.append(float(scan.amplitude[0]))
        rot.append(float(scan.phase[0]) % (2 * math.pi))
        track.append((float(scan.phase[0]) + k * float(fit.params["phi0"])) % (2 * math.pi))
    c_rot, p_rot = rayleigh_p(rot)
    c_track, p_track = rayleigh_p(track)
    verdict = {(True, True): "both", (True, False): "track position",
               (False, True): "rotor angle", (False, False): "neither"}[
        (p_track < alpha, p_rot < alpha)]
    return ResidualAlignment(
        period=period, revolutions=period / (2 * math.pi), track_length=period * rolling_radius,
        tests=tuple(r.name for r in members), amplitude=tuple(amps), phase_rotor=tuple(rot),
        phase_track=tuple(track), coherence_rotor=c_rot, coherence_track=c_track,
        p_rotor=p_rot, p_track=p_track, verdict=verdict)
