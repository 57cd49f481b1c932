"""rolling-contact --viscoelastic: the reported values against Hunter's closed form and
CONTACT's visc_cylindr numbers, units in JSON, one-line errors."""

from __future__ import annotations

import json
import math

import pytest

from contact.viscoelastic._hunter import hunter_cylinder
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
    assert out["creepage"]["unit"] == ""  # as the elastic record writes a ratio


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


_FREE = ["--radius", "20mm", "--load", "5N", "--materials", "steel,pmma", "--mu", "0.3",
         "--viscoelastic", "plate:Eg=3GPa:Er=1GPa:tau=1ms", "--speed", "0.1", "--grid", "32"]


def test_free_rolling_of_a_dissimilar_ball_is_coupled(capsys) -> None:
    # issue 34 item 9: steel on PMMA printed creepage 0, slip area 0 (the uncoupled q = 0)
    # where the elastic run gives 8.9e-4. In the relaxed limit (V tau << a) the
    # viscoelastic free rolling is the elastic one of the relaxed modulus: the elastic
    # command (two-way coupled, its own grid) is the truth, to its 1 % grid spread
    base = ["--radius", "20mm", "--load", "5N", "--mu", "0.3", "--grid", "128", "--json"]
    assert _run([*base, "--materials", "steel,pmma", "--viscoelastic",
                 "plate:Eg=3GPa:Er=1GPa:tau=1ns", "--speed", "0.1"]) == 0
    visco = json.loads(capsys.readouterr().out)
    assert _run([*base, "--materials", "steel,pmma:E=1GPa"]) == 0
    elastic = json.loads(capsys.readouterr().out)
    assert visco["tangential"]["solved"] is True and visco["free_rolling"] is True
    assert visco["creepage"]["value"] == pytest.approx(elastic["creepage"]["value"], rel=0.02)
    assert visco["slip_area"]["value"] > 0 and visco["stick_area"]["value"] > 0
    assert any("coupling one way" in n for n in visco["notes"])
    g1, nu1 = 210e9 / 2.6, 0.3  # steel
    g2, nu2 = 1e9 / 2.74, 0.37  # the plate, relaxed (pmma: nu 0.37)
    k = 0.25 * 2 / (1 / g1 + 1 / g2) * ((1 - 2 * nu1) / g1 - (1 - 2 * nu2) / g2)
    assert visco["kalker_K_relaxed"] == pytest.approx(k, rel=0.05)


def test_free_rolling_of_a_dissimilar_roller_is_not_solved(capsys) -> None:
    # plane strain has no coupled viscoelastic solve: in free rolling the coupling is the
    # only driver of the tractions, so the uncoupled q = 0 is no answer; it is said, and
    # no zeros are printed as results
    line = ["--line", "--radius", "25mm", "--load", "100N/mm", "--materials", "steel,pmma",
            "--mu", "0.3", "--viscoelastic", "plate:Eg=3GPa:Er=1GPa:tau=1ms", "--speed",
            "0.1", "--grid", "128"]
    assert _run([*line, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for key in ("creepage", "fx", "fy", "stick_area", "slip_area", "frictional_power"):
        assert key not in out
    assert out["tangential"]["solved"] is False
    assert any("not solved" in n and "coupling" in n for n in out["notes"])
    assert _run(line) == 0
    text = capsys.readouterr().out
    assert "not solved" in text
    assert not any(ln.split()[:1] == ["creepage"] for ln in text.splitlines())


def test_same_layout_as_the_elastic_record(capsys) -> None:
    # one vocabulary: the keys, units, grid record and sign convention of the elastic
    # command's record, and its text layout (grid line, quantity names)
    from surfmet.mechanics.rolling_contact import SIGN_CONVENTION

    assert _run([*_FREE, "--creepage", "1e-3", "--json"]) == 0
    visco = json.loads(capsys.readouterr().out)
    assert _run(["--radius", "20mm", "--load", "5N", "--materials", "steel,pmma", "--mu",
                 "0.3", "--creepage", "1e-3", "--grid", "32", "--json"]) == 0
    elastic = json.loads(capsys.readouterr().out)
    assert visco["sign_convention"] == elastic["sign_convention"] == SIGN_CONVENTION
    assert visco["grid"]["elements"] == 32
    assert set(visco["grid"]) == set(elastic["grid"])
    shared = ("creepage", "fx", "fy", "pmax", "approach", "contact_area", "stick_area",
              "slip_area", "frictional_power", "rolling_resistance_coefficient", "load",
              "radius", "free_rolling", "geometry", "solve")
    for key in shared:
        assert key in visco and key in elastic, key
        if isinstance(elastic[key], dict) and "unit" in elastic[key]:
            assert visco[key]["unit"] == elastic[key]["unit"], key
    assert any("coupling one way" in n for n in visco["notes"])
    assert _run([*_FREE, "--creepage", "1e-3"]) == 0
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    names = [ln.split()[0] for ln in lines[1:] if ln.startswith("  ") and "note" not in ln]
    assert {"creepage", "fx", "stick_area", "slip_area", "pmax", "grid"} <= set(names)
    assert any(ln.split()[0] == "grid" and "32 x 32 elements" in ln for ln in lines[1:])
    assert f"sign convention: {SIGN_CONVENTION}" in captured.err
