"""``surfmet rolling-contact``: Carter's closed form through the CLI, the JSON record's
units and sign convention, free rolling of identical bodies, and one-line refusals."""

from __future__ import annotations

import json
import math

import pytest

from contact._hertz import hertz_cylinder
from contact._materials import composite_modulus, material
from surfmet.cli import main

BASE = ["rolling-contact", "--radius", "25mm", "--materials", "steel,steel"]


def test_line_contact_matches_carter(capsys):
    """Steel on steel roller, 100 N/mm, mu 0.3, xi = 4e-4: F_x = -mu N (1 - c^2/a^2),
    c = a - xi R/mu (Carter 1926), to 1 % on 256 elements."""
    xi, mu, radius, load = 4e-4, 0.3, 0.025, 1e5
    assert main([*BASE, "--load", "100N/mm", "--line", "--mu", str(mu), "--creepage",
                 str(xi), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    steel = material("steel")
    a = hertz_cylinder(radius, load, composite_modulus(steel, steel)).a
    c = a - xi * radius / mu
    assert rec["fx"]["unit"] == "N/m"
    assert rec["fx"]["value"] == pytest.approx(-mu * load * (1 - c**2 / a**2), rel=0.01)
    assert rec["stick_area"]["value"] == pytest.approx(2 * c, rel=0.03)
    assert rec["stick_area"]["unit"] == "m"
    assert rec["creepage"] == {"value": xi, "unit": ""}
    assert "positive creepage gives negative fx" in rec["sign_convention"]


def test_json_fields_and_free_rolling_of_identical_bodies(capsys):
    """Free rolling of identical bodies: no force, no creepage, no slip, no dissipation;
    the pressure is Hertz's (pmax to 2 % on 24 elements a side)."""
    assert main([*BASE, "--load", "5N", "--mu", "0.3", "--grid", "24", "--speed", "2",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    for key, unit in (("creepage", ""), ("fx", "N"), ("fy", "N"), ("pmax", "Pa"),
                      ("approach", "m"), ("contact_area", "m^2"), ("stick_area", "m^2"),
                      ("slip_area", "m^2"), ("frictional_power", "W/(m/s)"),
                      ("rolling_resistance_coefficient", ""),
                      ("frictional_power_at_speed", "W")):
        assert rec[key]["unit"] == unit, key
    assert rec["creepage"]["value"] == 0.0
    assert rec["slip_area"]["value"] == 0.0
    assert rec["frictional_power"]["value"] == pytest.approx(0.0, abs=1e-15)
    steel = material("steel")
    e_star = composite_modulus(steel, steel)
    a = (3 * 5.0 * 0.025 / (4 * e_star)) ** (1 / 3)
    assert rec["pmax"]["value"] == pytest.approx(3 * 5.0 / (2 * math.pi * a**2), rel=0.02)


@pytest.mark.parametrize("args, message", [
    (["--load", "5N", "--mu", "0"], "--mu must be a positive"),
    (["--load", "5N", "--mu", "0.3", "--creepage", "inf"], "--creepage must be a finite"),
    (["--load", "5N", "--mu", "0.3", "--line"], "load per length"),
])
def test_bad_input_is_one_line(capsys, args, message):
    assert main([*BASE, *args]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0]


PAIR = ["--plate", "surfmet/data/paper_plate.x3p", "--ball", "surfmet/data/paper_ball.x3p"]
ROUGH = ["rolling-contact", *PAIR, "--radius", "20mm", "--load", "5N",
         "--materials", "steel,aluminium", "--mu", "0.3"]


def test_rough_domain_is_sized_from_the_scans(capsys):
    """The help's own example on the bundled pair: rough contact spreads beyond 1.5 Hertz
    radii, so the domain comes from the roughness (as for ``contact``) and holds the whole
    contact: no loaded element on the domain's edge, and the load carried in full."""
    from contact._geometry import contact_extent

    assert main([*ROUGH, "--grid", "32", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    e_star = composite_modulus(material("steel"), material("aluminium"))
    side = rec["grid"]["domain_side"]
    assert side["unit"] == "m"
    a = (3 * 5.0 * 0.02 / (4 * e_star)) ** (1 / 3)
    assert side["value"] > 2 * 1.5 * a  # main's fixed 1.5 a_Hertz did not hold it
    assert side["value"] >= 2 * 1.25 * contact_extent(0.02, 5.0, e_star, 0.0)
    assert rec["contact_area"]["value"] > 0
    assert abs(rec["fx"]["value"]) < 1e-6 * 5.0  # free rolling


def test_too_small_a_size_names_the_option(capsys):
    """A user-fixed domain the contact outgrows is refused in one line naming --size
    (after the notes on the scans' preparation)."""
    assert main([*ROUGH, "--grid", "16", "--size", "150um"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert not any(line.startswith("note") for line in err[-1:])
    assert "--size" in err[-1] and "leading edge" in err[-1]


@pytest.mark.parametrize("extra, shape", [
    (["--load", "5N", "--grid", "100000"], "x"),
    (["--load", "5N/mm", "--line", "--grid", "100000000"], None),
    (["--load", "5N", "--grid", "100000", "--viscoelastic",
      "plate:Eg=3GPa:Er=1GPa:tau=1ms", "--speed", "1"], "x"),
])
def test_grid_beyond_memory_is_refused_in_one_line(capsys, monkeypatch, extra, shape):
    """As ``contact`` and ``hertz-check`` do: a grid that cannot fit is refused before
    anything is allocated, in one line naming the largest grid that fits (here with 2 GB
    available; the named grid's estimate fits, the next even one's does not)."""
    import re

    from contact.bem._memory import SAFETY
    from contact.tangential import _memory as memory

    monkeypatch.setattr(memory, "available_bytes", lambda: 2 * 10**9)
    assert main([*BASE, "--mu", "0.3", *extra]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "largest grid that fits" in err[0]
    best = int(re.search(r"--grid (\d+)", err[0]).group(1))
    if shape:
        assert f"{best} x {best} elements" in err[0]
    line = "--line" in extra
    budget = SAFETY * 2e9
    assert memory.estimate_rolling_bytes(best, line=line) <= budget
    assert memory.estimate_rolling_bytes(best + 2, line=line) > budget


def test_memory_estimate_bounds_the_measured_peak():
    """The estimate is an upper bound of what a 3D solve adds to the peak resident set,
    measured in a fresh interpreter after a small warm-up solve; the peak is reset after
    the warm-up (Linux ``clear_refs``), so that compiling the kernels does not hide it."""
    import subprocess
    import sys

    from contact.tangential._memory import estimate_rolling_bytes

    code = (
        "from surfmet.mechanics.rolling_contact import solve_rolling_contact as s\n"
        "def kb(key):\n"
        "    return next(int(x.split()[1]) for x in open('/proc/self/status')\n"
        "                if x.startswith(key))\n"
        "s(0.02, 5.0, 'steel,aluminium', 0.3, grid=16)\n"
        "open('/proc/self/clear_refs', 'w').write('5')\n"
        "r = kb('VmRSS:')\n"
        "s(0.02, 5.0, 'steel,aluminium', 0.3, grid=192)\n"
        "print((kb('VmHWM:') - r) * 1024)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    added = int(out.stdout.split()[-1])
    assert 0 < added <= estimate_rolling_bytes(192)


def test_dissipation_is_never_negative_and_convergence_is_stated(capsys):
    """mu = 1e9: every element sticks, nothing slips, so nothing dissipates (main gave a
    negative frictional power: -q . s of the solver's tolerance-level stick slip); the
    record states its convergence as ``contact`` does (iterations, residual, converged)."""
    assert main([*BASE, "--load", "5N", "--materials", "steel,aluminium", "--mu", "1e9",
                 "--grid", "32", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["slip_area"]["value"] == 0.0
    assert rec["frictional_power"]["value"] == 0.0
    assert rec["converged"] is True and rec["iterations"] >= 1
    assert 0 <= rec["residual"]["value"] < 1e-3
    assert rec["solver"]["tolerance"] == 1e-6
    # issue 26: the one solve record, the same numbers
    solve = rec["solve"]
    assert solve["iterations"] == rec["iterations"] and solve["converged"] is True
    assert solve["residual"] == rec["residual"] and solve["edge_contact"] is False


def test_slip_elements_dissipate_mu_p_slip():
    """With slip, the dissipation is the sum over the slip elements of mu p |s| dA (the
    traction opposes the slip there), and positive."""
    import numpy as np

    from contact.tangential._kernels import SLIP
    from surfmet.mechanics.rolling_contact import solve_rolling_contact

    r = solve_rolling_contact(0.02, 5.0, "steel,aluminium", 0.3, creepage=2e-4,
                              grid=32).result
    slip = r.state == SLIP
    expected = float((0.3 * r.p * np.hypot(r.s[0], r.s[1]))[slip].sum() * r.grid.area)
    assert slip.any() and expected > 0
    assert r.frictional_power == pytest.approx(expected, rel=1e-9)


def test_speed_takes_units_like_every_quantity(capsys):
    """Issue 25 item 10: ``--speed 2km/h`` is 2/3.6 m/s (a bare number stays m/s)."""
    from surfmet.units import parse_speed

    assert parse_speed("1m/s") == 1.0 and parse_speed("0.1") == 0.1
    assert parse_speed("50mm/s") == pytest.approx(0.05, rel=1e-15)
    assert main(["rolling-contact", "--radius", "20mm", "--load", "5N", "--materials",
                 "steel,aluminium", "--mu", "0.3", "--speed", "2km/h", "--grid", "16",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["speed"] == {"value": pytest.approx(2 / 3.6, rel=1e-12), "unit": "m/s"}
    assert rec["frictional_power_at_speed"]["value"] == pytest.approx(
        rec["frictional_power"]["value"] * 2 / 3.6, rel=1e-12)


def test_rolling_resistance_is_the_dissipation_as_the_rolling_command_gives_it(capsys):
    """One question, one answer: steel on aluminium at 5 N, mu 0.3, free rolling, 32^2
    over 2.5 Hertz radii. rolling-contact's rolling_resistance_coefficient times N R is
    the micro-slip moment of surfmet rolling --model microslip (the same solve, to 1e-9);
    the pressure's moment is reported beside it under its own name, and differs (it is
    not the dissipation of an elastic contact)."""
    args = ["rolling-contact", "--radius", "20mm", "--materials", "steel,aluminium",
            "--load", "5N", "--mu", "0.3", "--grid", "32", "--json"]
    assert main(args) == 0
    rec = json.loads(capsys.readouterr().out)
    assert main(["rolling", "--radius", "20mm", "--materials", "steel,aluminium",
                 "--loads", "5N:7N:3", "--model", "microslip", "--json"]) == 0
    sweep = json.loads(capsys.readouterr().out)
    moment = sweep["moments"]["value"][0]
    assert moment > 0
    coefficient = rec["rolling_resistance_coefficient"]["value"]
    assert coefficient * 5.0 * 0.02 == pytest.approx(moment, rel=1e-9)
    pressure = rec["pressure_moment_coefficient"]
    assert pressure["unit"] == ""
    assert abs(pressure["value"] - coefficient) > 0.1 * coefficient
    assert "frictional dissipation per metre rolled" in rec["rolling_resistance_definition"]


def test_elements_coarser_than_the_scans_are_said(capsys):
    """On scans the text names its grid, and elements much coarser than the scans' pixel
    are a note (the bundled pair, 5 um pixel, on 32 elements over the automatic domain of
    about 0.95 mm); 160 elements over it (about 6 um) are not."""
    from surfmet.data import path as bundled_path

    scans = ["--plate", str(bundled_path("paper_plate.x3p")),
             "--ball", str(bundled_path("paper_ball.x3p"))]
    args = ["rolling-contact", "--radius", "10mm", "--materials", "steel,aluminium",
            "--load", "5N", "--mu", "0.3", *scans]
    assert main([*args, "--grid", "32"]) == 0
    out = capsys.readouterr().out
    grid = next(v for v in out.splitlines() if v.strip().startswith("grid "))
    assert "32 x 32 elements of" in grid
    note = next(v for v in out.splitlines() if "are sampled at the centres" in v)
    assert "(pixel 5 µm)" in note and "x coarser" in note
    assert main([*args, "--grid", "160", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["grid"]["element_size"]["value"] < 1.5 * 5e-6
    assert not any("sampled at the centres" in n for n in rec.get("notes", []))
