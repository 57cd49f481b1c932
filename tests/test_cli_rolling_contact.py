"""``surfmet rolling-contact``: Carter's closed form through the CLI, the JSON record's
units and sign convention, free rolling of identical bodies, and one-line refusals."""

from __future__ import annotations

import json
import math

import pytest

from contact.hertz import hertz_cylinder
from contact.materials import composite_modulus, material
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
    assert rec["creepage"] == {"value": xi, "unit": "1"}
    assert "positive creepage gives negative fx" in rec["sign_convention"]


def test_json_fields_and_free_rolling_of_identical_bodies(capsys):
    """Free rolling of identical bodies: no force, no creepage, no slip, no dissipation;
    the pressure is Hertz's (pmax to 2 % on 24 elements a side)."""
    assert main([*BASE, "--load", "5N", "--mu", "0.3", "--grid", "24", "--speed", "2",
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    for key, unit in (("creepage", "1"), ("fx", "N"), ("fy", "N"), ("pmax", "Pa"),
                      ("approach", "m"), ("contact_area", "m^2"), ("stick_area", "m^2"),
                      ("slip_area", "m^2"), ("frictional_power", "W/(m/s)"),
                      ("rolling_resistance_coefficient", "1"),
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
