"""The energy an adhesive sphere's approach-retraction cycle loses, on the rings
(``surfmet adhesion``'s default for a smooth sphere), against the physics of the cycle.

Under displacement control a Maugis sphere loses energy only at the jumps into and out of
contact (Maugis 1992, J. Colloid Interface Sci. 150:243; Greenwood & Johnson 1998, Phil.
Mag. A 77:1491); along a branch the elastic and adhesive energy is stored and given back.
At Maugis' lambda 0.0765 (R 1 mm, E* 1 GPa, w 50 mJ/m^2, h0 200 nm) the cycle has no
jump: the two legs are one curve and the loss is zero. On main the rings' Dugdale ramp
(5 sigma0 dr / E*) was narrower than the gap the outer rings open by letting go of
sigma0 (their self-compliance is ~6 dr / E*), so a ring had two equilibria and the legs
ended on different ones: 2.313e-14 J lost (1.5e-5 of the work on the approach leg).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

R, E_STAR, W = 1e-3, 1e9, 0.05
K = 4.0 * E_STAR / 3.0
# h0 for Maugis' lambda: lambda = 2 (w / h0) (R / (pi w K^2))^(1/3)
_SCALE = 2.0 * W * (R / (math.pi * W * K * K)) ** (1 / 3)


def _run(range_: float, steps: int):
    from surfmet.mechanics.adhesion import adhesion

    return adhesion(R, work=W, range_=range_, e_star=E_STAR, steps=steps,
                    model="axisymmetric").result


def _leg_work(leg) -> float:
    """The trapezoidal integral of |P| over the imposed approach (J)."""
    p = np.abs(leg.load)
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.abs(np.diff(leg.approach))))


def test_no_jump_no_loss_at_lambda_0_0765():
    """The command's case (40 steps a leg): no jump, so the legs coincide and the closed
    integral of P d(delta) is zero to round-off, far below 1e-6 of the approach work;
    reported as exactly 0 with its resolution (tol times the legs' work)."""
    from contact.adhesion.cycle import hysteresis

    res = _run(2e-7, 40)
    assert res.maugis_parameter == pytest.approx(0.0765, abs=1e-4)
    cyc = res.cycle
    a, r = cyc.approach_leg, cyc.retraction_leg
    np.testing.assert_array_equal(a.approach, r.approach[::-1])
    np.testing.assert_allclose(a.load, r.load[::-1], rtol=1e-9, atol=1e-12 * np.abs(a.load).max())
    work = _leg_work(a)
    assert abs(hysteresis(a, r)) < 1e-6 * work  # main: 2.313e-14 J, 1.5e-5 of it
    assert cyc.hysteresis_energy == 0.0
    assert 0.0 < cyc.hysteresis_resolution < 1e-5 * work


def test_every_ring_lets_go_of_its_tension_stably():
    """The rings' ramp s is wider than the gap sigma0 K_ii any ring opens by letting go of
    the peak tension (K_ii its displacement per unit pressure on itself, read from the
    ring matrix), so no ring has two equilibria at one approach (main: sigma0 K_ii was
    1.25 s on the outer ring at lambda 0.0765)."""
    from contact.adhesion._rings import ring_problem

    for range_ in (2e-7, _SCALE / 1.0):
        res = _run(range_, 4)
        problem = ring_problem(R, E_STAR, res.law, np.arange(res.rings + 1) * res.dr)
        assert res.law.peak * problem.diagonal.max() < 0.6 * res.law.smoothing


def test_a_jump_loses_energy_at_the_jumps():
    """Maugis' lambda 1 jumps in and out of contact: the cycle loses energy, far above its
    resolution, and 98 % of it is released over the two steps that hold the jumps (the
    machine's work over the step less the change of the stored energy read from the
    fields); the branches between them give back what they store (measured: 99.5 %)."""
    res = _run(_SCALE / 1.0, 16)
    cyc = res.cycle
    assert cyc.jump_in is not None and cyc.jump_in.abrupt
    assert cyc.jump_out is not None and cyc.jump_out.abrupt
    assert cyc.hysteresis_energy > 1e4 * cyc.hysteresis_resolution
    at_jumps = 0.0
    for leg, entering in ((cyc.approach_leg, True), (cyc.retraction_leg, False)):
        w = 0.5 * (leg.load[1:] + leg.load[:-1]) * np.diff(leg.approach)
        released = w - np.diff(leg.energy)
        touching = leg.contact_area > 0.0
        i = int(np.flatnonzero((touching[1:] != touching[:-1]) & (touching[1:] == entering))[0])
        at_jumps += released[i]
    assert at_jumps == pytest.approx(cyc.hysteresis_energy, rel=0.02)


def test_every_equilibrium_closes_its_disc():
    """Each ring state the cycle accepts holds the touching rings' own equation: their gap,
    recomputed from the pressures (h - delta + K p), is zero to the solve's tolerance (as
    the pressure that would close it over the pressure scale). Main read the touching
    rings' gap as zero by construction, so a damped Newton step after a set change could
    stop with the disc's edge ring 5.8e-12 m open (13 kPa, 5 % of sigma0): at lambda 0.0765
    step 31 the approach leg then held a load 3.5e-5 off the retraction's at the same
    approach."""
    from contact.adhesion._ring_ball import (
        approach_range,
        ring_edges,
        ring_law,
        ring_width,
        smoothing_width,
    )
    from contact.adhesion._rings import ring_problem
    from contact.adhesion.cycle import advance
    from contact.adhesion.laws import DugdaleLaw

    law = DugdaleLaw(work=W, sigma0=W / 2e-7)
    dr, outer = ring_width(R, E_STAR, law)
    law = ring_law(law, E_STAR, ring_edges(R, E_STAR, law, dr, outer),
                   smoothing_width(R, E_STAR, law, dr, outer))
    problem = ring_problem(R, E_STAR, law, ring_edges(R, E_STAR, law, dr, outer))
    far, deep = approach_range(R, E_STAR, law)
    steps = np.linspace(far, deep, 40)  # the command's steps, halved as the cycle does
    tol, worst, previous = 1e-7, 0.0, None
    for target in np.concatenate([steps, steps[::-1]]):
        reached = advance(problem, previous, float(target), tol)
        previous = reached[-1]
        for approach, state in reached:
            gap = state.gap
            k = int(np.argmax(gap > 0.0)) if np.any(gap > 0.0) else gap.size
            closing = np.abs(problem.gap0[:k] - approach + problem.matrix[:k] @ state.pressure)
            scale = max(law.peak, float(state.pressure.max()))
            worst = max(worst, float((closing / problem.diagonal[:k]).max(initial=0.0)) / scale)
    assert worst <= tol
