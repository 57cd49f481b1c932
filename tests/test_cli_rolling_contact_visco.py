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
    assert out["creepage"]["unit"] == "1"


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
