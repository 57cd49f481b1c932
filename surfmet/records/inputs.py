"""The inputs of a command, stated with their units: the ``"inputs"`` record of every
command's JSON and the ``inputs`` lines of its text.

A command's result is only as good as what it was given: ``contact --radius 20`` solves a
20 m ball (a bare number is metres), and a reader who cannot see the radius cannot catch
it. So every command echoes every input it used, in SI with its unit (JSON) and through
:func:`surfmet.units.format_quantity` (text): the options as parsed (defaults included),
the files, and each material with the moduli and hardness it stands for.

The unit of an option is that of its parser (:data:`TYPE_UNITS`, by the argparse type's
name) or, for an option parsed later by its command, of its name (:data:`OPTION_UNITS`).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from surfmet.units import format_quantity, quantity

#: Unit of the value an argparse type returns, by the type's ``__name__``.
TYPE_UNITS: dict[str, str] = {
    "length": "m", "positive_length": "m", "force": "N", "load range": "N",
    "pressure": "Pa", "speed": "m/s", "work": "J/m^2", "energy": "J/m^2",
}

#: Unit of an option's value by its name, for options whose text the command parses
#: itself (``--pressures``, ``rolling-contact --load``) or whose type has its own name.
OPTION_UNITS: dict[str, str] = {
    "radius": "m", "size": "m", "range": "m", "tip_radius": "m", "ls": "m", "lc": "m",
    "positions": "m", "load": "N", "loads": "N", "hardness": "Pa", "e_star": "Pa",
    "pressures": "Pa", "speed": "m/s", "work_of_adhesion": "J/m^2",
    "adhesion_hysteresis": "J/m^2", "mu": "", "creepage": "", "traction_ratio": "",
    "alpha_h": "", "tol": "", "exaggeration": "", "pixel": "m", "dx": "m", "dy": "m",
    "fps": "1/s", "step_deg": "°",
}

#: Options that say where the output goes or how the run is shown, not what it computes.
NOT_INPUTS = frozenset({"help", "func", "command", "json", "quiet", "out", "output", "plot",
                        "csv", "resume", "workers", "scheduler", "version"})


def _name(action: Any) -> str:
    """The input's name: the long option without dashes (``--e-star`` -> ``e_star``), or
    a positional's dest."""
    longs = [s for s in action.option_strings if s.startswith("--")]
    return (longs[0][2:] if longs else action.dest).replace("-", "_").strip("_")


def _unit(action: Any, name: str) -> str | None:
    tname = getattr(action.type, "__name__", None)
    return TYPE_UNITS.get(tname or "", OPTION_UNITS.get(name))


def _parse_text(name: str, text: str) -> Any:
    """An option's text that its command parses itself, parsed by the same function, or
    the text unchanged where it is not a quantity (``--lc none``)."""
    from surfmet.errors import SurfmetInputError
    from surfmet.units import parse_force, parse_length, parse_pressure, parse_speed

    parsers = {"m": parse_length, "N": parse_force, "m/s": parse_speed}
    try:
        if name == "pressures":
            from surfmet.mechanics.flat_contact import parse_pressures

            return [float(p) for p in parse_pressures(text)]
        unit = OPTION_UNITS.get(name)
        if unit == "Pa":
            return parse_pressure(text)
        if unit in parsers:
            return parsers[unit](text)
    except (SurfmetInputError, ValueError):
        pass
    return text


def _value(value: Any, unit: str | None) -> Any:
    """One input as JSON: a quantity where it has a unit, else the plain value. Integers
    are counts (``show --size 1200x900`` pixels), never quantities."""
    flat = value if isinstance(value, (list, tuple)) else [value]
    if (unit is None or isinstance(value, (str, bool)) or value is None
            or all(isinstance(v, int) and not isinstance(v, bool) for v in flat)):
        return list(value) if isinstance(value, tuple) else value
    if isinstance(value, tuple) and len(value) == 3 and (
            value[2] is None or isinstance(value[2], int)):  # F1:F2[:N]
        return {"start": quantity(value[0], unit), "stop": quantity(value[1], unit),
                "points": value[2]}
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


def inputs_record(actions: Iterable[Any], args: Any
                  ) -> dict[str, Any]:
    """The ``"inputs"`` record of a command: every option and positional it was run with
    (defaults included; unset options left out), each quantity as ``{"value", "unit"}``
    in SI, and ``materials`` with their moduli and hardness.

    Parameters
    ----------
    actions : iterable of argparse.Action
        The command's parser actions (``parser._actions``).
    args : argparse.Namespace
        The parsed arguments.
    """
    rec: dict[str, Any] = {}
    for action in actions:
        name = _name(action)
        if name in NOT_INPUTS or action.dest in NOT_INPUTS or not hasattr(args, action.dest):
            continue
        value = getattr(args, action.dest)
        if value is None:
            continue
        if name == "materials":  # one pair, or a sweep's list of pairs
            rec[name] = ([material_inputs(v) for v in value] if isinstance(value, list)
                         else material_inputs(value))
            continue
        if isinstance(value, str) and name in OPTION_UNITS:
            value = _parse_text(name, value)
        rec[name] = _value(value, _unit(action, name))
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
        return format_quantity(v, unit, 6)
    if isinstance(value, dict) and "start" in value:
        n = value["points"]
        return (f"{_text(value['start'])} to {_text(value['stop'])}"
                + (f", {n} points" if n else ""))
    if isinstance(value, list):
        return ", ".join(_text(v) for v in value)
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


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
