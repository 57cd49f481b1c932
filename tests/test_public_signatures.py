"""The contact engine's public faces take at most 8 parameters, and solve_normal takes a
Grid and SolveOptions (issue 37, item 4).

The same nine or ten solver settings used to be declared again at every level of the
ball-on-plate path (the facade 17, ``SphereContact.solve`` 13, ``solve_normal`` 21); they
now travel as one :class:`contact.SolveOptions` (and the domain as one
:class:`contact.DomainSpec`, a sweep's dissipation model as one
:class:`contact.Dissipation`).
"""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import math
import types

import numpy as np
import pytest

import contact

#: Most parameters of a public function or method (``self`` and ``cls`` not counted).
MOST = 8


def _faces() -> list[types.ModuleType]:
    """contact and its rooms, the rotor excepted (an engine of its own, issue 37 item 6)."""
    rooms = [importlib.import_module(f"contact.{name}") for name in contact.SUBPACKAGES
             if name != "rotor"]
    return [contact, *rooms]


def _written(cls: type, name: str) -> bool:
    """A method written in the class itself (not a dataclass's generated ``__init__``:
    the fields of a value object are its attributes, not a function's parameters)."""
    f = vars(cls).get(name)
    if isinstance(f, (staticmethod, classmethod)):
        f = f.__func__
    code = getattr(f, "__code__", None)
    return inspect.isfunction(f) and code is not None and not code.co_filename.startswith("<")


def _callables() -> dict[str, object]:
    """Every public function and public (or __init__) method of the faces' ``__all__``."""
    out: dict[str, object] = {}
    for face in _faces():
        for name in face.__all__:
            obj = getattr(face, name)
            if isinstance(obj, types.ModuleType) or not callable(obj):
                continue
            if getattr(obj, "__module__", "").startswith("contact.rotor"):
                continue
            if inspect.isclass(obj):
                for meth in vars(obj):
                    if (meth == "__init__" or not meth.startswith("_")) and _written(obj, meth):
                        f = vars(obj)[meth]
                        out[f"{obj.__module__}.{obj.__qualname__}.{meth}"] = getattr(
                            f, "__func__", f)
            elif inspect.isfunction(obj):
                out[f"{obj.__module__}.{obj.__qualname__}"] = obj
    return out


def _count(f: object) -> int:
    return sum(p.name not in ("self", "cls") for p in inspect.signature(f).parameters.values())


def test_no_public_function_of_contact_takes_more_than_eight_parameters():
    names = _callables()
    # the walk sees the solvers and the set-ups (on main: 21, 11, 13, 17 and 11 parameters)
    for expected in ("contact.bem._solver.solve_normal",
                     "contact.setups._ball_on_plate.solve_sphere",
                     "contact.setups._ball_on_plate.SphereContact.solve",
                     "contact._rolling.sphere_sweep", "contact._geometry.auto_domain"):
        assert expected in names
    assert len(names) > 60
    over = {name: _count(f) for name, f in names.items() if _count(f) > MOST}
    assert over == {}, f"public functions over {MOST} parameters: {over}"


def test_solve_normal_takes_a_grid_and_options_and_gives_the_hertz_peak_pressure():
    """A paraboloid gap h = r^2/(2R) at load W: the Hertz peak pressure
    p0 = (6 W E*^2 / (pi^3 R^2))^(1/3) (Johnson 1985, eq. 4.23)."""
    from contact import SolveOptions, solve_normal
    from contact._grid import centred_grid

    radius, load, e_star = 0.02, 10.0, 58.6e9
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    n, dx = 256, 2.5 * a / 128
    grid = centred_grid(n, dx)
    grid = grid.with_gap((grid.x[None, :] ** 2 + grid.y[:, None] ** 2) / (2 * radius))
    options = SolveOptions(tol=1e-8, precision="double")
    res = solve_normal(grid, e_star=e_star, load=load, options=options)
    p0 = (6 * load * e_star**2 / (math.pi**3 * radius**2)) ** (1 / 3)
    assert res.pmax == pytest.approx(p0, rel=2e-3)
    assert res.load == pytest.approx(load, rel=1e-10)
    assert res.solve.tolerance == 1e-8
    np.testing.assert_array_equal(np.asarray(res.x), grid.x)  # the grid's own coordinates


def test_solve_options_are_checked_and_derived():
    from contact import ContactInputError, SolveOptions, solve_normal
    from contact._grid import gap_grid

    with pytest.raises(ContactInputError, match="precision"):
        SolveOptions(precision="single")
    with pytest.raises(ContactInputError, match="tolerance"):
        SolveOptions(tol=0.0)
    loose = SolveOptions(tol=1e-4)
    assert loose.but(edge="ignore") == SolveOptions(tol=1e-4, edge="ignore")
    assert dataclasses.replace(loose) == loose
    with pytest.raises(ContactInputError, match="gap_grid"):
        solve_normal(np.zeros((8, 8)), e_star=1e9, load=1.0)
    with pytest.raises(ContactInputError, match="SolveOptions"):
        solve_normal(gap_grid(np.zeros((8, 8)), 1e-6), e_star=1e9, load=1.0, options={})
