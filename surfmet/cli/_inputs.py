"""Every command states its inputs: :func:`surfmet.cli.build_parser` wraps each command's
``func`` (:func:`stating_inputs`) to run inside :func:`invocation`, so that its JSON
(:func:`surfmet.cli._common.emit_json`) carries an ``"inputs"`` record and its text ends
with the ``inputs`` lines (:mod:`surfmet.records.inputs`): no command can forget them,
and a new one states its inputs without a line of its own.
"""

from __future__ import annotations

import argparse
import functools
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

# The command being run: (its parser, its arguments, whether JSON went out). A stack, as
# a command may run another (``report`` the rotor), and the outer one is what was asked.
_RUNNING: list[dict[str, Any]] = []


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
    from surfmet.records.inputs import inputs_record

    state = _RUNNING[0]
    return inputs_record(state["parser"]._actions, state["args"])


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
    from surfmet.records.inputs import inputs_lines

    print("\n".join(inputs_lines(rec)), file=sys.stdout)
