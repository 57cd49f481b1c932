"""A soft rig where lambda != 1 is physically possible and present (issue 35, "Done means"):
the verdict must find it, and on the same rig with lambda = 1 must not.

The rig: the paper's rotor (20 mm steel balls, its mass and inertia) on a PMMA plate
(E = 3 GPa, nu = 0.37, written out below), so that the Hertz contact radius at the
symmetric ball load is about 273 µm, 2.6 times the paper's 106 µm on aluminium; the
asymmetric group's ball loads the settling experiment's larger contrast, 6.7/2.6 N of the
9.3 N weight (:func:`rotor._tables.loaded_rotor`), against 4.67/4.67 N.

The design (the settling experiment of ``docs/rotor_verdict.md``): both groups on one lane
(a shared track, no lane-to-lane variation), 10 launches per group, launch spread 0.037
rad/s² (the spread Table 3 shows; its experiment table gives 8 per group for lambda = 4/3
at the bound on the aluminium rig at this contrast), the rig's slope given (the track's mean
equivalent slope, as a level laid along the lane reads it).

The hidden effect, drawn per table from a stated prior: ``M_r = s N**lambda`` with lambda
uniform in [4/3, 3/2] and a friction arm ``M_r / N`` at the symmetric load uniform in
[0.4, 0.6] a (well inside the contact), the same ``s`` for both groups: an offset of
0.08-0.21 rad/s² that only lambda != 1 makes. Everything else is the calibration's prior
(:func:`rotor._tables.draw_scenario`): acceleration 1.5-2.8 rad/s², a slope trend,
a plate wave of random amplitude, period and phase, reading scatter, release points and
misread rows. The start slope follows from the arm (0.8-1.2 deg).

The truths are closed forms written here: Hertz's radius, the level ball loads from the
load share, the offset ``s (sum_s N**lam - sum_as N**lam) / (J + M R^2)`` and the constant
acceleration of a launch on a plane plate.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from contact._errors import ContactInputError
from rotor._arm import arm_bound
from rotor._mechanics import G_STANDARD, mass_properties
from rotor._paper import FPS, MARK_STEP
from rotor._rig import Rig, RigGroup
from rotor._simulator import HiddenEffects, simulate_rotor
from rotor._tables import draw_scenario, group_loads, loaded_rotor, simulate_table
from rotor._verdict import judge_table

# PMMA on steel, written out (data sheets: E = 3 GPa, nu = 0.37; steel 210 GPa, 0.30)
E_PMMA, NU_PMMA, E_STEEL, NU_STEEL = 3.0e9, 0.37, 210e9, 0.30
E_STAR = 1.0 / ((1 - NU_PMMA**2) / E_PMMA + (1 - NU_STEEL**2) / E_STEEL)
SHARE = 6.7 / 9.3
"""Ball 1's share of the weight in the asymmetric group: 6.7/2.6 N."""
LAUNCHES = 10
LAUNCH_SD = 0.037
LAMBDA_PRIOR = (4 / 3, 1.5)
ARM_PRIOR = (0.4, 0.6)
"""The friction arm as a fraction of the Hertz radius."""

SYM = mass_properties(collar_offset="symmetric")
WEIGHT = SYM.mass * G_STANDARD
LOADS = {"as": (SHARE * WEIGHT, (1 - SHARE) * WEIGHT), "s": (WEIGHT / 2, WEIGHT / 2)}
HERTZ_A = (3 * LOADS["s"][0] * SYM.ball_radius / (4 * E_STAR)) ** (1 / 3)
COLUMNS = {g: [f"{g}{i}" for i in range(1, LAUNCHES + 1)] for g in ("as", "s")}


def _rotors() -> dict:
    return {"as": loaded_rotor(SHARE), "s": SYM}


def _mean_slope(track, length: float) -> float:
    """The track's mean equivalent slope over ``length`` rad of turn from the release: the
    trend's midpoint and the wave's mean, in closed form."""
    r, inertia = SYM.ball_radius, SYM.rolling_inertia
    w = track.wave_amplitude * inertia / (SYM.mass * G_STANDARD * r)  # the wave as a slope
    k = 2 * math.pi / track.wave_period
    wave = w * (math.cos(track.wave_phase) - math.cos(k * length + track.wave_phase)) / (
        k * length)
    return math.asin(track.slope - track.slope_gradient * r * length / 2 + wave)


def _rig(slope: float) -> Rig:
    return Rig(SYM.ball_radius, SYM.mass, SYM.axial_inertia, FPS, MARK_STEP, slope,
               tuple(RigGroup(g, LOADS[g], tuple(COLUMNS[g])) for g in ("as", "s")),
               e_star=E_STAR, plate="PMMA plate")


def _soft_table(seed: int, lam_one: bool = False):
    """One soft-rig table: the hidden lambda and arm drawn from the prior by ``seed``; with
    ``lam_one`` the same table's draws (track, noise, arm) at lambda = 1."""
    prior = np.random.default_rng([35, 7, seed])
    lam = 1.0 if lam_one else float(prior.uniform(*LAMBDA_PRIOR))
    arm = float(prior.uniform(*ARM_PRIOR)) * HERTZ_A
    rng = np.random.default_rng([35, 7, seed, 1])
    scn = replace(draw_scenario(rng, lam=lam, rotors=_rotors(), arm=arm),
                  launches=LAUNCHES, launch_sd=LAUNCH_SD)
    cols = simulate_table(scn, rng)
    sums = {g: sum(n**lam for n in LOADS[g]) for g in LOADS}
    s = arm / (WEIGHT / 2) ** (lam - 1)
    truth = {"lam": lam, "arm": arm,
             "offset": s * (sums["as"] - sums["s"]) / SYM.rolling_inertia}
    slope = _mean_slope(scn.tracks["s"], (scn.n_marks - 1) * MARK_STEP)
    # BLAS threads thrash on a busy 2-core machine (the joint fit's SVDs: 16 times slower)
    with threadpool_limits(limits=1, user_api="blas"):
        v = judge_table(cols, COLUMNS, fps=FPS, step=MARK_STEP, rig=_rig(slope),
                        permutation=False)
    return v, truth


def _found(v, truth) -> list[str]:
    """What the verdict misses of a present lambda != 1 (empty: all found)."""
    e, o, b = v.exponent, v.offset, v.arm
    miss = []
    if v.code != "difference":
        miss.append(f"code {v.code}")
    if not o.ci_low <= truth["offset"] <= o.ci_high:
        miss.append(f"offset {truth['offset']:.4f} outside [{o.ci_low:.4f}, {o.ci_high:.4f}]")
    if not e.ci_low <= truth["lam"] <= e.ci_high:
        miss.append(f"lambda {truth['lam']:.3f} outside [{e.ci_low:.3f}, {e.ci_high:.3f}]")
    if not b.lambda_low <= truth["lam"]:
        miss.append(f"the bound's lambda {b.lambda_low:.3f} above the true {truth['lam']:.3f}")
    return miss


def _arm_inside(v, truth) -> None:
    """The arm check: s_r <= a, with a the PMMA plate's Hertz radius, and the arm the one
    hidden (the lambda = 1 arm T / sum N differs from it by the tiny load contrast's share)."""
    b = v.arm
    assert b.arm_bound == pytest.approx(HERTZ_A, rel=1e-9)
    assert "PMMA" in b.bound_basis
    assert b.friction_arm == pytest.approx(truth["arm"], rel=0.1)
    assert b.arm_ratio < 0.7


def test_loaded_rotor_gives_the_stated_ball_loads_and_the_simulator_rolls_it() -> None:
    """The larger contrast's rotor: level ball loads share x M g, and a launch on a plane
    plate accelerates at the closed form (M g R S - s (N1**lam + N2**lam)) / (J + M R^2)."""
    rot = loaded_rotor(SHARE)
    assert group_loads("as", rotors=_rotors()) == pytest.approx(LOADS["as"], rel=1e-12)
    assert (rot.mass, rot.axial_inertia, rot.ball_radius) == (SYM.mass, SYM.axial_inertia,
                                                              SYM.ball_radius)
    lam, s, slope = 4 / 3, 1e-4, 0.02
    eps = (WEIGHT * SYM.ball_radius * slope - s * sum(n**lam for n in LOADS["as"])) / \
        SYM.rolling_inertia
    hidden = HiddenEffects(
        effect="none", decay_form=None, slope=slope, slope_gradient=0.0, viscous=0.0,
        com_offset=0.0, com_phase=0.0, s_r=s, lam=lam, start_angle=0.0, start_time=0.0,
        misread=(), misread_by=(), reading_sd=0.0, eps0=eps, eta=0.0, gamma=0.0,
        amplitude=0.0)
    run = simulate_rotor(hidden, props=rot, n_marks=6)
    phi = (np.asarray(run.k) - 1) * run.step
    assert np.asarray(run.true_times) == pytest.approx(np.sqrt(2 * phi / eps), rel=1e-8)
    with pytest.raises(ContactInputError, match="share"):
        loaded_rotor(1.2)


def test_an_arm_of_its_own_sets_the_friction_and_the_slope() -> None:
    """``draw_scenario(arm=...)``: the same s for both groups with s N_s**(lam - 1) = arm,
    and the start slope that gives the drawn acceleration with that torque."""
    lam, arm = 1.4, 120e-6
    scn = draw_scenario(np.random.default_rng(3), lam=lam, rotors=_rotors(), arm=arm)
    assert scn.s_r["as"] == pytest.approx(scn.s_r["s"], rel=1e-12)
    assert scn.s_r["s"] * (WEIGHT / 2) ** (lam - 1) == pytest.approx(arm, rel=1e-12)
    torque = arm * WEIGHT
    eps = (WEIGHT * SYM.ball_radius * scn.tracks["s"].slope - torque) / SYM.rolling_inertia
    assert 1.5 <= eps <= 2.8
    with pytest.raises(ContactInputError, match="arm"):
        draw_scenario(np.random.default_rng(3), arm=-1e-6)


def test_a_rigs_plate_sets_the_arm_bound() -> None:
    """The rig's own E* (a PMMA plate) gives Hertz's radius there, not the paper's
    aluminium one."""
    b = arm_bound(_rig(math.radians(1.0)), "s", "as", math.radians(1.0), 2.0, 0.1, 0.05, 0.15)
    assert b.arm_bound == pytest.approx(HERTZ_A, rel=1e-9)
    assert b.e_star == pytest.approx(E_STAR, rel=0.02)
    assert 260e-6 < b.arm_bound < 290e-6 and "PMMA" in b.bound_basis


@pytest.mark.parametrize("seed", [0, 1])
def test_soft_rig_lambda_present_is_found_and_absent_is_not(seed: int) -> None:
    """A present lambda != 1 (drawn from the prior) is found: a difference, the true offset
    and lambda inside their intervals (lambda at the rig's slope), the arm bound's lambda a
    lower bound, the arm inside the contact; the same table at lambda = 1: no difference."""
    v, truth = _soft_table(seed)
    assert not _found(v, truth), (truth, v.sentence)
    _arm_inside(v, truth)
    v1, truth1 = _soft_table(seed, lam_one=True)
    assert v1.code == "no_difference", v1.sentence
    _arm_inside(v1, truth1)


@pytest.mark.campaign
def test_soft_rig_campaign() -> None:
    """20 tables from the prior, each also at lambda = 1: lambda != 1 found (every check of
    :func:`_found`) in at least 17, a difference in at least 19; lambda = 1 read as no
    difference in at least 18 (the offset test's false-alarm rate is 2 %); the arm inside the
    contact in all. Measured (84 s): found 19, a difference 20, no difference at lambda = 1
    19 (seed 18's draws read as a difference both ways: the true offset below the
    interval)."""
    found = called = null_ok = 0
    misses = []
    for seed in range(20):
        v, truth = _soft_table(seed)
        miss = _found(v, truth)
        found += not miss
        called += v.code == "difference"
        misses += [(seed, m) for m in miss]
        _arm_inside(v, truth)
        v1, truth1 = _soft_table(seed, lam_one=True)
        null_ok += v1.code == "no_difference"
        _arm_inside(v1, truth1)
    assert found >= 17 and called >= 19 and null_ok >= 18, (found, called, null_ok, misses)
