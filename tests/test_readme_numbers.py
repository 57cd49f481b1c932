"""The numbers the README quotes are asserted (issue 16, item 18).

Each test reads the README's own sentence, so that the text and the code cannot drift apart.
The 10 N figures of the model hierarchy and ψ are asserted in tests/test_examples.py; the
rotor-load figures are asserted here, computed as examples/paper_2022/contact.py computes
them (``hertz_check`` of the bundled pair at the scans' own pixel). Speed figures are
benchmarks' (benchmarks/), not tests'.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())


def quoted(pattern: str) -> re.Match:
    m = re.search(pattern, README)
    assert m, f"the README no longer says {pattern!r}"
    return m


def span(values) -> tuple[float, float]:
    values = list(values)
    return min(values), max(values)


@pytest.fixture(scope="module")
def checks():
    """hertz_check of the bundled pair at the paper's 10 N and at the rotor's ball loads."""
    from rotor._mechanics import paper_ball_loads
    from surfmet.data import path
    from surfmet.mechanics.hertz_check import hertz_check

    loads = {"10 N": 10.0, **paper_ball_loads()}
    return {k: hertz_check(path("paper_plate.x3p"), ball=path("paper_ball.x3p"), radius=0.02,
                           load=w, materials="steel,aluminium") for k, w in loads.items()}


def test_rotor_load_figures_of_the_model_hierarchy(checks):
    m = quoted(r"At the rotor's three ball loads \((\d+\.\d\d), (\d+\.\d\d) and (\d+\.\d\d) N\) "
               r"elastic GT leaves a\* (\d+)–(\d+) % short\. GT capped at H removes (\d+)–(\d+) % "
               r"of the radius error and (\d+)–(\d+) % of the profile error, its profile "
               r"(\d+\.\d)–(\d+\.\d) % of p0 off the BEM \(inside the tolerance only at the "
               r"symmetric rotor's (\d+\.\d\d) N, where the verdict names it\)")
    q = [float(g) for g in m.groups()]
    rotor = [c for k, c in checks.items() if k != "10 N"]
    assert sorted(round(c.load, 2) for c in rotor) == q[0:3]
    gt = [c.hierarchy.models["greenwood_tripp"] for c in rotor]
    assert all(g.radius_error < 0 for g in gt)                       # "short"
    lo, hi = span(-100 * g.radius_error for g in gt)
    assert (round(lo), round(hi)) == (q[3], q[4])
    lo, hi = span(100 * c.hierarchy.gain("greenwood_tripp_plastic", "radius") for c in rotor)
    assert (round(lo), round(hi)) == (q[5], q[6])
    lo, hi = span(100 * c.hierarchy.gain("greenwood_tripp_plastic", "profile") for c in rotor)
    assert (round(lo), round(hi)) == (q[7], q[8])
    lo, hi = span(100 * c.hierarchy.models["greenwood_tripp_plastic"].profile_error
                  for c in rotor)
    assert (round(lo, 1), round(hi, 1)) == (q[9], q[10])
    named = [c for c in rotor if c.hierarchy.verdict == "greenwood_tripp_plastic"]
    assert [round(c.load, 2) for c in named] == [q[11]]
    assert round(checks["symmetric"].load, 2) == q[11]


def test_share_of_the_real_contact_area_at_the_hardness(checks):
    m = quoted(r"The BEM agrees: (\d+)–(\d+) % of the real contact area is at the hardness "
               r"\(at 10 N and the three ball loads\)")
    shares = [100 * c.comparison.plastic_fraction / c.comparison.area_fraction
              for c in checks.values()]
    lo, hi = span(shares)
    assert (round(lo), round(hi)) == (int(m.group(1)), int(m.group(2)))


def test_verdict_tolerance_and_the_scans_pixel():
    import surfmet
    from contact._hertzcheck import PROFILE_TOLERANCE, RADIUS_TOLERANCE
    from surfmet.data import path

    tol = float(quoted(r"The `verdict` names the simplest model within (\d+) %").group(1))
    assert 100 * PROFILE_TOLERANCE == tol and 100 * RADIUS_TOLERANCE == tol
    pixel = float(quoted(r"R = 20 mm, the scans' own (\d+) µm pixel").group(1))
    plate, ball = surfmet.read(path("paper_plate.x3p")), surfmet.read(path("paper_ball.x3p"))
    assert min(plate.dx, plate.dy, ball.dx, ball.dy) == pytest.approx(pixel * 1e-6, rel=1e-9)


def test_memory_estimate_per_cell():
    from contact.bem._memory import BYTES_PER_CELL

    m = quoted(r"about (\d+) bytes per cell, `contact\.bem\._memory`")
    assert BYTES_PER_CELL == int(m.group(1))


@pytest.mark.realdata
def test_number_of_real_instrument_files_the_tests_read(realdata):
    manifest = realdata("MANIFEST.tsv")
    names = [line.split("\t")[0] for line in manifest.read_text(encoding="utf-8").splitlines()[1:]
             if line.strip()]
    n = int(quoted(r"The tests read (\d+) real instrument files from `\.\./shared/realdata`")
            .group(1))
    assert len(names) == n
    tests = "".join(p.read_text(encoding="utf-8") for p in (ROOT / "tests").glob("*.py")
                    if p.name != Path(__file__).name)
    unread = [name for name in names if name not in tests]
    assert not unread, f"named in MANIFEST.tsv but read by no test: {unread}"


def test_quickstart_figures():
    """docs/quickstart.md: the shipped scans' pixels, the resolution study's halvings and
    its convergence threshold, the rolling exponent's default number of loads."""
    import inspect

    import surfmet
    from contact._convergence import CONVERGED
    from surfmet.data import path
    from surfmet.mechanics.resolution_study import contact_study
    from surfmet.mechanics.rolling_resistance import rolling_resistance

    doc = " ".join((ROOT / "docs" / "quickstart.md").read_text(encoding="utf-8").split())
    m = re.search(r"\(the paper's stand-in plate and ball scans, (\d+) µm and (\d+) µm pixel\)",
                  doc)
    assert m, "the quickstart no longer states the shipped scans' pixels"
    for name, um in (("paper_plate.x3p", m.group(1)), ("paper_ball.x3p", m.group(2))):
        t = surfmet.read(path(name))
        assert (t.dx, t.dy) == pytest.approx((float(um) * 1e-6,) * 2, rel=1e-9), name
    m = re.search(r"scans block-averaged (\d+)x, (\d+)x, (\d+)x, then native", doc)
    assert m and inspect.signature(contact_study).parameters["factors"].default == (
        *(int(g) for g in m.groups()), 1)
    m = re.search(r"which quantities changed < (\d+) % over the last halving", doc)
    assert m and 100 * CONVERGED == int(m.group(1))
    m = re.search(r'or model="plastic"; the default loads: (\d+)', doc)
    default = inspect.signature(rolling_resistance).parameters["loads"].default
    assert m and default.endswith(f":{m.group(1)}")


def test_rotor_paragraph_quotes_the_verdict_with_its_design_p_and_arm_bound():
    """The paragraph on the paper's question (issue 35): the critical F, the calibration's
    floor, the trend and the frames-only windows, the design's permutation p (10 splits of
    six launches into 3 + 3: C(6, 3) / 2, the real split the largest, so p = 1/10), and the
    friction arm against the Hertz radius, each checked against the verdict and the arm and
    radius against their closed forms."""
    import math

    from contact._materials import composite_modulus, material
    from surfmet.mechanics.rotor_verdict import paper_verdict

    v = paper_verdict()
    m = quoted(r"critical value of (\d\.\d\d) calibrated by simulation at (\d) % false alarms, "
               r"calibrated p ≤ (0\.\d+), the calibration's floor")
    assert float(m.group(1)) == round(v.f_critical, 2) and m.group(2) == "2"
    floor = float(m.group(3))
    assert v.shared_track_p <= floor and abs(v.shared_track_p - floor) < 5e-5
    assert "not the design's" in README and "permutation p is 0.1" in README
    m = quoted(r"a trend of s − as of \+(\d\.\d\d) ± (\d\.\d) rad/s² per m in the joint model; "
               r"read off the frames alone, in (\d) windows of (\d+) mm, no window's difference "
               r"exceeds its two standard errors")
    d = v.difference
    assert float(m.group(1)) == round(d.trend, 2) and float(m.group(2)) == round(
        d.trend_stderr, 1)
    assert int(m.group(3)) == d.windows.difference.size
    assert int(m.group(4)) == round(d.windows.window_length * 1e3)
    assert not d.windows.resolved.any()
    m = quoted(r"the groups' tracks differing more than the launches' within a group do "
               r"\(nominal p = (0\.\d+) against a critical (0\.\d+)\)")
    assert v.lanes.groups_differ
    assert float(m.group(1)) == float(f"{v.lanes.p_nominal:.2g}")
    assert float(m.group(2)) == float(f"{v.lanes.p_critical:.2g}")
    m = quoted(r"of the (\d+) ways to split the six launches into two groups of three the real "
               r"split has the largest F, so the design's exact permutation p is (0\.\d)")
    splits = math.comb(6, 3) // 2
    assert int(m.group(1)) == splits == v.permutation.n_splits
    assert v.permutation.f_rank == 1 and float(m.group(2)) == 1 / splits == v.permutation.f_p
    m = quoted(r"at 1° the friction arm s_r = M_r/N would be (\d\.\d+) mm, (\d\.\d) times the "
               r"Hertz contact radius \((\d+) µm\).*?the offset needs λ ≥ (\d\.\d+) "
               r"\((\d\.\d+) to (\d\.\d+) over its interval.*?only with s_r = (\d\.\d+) mm on a "
               r"slope of (\d\.\d+)°")
    rig, b = v.rig, v.arm
    # closed forms: a = (3 N R / (4 E*))^(1/3) at the symmetric ball load; the torque of both
    # contacts M g R sin(1 deg) - eps_mean (J + M R^2) shared by the loads of one rotor
    e_star = composite_modulus(material("steel"), material("aluminium"))
    n_sym = 0.5 * sum(rig.group("s").ball_loads)
    a = (3 * n_sym * rig.ball_radius / (4 * e_star)) ** (1 / 3)
    torque = (rig.mass * 9.80665 * rig.ball_radius * math.sin(math.radians(1.0))
              - v.mean_acceleration * rig.rolling_inertia)
    arm = torque / sum(rig.group("s").ball_loads)
    assert float(m.group(1)) == round(arm * 1e3, 3) == round(b.friction_arm * 1e3, 3)
    assert float(m.group(2)) == round(arm / a, 1)
    assert int(m.group(3)) == round(a * 1e6) == round(b.arm_bound * 1e6)
    assert [float(g) for g in m.groups()[3:6]] == [round(b.lambda_at_bound, 2),
                                                    round(b.lambda_low, 2),
                                                    round(b.lambda_high, 1)]
    assert float(m.group(7)) == round(b.arm_4_3 * 1e3, 2)
    assert float(m.group(8)) == round(math.degrees(b.slope_4_3), 2)
    from rotor._sensitivity import LARGER_CONTRAST, settling_experiment

    m = quoted(r"With s_r at the bound, telling 4/3 from 1 would take (\d+) launches per group "
               r"on these loads, and (\d+) with a larger load contrast \((\d\.\d) and "
               r"(\d\.\d) N\)")
    e = settling_experiment(v)
    at_bound = [r for r in e.rows if r.arm == b.arm_bound]
    assert [int(m.group(1)), int(m.group(2))] == [r.launches for r in at_bound]
    assert sorted([float(m.group(3)), float(m.group(4))]) == sorted(LARGER_CONTRAST)
    assert "swaps the labels of its two parabolas" in README
