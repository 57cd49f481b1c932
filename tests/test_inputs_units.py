"""Issue 34, items 10 and 13: every command states its inputs with their units, one rule
for bare numbers, one text formatter, one CSV header convention.

The truths are the documented readings (a bare length is metres; 20 mm = 0.02 m) and
hand conversions (820352 1/m² = 0.820352 1/mm²), not the code's own numbers."""

from __future__ import annotations

import argparse
import csv
import json

import numpy as np
import pytest

import surfmet
from surfmet._model import Topography
from surfmet.cli import main
from surfmet.units import split_quantity

SMOOTH = ["contact", "--load", "10N", "--materials", "steel,aluminium", "--grid", "32"]


@pytest.fixture
def scan(tmp_path):
    z = np.random.default_rng(3).standard_normal((48, 64)) * 1e-7
    return str(surfmet.write(Topography(z, 1e-6, 1e-6), tmp_path / "plate.npz"))


def test_bare_radius_is_metres_echoed_and_noted(capsys):
    """``--radius 20`` is a 20 m ball, as documented: the JSON and the text say so, and a
    note on stderr says how it was read (was: no radius anywhere in the output)."""
    assert main([*SMOOTH, "--radius", "20", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["inputs"]["radius"] == {"value": 20.0, "unit": "m"}
    assert "20 read as 20 m" in err and "20mm" in err
    assert main([*SMOOTH, "--radius", "20"]) == 0
    text = capsys.readouterr().out.split("\ninputs\n")[1]
    assert "radius" in text and "20 m\n" in text


def test_millimetres_raise_no_note(capsys):
    assert main([*SMOOTH, "--radius", "20mm", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["inputs"]["radius"] == {"value": pytest.approx(0.02), "unit": "m"}
    assert "read as" not in err


def test_text_inputs_give_materials_with_moduli_and_load(capsys):
    assert main(["contact", "--radius", "20mm", "--load", "500mN", "--grid", "32",
                 "--materials", "steel:E=200GPa:nu=0.29,aluminium:H=1.1GPa"]) == 0
    inputs = capsys.readouterr().out.split("\ninputs\n")[1]
    assert "steel (E 200 GPa, ν 0.29" in inputs
    assert "aluminium (E 70 GPa, ν 0.33, H 1.1 GPa)" in inputs  # the table's E, the given H
    assert "500 mN" in inputs and "20 mm" in inputs


@pytest.mark.parametrize("argv", [
    [*SMOOTH, "--radius", "20mm", "--hardness", "1"],  # was 1 Pa (steel:H=1 was refused)
    ["adhesion", "--radius", "10um", "--e-star", "1", "--work-of-adhesion", "50mJ/m2",
     "--range", "2nm"],  # was 1 Pa
    ["flat-contact", "{scan}", "--e-star", "1GPa", "--pressures", "1000000"],  # was 1 MPa
])
def test_a_pressure_needs_its_unit_everywhere(argv, scan, capsys):
    """One rule: a typed pressure (modulus, hardness, applied pressure) needs its unit, in
    an option as in a material spec (was: --hardness 1 read as 1 Pa, steel:H=1 refused)."""
    assert main([a.format(scan=scan) for a in argv]) == 1
    err = capsys.readouterr().err
    assert "has no unit" in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize(("argv", "shown"), [
    ([*SMOOTH, "--radius", "20mm"], ["20 mm", "10 N", "steel (E 210 GPa"]),
    (["info", "{scan}"], ["{scan}"]),
    (["spectrum", "{scan}", "--materials", "steel"], ["{scan}", "steel (E 210 GPa"]),
    (["roughness", "{scan}", "--lc", "20um"], ["{scan}", "20 µm"]),
    (["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion", "50mJ/m2",
      "--range", "2nm", "--grid", "32", "--steps", "8", "--quiet"],
     ["10 µm", "1 GPa", "50 mJ/m²", "2 nm"]),
    (["rolling-contact", "--radius", "20mm", "--load", "5N", "--materials", "steel,aluminium",
      "--mu", "0.3", "--grid", "16"], ["20 mm", "5 N", "0.3"]),
])
def test_every_text_output_ends_with_its_inputs(argv, shown, scan, capsys):
    assert main([a.format(scan=scan) for a in argv]) == 0
    out = capsys.readouterr().out
    assert "\ninputs\n" in out
    tail = out.split("\ninputs\n")[1]
    for text in shown:
        assert text.format(scan=scan) in tail, text


def test_inputs_record_reads_units_from_the_parsers():
    """Lists, ranges and values the command parses itself, each with its unit."""
    from surfmet.cli._common import force, positive_length
    from surfmet.cli._inputs import command_inputs
    from surfmet.cli._values import loads
    from surfmet.records._inputs import inputs_lines

    p = argparse.ArgumentParser()
    p.add_argument("--radius", type=positive_length)
    p.add_argument("--loads", type=loads)  # the commands' list-or-range type
    p.add_argument("--load")  # parsed later by its command, as rolling-contact's
    p.add_argument("--pressures")
    p.add_argument("--f", type=force)
    p.add_argument("--json", action="store_true")
    args = p.parse_args(["--radius", "5mm", "--loads", "1N:3N:3", "--load", "250mN",
                         "--pressures", "1MPa,2MPa", "--json"])
    rec = command_inputs(p._actions, args)
    assert rec["radius"] == {"value": pytest.approx(5e-3), "unit": "m"}
    assert rec["loads"] == {"value": pytest.approx([1.0, 3.0 ** 0.5, 3.0]), "unit": "N"}
    assert rec["load"] == {"value": pytest.approx(0.25), "unit": "N"}
    assert rec["pressures"] == {"value": [1e6, 2e6], "unit": "Pa"}
    assert "f" not in rec and "json" not in rec  # unset, and not an input
    assert "  loads              1 N, 1.73205 N, 3 N" in inputs_lines(rec)
    p.add_argument("--line", action="store_true")  # rolling-contact's load per length
    rec = command_inputs(p._actions, p.parse_args(["--line", "--load", "100N/mm"]))
    assert rec["load_per_length"] == {"value": pytest.approx(1e5), "unit": "N/m"}


def test_every_type_unit_names_a_type_the_commands_use():
    """TYPE_UNITS is looked up by an argparse type's ``__name__``: a key that no option of
    any command has as its type is dead data (it held "load range" and "energy", types
    that no longer exist)."""
    from surfmet.cli import build_parser
    from surfmet.cli._inputs import TYPE_UNITS

    sub = next(a for a in build_parser()._actions
               if isinstance(a, argparse._SubParsersAction))
    used = {getattr(a.type, "__name__", None) for parser in sub.choices.values()
            for a in parser._actions if a.type is not None}
    assert sorted(set(TYPE_UNITS) - used) == []


@pytest.mark.parametrize(("value", "unit", "shown"), [
    (820352.0, "1/m^2", ("0.8204", "1/mm²")),  # plu-1's Spd, was "820352 1/m²"
    (12758.0, "1/m", ("0.01276", "1/µm")),  # plu-1's Spc, was "12.758 1/mm"
    (3.0e3, "1/m", ("0.003", "1/µm")),  # was "3 1/mm"
])
def test_densities_and_curvatures_keep_one_display_unit(value, unit, shown):
    assert split_quantity(value, unit) == shown


def test_roughness_text_states_spd_in_one_unit(realdata, capsys):
    """The same quantity in the same unit whatever the scan (was 1/m² for plu-1, 1/mm²
    for mi-1)."""
    units = set()
    for name in ("plu-1.plu", "mi-1.mi"):
        assert main(["roughness", str(realdata(name))]) == 0
        line = next(s for s in capsys.readouterr().out.splitlines()
                    if s.strip().startswith("Spd"))
        units.add(line.split()[-1])
    assert units == {"1/mm²"}


def test_csv_headers_are_name_and_unit_in_brackets(scan, tmp_path, capsys):
    """One CSV convention: ``roughness`` wrote ``Sa_m``/``lc_m`` while ``sweep`` writes
    ``load [N]``; now both are ``NAME [UNIT]`` with the JSON unit."""
    from surfmet.units import JSON_UNITS, csv_column

    out = tmp_path / "r.csv"
    assert main(["roughness", scan, "--csv", str(out)]) == 0
    header = next(csv.reader(out.open(encoding="utf-8")))
    assert "Sa [m]" in header and "lc [m]" in header and "Sdr [%]" in header
    assert "Ssk" in header  # dimensionless: the name alone
    assert not [h for h in header if h.endswith("_m")]
    for h in header:
        if "[" in h:
            assert h[h.index("[") + 1:-1] in JSON_UNITS, h
    from surfmet.sweep import columns

    assert csv_column("load", "N") in [csv_column(n, u) for n, u in columns("contact")]


def test_text_spells_micro_and_powers(scan, tmp_path, capsys):
    """µN, µm and rad/s² in text (was uN in adhesion, 'gap (um)' in flat-contact,
    'rad/s2' beside 'rad/s²' in rotor)."""
    assert main(["adhesion", "--radius", "10um", "--e-star", "1GPa", "--work-of-adhesion",
                 "50mJ/m2", "--range", "2nm", "--grid", "32", "--steps", "8", "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "µN" in text and "uN" not in text and "m^2" not in text
    assert main(["flat-contact", scan, "--e-star", "1GPa", "--pressures", "1MPa",
                 "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "gap (µm)" in text and "(um)" not in text and "MPa/um" not in text
    k = np.arange(1, 13)
    frames = np.rint(120 * np.sqrt((k - 1) * np.pi / 3.0)).astype(int)
    tsv = tmp_path / "frames.tsv"
    tsv.write_text("k\tas1\n" + "".join(f"{a}\t{b}\n" for a, b in zip(k, frames)))
    assert main(["rotor", str(tsv), "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "rad/s²" in text and "rad/s2" not in text and "^2" not in text


def test_info_of_every_real_file_states_units_of_the_vocabulary(realdata, capsys):
    """File metadata in the same vocabulary (was opdx-3's "µm" and "mg" settings as read):
    a setting with a length is in metres (the file's 50 µm scan length = 5e-5 m), one in
    a unit outside the vocabulary is the instrument's words."""
    from test_cli_conventions import _units

    from surfmet.units import JSON_UNITS

    folder = realdata("MANIFEST.tsv").parent
    for path in sorted(p for p in folder.iterdir() if p.name != "MANIFEST.tsv"):
        if main(["info", str(path), "--json"]) != 0:
            capsys.readouterr()
            continue
        doc = json.loads(capsys.readouterr().out)
        bad = {u for _, u in _units(doc) if u not in JSON_UNITS}
        assert not bad, (path.name, bad)
        if path.name == "opdx-3.opdx":
            settings = doc["metadata"]["measurement_settings"]
            assert settings["ScanLength"] == {"value": pytest.approx(50e-6), "unit": "m"}
            assert settings["StylusForce"] == "3 mg"
