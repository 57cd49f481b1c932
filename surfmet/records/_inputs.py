"""The inputs of a command, stated with their units: the ``"inputs"`` record of every
command's JSON and the ``inputs`` lines of its text.

A command's result is only as good as what it was given: ``contact --radius 20`` solves a
20 m ball (a bare number is metres), and a reader who cannot see the radius cannot catch
it. So every command echoes every input it used, in SI with its unit (JSON) and through
:func:`surfmet.units.format_quantity` (text): the options as parsed (defaults included),
the files, and each material with the moduli and hardness it stands for. Which options a
command has and their units is the command line's knowledge
(:mod:`surfmet.cli._inputs`); this module builds the record from plain values.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from surfmet.units import format_quantity, quantity, valid_text


def _value(value: Any, unit: str | None) -> Any:
    """One input as JSON: a quantity where it has a unit, else the plain value. Integers
    are counts (``show --size 1200x900`` pixels), never quantities."""
    flat = value if isinstance(value, (list, tuple)) else [value]
    if (unit is None or isinstance(value, (str, bool)) or value is None
            or all(isinstance(v, int) and not isinstance(v, bool) for v in flat)):
        return list(value) if isinstance(value, tuple) else value
    if isinstance(value, (list, tuple)):
        return quantity([list(v) if isinstance(v, tuple) else v for v in value], unit)
    return quantity(value, unit)


def material_inputs(text: str) -> list[dict[str, Any]]:
    """Each body of a ``--materials`` text with the constants it stands for (the table's,
    or those given), parsed by :func:`surfmet.mechanics.material_spec.parse_material`."""
    from surfmet.mechanics.material_spec import parse_material

    out = []
    for part in (s for s in str(text).split(",") if s.strip()):
        m = parse_material(part.strip())
        out.append({"name": m.name, "E": quantity(m.E, "Pa"), "nu": quantity(m.nu, ""),
                    "hardness": quantity(m.hardness, "Pa"), "source": m.source})
    return out


def inputs_record(values: Iterable[tuple[str, Any, str | None]]) -> dict[str, Any]:
    """The ``"inputs"`` record of a command from its ``(name, value, unit)`` triples (SI
    values; ``unit`` None for a value without one): each quantity as ``{"value", "unit"}``,
    ``materials`` (``"BALL,PLATE"`` text, or a list of them) with their moduli and
    hardness, unset (None) values left out."""
    rec: dict[str, Any] = {}
    for name, value, unit in values:
        if value is None:
            continue
        if name == "materials":  # one pair, or a sweep's list of pairs
            rec[name] = ([material_inputs(v) for v in value] if isinstance(value, list)
                         else material_inputs(value))
            continue
        rec[name] = _value(value, unit)
    return rec


def _text(value: Any) -> str:
    if isinstance(value, dict) and "unit" in value:
        v, unit = value["value"], value["unit"]
        if isinstance(v, list):
            return ", ".join(_text({"value": x, "unit": unit}) for x in v)
        if v is None:
            return "n/a"
        if unit == "":
            return f"{v:.6g}"
        if unit == "rad":  # an angle reads in degrees, as one is given (30deg); SI in JSON
            return f"{math.degrees(v):.6g}°"
        return format_quantity(v, unit, 6)
    if isinstance(value, list):
        return ", ".join(_text(v) for v in value)
    if isinstance(value, float):
        return f"{value:.6g}"
    return valid_text(str(value))  # a file name's undecodable bytes as \xNN


def material_text(m: dict[str, Any]) -> str:
    """``steel (E 210 GPa, ν 0.3, H 2.1 GPa)``: a body as :func:`material_inputs` gives it."""
    hard = "" if m["hardness"]["value"] is None else f", H {_text(m['hardness'])}"
    return f"{m['name']} (E {_text(m['E'])}, ν {_text(m['nu'])}{hard})"


def inputs_lines(record: dict[str, Any]) -> list[str]:
    """The text of an ``"inputs"`` record: a heading and one line per input, the label
    padded as in the commands' tables; flags that are off are left out."""
    lines = ["inputs"]
    for name, value in record.items():
        if value is False:
            continue
        if name == "materials":
            pairs = value if value and isinstance(value[0], list) else [value]
            shown = "; ".join(", ".join(material_text(m) for m in pair) for pair in pairs)
        elif value is True:
            shown = "yes"
        else:
            shown = _text(value)
        lines.append(f"  {name.replace('_', ' '):18s} {shown}")
    return lines
