"""surfmet rolling --model viscoelastic|all: option parsing, units in JSON, bad input."""

from __future__ import annotations

import json

import pytest

from surfmet.cli import main


def test_viscoelastic_json_units(capsys) -> None:
    rc = main(["rolling", "--radius", "20mm", "--materials", "steel,pmma", "--loads",
               "1N:10N:3", "--model", "viscoelastic", "--viscoelastic",
               "plate:Eg=3GPa:Er=1GPa:tau=2ms", "--speed", "0.05", "--grid", "48", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "viscoelastic"
    assert out["moments"]["unit"] == "N m" and len(out["moments"]["value"]) == 3
    assert all(m > 0 for m in out["moments"]["value"])
    assert out["settings"]["speed"] == {"value": 0.05, "unit": "m/s"}


@pytest.mark.parametrize("spec, message", [
    ("plate:Eg=1GPa:Er=3GPa:tau=2ms", "exceeds the glassy"),
    ("plate:Eg=3GPa:Er=1GPa:tau=0", "creep time"),
    ("plate:Eg=3GPa:Er=1GPa:tau=-1s", "creep time"),
    ("table:Eg=3GPa:Er=1GPa:tau=1s", "ball or plate"),
    ("plate:Eg=3GPa:tau=1s", "missing"),
])
def test_bad_viscoelastic_input(spec: str, message: str, capsys) -> None:
    rc = main(["rolling", "--radius", "20mm", "--materials", "steel,pmma", "--loads",
               "1N:10N:3", "--model", "viscoelastic", "--viscoelastic", spec])
    err = capsys.readouterr().err
    assert rc != 0 and message in err and len(err.strip().splitlines()) == 1


def test_bad_speed(capsys) -> None:
    rc = main(["rolling", "--radius", "20mm", "--materials", "steel,pmma", "--loads",
               "1N:10N:3", "--model", "viscoelastic", "--loss", "0.01,0.05", "--speed", "0"])
    err = capsys.readouterr().err
    assert rc != 0 and "speed" in err and len(err.strip().splitlines()) == 1


def test_all_mechanisms_json(capsys) -> None:
    rc = main(["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
               "2N:12N:4", "--model", "all", "--grid", "64", "--no-microslip", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["mechanisms"]) >= {"viscoelastic", "hysteresis", "plastic"}
    ns, n1, n2 = out["rotor_loads"]["value"]
    assert min(n1, n2) < ns < max(n1, n2)
    assert 3.9 < min(n1, n2) < 4.0 and 5.3 < max(n1, n2) < 5.4  # the paper's 3.97-5.36 N
    # the rotor verdict's group offset, the same numbers as `surfmet rotor paper2022 --json`
    from surfmet.mechanics.rotor_verdict import paper_verdict
    from surfmet.records._rotor_verdict import offset_record

    v = paper_verdict()
    assert out["group_offset"] == json.loads(json.dumps(offset_record(v)))
    assert out["verdict"]["code"] == v.code
    for m in out["mechanisms"].values():
        assert m["raw_second_difference"]["unit"] == "N m"
    for m in out["mechanisms"].values():
        assert m["delta_eps"]["unit"] == "rad/s^2"
        assert m["delta_eps"]["value"] < 1e-3  # none comes near the measurement


def test_all_mechanisms_refuse_scans_they_would_ignore(capsys) -> None:
    rc = main(["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
               "2N:12N:4", "--model", "all", "--plate", "surfmet/data/paper_plate.x3p"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1 and "takes no scans" in err[0]


def test_all_mechanisms_adhesion_hysteresis(capsys) -> None:
    """The adhesion-hysteresis row: with the default w = Delta_w = 0.1 J/m^2 and with a
    given Delta_w, whose moment it scales in proportion (Kendall 1975: F_r = Delta_w 2a at
    a fixed JKR radius); a Delta_w above w is one line."""
    base = ["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
            "2N:12N:4", "--model", "all", "--grid", "32", "--no-microslip", "--json"]
    assert main(base) == 0
    full = json.loads(capsys.readouterr().out)["mechanisms"]["adhesion_hysteresis"]
    assert full["ranked"] is False and full["moments_at_rotor_loads"]["unit"] == "N m"
    assert main([*base, "--adhesion-hysteresis", "25mJ/m2"]) == 0
    out = json.loads(capsys.readouterr().out)
    quarter = out["mechanisms"]["adhesion_hysteresis"]
    for a, b in zip(quarter["moments_at_rotor_loads"]["value"],
                    full["moments_at_rotor_loads"]["value"]):
        assert a == pytest.approx(b / 4, rel=1e-12)
    assert out["mechanisms"]["hysteresis"]["ranked"] is True
    rc = main([*base, "--adhesion-hysteresis", "0.2J/m2"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1 and "hysteresis" in err[0]


def test_all_mechanisms_refuse_a_ball_that_is_not_the_rotors(capsys) -> None:
    """Issue 35 item 8: --model all sets the mechanisms beside the 20 mm rotor; a 10 mm ball
    would compare 10 mm contacts with it without a word."""
    rc = main(["rolling", "--radius", "10mm", "--materials", "steel,aluminium", "--loads",
               "2N:12N:4", "--model", "all", "--grid", "32", "--no-microslip"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1
    assert "10 mm contacts" in err[0] and "20 mm rotor" in err[0]


def test_all_mechanisms_say_that_loads_only_set_the_fit(capsys) -> None:
    """Issue 35 item 8: the moments are at the rotor's ball loads, not at --loads: said in
    the notes of the JSON and of the text."""
    base = ["rolling", "--radius", "20mm", "--materials", "steel,aluminium", "--loads",
            "1N:100N:3", "--model", "all", "--grid", "32", "--no-microslip"]
    assert main([*base, "--json"]) == 0
    notes = " ".join(json.loads(capsys.readouterr().out)["notes"])
    assert "--loads sweep (1-100 N, 3 loads)" in notes
    # the paper's loads: 2 x 4.67 N symmetric, 3.97 and 5.36 N asymmetric
    assert ("rotor's ball loads (symmetric 4.67 N; asymmetric 3.97 and 5.36 N), which "
            "--loads does not set") in notes
    assert main(base) == 0
    cap = capsys.readouterr()
    assert "which --loads does not set" in cap.out + cap.err
