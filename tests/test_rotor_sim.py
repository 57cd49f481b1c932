"""The rotor simulator: exact Lagrangian integration read out as Table-3 frame indices."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from contact._errors import ContactInputError
from rotor._forward import crossing_times
from rotor._simulator import (
    EFFECTS,
    effect_signature,
    random_hidden_effects,
    simulate_random_run,
    simulate_rotor,
)

PHI = np.arange(25) * math.pi / 2


def test_constant_acceleration_gives_the_closed_form_and_ceil_frames():
    h = random_hidden_effects(3, "none", n_misread=0)
    run = simulate_rotor(h)
    t = np.asarray(run.true_times) - h.start_time
    # from rest at phi0 < 0: t(phi) = sqrt(2 (phi - phi0)/eps0)
    exact = np.sqrt(2 * (PHI - h.start_angle) / h.eps0)
    if h.start_angle == 0.0:
        exact[0] = 0.0
    assert np.max(np.abs(t - exact)) < 1e-8
    assert np.array_equal(run.frames, np.ceil(np.asarray(run.true_times) * 120 - 1e-9))
    assert np.all(np.diff(run.frames) > 0)


@pytest.mark.parametrize("seed", [1, 2])
def test_decay_forms_match_the_analysis_equation_of_motion(seed):
    # the simulator (solve_ivp in time) and crossing_times (quadrature in angle) are
    # independent; without unbalance their equations of motion coincide
    for form in ("position", "speed"):
        h = random_hidden_effects(seed, "decaying", decay_form=form, n_misread=0)
        run = simulate_rotor(h)
        t = np.asarray(run.true_times) - h.start_time
        pred = crossing_times(PHI, h.eps0, eta=h.eta, gamma=h.gamma, phi0=h.start_angle)
        assert np.max(np.abs(pred - t)) * 120 < 0.01


def test_unbalance_is_a_sin_torque_up_to_the_exact_lagrangian_terms():
    h = random_hidden_effects(5, "unbalance", n_misread=0)
    run = simulate_rotor(h)
    t = np.asarray(run.true_times) - h.start_time
    a, psi = h.amplitude, h.com_phase
    pred = crossing_times(PHI, h.eps0, a_c=a * math.sin(psi), a_s=a * math.cos(psi),
                          phi0=h.start_angle)
    no_unbalance = crossing_times(PHI, h.eps0, phi0=h.start_angle)
    # the reduced torque A sin(phi + psi) explains the motion to a fraction of a frame ...
    assert np.max(np.abs(pred - t)) * 120 < 0.3
    # ... while ignoring the unbalance misses it by many frames
    assert np.max(np.abs(no_unbalance - t)) * 120 > 3
    # the parameters are those of a centre of mass tens of micrometres off the axis
    assert 1e-6 < h.com_offset < 1e-4


def test_misreads_shift_single_rows_and_keep_the_order():
    run = simulate_random_run(7, "decaying", n_misread=2)
    h = run.hidden
    assert len(h.misread) >= 1
    diff = np.asarray(run.frames) - np.asarray(run.clean_frames)
    assert set(np.flatnonzero(diff) + 1) == set(h.misread)
    assert all(abs(d) >= 5 for d in diff[diff != 0])
    assert np.all(np.diff(run.frames) > 0)


def test_reading_noise_scatters_the_slow_rows_most():
    h = replace(random_hidden_effects(11, "none", n_misread=0), reading_sd=0.05)
    noisy = simulate_rotor(h, seed=1)
    clean = simulate_rotor(replace(h, reading_sd=0.0))
    d = np.abs(np.asarray(noisy.frames) - np.asarray(clean.frames))
    assert d[0] == 0
    assert d[1:6].mean() > d[-6:].mean()


def test_random_effects_cover_every_class_and_signatures_are_measured():
    seen = {random_hidden_effects(s).effect for s in range(40)}
    assert seen == set(EFFECTS)
    run = simulate_random_run(4, "decaying+unbalance", min_signature=1.0)
    sig = effect_signature(run)
    assert set(sig) == {"decay", "unbalance"} and min(sig.values()) >= 1.0
    assert effect_signature(simulate_random_run(4, "none")) == {}


def test_bad_simulation_inputs_raise():
    h = random_hidden_effects(0, "none", n_misread=0)
    with pytest.raises(ContactInputError):
        simulate_rotor(replace(h, start_angle=0.5))
    with pytest.raises(ContactInputError):
        simulate_rotor(replace(h, slope=0.0))
    with pytest.raises(ContactInputError):
        simulate_rotor(replace(h, misread=(1,), misread_by=(5,)))
    with pytest.raises(ContactInputError):
        random_hidden_effects(0, "wobble")
