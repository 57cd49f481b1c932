"""Every command states its inputs: :func:`surfmet.cli.build_parser` wraps each command's
``func`` (:func:`stating_inputs`) to run inside :func:`invocation`, so that its JSON
(:func:`surfmet.cli._common.emit_json`) carries an ``"inputs"`` record and its text ends
with the ``inputs`` lines (:mod:`surfmet.records._inputs`): no command can forget them,
and a new one states its inputs without a line of its own.
"""

from __future__ import annotations

import argparse
import functools
import sys
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from typing import Any

# The command being run: (its parser, its arguments, whether JSON went out). A stack, as
# a command may run another (``report`` the rotor), and the outer one is what was asked.
_RUNNING: list[dict[str, Any]] = []


#: Unit of the value an argparse type returns, by the type's ``__name__``.
TYPE_UNITS: dict[str, str] = {
    "length": "m", "positive_length": "m", "force": "N", "pressure": "Pa", "speed": "m/s",
    "work": "J/m^2", "surface tension": "N/m", "angle": "rad",
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


def _name(action: argparse.Action) -> str:
    """The input's name: the long option without dashes (``--e-star`` -> ``e_star``), or
    a positional's dest."""
    longs = [s for s in action.option_strings if s.startswith("--")]
    return (longs[0][2:] if longs else action.dest).replace("-", "_").strip("_")


def _unit(action: argparse.Action, name: str) -> str | None:
    tname = getattr(action.type, "__name__", None)
    return TYPE_UNITS.get(tname or "", OPTION_UNITS.get(name))


def _parse_text(name: str, text: str) -> Any:
    """An option's text that its command parses itself, parsed by the same function, or
    the text unchanged where it is not a quantity (``--lc none``)."""
    from surfmet._errors import SurfmetInputError
    from surfmet.units import parse_force, parse_length, parse_pressure, parse_speed

    parsers = {"m": parse_length, "N": parse_force, "m/s": parse_speed}
    try:
        if name == "line_load":
            from surfmet.mechanics.rolling_contact import parse_line_load

            return parse_line_load(text)
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


def command_inputs(actions: Iterable[argparse.Action], args: argparse.Namespace
                   ) -> dict[str, Any]:
    """The ``"inputs"`` record (:func:`surfmet.records._inputs.inputs_record`) of a command
    run with ``args``: every option and positional of its parser (``actions``) but those
    of :data:`NOT_INPUTS`, defaults included, each with the unit of its parser."""
    from surfmet.records._inputs import inputs_record

    def triples() -> Iterator[tuple[str, Any, str | None]]:
        for action in actions:
            name = _name(action)
            if name in NOT_INPUTS or action.dest in NOT_INPUTS:
                continue
            value, unit = getattr(args, action.dest, None), _unit(action, name)
            if hasattr(value, "calibration") and hasattr(value, "metadata"):
                # a body read in place (read_bodies): the file the user named
                value = value.metadata.get("source") or value.metadata.get("container")
            if name == "load" and getattr(args, "line", False) is True:
                name, unit = "load_per_length", "N/m"  # rolling-contact --line 100N/mm
                value = _parse_text("line_load", value) if isinstance(value, str) else value
            elif isinstance(value, str) and name in OPTION_UNITS:
                value = _parse_text(name, value)
            yield name, value, unit

    return inputs_record(triples())


def stating_inputs(parser: argparse.ArgumentParser | None) -> None:
    """Make the command of ``parser`` (its ``func`` default) run inside
    :func:`invocation` and end its text with its inputs when it succeeds."""
    func = parser.get_default("func") if parser is not None else None
    if func is None or getattr(func, "states_inputs", False):
        return

    @functools.wraps(func)
    def run(args: argparse.Namespace) -> Any:
        with invocation(parser, args) as state:
            rc = func(args)
            if not rc:  # every command ends its text with what it was given
                print_text(state)
        return rc

    run.states_inputs = True  # type: ignore[attr-defined]
    parser.set_defaults(func=run)


@contextmanager
def invocation(parser: argparse.ArgumentParser | None,
               args: argparse.Namespace) -> Iterator[dict[str, Any]]:
    """Run a command's ``func`` inside this, with its own parser."""
    state = {"parser": parser, "args": args, "json": False}
    _RUNNING.append(state)
    try:
        yield state
    finally:
        _RUNNING.remove(state)


def current_inputs() -> dict[str, Any] | None:
    """The ``"inputs"`` record of the command being run (None outside one)."""
    if not _RUNNING or _RUNNING[0]["parser"] is None:
        return None
    state = _RUNNING[0]
    return command_inputs(state["parser"]._actions, state["args"])


def attach(obj: Any) -> Any:
    """``obj`` (a command's JSON) with the ``"inputs"`` of the command being run: a record
    gets the key, a list of records (``roughness``) each record."""
    rec = current_inputs()
    if _RUNNING:
        _RUNNING[0]["json"] = True
    if not rec:
        return obj
    if isinstance(obj, dict):
        return {**obj, "inputs": obj.get("inputs", rec)}
    if isinstance(obj, list) and obj and all(isinstance(o, dict) for o in obj):
        # each record names its own file: the others' names are not its inputs
        rec = {k: v for k, v in rec.items() if k != "files"}
        return [{**o, "inputs": o.get("inputs", rec)} for o in obj]
    return obj


def print_text(state: dict[str, Any]) -> None:
    """The ``inputs`` lines at the end of a command's text, unless stdout carried JSON or
    CSV (``--csv -``), where text would spoil it."""
    args = state["args"]
    on_stdout = (True, "-")  # --json is a flag, or sweep's path ("-" for stdout)
    if (state["json"] or getattr(args, "json", None) in on_stdout
            or getattr(args, "csv", None) == "-"):
        return
    rec = current_inputs()
    if not rec:
        return
    from surfmet.records._inputs import inputs_lines

    print("\n".join(inputs_lines(rec)), file=sys.stdout)
