"""The pressure bounds object of the normal BEM (contact.bem.bounds)."""

import math

import numpy as np
import pytest

from contact.adhesion.laws import DugdaleLaw
from contact.bem import solve_normal
from contact.bem.bounds import PressureBounds
from contact.errors import ContactInputError


def _sphere(n=32, dx=2e-6, radius=1e-3):
    x = (np.arange(n) - n / 2) * dx
    return (x[:, None] ** 2 + x[None, :] ** 2) / (2 * radius), dx


def test_hardness_shorthand_and_bounds_give_the_same_bits():
    h, dx = _sphere()
    a = solve_normal(h, dx, e_star=1e11, load=0.05, hardness=2e9)
    b = solve_normal(h, dx, e_star=1e11, load=0.05, bounds=PressureBounds.elastic(2e9))
    assert np.array_equal(np.asarray(a.pressure), np.asarray(b.pressure))
    assert a.approach == b.approach
    assert np.asarray(a.pressure).max() <= 2e9


def test_default_bounds_are_non_adhesive_and_elastic():
    b = PressureBounds()
    assert b.tensile == 0.0 and math.isinf(b.hardness) and not b.plastic
    assert not b.is_adhesive


def test_adhesive_bounds_are_refused_by_the_non_adhesive_solver():
    h, dx = _sphere()
    law = DugdaleLaw(0.05, 1e7)
    bounds = PressureBounds.adhesive(law)
    assert bounds.tensile == pytest.approx(1e7) and bounds.is_adhesive
    with pytest.raises(ContactInputError, match="solve_adhesive"):
        solve_normal(h, dx, e_star=1e11, load=0.05, bounds=bounds)


@pytest.mark.parametrize("kwargs", [{"tensile": -1.0}, {"tensile": math.nan},
                                    {"hardness": 0.0}, {"hardness": math.nan}])
def test_bad_bounds_are_one_input_error(kwargs):
    with pytest.raises(ContactInputError):
        PressureBounds(**kwargs)


def test_hardness_given_twice_is_refused():
    h, dx = _sphere()
    with pytest.raises(ContactInputError, match="not both"):
        solve_normal(h, dx, e_star=1e11, load=0.05, hardness=1e9,
                     bounds=PressureBounds.elastic(1e9))
