"""Bad input and non-convergence: clear errors, never a silent wrong answer."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact import (
    ContactInputError,
    ConvergenceError,
    DomainSpec,
    PressureBounds,
    SolveOptions,
    composite_modulus,
    hertz_sphere,
    material,
    solve_sphere,
)
from contact._geometry import sphere_gap
from contact._grid import gap_grid
from contact.bem import solve_normal
from contact.setups import CompositeRoughness

E_STAR = composite_modulus(material("steel"), material("aluminium"))


def _gap():
    hz = hertz_sphere(0.02, 10.0, E_STAR)
    dx = 2.5 * hz.a / 64
    return sphere_gap(64, dx, 0.02), dx


def test_non_convergence_raises_with_the_residual():
    h, dx = _gap()
    with pytest.raises(ConvergenceError) as err:
        solve_normal(gap_grid(h, dx), e_star=E_STAR, load=10.0,
                     options=SolveOptions(max_iter=2, tol=1e-12, nested=False))
    assert err.value.iterations == 2
    assert err.value.residual > 1e-12
    assert "residual" in str(err.value)


def test_non_convergence_is_flagged_when_not_strict():
    h, dx = _gap()
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=10.0,
                       options=SolveOptions(max_iter=2, tol=1e-12, nested=False, strict=False))
    assert not res.converged
    assert res.residual > 1e-12 and res.iterations == 2
    assert res.load == pytest.approx(10.0, rel=1e-10)  # balanced even when stopped early


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"load": -1.0}, "load"),
    ({"load": 0.0}, "load"),
    ({"load": math.nan}, "load"),
    ({"load": 10.0, "hardness": -1.0}, "hardness"),
    ({"load": 10.0, "hardness": 1.0}, "hardness"),  # cannot carry 10 N below 1 Pa
    ({}, "exactly one"),
    ({"load": 10.0, "approach": 1e-6}, "exactly one"),
])
def test_bad_solver_input(kwargs, match):
    h, dx = _gap()
    kwargs = dict(kwargs)
    with pytest.raises(ContactInputError, match=match):
        if "hardness" in kwargs:  # the cap travels in the bounds
            kwargs["bounds"] = PressureBounds.elastic(kwargs.pop("hardness"))
        solve_normal(gap_grid(h, dx), e_star=E_STAR, **kwargs)


def test_bad_gap_arrays():
    h, dx = _gap()
    with pytest.raises(ContactInputError, match="NaN everywhere"):
        solve_normal(gap_grid(np.full_like(h, np.nan), dx), e_star=E_STAR, load=1.0)
    holes = h.copy()
    holes[3, 4] = np.nan
    with pytest.raises(ContactInputError, match="fill"):
        solve_normal(gap_grid(holes, dx), e_star=E_STAR, load=1.0)
    with pytest.raises(ContactInputError, match="2D"):
        solve_normal(gap_grid(h[0], dx), e_star=E_STAR, load=1.0)
    with pytest.raises(ContactInputError, match="dx"):
        solve_normal(gap_grid(h, -dx), e_star=E_STAR, load=1.0)


@pytest.mark.parametrize(("args", "kwargs", "match"), [
    ((0.0, 10.0), {}, "radius"),
    ((0.02, -5.0), {}, "load"),
    ((0.02, 10.0), {"roughness": (np.full((32, 32), np.nan), 1e-6)}, "NaN everywhere"),
    ((0.02, 10.0), {"roughness": (np.zeros((32, 32)), None)}, "pitch"),
    ((0.02, 10.0), {"roughness": (np.zeros(32), 1e-6)}, "2D map"),
    ((0.02, 10.0), {"roughness": (np.zeros((32, 32)), 1e-6, None, (0.0, np.inf))}, "finite"),
    ((0.02, 10.0), {"on_edge": "ignore"}, "on_edge"),
])
def test_bad_sphere_input(args, kwargs, match):
    with pytest.raises(ContactInputError, match=match):
        if "roughness" in kwargs:
            kwargs = {**kwargs, "roughness": CompositeRoughness(*kwargs["roughness"])}
        solve_sphere(args[0], args[1], E_STAR, **kwargs)


def test_roughness_must_come_as_the_value_object():
    with pytest.raises(ContactInputError, match="CompositeRoughness"):
        solve_sphere(0.02, 10.0, E_STAR, roughness=np.zeros((32, 32)))


def test_partially_measured_roughness_is_filled_and_reported():
    rng = np.random.default_rng(2)
    z = rng.normal(scale=1e-8, size=(200, 200))
    z[rng.random(z.shape) < 0.1] = np.nan
    res = solve_sphere(
        0.02, 10.0, E_STAR, roughness=CompositeRoughness(z, 4e-6), domain=DomainSpec(grid=64)
    )
    assert res.converged
    assert any("not measured" in note for note in res.notes)


def test_result_fields_are_read_only():
    # the derived scalars (load, pmax, contact area) were computed from the fields: a
    # field changed afterwards would silently contradict them
    h, dx = _gap()
    res = solve_normal(gap_grid(h, dx), e_star=E_STAR, load=10.0)
    for name, field in res.arrays().items():
        assert field.flags.c_contiguous, name
        with pytest.raises(ValueError, match="read-only"):
            field[0] = 1.0
