"""``surfmet rotor``: the paper's Table 3 end to end (JSON, summary, figure) and bad input."""

from __future__ import annotations

import json

import pytest

from surfmet.cli import main


@pytest.fixture(scope="module")
def paper_run(tmp_path_factory):
    """One run of the CLI on the shipped Table 3, with the residual figure."""
    out = tmp_path_factory.mktemp("rotor")
    plot = out / "residuals.png"
    capture = pytest.MonkeyPatch()
    import io
    import sys

    buf = io.StringIO()
    capture.setattr(sys, "stdout", buf)
    try:
        code = main(["rotor", "paper2022", "--json", "--plot", str(plot)])
    finally:
        capture.undo()
    return code, json.loads(buf.getvalue()), plot


def test_json_structure_and_units(paper_run):
    code, rec, plot = paper_run
    assert code == 0
    assert plot.exists() and plot.stat().st_size > 10_000
    assert rec["fps"] == {"value": 120.0, "unit": "1/s"}
    assert rec["step"]["unit"] == "rad"
    assert rec["noise_floor"]["value"] == pytest.approx(1 / (120 * 12**0.5))
    names = [t["name"] for t in rec["tests"]]
    assert names == ["as1", "as2", "as3", "s1", "s2", "s3"]
    for t in rec["tests"]:
        assert t["effect"] in ("none", "decaying", "unbalance", "decaying+unbalance", "wave",
                               "decaying+wave")
        assert t["eps0"]["unit"] == "rad/s^2"
        assert set(t["models"]) >= {"rest", "parabola", "const", "position", "speed",
                                    "unbalance", "position+unbalance"}
        for m in t["models"].values():
            assert m["rms"]["unit"] == "s"
            assert isinstance(m["bic"], float)
            for q in m["params"].values():
                assert set(q) == {"value", "unit"}
    groups = {g["name"]: g for g in rec["groups"]}
    assert set(groups) == {"as", "s"}
    assert [q["unit"] for q in groups["as"]["paper_parabola"]] == ["rad/s^2", "rad/s", "rad"]


def test_paper_findings(paper_run):
    _, rec, _ = paper_run
    groups = {g["name"]: g for g in rec["groups"]}
    # the paper's two parabolas, through the mean times, to three digits; its "phi_s" is the
    # asymmetric columns' and its "phi_a" the symmetric ones'
    c_as = [q["value"] for q in groups["as"]["paper_parabola"]]
    c_s = [q["value"] for q in groups["s"]["paper_parabola"]]
    assert c_as == pytest.approx([0.821, 1.134, -0.527], abs=5e-4)
    assert c_s == pytest.approx([0.951, 1.0254, -0.249], abs=7e-4)
    tests = {t["name"]: t for t in rec["tests"]}
    # the rows that were misread or mistyped (each 8-10 frames off, z > 10)
    assert tests["as2"]["outliers"] == [7, 24]
    assert 23 in tests["s1"]["outliers"]
    assert tests["s2"]["outliers"] == [20]
    assert 22 in tests["s3"]["outliers"]
    assert tests["as1"]["outliers"] == [] and tests["as3"]["outliers"] == []
    # every test: the acceleration decays; constant acceleration is far outside the noise
    for t in tests.values():
        assert t["effect"].startswith("decaying")
        sel = t["models"][t["selected_model"]]
        assert sel["rms_frames"]["value"] < 1.6
        assert t["models"]["rest"]["rms_frames"]["value"] > 8
        assert t["models"]["const"]["runs_z"] < -2  # systematic
        assert sel["bic"] < t["models"]["const"]["bic"] - 20
        assert sel["loo_rms"]["value"] < t["models"]["const"]["loo_rms"]["value"]
        # the decay is far beyond what clean columns reach (calibrated false alarm < 1 %)
        ev = t["evidence"]
        assert ev["effect_evidence_delta_bic"] > 20 and ev["false_alarm_probability"] < 0.01
        # a verdict beyond 'decaying' that rests on less than 10 BIC units is called weak
        assert ev["weak"] == (ev["delta_bic_to_next_simpler"] < 10)
    assert rec["study_model"] == "position"
    tb = rec["total_bic"]
    assert tb["position"] < tb["speed"] - 50  # the position form is clearly preferred
    comp = {(c["model"], c["quantity"]): c for c in rec["comparisons"]}
    # constant acceleration: the symmetric rotor is faster by ~0.26 rad/s^2 (z > 4) ...
    assert comp[("paper", "eps0")]["difference"]["value"] == pytest.approx(0.259, abs=0.002)
    assert comp[("const", "eps0")]["z"] > 4
    # ... with the decay modelled the initial accelerations agree, the decay rates do not
    assert abs(comp[("position", "eps0")]["z"]) < 1
    assert comp[("position", "eta")]["z"] < -4


def test_human_summary(capsys, tmp_path):
    table = tmp_path / "t.tsv"
    from rotor._simulator import simulate_random_run

    a = simulate_random_run(40, "none", n_misread=0).frames
    b = simulate_random_run(41, "none", n_misread=0).frames
    rows = ["k\tx1\tx2"] + [f"{k}\t{int(p)}\t{int(q)}" for k, (p, q) in enumerate(zip(a, b), 1)]
    table.write_text("\n".join(rows) + "\n")
    assert main(["rotor", str(table)]) == 0
    out = capsys.readouterr().out
    assert "group 'x'" in out and "paper's parabola" in out
    assert "const" in out and "none" in out


@pytest.mark.parametrize(
    ("content", "args", "needle"),
    [
        (None, [], "no such file"),
        ("a\tb\n1\t2\n", [], "header"),
        ("k\tx1\n1\t10\n2\tten\n", [], "frame index"),
        ("k\tx1\n1\t10\n2\t20\n3\t25\n", [], "readings"),
        ("k\tx1\n2\t10\n1\t20\n", [], "increase"),
        ("k\tx1\n" + "".join(f"{k}\t{10 * k}\n" for k in range(1, 6)), [], "needs >= 6"),
        ("k\tx1\n" + "".join(f"{k}\t{10 * k if k != 5 else 25}\n" for k in range(1, 12)),
         [], "must increase down the column"),
        ("k\tx1\n1\t10\n2\t20\n", ["--fps", "-5"], "fps"),
    ],
)
def test_bad_input_is_a_one_line_user_error(tmp_path, capsys, content, args, needle):
    path = tmp_path / "bad.tsv"
    if content is not None:
        path.write_text(content)
    assert main(["rotor", str(path), *args]) == 1
    err = capsys.readouterr().err
    assert "error" in err and needle in err and "Traceback" not in err


def test_ragged_table_at_any_frame_rate_and_step(tmp_path, capsys):
    # columns of different lengths, a NaN and a blank cell; 1000 fps, 15 deg marks
    import math

    import numpy as np
    from rotor_clean_columns import clean_column

    rng = np.random.default_rng(11)
    cols = [clean_column(rng, fps=1000, step_deg=15, n=n, x=0.9).frames for n in (30, 14, 8)]
    cols[1][5] = math.nan
    lines = ["k\ta1\ta2\tb1"]
    for i in range(30):
        cells = [str(i + 1)] + [("" if i >= c.size else ("nan" if math.isnan(c[i]) else
                                                          f"{c[i]:.0f}")) for c in cols]
        lines.append("\t".join(cells).rstrip("\t"))
    table = tmp_path / "ragged.tsv"
    table.write_text("\n".join(lines) + "\n")
    assert main(["rotor", str(table), "--fps", "1000", "--step-deg", "15", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    tests = {t["name"]: t for t in rec["tests"]}
    assert [len(tests[n]["k"]) for n in ("a1", "a2", "b1")] == [30, 13, 8]
    for t in tests.values():
        assert t["effect"] == "none" and t["outliers"] == []
        ev = t["evidence"]
        assert ev["weak"] is False and ev["effect_evidence_delta_bic"] < 6
        assert 0 < ev["false_alarm_probability"] <= 1


def test_verdict_json_permutation_p_over_the_group_labels(paper_run):
    """Issue 35 item 1: the design's exact permutation p beside the model's, and the verdict
    worded by the weaker. 3 + 3 launches have C(6, 3)/2 = 10 splits; p = rank / splits."""
    import itertools
    import math

    _, rec, _ = paper_run
    v = rec["verdict"]
    pp = v["permutation_p"]
    n = len({frozenset({c, frozenset(range(6)) - frozenset(c)})
             for c in map(frozenset, itertools.combinations(range(6), 3))})
    assert pp["n_splits"] == n == 10 and pp["exact"]
    fs = [q["value"] for q in pp["f_by_split"]]
    assert len(fs) == n and fs[0] == pytest.approx(v["shared_track"]["f_statistic"]["value"])
    rank = 1 + sum(f > fs[0] for f in fs[1:])
    assert pp["f_rank"] == rank == 1  # the real split has the largest F (17.4)
    assert pp["shared_track_f"]["value"] == pytest.approx(rank / n) == pytest.approx(0.1)
    assert pp["smallest_possible"]["value"] == pytest.approx(1 / n)
    offs = [abs(q["value"]) for q in pp["offset_by_split"]]
    assert pp["offset"]["value"] == pytest.approx(sum(o >= offs[0] for o in offs) / n)
    weaker = max(pp["shared_track_f"]["value"], v["shared_track"]["p_value"]["value"])
    assert pp["weaker_p"]["value"] == pytest.approx(weaker)
    # the model's p alone would say 0.0083; the wording follows the design's 0.1
    s = v["sentence"]
    assert "exact permutation p = 0.1" in s and "not by the design alone" in s
    assert "constant-offset model is rejected" in s
    assert "session effect (run-in, lane, slope reset)" in s and "block" in s
    assert not math.isnan(weaker)


def test_verdict_json_arm_against_its_bound(paper_run):
    """Issue 35 item 2: the friction arm, its bound and lambda there, from the record's own
    rig and mean acceleration by the closed forms (Eq. 49; Hertz)."""
    import math

    _, rec, _ = paper_run
    v = rec["verdict"]
    rig = v["rig"]
    assert rig["ball_radius"] == {"value": 0.02, "unit": "m"}
    assert rig["mass"]["unit"] == "kg" and rig["axial_inertia"]["unit"] == "kg m^2"
    loads = {g["name"]: [q["value"] for q in g["ball_loads"]] for g in rig["groups"]}
    assert all(q["unit"] == "N" for g in rig["groups"] for q in g["ball_loads"])
    m, r, j = rig["mass"]["value"], 0.02, rig["axial_inertia"]["value"]
    inertia = j + m * r * r
    eps = v["mean_acceleration"]["value"]
    slope = v["lambda_assumptions"]["slope"]["value"]
    sum_n = 0.5 * (sum(loads["s"]) + sum(loads["as"]))
    arm = v["friction_arm"]["arm"]
    assert arm["unit"] == "m" and v["friction_arm"]["lambda"] == 1
    assert arm["value"] == pytest.approx((m * 9.80665 * r * math.sin(slope) - eps * inertia)
                                         / sum_n, rel=1e-9)
    e_star = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.33**2) / 70e9)
    a = (3 * loads["s"][0] * r / (4 * e_star)) ** (1 / 3)
    bound = v["arm_bound"]["radius"]
    assert bound["value"] == pytest.approx(a, rel=1e-9) and bound["unit"] == "m"
    basis = v["arm_bound"]["basis"]
    assert "Hertz" in basis and "4.67 N" in basis
    assert arm["value"] / a == pytest.approx(v["friction_arm"]["ratio_to_bound"]["value"]) \
        and arm["value"] > 2 * a
    lam = v["lambda_at_arm_bound"]
    assert lam["lambda"]["value"] == pytest.approx(3.7, abs=0.1)
    assert lam["lambda"]["ci_low"] >= 2.95
    assert "lower bound" in lam["meaning"] and "not a confidence interval" in lam["meaning"]
    assert lam["slope_lambda_infinite"]["value"] == pytest.approx(
        math.asin(eps * inertia / (m * 9.80665 * r)), rel=1e-9)
    s43 = v["slope_lambda_4_3"]["slope"]
    assert s43["unit"] == "rad" and math.degrees(s43["ci_low"]) > 4


def test_verdict_json_four_differences_in_one_table(paper_run):
    """Issue 35 item 4: the four differences, their models, whether each fits, the one the
    verdict uses; the two misread rules side by side (as2 k = 24, frame 951, is the
    per-test analysis' alone)."""
    _, rec, _ = paper_run
    rows = rec["verdict"]["differences"]["rows"]
    assert [r["model"] for r in rows] == ["paper", "const", "joint", "position"]
    vals = {r["model"]: r["difference"]["value"] for r in rows}
    # the paper's parabolas: 2 (0.9506 - 0.8211) rad/s² (its phi_s and phi_a, swapped labels)
    assert vals["paper"] == pytest.approx(2 * (0.9506 - 0.8211), abs=5e-4)
    assert vals["const"] == pytest.approx(0.204, abs=5e-4)
    assert vals["joint"] == pytest.approx(0.200, abs=5e-4)
    assert vals["position"] == pytest.approx(-0.006, abs=5e-4)
    assert [r["used_by_verdict"] for r in rows] == [False, False, True, False]
    assert not any(r["model_fits"] for r in rows)
    m = rec["verdict"]["misread_rules"]
    joint = {(x["column"], x["k"]) for x in m["joint"]}
    per = {(x["column"], x["k"]) for x in m["per_test"]}
    assert ("as2", 24) in per - joint and joint <= per
    only = {(x["column"], x["k"]) for x in m["only_per_test"]}
    assert only == per - joint
    assert m["joint_without_both"]["shared_track_outcome_unchanged"] is True


def test_differences_on_a_clean_table_read_the_constant_acceleration_as_fitting(tmp_path,
                                                                                capsys):
    """Simulated launches at constant acceleration (no effect): the constant-acceleration
    rows fit, and the study model (const) is not listed twice."""
    from rotor._simulator import simulate_random_run

    fr = [simulate_random_run(40 + i, "none", n_misread=0).frames for i in range(5)]
    rows = ["k\tx1\tx2\ty1\ty2\ty3"] + ["\t".join([str(k)] + [str(int(f[k - 1])) for f in fr])
                                        for k in range(1, len(fr[0]) + 1)]
    table = tmp_path / "t.tsv"
    table.write_text("\n".join(rows) + "\n")
    assert main(["rotor", str(table), "--json"]) == 0
    v = json.loads(capsys.readouterr().out)["verdict"]
    got = {r["model"]: r for r in v["differences"]["rows"]}
    assert list(got) == ["paper", "const", "joint"]
    assert got["const"]["model_fits"] and got["paper"]["model_fits"]
    assert v["permutation_p"]["n_splits"] == 10  # C(5, 2): groups of 2 and 3
    assert v["rig"] is None and v["friction_arm"] is None


def _stdout(args):
    import io
    import sys

    buf = io.StringIO()
    capture = pytest.MonkeyPatch()
    capture.setattr(sys, "stdout", buf)
    try:
        code = main(args)
    finally:
        capture.undo()
    assert code == 0
    return buf.getvalue()


@pytest.fixture(scope="module")
def scans():
    from surfmet.data import path

    return str(path("paper_plate.x3p")), str(path("paper_ball.x3p"))


@pytest.fixture(scope="module")
def rough_run(scans):
    """The paper's table with the bundled scans, on a coarse contact grid."""
    plate, ball = scans
    return json.loads(_stdout(["rotor", "paper2022", "--plate", plate, "--ball", ball,
                               "--grid", "64", "--json", "-q"]))


def test_arm_bound_states_the_rough_contacts_extent_beside_hertz(rough_run, paper_run, scans):
    """Issue 35 item 2: with scans, ``arm_bound`` carries the rough contact's a* at the
    symmetric load, equal to ``surfmet hertz-check``'s for the same inputs, beside the Hertz
    radius, and says which decides (the larger)."""
    plate, ball = scans
    b = rough_run["verdict"]["arm_bound"]
    hertz = paper_run[1]["verdict"]["arm_bound"]
    assert b["radius"] == hertz["radius"] and b["basis"] == hertz["basis"]
    load = b["load"]["value"]
    check = json.loads(_stdout(["hertz-check", "--plate", plate, "--ball", ball,
                                "--radius", "20mm", "--materials", "steel,aluminium",
                                "--load", f"{load!r}N", "--grid", "64", "--json"]))
    rough = b["rough"]
    assert rough["radius"] == check["bem"]["effective_radius"]  # the same function's answer
    assert rough["load"] == b["load"] and rough["files"] == {"plate": plate, "ball": ball}
    assert rough["grid"] == [64, 64] and plate in rough["basis"] and "64 x 64" in rough["basis"]
    larger = max(rough["radius"]["value"], b["radius"]["value"])
    assert b["deciding_radius"] == {"value": larger, "unit": "m"}
    assert b["decides"] == ("rough" if rough["radius"]["value"] > b["radius"]["value"]
                            else "hertz")
    arm = rough_run["verdict"]["friction_arm"]["arm"]["value"]
    assert b["friction_arm_ratio_to_deciding"]["value"] == pytest.approx(arm / larger)


def test_without_scans_the_verdict_is_unchanged(rough_run, paper_run):
    v0, v1 = paper_run[1]["verdict"], rough_run["verdict"]
    assert set(v0["arm_bound"]) == {"radius", "basis", "load", "group", "e_star"}
    extra = {"rough", "decides", "deciding_radius", "friction_arm_ratio_to_deciding", "why"}
    assert set(v1["arm_bound"]) == set(v0["arm_bound"]) | extra
    moved = {"arm_bound", "lambda_at_arm_bound"}  # the lambda is at the deciding radius
    strip = {k: v for k, v in v1.items() if k not in moved}
    assert strip == {k: v for k, v in v0.items() if k not in moved}


def test_lambda_at_the_arm_bound_is_at_the_radius_that_decides(rough_run, paper_run):
    """With scans whose a* exceeds Hertz's radius, the least lambda the offset needs is
    taken at a*: a wider bound allows a larger torque, so a smaller lambda (without scans
    it stays at Hertz's radius)."""
    v0, v1 = paper_run[1]["verdict"], rough_run["verdict"]
    l0, l1 = v0["lambda_at_arm_bound"], v1["lambda_at_arm_bound"]
    assert l0["radius"] == v0["arm_bound"]["radius"] and "Hertz" in l0["basis"]
    assert l1["radius"] == v1["arm_bound"]["deciding_radius"]
    if v1["arm_bound"]["decides"] == "rough":
        assert "a*" in l1["basis"]
        assert l1["lambda"]["value"] < l0["lambda"]["value"]
        assert l1["slope"]["value"] > l0["slope"]["value"]  # s_r = a* needs a steeper slope


@pytest.mark.parametrize(("args", "needle"), [
    (["--ball", "x.x3p"], "--ball needs --plate"),
    (["--grid", "64"], "--grid is the rough contact's"),
    (["--plate", "no_such_scan.x3p"], "no_such_scan.x3p: no such file"),
])
def test_scan_options_refused_in_one_line(capsys, args, needle):
    assert main(["rotor", "paper2022", *args]) == 1
    err = capsys.readouterr().err
    assert "error" in err and needle in err and "Traceback" not in err


def test_rough_bound_in_words_says_which_radius_decides():
    from surfmet.mechanics.rotor_rough_bound import RoughArmBound
    from surfmet.mechanics.rotor_verdict import paper_verdict, verdict_lines

    v = paper_verdict()
    rb = RoughArmBound(radius=3 * v.arm.arm_bound, hertz_radius=v.arm.arm_bound,
                       load=v.arm.bound_load, ball_radius=0.02, plate_file="p.x3p",
                       ball_file=None, grid=(64, 64), cell=2e-5, warnings=())
    plain, rough = verdict_lines(v), verdict_lines(v, rough=rb)
    added = [x for x in rough if x not in plain]
    assert len(rough) == len(plain) + 1
    line = next(x for x in added if "rough contact's extent a*" in x)
    assert "the rough contact's a* decides" in line and "p.x3p" in line
    wide = f"{3 * v.arm.arm_bound * 1e6:.0f} µm"
    assert wide in line
    # the lambda at the bound is taken at the radius that decides, and says so
    assert any(x.startswith("  lambda at the arm bound (s_r = a = " + wide) for x in added)
    # the Hertz line says its judgement is Hertz's alone
    assert any("by Hertz's radius alone" in x for x in added)
