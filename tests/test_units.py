"""Unit parsing at the edges, and JSON quantities."""

import json
import math

import numpy as np
import pytest

from surfmet import SurfmetInputError
from surfmet.units import (
    format_length,
    jsonable,
    length_factor,
    parse_force,
    parse_length,
    parse_length_range,
    parse_pressure,
    quantity,
)


@pytest.mark.parametrize(
    ("text", "metres"),
    [
        ("468um", 468e-6),
        ("468 µm", 468e-6),
        ("468μm", 468e-6),  # Greek mu
        ("0.5mm", 0.5e-3),
        ("20 mm", 0.02),
        ("312.5nm", 312.5e-9),
        ("2e-6", 2e-6),
        ("1.5m", 1.5),
        (".25um", 0.25e-6),
    ],
)
def test_parse_length(text, metres):
    assert parse_length(text) == pytest.approx(metres, rel=1e-15)


@pytest.mark.parametrize("text", ["", "abc", "12 furlongs", "5 N", "1e999mm", "nan"])
def test_parse_length_rejects(text):
    with pytest.raises(SurfmetInputError):
        parse_length(text)


def test_other_quantities():
    assert parse_force("500mN") == pytest.approx(0.5)
    assert parse_force("10") == 10.0
    assert parse_pressure("1.2GPa") == pytest.approx(1.2e9)
    assert parse_pressure("300 MPa") == pytest.approx(3e8)
    assert parse_length_range("468um:733um") == pytest.approx((468e-6, 733e-6))
    for bad in ("733um:468um", "1um", "a:b"):
        with pytest.raises(SurfmetInputError):
            parse_length_range(bad)


def test_header_unit_names():
    assert length_factor("micrometer") == 1e-6
    assert length_factor("Microns") == 1e-6
    assert length_factor("µm") == 1e-6
    assert length_factor("mm") == 1e-3
    with pytest.raises(SurfmetInputError):
        length_factor("rad")


def test_json_quantities():
    q = quantity(np.float32(1.5), "m")
    assert q == {"value": 1.5, "unit": "m"}
    assert quantity(float("nan"), "m")["value"] is None
    obj = jsonable({"a": np.arange(3), "b": (np.int64(2), math.inf), "c": b"x"})
    assert obj == {"a": [0, 1, 2], "b": [2, None], "c": "x"}
    json.dumps(obj, allow_nan=False)


def test_format_length():
    assert format_length(136e-6) == "136 µm"
    assert format_length(0.02) == "20 mm"
    assert format_length(float("nan")) == "n/a"


# issue 16, item 2: SI prefixes are case-sensitive (m = milli, M = mega)
@pytest.mark.parametrize(("text", "parse", "value"), [
    ("10mN", parse_force, 0.01), ("2kN", parse_force, 2e3), ("3 µN", parse_force, 3e-6),
    ("1MPa", parse_pressure, 1e6), ("1kPa", parse_pressure, 1e3),
    ("2 N/mm2", parse_pressure, 2e6), ("5mm", parse_length, 5e-3), ("2Å", parse_length, 2e-10),
])
def test_typed_units_are_exact(text, parse, value):
    assert parse(text) == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize(("text", "parse", "accepted"), [
    ("10MN", parse_force, "mN"),      # was read as 0.01 N
    ("10n", parse_force, "N"),
    ("1mPa", parse_pressure, "MPa"),  # was read as 1 MPa
    ("1gpa", parse_pressure, "GPa"),
    ("3Mm", parse_length, "mm"),      # megametres are not millimetres
    ("5 UM", parse_length, "um"),
])
def test_wrong_case_is_one_error_naming_the_accepted_units(text, parse, accepted):
    with pytest.raises(SurfmetInputError) as exc:
        parse(text)
    msg = str(exc.value)
    assert "case-sensitive" in msg and repr(accepted) in msg and "\n" not in msg


def test_unknown_unit_names_the_accepted_ones():
    with pytest.raises(SurfmetInputError) as exc:
        parse_force("4 furlong")
    assert "accepted: N, kN, mN" in str(exc.value)


def test_cli_refuses_a_load_in_meganewtons(capsys):
    from surfmet.cli import main

    rc = main(["contact", "--radius", "20mm", "--load", "10MN", "--materials",
               "steel,aluminium"])
    err = capsys.readouterr().err
    assert rc == 1 and "case-sensitive" in err and len(err.strip().splitlines()) == 1


# issue 25, item 19: one formatter for text, one unit vocabulary for JSON
@pytest.mark.parametrize(("value", "unit", "text"), [
    (2.03719e8, "Pa", "203.7 MPa"), (0.0037246e-6, "m", "3.725 nm"),
    (3.7267e-8, "m^2", "37267 µm²"), (2.7466e9, "1/m^2", "2747 1/mm²"),
    (5.44e6, "1/m", "5.44 1/µm"), (1.781e-10, "N", "0.1781 nN"), (0.2, "", "0.2"),
    (float("nan"), "Pa", "n/a"), (2e11, "Pa", "200 GPa"),
])
def test_format_quantity_reads_as_a_metrologist_writes(value, unit, text):
    from surfmet.units import format_quantity

    assert format_quantity(value, unit) == text


def test_json_units_share_one_vocabulary(capsys):
    """Every unit in the JSON of roughness, spectrum, contact and rolling-contact is
    spelled in the one ASCII vocabulary (``m^2``, ``1/m^2``, ``""`` for a ratio): no
    superscripts, no ``um``, no ``"1"`` (main: ``1/m²`` in roughness, ``1/m^2`` in
    spectrum, ``"1"`` and ``""`` side by side)."""
    import json

    from surfmet.cli import main

    plate = "surfmet/data/paper_plate.x3p"
    runs = [["roughness", plate, "--json"], ["spectrum", plate, "--json"],
            ["contact", "--radius", "20mm", "--load", "5N", "--materials",
             "steel,aluminium", "--grid", "32", "--json"],
            ["rolling-contact", "--radius", "20mm", "--load", "5N", "--materials",
             "steel,aluminium", "--mu", "0.3", "--grid", "16", "--json"]]
    units: set[str] = set()

    def collect(obj):
        if isinstance(obj, dict):
            if set(obj) >= {"value", "unit"} and isinstance(obj["unit"], str):
                units.add(obj["unit"])
            for v in obj.values():
                collect(v)
        elif isinstance(obj, list):
            for v in obj:
                collect(v)

    for argv in runs:
        assert main(argv) == 0, argv
        collect(json.loads(capsys.readouterr().out))
    assert {"m", "m^2", "1/m^2", "Pa", ""} <= units
    bad = {u for u in units if u == "1" or "um" in u or any(c in u for c in "²³⁻¹µ")}
    assert not bad, bad
