"""Adequacy of the rotor's law of motion (issue 17): the plate-wave forward term against an
ODE, the first-order wave response against finite differences, the calibrated check on clean
columns made independently of the analysis, hidden plate waves flagged or named, Rayleigh
and Welch against closed forms and a reference implementation, and the CLI's words."""

from __future__ import annotations

import io
import json
import math
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from rotor_clean_columns import clean_column
from scipy.integrate import solve_ivp

from rotor._adequacy import ALPHA, _wave_response, check_adequacy
from rotor._alignment import rayleigh_p
from rotor._analysis import analyse_test
from rotor._forward import PARAM_NAMES, crossing_times
from rotor._groups import welch_p_value
from rotor._simulator import simulate_random_run
from surfmet.cli import main

PHI = np.arange(25) * math.pi / 2
IN_FAMILY = ("none", "decaying", "unbalance", "decaying+unbalance")


def _ode_times(phi, eps0, wave_c, wave_s, period, phi0):
    k = 2 * math.pi / period

    def rhs(_t, y):
        return [y[1], eps0 + wave_c * math.sin(k * y[0]) + wave_s * math.cos(k * y[0])]

    events = []
    for m in phi:
        def ev(_t, y, m=m):
            return y[0] - m
        ev.direction = 1.0
        events.append(ev)
    sol = solve_ivp(rhs, (0.0, 60.0), [phi0, 0.0], events=events, rtol=1e-11, atol=1e-12,
                    max_step=0.05)
    return np.array([e[0] for e in sol.t_events])


@pytest.mark.parametrize("period_rev, amp", [(0.7, 0.5), (1.65, -0.6), (2.9, 0.3)])
def test_plate_wave_forward_term_matches_the_ode(period_rev, amp):
    eps0, phi0 = 2.0, -0.4
    period = 2 * math.pi * period_rev
    want = _ode_times(PHI, eps0, amp, 0.4 * amp, period, phi0)
    got = crossing_times(PHI, eps0, t0=0.0, phi0=phi0, wave_c=amp, wave_s=0.4 * amp,
                         wave_period=period)
    # 1e-3 frame at 120 fps
    assert np.max(np.abs(got - want)) < 1e-3 / 120


def test_first_order_wave_response_matches_finite_differences():
    rep = analyse_test("t", simulate_random_run(3, "decaying", n_misread=0).frames)
    fit = rep.fit
    periods = np.array([0.8, 1.9]) * 2 * math.pi
    resp = _wave_response(rep.angles, fit, periods)
    p = {k: fit.params[k] for k in PARAM_NAMES}
    base = crossing_times(rep.angles, **p)
    h = 1e-5
    for j, per in enumerate(periods):
        for col, key in ((2 * j, "wave_c"), (2 * j + 1, "wave_s")):
            fd = (crossing_times(rep.angles, **{**p, key: h, "wave_period": per}) - base) / h
            # first order and without the speed term's feedback: within 3 % of the largest
            assert np.max(np.abs(resp[:, col] - fd)) < 0.03 * np.max(np.abs(fd))


@pytest.mark.campaign
@settings(deadline=None, derandomize=True, max_examples=8)
@given(seed=st.integers(0, 2**32 - 1))
def test_clean_columns_are_adequate_at_the_calibrated_rate(seed):
    # each draw is a batch of 3 closed-form clean columns (not the analysis' forward model,
    # not the calibration's generator); at a 2 % false-alarm rate, 2 or more inadequate of 3
    # happens with probability 0.0012 per batch (1 % over the 8 batches); at 20 % it
    # happens in 58 % of runs of this test
    rng = np.random.default_rng(seed)
    bad = 0
    for _ in range(3):
        c = clean_column(rng)
        rep = analyse_test("c", c.frames, fps=c.fps, step=c.step)
        bad += not rep.adequacy.adequate
        assert rep.effect == "none", rep.selected
        # the smooth term (the last resort) is tried only where the check rejects
        assert rep.smooth is None or not rep.adequacy.adequate
        assert 0 < rep.adequacy.p_value <= 1
    assert bad <= 1


# the smallest amplitudes (fraction of eps0) flagged or named in every column of their cell at
# 240 fps, 45 deg marks, 40 rows, measured by benchmarks/rotor_adequacy.py
# (docs/rotor_adequacy.md); at the paper's 90 deg marks waves shorter than about 1.2 turns
# are not found at these sizes
POWER = {(0.6, 1.2): 0.35, (1.2, 3.0): 0.2}
# waves of 0.3-0.6 turns (benchmarks/rotor_short_waves.py): flagged or named in 46 of 50
# columns at 0.35 eps0, 49 of 50 at 0.5 and 17 of 20 at 0.7 (some are taken for an adequate
# unbalance): the band's power stays near 90 %, so its test asks for most columns, not all
SHORT_BAND, SHORT_SIZE = (0.3, 0.6), 0.5


@pytest.mark.parametrize("band", sorted(POWER))
@settings(deadline=None, derandomize=True, max_examples=4)
@given(seed=st.integers(0, 2**32 - 1),
       log_factor=st.floats(0.0, math.log(1.3)), effect=st.sampled_from(["none", "decaying"]))
def test_a_hidden_plate_wave_is_flagged_or_named(band, seed, log_factor, effect):
    # the period is drawn within the band, the amplitude at or above the band's measured
    # threshold (0.3-0.6 turns: the test below)
    size = POWER[band] * math.exp(log_factor)
    run = simulate_random_run(seed, effect, n_marks=40, fps=240.0, step=math.pi / 4,
                              n_misread=0, wave_fraction=(size, size), wave_period_rev=band)
    rep = analyse_test("w", run.frames, run.k, fps=run.fps, step=run.step)
    named = "wave" in rep.effect
    assert named or not rep.adequacy.adequate, (band, size, rep.selected)
    # never a bare in-family verdict that claims to explain the data
    assert not (rep.effect in IN_FAMILY and rep.adequacy.adequate)


@pytest.mark.campaign
@settings(deadline=None, derandomize=True, max_examples=2)
@given(seed=st.integers(0, 2**31), log_factor=st.floats(0.0, math.log(1.3)))
def test_a_short_hidden_plate_wave_is_mostly_flagged_or_named(seed, log_factor):
    # 4 columns per draw, 0.3-0.6 turns at or above 0.5 eps0: at the measured ~93-98 %
    # power, 2 or more missed of 4 happens in 0.2-3 % of draws; at 70 % power in 35 %
    size = SHORT_SIZE * math.exp(log_factor)
    missed = 0
    for i in range(4):
        run = simulate_random_run(seed + i, ("none", "decaying")[i % 2], n_marks=40, fps=240.0,
                                  step=math.pi / 4, n_misread=0, wave_fraction=(size, size),
                                  wave_period_rev=SHORT_BAND)
        rep = analyse_test("w", run.frames, run.k, fps=run.fps, step=run.step)
        missed += not ("wave" in rep.effect or not rep.adequacy.adequate)
    assert missed <= 1


def test_rayleigh_closed_forms():
    # three equal phases: R = 1, p = exp(sqrt(1 + 4n) - (1 + 2n)) with n = 3
    rbar, p = rayleigh_p([1.0, 1.0, 1.0])
    assert rbar == pytest.approx(1.0)
    assert p == pytest.approx(math.exp(math.sqrt(13.0) - 7.0))
    # evenly spread: R = 0, p = 1
    rbar, p = rayleigh_p([0.0, 2 * math.pi / 3, 4 * math.pi / 3])
    assert rbar == pytest.approx(0.0, abs=1e-12)
    assert p == pytest.approx(1.0)


def test_welch_against_scipy():
    from scipy import stats

    rng = np.random.default_rng(7)
    for _ in range(5):
        a, b = rng.normal(0, 1, 3), rng.normal(0.3, 2, 4)
        assert welch_p_value(a, b) == pytest.approx(
            stats.ttest_ind(a, b, equal_var=False).pvalue, rel=1e-10)


def _cli(args):
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(args)
    return code, out.getvalue(), err.getvalue()


def test_six_row_table_prints_a_summary(tmp_path):
    # issue 16 item 8: a valid 6-row table ended in KeyError 'const' without --json
    table = tmp_path / "six.tsv"
    table.write_text("k\tc1\n" + "".join(f"{i + 1}\t{f}\n" for i, f in
                                         enumerate((100, 150, 180, 200, 215, 228))))
    code, out, _ = _cli(["rotor", str(table), "-q"])
    assert code == 0
    assert "not judged" in out  # fewer rows than the adequacy calibration covers


def test_summary_words_for_a_plate_wave(tmp_path):
    run = simulate_random_run(11, "none", n_misread=0, wave_fraction=(0.3, 0.3),
                              wave_period_rev=(1.6, 1.7))
    other = simulate_random_run(12, "none", n_misread=0)
    table = tmp_path / "w.tsv"
    table.write_text("k\tw1\tc1\n" + "".join(
        f"{k}\t{a}\t{b}\n" for k, a, b in zip(run.k, run.frames, other.frames)))
    code, out, err = _cli(["rotor", str(table)])
    assert code == 0
    assert "rotor: test w1 (1/2)" in err  # progress on stderr
    assert "plate wave is named" in out or "NOT ADEQUATE" in out
    assert "p nan" not in out
    header = next(line for line in out.splitlines() if line.strip().startswith("model "))
    assert len(header.split()) == len(set(header.split()))  # no duplicated column
    code, _, err = _cli(["rotor", str(table), "--quiet"])
    assert code == 0 and "rotor: test" not in err
    code, out, _ = _cli(["rotor", str(table), "--json", "-q"])
    rec = json.loads(out)
    w1 = rec["tests"][0]["adequacy"]
    assert w1["alpha"] == ALPHA and isinstance(w1["adequate"], bool)
    assert w1["p_value_floor"] > 0
    wave = w1.get("named_wave") or w1.get("residual_wave")
    assert wave["revolutions"] == pytest.approx(1.65, abs=0.25)
    assert wave["track_length"]["unit"] == "m"


def test_check_on_a_fit_reports_order_statistics():
    c = clean_column(np.random.default_rng(5), fps=120, step_deg=90, n=25)
    rep = analyse_test("c", c.frames, fps=c.fps, step=c.step, extend=False)
    a = check_adequacy(rep.times, rep.angles, rep.fit, step=rep.step)
    assert a.judged and math.isfinite(a.runs_z) and -1 <= a.lag1 <= 1
    assert 0 <= a.wave_share <= 1
    assert a.statistic == pytest.approx(-math.log10(min(a.nominal.values())))
