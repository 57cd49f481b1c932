"""rolling-contact --viscoelastic: the reported values against Hunter's closed form and
CONTACT's visc_cylindr numbers, units in JSON, one-line errors."""

from __future__ import annotations

import json
import math

import pytest

from contact.viscoelastic.hunter import hunter_cylinder
from surfmet.cli import main


def _run(argv: list[str]) -> int:
    return main(["rolling-contact", *argv])


def test_line_against_hunter(capsys) -> None:
    # rigid roller (tungsten carbide stand-in: 620 GPa, far stiffer) on a PA6-like SLS
    rc = _run(["--line", "--radius", "50mm", "--load", "600N/mm", "--materials",
               "tungsten_carbide:E=1e15GPa,pmma", "--viscoelastic",
               "plate:Eg=3.2GPa:Er=1.6GPa:tau=4.48ms:nu=0.4", "--speed", "1", "--grid", "512",
               "--mu", "0.3",
               "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    cg, cr = (1 - 0.16) / 3.2e9, (1 - 0.16) / 1.6e9
    ref = hunter_cylinder(0.05, 6e5, cg, cr, 4.48e-3, 1.0)
    assert out["rolling_resistance_coefficient"]["value"] == pytest.approx(
        ref.rolling_resistance, rel=0.01)
    assert out["leading_edge"]["value"] == pytest.approx(ref.leading, rel=0.01)
    assert out["trailing_edge"]["value"] == pytest.approx(ref.trailing, rel=0.01)
    assert out["pmax"]["unit"] == "Pa" and out["load"]["unit"] == "N/m"


def test_line_tangential_contact_case2(capsys) -> None:
    # CONTACT visc_cylindr case 2 at its printed creepage: the force comes back at -0.6 mu N
    spec = "Eg=3200.4MPa:Er=1600.2MPa:tau=9ms:nu=0.4"
    rc = _run(["--line", "--radius", "50mm", "--load", "600N/mm", "--materials", "pmma,pmma",
               "--viscoelastic", f"ball:{spec}", "--viscoelastic", f"plate:{spec}",
               "--speed", "1", "--mu", "0.3", "--creepage", "1.365e-2", "--grid", "512",
               "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert out["fx"]["value"] / (0.3 * 6e5) == pytest.approx(-0.6, abs=0.01)
    assert out["creepage"]["unit"] == ""


def test_ball_runs_and_errors(capsys) -> None:
    rc = _run(["--radius", "20mm", "--load", "5N", "--materials", "steel,pmma",
               "--viscoelastic", "plate:Eg=3GPa:Er=1GPa:tau=1ms", "--speed", "0.1",
               "--grid", "48", "--mu", "0.3", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert out["rolling_resistance_coefficient"]["value"] > 0
    assert out["leading_edge"]["value"] > -out["trailing_edge"]["value"]
    assert math.isfinite(out["approach"]["value"])
    for bad, message in (("--speed=-1", "speed"), ("--speed=0", "speed")):
        rc = _run(["--radius", "20mm", "--load", "5N", "--materials", "steel,pmma", "--mu",
                   "0.3", "--viscoelastic", "plate:Eg=3GPa:Er=1GPa:tau=1ms", bad])
        err = capsys.readouterr().err
        assert rc == 1 and message in err and len(err.strip().splitlines()) == 1
    for spec, message in (("plate:Eg=1GPa:Er=3GPa:tau=1ms", "exceeds the glassy"),
                          ("plate:Eg=3GPa:Er=1GPa:tau=0s", "creep time")):
        rc = _run(["--radius", "20mm", "--load", "5N", "--materials", "steel,pmma", "--mu",
                   "0.3", "--viscoelastic", spec, "--speed", "0.1"])
        err = capsys.readouterr().err
        assert rc == 1 and message in err and len(err.strip().splitlines()) == 1


def test_ball_tangential_kalker_and_full_slip(capsys) -> None:
    # near-rigid ball on an incompressible SLS plate (nu = 0.5: K = 0, no coupling) in the
    # relaxed limit (V tau/a ~ 1e-10): full adhesion gives Kalker's C11 = 5.20 (Kalker
    # 1990, Table E.3, a/b = 1, nu = 0.5); a large creepage gives fx = -mu N
    base = ["--radius", "20mm", "--load", "5N", "--materials",
            "tungsten_carbide:E=1e15GPa,pmma", "--viscoelastic",
            "plate:Eg=3GPa:Er=1GPa:tau=1ns:nu=0.5", "--speed", "0.1", "--grid", "64",
            "--json"]
    assert _run([*base, "--mu", "1e4", "--creepage", "1e-5"]) == 0
    out = json.loads(capsys.readouterr().out)
    G = 2 * 1e9 / 3.0  # Kalker's combined modulus: 1/G = (1/G1 + 1/G2)/2, G1 -> inf
    a = (3 * 5.0 * 0.02 * (1 - 0.25) / (4 * 1e9)) ** (1 / 3)
    assert out["fx"]["unit"] == "N" and out["stick_area"]["unit"] == "m^2"
    assert -out["fx"]["value"] / (G * a * a * 1e-5) == pytest.approx(5.20, rel=0.03)
    assert out["slip_area"]["value"] == 0.0
    assert out["stick_area"]["value"] == pytest.approx(math.pi * a * a, rel=0.03)
    assert "3D" in out["model"] and "note" not in out
    assert _run([*base, "--mu", "0.3", "--creepage", "0.5"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["fx"]["value"] == pytest.approx(-0.3 * 5.0, rel=1e-3)
    assert out["stick_area"]["value"] == 0.0
    assert out["creepage"]["value"] == 0.5
