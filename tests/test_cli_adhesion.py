"""``surfmet adhesion`` end to end: JSON record, units, bad input, resolution warning."""

from __future__ import annotations

import json
import math

import pytest
from maugis_reference import md_pull_off

from contact import composite_modulus, material
from surfmet._errors import SurfmetInputError
from surfmet.cli import main
from surfmet.units import parse_surface_energy

BASE = ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--range", "2nm"]
FAST = ["--grid", "64", "--steps", "8", "--quiet"]


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_json_record(capsys):
    # range 10 nm: lambda 0.33, a cohesive zone of about 60 pixels (no warning)
    rec = _json(capsys, ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--range", "10nm",
                         "--work-of-adhesion", "50mJ/m2", *FAST, "--json"])
    w, r, h0 = 0.05, 10e-6, 10e-9
    assert rec["work_of_adhesion"] == {"value": pytest.approx(w), "unit": "J/m^2"}
    assert rec["range"] == {"value": pytest.approx(h0), "unit": "m"}
    assert rec["interaction"] == "dugdale"
    f = rec["pull_off_force"]
    assert f["unit"] == "N"
    # Maugis-Dugdale at lambda 0.33 gives 1.80 pi w R (tests/maugis_reference.py)
    lam = rec["maugis_parameter"]
    assert lam["unit"] == "" and rec["tabor_parameter"]["unit"] == ""
    assert f["value"] == pytest.approx(md_pull_off(lam["value"]) * math.pi * w * r, rel=0.03)
    # Maugis' lambda = 2 sigma0 (R / (pi w K^2))^(1/3), sigma0 = w / h0, by hand
    k = 4e9 / 3
    assert lam["value"] == pytest.approx(
        2 * (w / h0) * (r / (math.pi * w * k * k)) ** (1 / 3), rel=1e-12)
    # lambda 0.33 has no jump in or out (Maugis): the legs coincide and the cycle loses
    # nothing; its closed integral (6.5e-22 J) is within the resolution (tol times the legs'
    # work, 4.6e-19 J), so it is reported as 0 (it was asserted > 0 before: noise)
    assert rec["jump_in"]["abrupt"] is False and rec["jump_out"]["abrupt"] is False
    assert rec["hysteresis_energy"] == {"value": 0.0, "unit": "J"}
    assert rec["hysteresis_resolution"]["unit"] == "J"
    assert 0.0 < rec["hysteresis_resolution"]["value"] < 1e-15
    for leg in ("in", "out"):
        curve = rec["curve"][leg]
        assert {curve[k]["unit"] for k in ("approach", "load", "contact_radius")} == \
            {"m", "N"}
        assert len(curve["approach"]["value"]) == len(curve["load"]["value"]) >= 8
    assert min(rec["curve"]["out"]["load"]["value"]) >= -f["value"] * (1 + 1e-12)
    assert rec["jump_in"]["approach"]["unit"] == "m"
    assert rec["grid"]["cells"] == 64 and rec["warnings"] == []


@pytest.mark.parametrize("text", ["0.05J/m2", "0.05J/m^2", "50mJ/m2", "50 mJ/m^2", "0.05"])
def test_work_of_adhesion_units(text):
    assert parse_surface_energy(text) == pytest.approx(0.05, rel=1e-15)


def test_prefixes_are_case_sensitive():
    with pytest.raises(SurfmetInputError, match="case-sensitive"):
        parse_surface_energy("50MJ/m2")


@pytest.mark.parametrize("argv, words", [
    (["--work-of-adhesion", "0J/m2"], "work of adhesion must be positive"),
    (["--work-of-adhesion", "-5mJ/m2"], "work of adhesion must be positive"),
    (["--work-of-adhesion", "50mJ/m2", "--range", "0nm"], "must be positive"),
    (["--work-of-adhesion", "50MJ/m2"], "case-sensitive"),
    (["--work-of-adhesion", "50mJ/m2", "--grid", "4"], "grid must be an integer of at least"),
])
def test_bad_input_is_one_line(capsys, argv, words):
    assert main([*BASE, *argv, "--quiet"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "Traceback" not in err


def test_coarse_grid_warns_in_text_and_json(capsys):
    argv = [*BASE, "--work-of-adhesion", "50mJ/m2", "--grid", "16", "--steps", "8", "--quiet"]
    assert main(argv) == 0
    assert "grid too coarse for the interaction" in capsys.readouterr().out
    rec = _json(capsys, [*argv, "--json"])
    assert any("grid too coarse for the interaction" in w for w in rec["warnings"])


def test_materials_give_the_composite_modulus(capsys):
    rec = _json(capsys, ["adhesion", "--radius", "1um", "--materials", "steel,aluminium",
                         "--work-of-adhesion", "0.5J/m2", "--range", "0.3nm",
                         "--grid", "16", "--steps", "6", "--quiet", "--json"])
    e = composite_modulus(material("steel"), material("aluminium"))
    assert rec["e_star"] == {"value": pytest.approx(e, rel=1e-12), "unit": "Pa"}


def test_plot_path_checked_before_the_work(capsys, tmp_path):
    bad = tmp_path / "missing" / "cycle.png"
    assert main([*BASE, "--work-of-adhesion", "50mJ/m2", *FAST, "--plot", str(bad)]) == 1
    assert "does not exist" in capsys.readouterr().err


def test_plot_is_written(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "cycle.png"
    argv = [*BASE, "--work-of-adhesion", "50mJ/m2", "--grid", "16", "--steps", "6",
            "--quiet", "--plot", str(out)]
    assert main(argv) == 0
    assert out.stat().st_size > 1000 and out.read_bytes()[:4] == b"\x89PNG"


def test_a_negative_loss_is_named_an_integration_error(capsys, monkeypatch):
    # a cycle cannot gain energy: the text must not print a negative loss as a loss
    import dataclasses

    import surfmet.mechanics.adhesion as facade

    real = facade.adhesion

    def gaining(*args, **kwargs):
        run = real(*args, **kwargs)
        ball = run.result
        cycle = dataclasses.replace(ball.cycle, hysteresis_energy=-1e-11)
        return dataclasses.replace(run, result=dataclasses.replace(ball, cycle=cycle))

    argv = [*BASE, "--work-of-adhesion", "50mJ/m2", "--grid", "16", "--steps", "8", "--quiet"]
    assert main(argv) == 0
    assert "below the integration error" not in capsys.readouterr().out
    monkeypatch.setattr(facade, "adhesion", gaining)
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "-1e-11 J lost in the cycle (negative: below the integration error" in out


def test_dugdale_pull_off_meets_maugis_on_the_default_cell(capsys):
    """The command smooths the Dugdale step on the grid's scale (the law the Maugis-Dugdale
    validation holds): at lambda = 1.65 on 64^2 (the cohesive zone 2.4 pixels) the pull-off
    is within 2 % of Maugis' (1992) curve; the plain step gave +11.6 % on 128^2."""
    rec = _json(capsys, ["adhesion", "--radius", "10um", "--e-star", "1GPa",
                         "--work-of-adhesion",
                         "50mJ/m2", "--range", "2nm", "--grid", "64", "--quiet", "--json"])
    lam = rec["maugis_parameter"]["value"]
    assert rec["step_smoothing"]["value"] > 0.0 and rec["step_smoothing"]["unit"] == "m"
    ratio = rec["pull_off_force"]["value"] / (math.pi * 0.05 * 1e-5)
    assert ratio == pytest.approx(md_pull_off(lam), rel=0.02)
    assert not any("cohesive zone" in w for w in rec["warnings"])


@pytest.mark.parametrize("grid, capped", [("64", True), ("128", False)])
def test_dugdale_smoothing_line_says_when_capped_at_the_range(capsys, grid, capped):
    """5 sigma0 dx / E* is 3.2 nm on 64^2 (25.8 nm pixels), above h0 = 2 nm, so the ramp is
    capped at the range and the text says so; on 128^2 it is 1.6 nm and is not."""
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
                 "50mJ/m2", "--range", "2nm", "--grid", grid, "--steps", "8"]) == 0
    line = next(v for v in capsys.readouterr().out.splitlines() if v.startswith("Dugdale"))
    assert ("capped at the range" in line) == capped
    assert ("2 nm of gap" in line) == capped


def test_a_retraction_that_never_pulled_is_named(capsys, monkeypatch):
    # a rough pair can hide adhesion: no tensile load on the way out is a pull-off of 0,
    # said in words, not printed as a (negative) force
    import dataclasses

    import numpy as np

    import surfmet.mechanics.adhesion as facade

    real = facade.adhesion

    def pressed(*args, **kwargs):
        run = real(*args, **kwargs)
        ball = run.result
        leg = dataclasses.replace(ball.cycle.retraction_leg,
                                  load=np.abs(ball.cycle.retraction_leg.load) + 1e-9)
        cycle = dataclasses.replace(ball.cycle, retraction_leg=leg, pull_off_force=0.0)
        return dataclasses.replace(run, result=dataclasses.replace(ball, cycle=cycle))

    monkeypatch.setattr(facade, "adhesion", pressed)
    argv = [*BASE, "--work-of-adhesion", "50mJ/m2", "--grid", "16", "--steps", "8", "--quiet"]
    assert main(argv) == 0
    line = next(v for v in capsys.readouterr().out.splitlines() if v.startswith("pull-off"))
    assert "0 µN: the retraction never pulled (its least load, 0.001" in line
    assert "is not tensile" in line


def test_the_jump_lines_show_a_round_off_load_as_zero(capsys):
    """Before contact the load is round-off (~1e-29 of the pull-off): the jump-in line reads
    'load 0 -> -4.7 µN', the number a person compares with the pull-off, not 2.1e-29 (and
    the jump-out ends at 0, not at 1e-21); the JSON keeps the solver's values."""
    argv = ["adhesion", "--radius", "10um", "--e-star", "1GPa", "--interaction", "dugdale",
            "--work-of-adhesion", "50mJ/m2", "--range", "2nm", "--grid", "32", "--steps", "8",
            "--quiet"]
    assert main(argv) == 0
    lines = {ln.split()[0]: ln for ln in capsys.readouterr().out.splitlines() if ln.strip()}
    for name in ("jump-in", "jump-out"):
        loads = lines[name].split(", load ")[1].split(" ->")[0], lines[name].split("-> ")[1]
        shown = [float(x.split()[0]) for x in loads]
        assert all(x == 0.0 or abs(x) > 1e-9 * max(map(abs, shown)) for x in shown), lines[name]
    assert lines["jump-out"].split("-> ")[1].startswith("0 µN")  # apart again: no load


def test_ring_width_is_written_as_a_person_reads_it(capsys):
    """The default ring solve's reason names the ring width with an SI prefix (nm), in the
    text and in the JSON, never as a bare exponent of metres ("4.45e-08 m")."""
    import re

    argv = ["adhesion", "--radius", "1mm", "--e-star", "1GPa", "--range", "5nm",
            "--work-of-adhesion", "50mJ/m2", "--steps", "8", "--quiet"]
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert re.search(r"axisymmetric rings \(\d+ of [\d.]+ nm\)", text), text
    rec = _json(capsys, [*argv, "--json"])
    dumped = json.dumps(rec)
    assert "axisymmetric rings" in dumped
    assert not re.search(r"\d(\.\d+)?e-\d+ m\b", dumped), dumped


def test_ring_width_reads_the_same_on_both_lines(capsys):
    """The rings line and the reason below it name one ring width, written alike (main:
    "399 rings of 44.54 nm" above "axisymmetric rings (399 of 44.5 nm)")."""
    import re

    argv = ["adhesion", "--radius", "1mm", "--e-star", "1GPa", "--range", "10nm",
            "--work-of-adhesion", "50mJ/m2", "--interaction", "exponential", "--steps", "8",
            "--quiet"]
    assert main(argv) == 0
    text = capsys.readouterr().out
    above = re.search(r"rings +(\d+) rings of ([\d.]+ nm)", text)
    below = re.search(r"axisymmetric rings \((\d+) of ([\d.]+ nm)\)", text)
    assert above and below, text
    assert above.groups() == below.groups()
