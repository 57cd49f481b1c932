"""Every assumption's weight, the experiment that would settle it, and the paper's swapped
labels said by every entry point (issue 35, items 5 and 6), checked against refits and
closed forms."""

from __future__ import annotations

import json
import math

import pytest
from scipy.stats import norm

from rotor._sensitivity import sensitivity_table, settling_experiment, with_contrast
from surfmet.mechanics.rotor_verdict import paper_verdict


@pytest.fixture(scope="module")
def v():
    return paper_verdict()


@pytest.fixture(scope="module")
def rows(v):
    return {(r.assumption, r.setting): r for r in sensitivity_table(v)}


def _find(rows, assumption, part):
    return next(r for (a, s), r in rows.items() if a == assumption and part in s)


def test_frame_rate_scales_every_acceleration_as_its_square(v, rows) -> None:
    """A refit of Table 3 at 118.8 /s gives the offset the table says (times f / fps, so
    eps scales as fps²) and the same code."""
    from rotor._rig import paper_rig
    from rotor._verdict import judge_table
    from surfmet._frames import read_frames_table
    from surfmet.data import path

    ks, cols = read_frames_table(path("table3_frames.tsv"))
    rig = paper_rig()
    groups = {g.name: list(g.columns) for g in rig.groups}
    refit = judge_table(cols, groups, fps=118.8, step=rig.step, k=ks, permutation=False)
    r = _find(rows, "frame rate", "118.8")
    assert r.offset == pytest.approx(refit.offset.value, rel=2e-3)
    assert r.offset == pytest.approx(v.offset.value * (118.8 / 120) ** 2, rel=1e-12)
    assert refit.code == r.code == v.code


def test_swapped_labels_flip_the_offset_and_no_lambda_makes_it(v, rows) -> None:
    """Read with the text's labels (Table 3's as columns as the symmetric group) a refit
    gives -0.200 and the same F; 0 < lambda < 1 makes at most ~0.01 rad/s² of that sign."""
    from rotor._rig import offset_for_lambda, paper_rig
    from rotor._verdict import judge_table
    from surfmet._frames import read_frames_table
    from surfmet.data import path

    ks, cols = read_frames_table(path("table3_frames.tsv"))
    swapped = {"as": ["s1", "s2", "s3"], "s": ["as1", "as2", "as3"]}
    refit = judge_table(cols, swapped, fps=120.0, step=math.pi / 2, k=ks, permutation=False)
    r = _find(rows, "labels", "swapped")
    assert refit.offset.value == pytest.approx(-v.offset.value, abs=2e-3)
    assert refit.f_statistic == pytest.approx(v.f_statistic, rel=1e-3)
    assert r.offset == -v.offset.value and math.isnan(r.lambda_needed)
    rig = paper_rig()
    most = min(offset_for_lambda(lam / 100, rig, "s", "as", v.exponent.slope,
                                 v.mean_acceleration) for lam in range(5, 100))
    assert -0.02 < most < 0 and most > v.offset.ci_low * -1


def test_xi_g_scales_the_load_contrast_with_its_sum_kept(v) -> None:
    rig = with_contrast(v.rig, 1.2)
    a0 = v.rig.group("as").ball_loads
    a1 = rig.group("as").ball_loads
    assert sum(a1) == pytest.approx(sum(a0))
    assert a1[0] - a1[1] == pytest.approx(1.2 * (a0[0] - a0[1]))
    assert rig.group("s").ball_loads == v.rig.group("s").ball_loads


def test_every_assumption_keeps_the_code_and_lambda_at_the_bound_above_2_5(rows, v) -> None:
    names = {a for a, _ in rows}
    assert {"slope", "xi_G", "mass and inertia", "frame rate", "collar clearance",
            "run order", "labels"} <= names
    for (a, _), r in rows.items():
        assert r.code == v.code
        if a != "labels":
            assert r.lambda_bound > 3.0 and r.lambda_bound_low > 2.5
    # the slope moves the lambda needed at the slope, not the one at the bound
    lo, hi = _find(rows, "slope", "0.5 deg"), _find(rows, "slope", "1.5 deg")
    assert lo.lambda_needed > v.exponent.value > hi.lambda_needed
    assert lo.lambda_bound == hi.lambda_bound == pytest.approx(v.arm.lambda_at_bound)


def test_settling_experiment_against_closed_forms(v) -> None:
    """lambda = 4/3's offset with the arm s_r: s_r sum N_s 2 (sum_as N^(4/3) - sum_s
    N^(4/3)) / (sum_as + sum_s) / (J + M R²); launches by the normal approximation
    2 (z_0.99 + z_0.9)² sd² / offset² (the noncentral t needs a little more); the sag
    Delta theta L / 8."""
    e = settling_experiment(v)
    rig = v.rig
    ns, na = rig.group("s").ball_loads, rig.group("as").ball_loads

    def offset(arm, a, s):
        sa, ss = sum(n ** (4 / 3) for n in a), sum(n ** (4 / 3) for n in s)
        return arm * sum(s) * 2 * (sa - ss) / (sa + ss) / rig.rolling_inertia

    z = norm.ppf(0.99) + norm.ppf(0.9)
    big = ((6.7, 2.6), (4.65, 4.65))
    for r in e.rows:
        a, s = (na, ns) if r.loads.startswith("5.36") else big
        assert r.offset_4_3 == pytest.approx(offset(r.arm, a, s), rel=1e-9)
        if r.launches is not None:
            approx = 2 * z**2 * e.launch_sd**2 / r.offset_4_3**2
            assert approx <= r.launches <= approx * 1.25 + 3
    arms = sorted({round(r.arm * 1e6, 1) for r in e.rows})
    assert arms == [5.0, 20.0, round(v.arm.arm_bound * 1e6, 1)]
    assert e.sag == pytest.approx(e.slope_change * e.length / 8)
    assert 0.35e-3 < e.sag < 0.6e-3 and 0.2 < math.degrees(e.slope_change) < 0.35


def test_label_swap_said_by_every_entry_point(v, capsys) -> None:
    """surfmet rotor (text and JSON), the verdict record every entry point carries, the
    report and the demo's story all say the paper's labels are swapped."""
    import html

    from surfmet._report_rotor import rotor_html
    from surfmet.cli import main
    from surfmet.demo._story import _Text, _verdict
    from surfmet.mechanics._rotor_sensitivity import LABEL_SWAP, label_swap_text
    from surfmet.mechanics.rotor_verdict import verdict_lines
    from surfmet.records._rotor_verdict import verdict_record

    assert label_swap_text(v) == LABEL_SWAP
    assert any(LABEL_SWAP in line for line in verdict_lines(v))
    rec = verdict_record(v)
    assert rec["label_swap"] == LABEL_SWAP
    assert LABEL_SWAP in html.unescape(rotor_html(v))
    t = _Text()
    _verdict(t, {"verdict": json.loads(json.dumps(rec))})
    assert "the other way round" in " ".join(" ".join(t.lines).split())
    assert main(["rotor", "paper2022", "--json", "-q"]) == 0
    assert json.loads(capsys.readouterr().out)["verdict"]["label_swap"] == LABEL_SWAP
    assert {r["assumption"] for r in rec["sensitivity"]} >= {"labels", "xi_G", "run order"}
    assert rec["experiment"]["straightedge_check"]["concave_sag"]["unit"] == "m"
