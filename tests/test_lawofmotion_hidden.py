"""Hidden effects: the simulator hides a random mix of unbalance (random amplitude and
phase), decaying acceleration (position or speed form), a random start offset and misread
rows, reads the motion out as frame indices like Table 3; the analysis must name the effect
and the misread rows, and report nothing on clean data.

Draws are made visible in principle (``min_signature``: the model lacking an effect misses
the exact, noise-free times by at least that many frames rms); below a fraction of a frame
no analysis of frame indices can see an effect (a free start absorbs much of an unbalance at
some phases). With the quantisation noise alone (as Table 3 was made), detection was measured
at 100 % over 70 such draws while developing this; see the module report.
"""

from __future__ import annotations

import pytest

from rotor._analysis import analyse_test
from rotor._simulator import simulate_random_run

CLEAN_SEEDS = [40, 41, 42]
HIDDEN = [(0, None), (1, None), (2, None), (3, "decaying+unbalance"), (4, "unbalance"),
          (5, "decaying")]


@pytest.mark.parametrize("seed", CLEAN_SEEDS)
def test_clean_data_report_nothing(seed):
    run = simulate_random_run(seed, "none", n_misread=0)
    assert run.hidden.effect == "none" and not run.hidden.misread
    rep = analyse_test("c1", run.frames)
    assert rep.effect == "none"
    assert rep.outliers == ()
    # constant acceleration recovered; the start offset is fitted, not mistaken for an effect
    assert rep.eps0 == pytest.approx(run.hidden.eps0, rel=0.01)


@pytest.mark.parametrize(("seed", "effect"), HIDDEN)
def test_hidden_effect_and_misread_rows_are_recovered(seed, effect):
    run = simulate_random_run(seed, effect, min_signature=0.7)
    h = run.hidden
    rep = analyse_test("h1", run.frames)
    assert rep.effect == h.effect, (h, rep.selected)
    assert set(rep.outliers) == set(h.misread), (h.misread, h.misread_by, rep.outliers)
    # the model of the true form recovers the initial acceleration (the selected one may
    # have the other decay form: position and speed decay are often within a few BIC
    # units, and eps0 is an extrapolation to the start that depends on the form)
    parts = [h.decay_form] if h.decay_form else []
    parts += ["unbalance"] if "unbalance" in h.effect else []
    true_model = "+".join(parts) or "const"
    assert rep.fits[true_model].eps0 == pytest.approx(h.eps0, rel=0.02)
    if "unbalance" in h.effect:
        assert rep.fits[true_model].params["amplitude"] == pytest.approx(h.amplitude, rel=0.3)


def test_effect_classes_are_all_covered():
    effects = {simulate_random_run(s, e, min_signature=0.7).hidden.effect for s, e in HIDDEN}
    assert effects == {"decaying", "unbalance", "decaying+unbalance"}


@pytest.mark.parametrize("seed", [100, 101])
def test_angular_reading_noise_is_not_taken_for_an_effect(seed):
    # reading scatter of 0.03 rad makes the slow early rows noisy by a few frames
    run = simulate_random_run(seed, "none", n_misread=0, reading_sd=0.03)
    rep = analyse_test("n1", run.frames)
    assert rep.effect == "none"


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(6, 14))
def test_more_hidden_draws(seed):
    run = simulate_random_run(seed, min_signature=0.7)
    rep = analyse_test("h1", run.frames)
    assert rep.effect == run.hidden.effect
    assert set(rep.outliers) == set(run.hidden.misread)
