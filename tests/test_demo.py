"""``surfmet demo``: the whole story on the shipped scans, checked against the paper's own
numbers (``paper_values.json`` through the ``paperdata`` fixture), the generator's truths
(``examples/paper_2022/make_surfaces.py``) and an independent sphere fit of the shipped ball.

The demo runs once (``--quick``) for the module, through the command line.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

import surfmet
from surfmet.cli import main
from surfmet.demo import FIGURES, GENERATOR, SUMMARY, data_file, prepare_output

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.slow  # the module runs the demo once (about 20-30 s)


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    out = tmp_path_factory.mktemp("demo") / "out"
    buf, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(err):
        rc = main(["demo", "--out", str(out), "--quick"])
    assert rc == 0, err.getvalue()
    summary = json.loads((out / SUMMARY).read_text(encoding="utf-8"),
                         parse_constant=lambda c: pytest.fail(f"{c} in summary.json"))
    return {"out": out, "summary": summary, "stdout": buf.getvalue(), "stderr": err.getvalue()}


@pytest.fixture(scope="module")
def generator():
    """The generator of the shipped scans (its constants are the truth they were built on)."""
    path = ROOT / "examples" / "paper_2022" / "make_surfaces.py"
    spec = importlib.util.spec_from_file_location("make_surfaces_for_test", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture
def paper(paperdata):
    return json.loads(paperdata("paper_values.json").read_text(encoding="utf-8"))


_INTERVAL = {"value", "unit", "ci_low", "ci_high", "level", "minuend", "subtrahend"}


def _floats_outside_quantities(obj, path="$"):
    """Paths of numbers that are not the value of a {"value", "unit"} quantity."""
    bad = []
    if isinstance(obj, dict):
        if "value" in obj:
            # a quantity, or an interval quantity (the rotor verdict's offset and exponent)
            if not ({"value", "unit"} <= set(obj) <= _INTERVAL) or not isinstance(
                    obj["unit"], str):
                bad.append(f"{path}: {sorted(obj)}")
            return bad
        for k, v in obj.items():
            bad += _floats_outside_quantities(v, f"{path}.{k}")
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            bad += _floats_outside_quantities(v, f"{path}[{i}]")
    elif isinstance(obj, float):
        bad.append(path)
    return bad


def test_summary_is_complete_json_with_units(demo):
    s = demo["summary"]
    assert s["generator"] == GENERATOR and s["status"] == "complete" and s["quick"] is True
    for key in ("scans", "roughness", "ball", "hertz_check", "contact", "rolling", "rotor",
                "figures", "timings"):
        assert key in s, key
    # every non-integer number is a {"value": v, "unit": "..."} quantity
    assert _floats_outside_quantities(s) == []
    assert s["ball"]["sphere"]["radius"]["unit"] == "m"
    assert s["roughness"]["plate_rows"]["median"]["Ra"]["unit"] == "m"
    assert s["hertz_check"]["hertz"]["p0"]["unit"] == "Pa"
    assert s["contact"]["load"]["unit"] == "N"
    assert s["rolling"]["moments"]["unit"] == "N m"
    assert s["rolling"]["lambda_eff"]["unit"] == ""
    assert s["rotor"]["groups"][0]["paper_parabola"]["c2"]["unit"] == "rad/s^2"
    assert all(q["unit"] == "s" for q in s["timings"].values())
    # the progress went to stderr, the story to stdout
    assert "step 7/7" in demo["stderr"] and "step 7/7" not in demo["stdout"]


def test_hertz_does_not_hold_with_reasons(demo, paper):
    h = demo["summary"]["hertz_check"]
    assert h["hertz_holds"] is False
    assert h["alpha"]["value"] > 0.05  # GJM's limit
    assert len(h["reasons"]) >= 2 and any("α" in r for r in h["reasons"])
    failed = [c["name"] for c in h["details"]["criteria"] if c["decisive"] and not c["passed"]]
    assert "alpha" in failed
    # the Hertz numbers of the paper's own check (10 N, R = 20 mm)
    ref = paper["hertz_check_in_paper"]
    assert h["details"]["load"]["value"] == ref["normal_force_N"]
    assert h["hertz"]["delta"]["value"] == pytest.approx(ref["max_approach_um"] * 1e-6, rel=0.01)
    assert h["hertz"]["a"]["value"] == pytest.approx(ref["contact_radius_um"] * 1e-6, rel=0.01)
    assert "Hertz does NOT hold" in demo["stdout"]
    for reason in h["reasons"]:
        assert reason.split()[0] in demo["stdout"]


def test_ball_radius_and_form(demo, generator):
    from surfmet.fitting import fit_sphere

    b = demo["summary"]["ball"]
    r, u = b["sphere"]["radius"]["value"], b["sphere"]["radius_uncertainty"]["value"]
    fit = fit_sphere(surfmet.read(data_file("paper_ball.x3p")))
    assert abs(r - fit.radius) <= u
    assert r == pytest.approx(0.02, rel=0.01)
    # the generator's cap: radii Rx along x and Ry along y, mean curvature 1/r_m
    rx, ry = generator.BALL_RADIUS_X, generator.BALL_RADIUS_Y
    r_m = 2 / (1 / rx + 1 / ry)
    assert rx < r < ry and r == pytest.approx(r_m, rel=1e-3)
    assert b["row_circle"]["radius"]["value"] == pytest.approx(rx, rel=2e-3)
    assert b["column_circle"]["radius"]["value"] == pytest.approx(ry, rel=2e-3)
    # the generator's form error 0.25 (x² - y²)(1/Rx - 1/Ry), less what a sphere (to second
    # order: 1, x, y, x² + y²) absorbs of it, peak to valley over the scan
    ny, nx = generator.BALL_SHAPE
    x = np.arange(nx) * generator.BALL_PITCH - generator.BALL_APEX[0]
    y = np.arange(ny) * generator.BALL_PITCH - generator.BALL_APEX[1]
    X, Y = (a.ravel() for a in np.meshgrid(x, y))
    astig = 0.25 * (X**2 - Y**2) * (1 / rx - 1 / ry)
    basis = np.column_stack([np.ones_like(X), X, Y, X**2 + Y**2])
    left = astig - basis @ np.linalg.lstsq(basis, astig, rcond=None)[0]
    truth = float(left.max() - left.min())
    assert b["sphere"]["form_pv"]["value"] == pytest.approx(truth, rel=0.1)


def test_plate_and_ball_roughness_match_table2(demo, paper):
    # the tolerances of tests/test_paper_surfaces.py: within the spread of the paper's
    # three profiles, and within 5 % of their mean (plate)
    rough = demo["summary"]["roughness"]
    rows = paper["table2_profile_um"]
    med = rough["plate_rows"]["median"]
    assert rough["plate_rows"]["rows"] == demo["summary"]["scans"]["plate"]["ny"]
    for key in ("Ra", "Rq", "Rz", "Rt"):
        table = np.array([r[key] for r in rows["aluminium_plate"]])
        v = med[key]["value"] * 1e6
        assert table.min() <= v <= table.max(), key
        assert v == pytest.approx(table.mean(), rel=0.05), key
    for key in ("Ra", "Rq"):
        table = np.array([r[key] for r in rows["steel_ball"]])
        assert table.min() <= rough["ball_rows"]["median"][key]["value"] * 1e6 <= table.max()
    # the spikes: found, removed, and the cleaned plate is Gaussian again
    areal = rough["plate_areal"]
    assert areal["as_scanned"]["spikes_suspected"] is True
    assert 20 <= areal["spikes_removed"]["count"] <= 200
    assert areal["cleaned"]["sq_over_sa"]["value"] == pytest.approx(math.sqrt(math.pi / 2),
                                                                    abs=0.03)


def test_rotor_reproduces_the_paper_parabolas(demo, paper):
    rotor = demo["summary"]["rotor"]
    assert rotor["equals_the_split_of_the_printed_rows"] is True
    found = {}
    fits = {k: v for k, v in paper["table3"]["paper_reported_fits"].items()
            if isinstance(v, dict)}
    assert set(fits) == {"phi_s", "phi_a"}
    for label, ref in fits.items():
        want = np.round([ref["t2"], ref["t1"], ref["t0"]], 3)
        hits = [g["name"] for g in rotor["groups"]
                if np.array_equal(np.round([g["paper_parabola"][c]["value"]
                                            for c in ("c2", "c1", "c0")], 3), want)]
        assert len(hits) == 1, (label, hits)
        found[label] = hits[0]
    assert found["phi_s"] != found["phi_a"]
    assert rotor["paper_label_match"] == found
    for g in rotor["groups"]:
        assert len(g["tests"]) == 3


def test_contact_and_rolling_are_sound(demo):
    s = demo["summary"]
    c = s["contact"]
    assert c["converged"] and not c["touches_edge"]
    assert c["load"]["value"] == pytest.approx(c["rotor_loads"]["symmetric"]["value"])
    # the rotor (about 0.95 kg) rests on two balls
    assert 2 * c["load"]["value"] == pytest.approx(0.954 * 9.80665, rel=0.02)
    ro = s["rolling"]
    assert len(ro["loads"]["value"]) == 5  # the full run's sweep, --quick included
    assert all(m > 0 for m in ro["moments"]["value"])
    # the exponent and its interval: least squares on ln M, ln N with a Student-t interval
    # at the stated confidence, against scipy's regression (was lo <= λ <= hi)
    from scipy import stats

    loads, moments = np.array(ro["loads"]["value"]), np.array(ro["moments"]["value"])
    fit = stats.linregress(np.log(loads), np.log(moments))
    conf = ro["settings"]["confidence"]["value"]
    t = stats.t.ppf(0.5 + conf / 2, len(loads) - 2)
    assert ro["lambda_eff"]["value"] == pytest.approx(fit.slope, rel=1e-12)
    assert ro["lambda_ci"]["value"] == pytest.approx(
        [fit.slope - t * fit.stderr, fit.slope + t * fit.stderr], rel=1e-9)


def test_the_verdict_comes_first_and_equals_the_rotor_commands(demo):
    """The paper's question is answered first, after the story's own header (issue 34
    item 16: the verdict came before it), with the numbers of `surfmet rotor`."""
    from surfmet.demo._story import TITLE
    from surfmet.mechanics.rotor_verdict import paper_verdict
    from surfmet.records._rotor_verdict import verdict_record

    got = demo["summary"]["verdict"]
    want = json.loads(json.dumps(verdict_record(paper_verdict())))
    assert got["code"] == want["code"] and got["group_offset"] == want["group_offset"]
    lines = [ln for ln in demo["stdout"].splitlines() if ln.strip()]
    assert lines[0] == TITLE
    assert lines[1].startswith("The paper's question")
    assert got["sentence"][:60] in " ".join(demo["stdout"].split())


def test_every_figure_is_a_non_blank_png(demo):
    from matplotlib.image import imread

    figures = demo["summary"]["figures"]
    assert set(figures.values()) <= set(FIGURES.values())
    # --quick leaves out the PSD, the Abbott-Firestone curve and the two law-of-motion
    # figures
    assert len(figures) >= 7
    for name in figures.values():
        path = demo["out"] / name
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
        img = imread(path)[..., :3]
        assert img.shape[0] > 200 and img.shape[1] > 200
        # more than a blank canvas: plenty of pixels differ from the background
        assert np.mean(np.any(np.abs(img - img[0, 0]) > 0.05, axis=-1)) > 0.02, name
    assert "summary.json" in demo["stdout"]


def test_refuses_a_foreign_folder(tmp_path, capsys):
    (tmp_path / "thesis.tex").write_text("precious")
    assert main(["demo", "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert "does not look like a previous 'surfmet demo' output" in err
    assert "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis.tex"]
    f = tmp_path / "thesis.tex"
    assert main(["demo", "--out", str(f)]) == 1
    assert "not a folder" in capsys.readouterr().err


def test_reuses_a_previous_demo_folder(tmp_path):
    (tmp_path / SUMMARY).write_text(json.dumps(
        {"generator": GENERATOR, "figures": {"rolling": "rolling.png", "evil": "../x.png"}}))
    (tmp_path / "rolling.png").write_bytes(b"old")
    (tmp_path / "notes.txt").write_text("mine")
    (tmp_path.parent / "x.png").write_bytes(b"outside")
    prepare_output(tmp_path)
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["notes.txt", SUMMARY]  # its own old figure removed, nothing else
    assert (tmp_path.parent / "x.png").exists()
    assert json.loads((tmp_path / SUMMARY).read_text())["status"] == "running"


def test_rolling_section_states_its_assumptions_and_notes(demo):
    """Issue 25 item 5: the rolling section's α_h = 1 (all input work lost) is said where
    the moments are, with μ_r = M_r/(N R) computed from them; the elastic solve is set
    against section 4's plastic regime; the sweep's resolution notes are in the text, not
    only in summary.json."""
    s = demo["summary"]
    ro, st = s["rolling"], s["rolling"]["settings"]
    flat = " ".join(demo["stdout"].split())
    assert st["alpha_h"]["value"] == 1.0
    assert "Assumed: α_h = 1" in flat and "an upper bound" in flat
    radius = st["radius"]["value"]
    for w, m in zip(ro["loads"]["value"], ro["moments"]["value"]):
        assert f"{m / (w * radius):.3g}" in flat
    if s["contact"]["regime"].startswith("plastic"):
        assert "solves the contact elastically" in flat
    prepared = set(st.get("scan_preparation", {}).get("notes", []))
    for note in st["notes"]:
        if note not in prepared:
            assert " ".join(note.split()) in flat


def test_quick_says_what_it_leaves_out_and_prints_only_the_full_runs_numbers(demo):
    """Issue 34 item 16: --quick (43 s) was not quicker than the full run (47 s): the
    per-test law-of-motion models are most of the run and --quick left them in. It leaves
    them out now and says so; what it prints is computed as in the full run (the rolling
    sweep has the full run's 5 loads; the parabolas are analyse_table's)."""
    from rotor._paper import PARABOLAS

    s = demo["summary"]
    assert "tests" not in s["rotor"] and "comparisons" not in s["rotor"]
    assert f"Left out by --quick: {s['rotor']['left_out'][:40]}" in " ".join(
        demo["stdout"].split())
    assert {"rotor_law_of_motion", "rotor_residuals"}.isdisjoint(s["figures"])
    assert len(s["rolling"]["loads"]["value"]) == 5
    # the paper's two parabolas, to the three decimals it prints, from the groups
    got = sorted(tuple(round(g["paper_parabola"][c]["value"], 3) for c in ("c2", "c1", "c0"))
                 for g in s["rotor"]["groups"])
    assert got == sorted(tuple(round(float(c), 3) for c in ref) for ref in PARABOLAS.values())
