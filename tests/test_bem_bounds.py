"""The pressure bounds object of the normal BEM (contact.bem._bounds)."""

import math

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._grid import gap_grid
from contact.adhesion.laws import DugdaleLaw
from contact.bem import solve_normal
from contact.bem._bounds import PressureBounds


def _sphere(n=32, dx=2e-6, radius=1e-3):
    x = (np.arange(n) - n / 2) * dx
    return (x[:, None] ** 2 + x[None, :] ** 2) / (2 * radius), dx


def test_hardness_bounds_cap_the_pressure():
    h, dx = _sphere()
    a = solve_normal(gap_grid(h, dx), e_star=1e11, load=0.05, bounds=PressureBounds.elastic(3e8))
    assert np.asarray(a.pressure).max() <= 3e8  # the elastic peak is 4.6e8 Pa
    assert a.plastic_area > 0


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
        solve_normal(gap_grid(h, dx), e_star=1e11, load=0.05, bounds=bounds)


@pytest.mark.parametrize("kwargs", [{"tensile": -1.0}, {"tensile": math.nan},
                                    {"hardness": 0.0}, {"hardness": math.nan}])
def test_bad_bounds_are_one_input_error(kwargs):
    with pytest.raises(ContactInputError):
        PressureBounds(**kwargs)


def test_bounds_that_are_not_bounds_are_refused():
    h, dx = _sphere()
    with pytest.raises(ContactInputError, match="PressureBounds"):
        solve_normal(gap_grid(h, dx), e_star=1e11, load=0.05, bounds=1e9)
