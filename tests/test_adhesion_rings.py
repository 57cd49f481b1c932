"""The smooth adhesive sphere on axisymmetric rings (``surfmet adhesion``'s default for a
smooth sphere) against closed forms: Hertz (no adhesion), Maugis-Dugdale's pull-off and
the approach at it (Maugis 1992, solved independently in tests/maugis_reference.py) from
lambda 0.05 to 10, and the JKR and DMT limits 1.5 and 2 pi w R.

On main the command's default at lambda 10 was the 1952^2 periodic grid (more than an
hour of CPU) and there was no ``--model``: these tests fail there (the facade has no
``model``, the JSON no ``discretisation``).
"""

from __future__ import annotations

import functools
import json
import math

import numpy as np
import pytest
from maugis_reference import md_pull_off, md_pull_off_approach

from surfmet.cli import main

R, E_STAR, W = 1e-3, 1e9, 0.05
K = 4.0 * E_STAR / 3.0
# h0 for Maugis' lambda: lambda = 2 (w / h0) (R / (pi w K^2))^(1/3)
_SCALE = 2.0 * W * (R / (math.pi * W * K * K)) ** (1 / 3)
# Maugis' approach scale (pi^2 w^2 R / K^2)^(1/3)
D_SCALE = (math.pi ** 2 * W * W * R / (K * K)) ** (1 / 3)


@functools.cache
def _run(lam: float, steps: int = 16, law: str = "dugdale"):
    """The rings' cycle at Maugis' ``lam`` (16 steps a leg: the pull-off is refined by the
    golden section between them; measured with them, benchmarks/adhesion_rings.py)."""
    from surfmet.mechanics.adhesion import adhesion

    return adhesion(R, work=W, range_=_SCALE / lam, e_star=E_STAR, interaction=law,
                    steps=steps, model="axisymmetric")


def test_without_adhesion_the_rings_give_hertz():
    """w = 1e-9 J/m^2: P = (4/3) E* sqrt(R) delta^(3/2), a = sqrt(R delta) (Hertz)."""
    from contact.adhesion._rings import ring_problem, solve_rings
    from contact.adhesion.laws import DugdaleLaw

    law = DugdaleLaw.from_range(1e-9, 1e-9)
    delta = 1e-7
    a = math.sqrt(R * delta)
    problem = ring_problem(R, E_STAR, law, np.linspace(0.0, 3.0 * a, 601))
    st = solve_rings(problem, delta)
    assert st.load == pytest.approx(4.0 / 3.0 * E_STAR * math.sqrt(R) * delta ** 1.5, rel=5e-3)
    assert math.sqrt(st.contact_area / math.pi) == pytest.approx(a, abs=problem.dx)


def test_graded_rings_give_hertz_and_the_uniform_disc():
    """Rings of unequal widths (fine at the contact edge, growing by 10 % a ring away from
    it): each ring's influence is the difference of two discs' (Johnson eq. 3.39), so a
    uniform pressure on the rings inside b is the disc's displacement to rounding, and the
    Hertz solve on 90 graded rings is as close as on 600 uniform ones. On main
    ring_problem refused rings that are not uniform."""
    from contact.adhesion._ring_ball import graded_edges
    from contact.adhesion._rings import ring_problem, solve_rings
    from contact.adhesion.laws import DugdaleLaw
    from contact.halfspace.axisymmetric import RingOperator, disc_displacement

    law = DugdaleLaw.from_range(1e-9, 1e-9)
    delta = 1e-7
    a = math.sqrt(R * delta)
    fine = 3.0 * a / 600
    edges = graded_edges(3.0 * a, [(0.95 * a, 1.05 * a, fine)], 40.0 * fine)
    widths = np.diff(edges)
    assert edges.size - 1 < 100 and widths.max() > 30.0 * widths.min()
    op = RingOperator(edges)
    inside = edges[1:] <= a * 1.0000001
    b = float(edges[1:][inside][-1])
    u = op.matrix[:, inside].sum(axis=1)
    assert np.allclose(u, disc_displacement(op.r, b), rtol=1e-12, atol=0.0)
    problem = ring_problem(R, E_STAR, law, edges)
    st = solve_rings(problem, delta)
    assert st.load == pytest.approx(4.0 / 3.0 * E_STAR * math.sqrt(R) * delta ** 1.5, rel=5e-3)
    assert math.sqrt(st.contact_area / math.pi) == pytest.approx(a, abs=problem.dx)


_SLOW = pytest.mark.campaign  # over 10 s of CPU on the shared box (or not yet measured)
# lambda 10 on graded rings: about 25 s of CPU for the cycle (1,011 rings; 613 s on the
# 3,329 uniform ones before), shared by the three tests below through _run's cache
_LAMBDA_10 = pytest.mark.campaign


@pytest.mark.parametrize("lam", [0.05, 0.1, pytest.param(0.5, marks=_SLOW), 1.0,
                                 pytest.param(2.0, marks=_SLOW), pytest.param(5.0, marks=_SLOW),
                                 pytest.param(10.0, marks=_LAMBDA_10)])
def test_pull_off_is_maugis_from_lambda_0_05_to_10(lam):
    """Measured (16 steps): lambda 0.05 -0.07 %, 0.1 +0.37 %, 0.5 +0.14 %, 1 +0.18 %,
    2 +0.19 %, 5 +0.30 % with the rings' stable ramp (contact.adhesion._ring_ball.ring_law),
    10 +0.33 % on 1,011 graded rings (28 s CPU); with the grid's ramp before it 0.5 +0.45 %,
    1 +0.39 %, 2 +0.78 %, 5 +1.20 %, 10 +1.04 % (3,329 uniform rings, 613 s CPU)."""
    run = _run(lam)
    res = run.result
    assert run.axisymmetric and res.maugis_parameter == pytest.approx(lam, rel=1e-3)
    assert res.graded == (lam > 5.5) and res.rings < 1100
    want = md_pull_off(res.maugis_parameter) * math.pi * W * R
    assert res.cycle.pull_off_force == pytest.approx(want, rel=0.02)
    assert not res.warnings


@pytest.mark.parametrize("lam", [1.0, pytest.param(10.0, marks=_LAMBDA_10)])
def test_the_approach_at_pull_off_is_maugis(lam):
    """The rings' half-space is free: the approach is Maugis' delta itself, from the
    distant surface (the periodic grid's is from the deformed mean plane). Measured at
    lambda 1: -0.4798 against Maugis' -0.4842 (-0.9 %), lambda 10 -0.4324 against
    -0.4375 (-1.2 %, graded rings). On the DMT side the load is flat
    around its least value, so the approach there is ill-defined: -0.3935 against
    -0.4304 at lambda 0.1 (-8.6 %) for a pull-off within 0.4 %; not asserted. At lambda 1
    the load is flat too (0.03 % over +-0.05 of the approach scale), so the approach of
    its least value moves with the steps: measured -0.9 % to +5.1 % over 12 to 32 steps
    with the grid's ramp, -3.7 % to +5.4 % with the rings' stable ramp
    (contact.adhesion._ring_ball.ring_law; +5.4 % at 16 steps), for pull-offs within
    0.4 % and 0.2 %."""
    res = _run(lam).result
    want = md_pull_off_approach(res.maugis_parameter) * D_SCALE
    assert res.cycle.pull_off_approach == pytest.approx(want, rel=0.06, abs=0.01 * D_SCALE)


def test_dmt_limit():
    """lambda 0.05: within 2 % of DMT's 2 pi w R (measured 1.980 pi w R, -1.0 %)."""
    dmt = _run(0.05).result
    assert dmt.cycle.pull_off_force == pytest.approx(dmt.dmt_pull_off, rel=0.02)


@_LAMBDA_10
def test_jkr_limit():
    """lambda 10: within 2 % of JKR's 1.5 pi w R (measured +0.45 %, graded rings)."""
    jkr = _run(10.0).result
    assert jkr.cycle.pull_off_force == pytest.approx(jkr.jkr_pull_off, rel=0.02)


@_LAMBDA_10
def test_command_default_at_lambda_10_is_maugis_on_rings(capsys):
    """The issue's command at lambda 10: the default is the rings (graded), within 2 % of
    Maugis, the JSON naming the discretisation and the zone's rings."""
    rc = main(["adhesion", "--radius", "1mm", "--e-star", "1GPa", "--work-of-adhesion",
               "0.05J/m2", "--range", f"{_SCALE / 10.0 * 1e9:.6g}nm", "--interaction",
               "dugdale", "--json", "--quiet"])
    assert rc == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["discretisation"] == "axisymmetric"
    assert rec["grid"]["discretisation"] == "axisymmetric"
    assert rec["grid"]["process_zone_rings"]["value"] >= 8.0
    assert rec["grid"]["graded"] and "graded axisymmetric rings" in rec["grid"]["why"]
    lam = rec["maugis_parameter"]["value"]
    assert lam == pytest.approx(10.0, rel=1e-3)
    want = md_pull_off(lam) * math.pi * W * R
    assert rec["pull_off_force"]["value"] == pytest.approx(want, rel=0.02)


def test_model_3d_and_a_grid_keep_the_periodic_grid(capsys):
    base = ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
            "50mJ/m2", "--range", "2nm", "--steps", "6", "--json", "--quiet"]
    for extra in (["--grid", "16"], ["--model", "3d", "--grid", "16"]):
        assert main(base + extra) == 0
        rec = json.loads(capsys.readouterr().out)
        assert rec["discretisation"] == "3d" and rec["grid"]["cells"] == 16


def test_axisymmetric_with_a_grid_is_one_line(capsys):
    rc = main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
               "50mJ/m2", "--range", "2nm", "--model", "axisymmetric", "--grid", "32"])
    assert rc == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--model 3d" in err[0]


@pytest.mark.filterwarnings("error::RuntimeWarning")
def test_the_exponential_law_on_rings_runs_clean_between_jkr_and_dmt():
    """A Newton iterate's overlap (a gap far below zero) was handed to exp(-g / rho),
    which overflowed (main: "RuntimeWarning: overflow encountered in exp" at lambda 2 and
    5); the law is defined for g >= 0, and the iterate is now taken at contact there. The
    pull-off of any attraction on a sphere lies between JKR's 1.5 and DMT's 2 pi w R
    (measured 1.588 at lambda 2, 4.7 s)."""
    res = _run(2.0, law="exponential").result
    ratio = res.cycle.pull_off_force / (math.pi * W * R)
    assert ratio > 1.5 and ratio < 2.0, ratio
    assert not res.warnings
