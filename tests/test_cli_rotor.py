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
    from contact.rotor.simulator import simulate_random_run

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
