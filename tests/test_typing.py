"""The facades' public signatures are typed: every scan, materials, spikes and loads
parameter has a real type (resolved from ``surfmet.mechanics._types`` as a type checker
resolves the ``TYPE_CHECKING`` imports), and the packages carry ``py.typed``."""

from __future__ import annotations

import importlib
import inspect
import typing

import pytest

FACADES = [
    ("ball_contact", "ball_contact"),
    ("hertz_check", "hertz_check"),
    ("flat_contact", "flat_contact"),
    ("rolling_resistance", "rolling_resistance"),
    ("spectrum", "spectrum"),
    ("adhesion", "adhesion"),
    ("adhesion_line", "line_adhesion"),
    ("rolling_contact", "solve_rolling_contact"),
    ("viscoelastic_rolling", "viscoelastic_rolling"),
    ("viscoelastic_rolling_contact", "viscoelastic_rolling_contact"),
    ("resolution_study", "contact_study"),
    ("resolution_study", "rolling_study"),
    ("scan_preparation", "prepare_scans"),
    ("material_spec", "material_pair"),
]
TYPED = {"plate", "ball", "scan", "topo", "materials", "spikes", "loads", "progress", "path"}


@pytest.mark.parametrize(("module", "name"), FACADES)
def test_facade_inputs_are_typed(module, name):
    mod = importlib.import_module(f"surfmet.mechanics.{module}")
    types = importlib.import_module("surfmet.mechanics._types")
    func = getattr(mod, name)
    hints = typing.get_type_hints(func, {**vars(types), **vars(mod)})
    loose = [p for p in inspect.signature(func).parameters
             if p in TYPED and hints.get(p, typing.Any) is typing.Any]
    assert loose == [], f"{module}.{name}: {loose} typed Any"
