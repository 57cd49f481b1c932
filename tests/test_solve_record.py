"""The one solve record (contact._record) of every solver family, and the one treatment of
contact at the domain edge: the record is present and tells the truth (a solve cut short
says so; a contact cut by the domain says so, in the record, the warning, the text and
the JSON of a command)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from contact import DomainSpec
from contact._errors import EdgeContactError, EdgeContactWarning
from contact._geometry import sphere_gap
from contact._hertz import hertz_sphere
from contact._record import SolveRecord, combine, edge_contact
from surfmet.records._solve import solve_from_record, solve_record

E_STAR, R, W = 1.1e11, 0.01, 5.0


def test_edge_contact_is_pressure_on_the_outermost_cells():
    p = np.zeros((6, 7))
    p[2:4, 2:5] = 1.0
    assert not edge_contact(p)
    for cell in ((0, 3), (5, 3), (3, 0), (3, 6)):
        q = p.copy()
        q[cell] = 0.5
        assert edge_contact(q)
        assert not edge_contact(q, periodic=True)  # a periodic domain has no edge
    q = p.copy()
    q[3, 0] = 1.0
    assert not edge_contact(q, leading_only=True)  # trailing side only
    q[3, 6] = 1.0
    assert edge_contact(q, leading_only=True)
    line = np.array([0.0, 1.0, 2.0, 0.0])
    assert not edge_contact(line) and edge_contact(line[1:])
    assert edge_contact(np.array([[1.0, 2.0, 0.0]]))  # one row stands for a line


def test_record_text_and_json_say_the_same():
    rec = SolveRecord("normal BEM", 7, 2.5e-3, 1e-6, False, True, "what it is", 3)
    text = rec.text()
    assert "7 iterations (3 outer)" in text and "NOT converged" in text
    assert "edge contact: yes" in text and "0.0025" in text
    js = solve_record(rec)
    assert js["converged"] is False and js["edge_contact"] is True
    assert js["residual"] == {"value": 2.5e-3, "unit": ""}
    assert js["residual_definition"] == "what it is"
    assert "too small" in js["warning"] and "enlarge" in js["warning"]
    assert solve_from_record(json.loads(json.dumps(js))) == rec
    both = combine([rec, SolveRecord("normal BEM", 5, 1e-7, 1e-6, True, False)], "sweep")
    assert (both.iterations, both.solves, both.converged, both.edge_contact) == (12, 2, False,
                                                                                 True)
    assert both.residual == 2.5e-3 and both.outer_iterations == 3


def test_bem_record_says_not_converged_after_two_iterations():
    from contact import SolveOptions
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    hz = hertz_sphere(R, W, E_STAR)
    n = 64
    dx = 3 * hz.a / n
    res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, load=W,
                       options=SolveOptions(max_iter=2, nested=False, strict=False))
    rec = res.solve
    assert rec.iterations == 2 and rec.converged is False
    assert rec.residual > rec.tolerance == 1e-6
    assert not rec.edge_contact
    assert res.iterations == rec.iterations and res.converged is rec.converged


def test_bem_hertz_on_a_too_small_domain_says_edge_contact():
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    hz = hertz_sphere(R, W, E_STAR)
    n = 32
    dx = 1.6 * hz.a / n  # the Hertz disc (diameter 2a) does not fit in 1.6 a
    with pytest.warns(EdgeContactWarning, match="too small"):
        res = solve_normal(gap_grid(sphere_gap(n, dx, R), dx), e_star=E_STAR, load=W)
    assert res.solve.edge_contact and res.touches_edge and res.solve.converged
    assert res.solve.warning in res.notes
    fits = solve_normal(gap_grid(sphere_gap(n, 3 * hz.a / n, R), 3 * hz.a / n), e_star=E_STAR,
                        load=W)
    assert not fits.solve.edge_contact and fits.solve.warning is None


def test_line_record():
    from contact._hertz import hertz_cylinder
    from contact.setups._line import solve_cylinder

    res = solve_cylinder(0.01, 1e5, E_STAR, n=128)
    rec = res.solve
    assert rec.converged and rec.residual <= rec.tolerance and not rec.edge_contact
    assert rec.iterations == res.iterations >= 1
    a = hertz_cylinder(0.01, 1e5, E_STAR).a
    with pytest.warns(EdgeContactWarning, match="too small"):
        cut = solve_cylinder(0.01, 1e5, E_STAR, n=128, size=1.5 * a)
    assert cut.solve.edge_contact and cut.touches_edge


def test_tangential_record_and_leading_edge_error():
    from contact.tangential import Creepage, pair_constants_from, sphere_grid, steady_rolling

    c = pair_constants_from(80e9, 0.3, 200e9, 0.28)
    a = (3 * 10.0 * 0.01 / (4 * c.e_star)) ** (1 / 3)
    r = steady_rolling(sphere_grid(0.01, 1.2 * a, 16), c, 10.0, 0.3, Creepage(xi=-1e-4))
    rec = r.solve
    assert rec.method == "steady rolling" and rec.converged
    assert rec.iterations == r.outer and rec.outer_iterations == r.iterations
    assert rec.tolerance == r.tol and 0 <= rec.residual < 1e-3
    assert not rec.edge_contact
    with pytest.raises(EdgeContactError, match="leading edge"):
        steady_rolling(sphere_grid(0.01, 0.8 * a, 16), c, 10.0, 0.3, Creepage(xi=-1e-4))


def test_viscoelastic_record_replaces_the_untyped_dict():
    from contact.viscoelastic._rheology import StandardLinearSolid, pair_creep
    from contact.viscoelastic._surface import rolling_sphere

    nu, eg, er = 0.5, 30e6, 10e6
    a_r = (3 * 1.0 * 0.01 * ((1 - nu**2) / er) / 4) ** (1 / 3)
    creep = pair_creep(None, StandardLinearSolid(eg, er, a_r, nu))
    res = rolling_sphere(0.01, 1.0, creep, 1.0, n=16, nested=False)
    rec = res.solve
    assert rec.converged and rec.residual <= rec.tolerance and rec.iterations == res.iterations
    assert not rec.edge_contact and res.gap_residual < 1e-3 and res.inner_iterations >= 0
    assert solve_record(res.solve)["edge_contact"] is False
    assert not hasattr(res, "extra")
    with pytest.warns(EdgeContactWarning, match="too small"):
        cut = rolling_sphere(0.01, 1.0, creep, 1.0, n=16, nested=False, half_width=0.7 * a_r)
    assert cut.solve.edge_contact


def test_adhesive_record():
    from contact.adhesion.laws import ExponentialLaw
    from contact.adhesion.solver import adhesive_problem, solve_adhesive

    x = (np.arange(32) - 16) * 0.02
    h = (x[:, None] ** 2 + x[None, :] ** 2) / 2
    st = solve_adhesive(adhesive_problem(h, 0.02, 1.0, ExponentialLaw(0.01, 0.01)), 0.01,
                        tol=1e-7)
    rec = st.solve
    assert rec.converged and rec.residual == st.residual <= rec.tolerance == 1e-7
    assert rec.iterations == st.iterations and not rec.edge_contact
    # periodic: edge contact does not apply, and the record says so rather than "no"
    assert rec.periodic and "edge contact: not applicable (periodic domain)" in rec.text()
    assert solve_record(rec)["periodic"] is True and solve_record(rec)["edge_contact"] is False


def test_periodic_and_free_bem_records_say_whether_edge_contact_applies():
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    x = (np.arange(32) - 16) * 1e-5
    h = (x[:, None] ** 2 + x[None, :] ** 2) / (2 * R)
    free = solve_normal(gap_grid(h, 1e-5), e_star=E_STAR, load=1.0).solve
    per = solve_normal(gap_grid(h, 1e-5, periodic=True), e_star=E_STAR, load=1.0).solve
    assert not free.periodic and free.text().endswith("edge contact: no")
    assert "periodic" not in solve_record(free)
    assert per.periodic and per.text().endswith("edge contact: not applicable (periodic domain)")
    back = solve_from_record(json.loads(json.dumps(solve_record(per))))
    assert back == per and back.text() == per.text()
    assert combine([per, per]).periodic and not combine([per, free]).periodic


def test_bem_counters_are_part_of_the_one_record():
    """The BEM's FFT and level counters live in its SolveRecord (not a second result
    type), cover every level of a nested solve and stay out of the JSON."""
    import contact.bem as bem
    from contact._grid import gap_grid
    from contact.bem import solve_normal

    x = (np.arange(256) - 128) * 2.5e-6
    res = solve_normal(gap_grid((x[:, None] ** 2 + x[None, :] ** 2) / (2 * R), 2.5e-6),
                       e_star=E_STAR, load=1.0)
    c = res.solve.counters
    assert c["levels"] == tuple(res.extra["levels"]) and len(c["levels"]) > 1
    assert c["levels"][-1] == (256, 256, res.iterations) and c["iterations"] == res.iterations
    # at least one float32 product per iteration of every level, and an exact re-sync
    assert c["fft_single"] >= sum(it for *_, it in c["levels"]) and c["fft_double"] >= 1
    assert "counters" not in solve_record(res.solve) and "SolverStats" not in bem.__all__
    import pickle
    assert pickle.loads(pickle.dumps(res.solve)).counters == c  # results still pickle


def test_adhesive_cycle_counts_the_pull_off_refinement():
    """The cycle's record stands for every solve run: the legs' steps and the
    golden-section solves that refine the pull-off (counted here by wrapping the solver)."""
    import contact.adhesion.solver as cycle  # the periodic problem's equilibrium calls it
    from contact.adhesion.ball import adhesive_ball
    from contact.adhesion.laws import DugdaleLaw

    calls = []
    real = cycle.solve_adhesive

    def counting(*a, **k):
        calls.append(1)
        return real(*a, **k)

    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cycle.solve_adhesive = counting
        try:
            ball = adhesive_ball(
                1e-5, 1e9, DugdaleLaw.from_range(0.05, 2e-9), steps=6, domain=DomainSpec(grid=16)
            )
        finally:
            cycle.solve_adhesive = real
    cyc = ball.cycle
    legs = cyc.approach_leg.solve.solves + cyc.retraction_leg.solve.solves
    assert cyc.solve.solves == len(calls)  # every solve run, the refinement's included
    assert cyc.pull_off_solve is not None and cyc.pull_off_solve.solves == len(calls) - legs > 0
    assert cyc.solve.iterations == (cyc.approach_leg.solve.iterations
                                    + cyc.retraction_leg.solve.iterations
                                    + cyc.pull_off_solve.iterations)
    assert cyc.approach_leg.solve.iterations >= cyc.approach_leg.iterations.sum()
    assert cyc.solve.periodic and "golden-section" in cyc.solve.method


def test_contact_command_prints_the_record_and_the_edge_warning(capsys):
    from surfmet.cli import main

    argv = ["contact", "--radius", "10mm", "--load", "5N", "--materials", "steel,aluminium",
            "--grid", "32", "--size", "0.1mm", "--on-edge", "warn"]
    assert main(argv) == 0  # the command turns the warning into its text and JSON
    text = capsys.readouterr().out
    line = next(s for s in text.splitlines() if s.startswith("solver"))
    assert "iterations" in line and "residual" in line and "converged" in line
    assert "edge contact: yes" in line
    assert any("too small" in s and s.startswith("warning") for s in text.splitlines())
    assert main([*argv, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    solve = rec["solve"]
    assert solve["edge_contact"] is True and "too small" in solve["warning"]
    assert solve["converged"] is True and solve["iterations"] == rec["iterations"] >= 1
    assert solve["residual"]["unit"] == "" and math.isfinite(solve["residual"]["value"])
    assert rec["touches_edge"] is True


def test_flat_contact_free_boundary_reaches_the_edge_periodic_has_none(tmp_path, capsys):
    import surfmet
    from surfmet.cli import main
    from surfmet.synth import self_affine

    topo = self_affine(32, 1e-6, hurst=0.7, slope_rms=0.05, short_cutoff=4e-6, seed=2)
    scan = str(surfmet.write(topo, tmp_path / "sa.npz"))
    argv = ["flat-contact", scan, "--e-star", "1GPa", "--pressures", "1MPa", "--quiet"]
    assert main([*argv, "--periodic", "no"]) == 0
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    solve = next(s for s in lines if s.strip().startswith("solve"))
    assert "edge contact: yes" in solve and "converged" in solve
    # a scan pressed on a flat reaches its edge by nature: said once, as a note, not as a
    # "domain too small" warning (issue 34, item 15)
    assert not any(s.strip().startswith("warning") and "too small" in s for s in lines)
    assert captured.err.count("contact reaches the edge of the scan, as it must") == 1
    assert main([*argv, "--periodic", "no", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["solve"]["edge_contact"] is True and "too small" in rec["solve"]["warning"]
    assert rec["results"][0]["bem"]["solve"]["edge_contact"] is True
    assert main([*argv, "--periodic", "yes", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["solve"]["edge_contact"] is False and rec["solve"]["warning"] is None
