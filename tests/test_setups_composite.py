"""The composite-roughness value object of the contact set-ups (contact.setups._composite)."""

from __future__ import annotations

import numpy as np
import pytest

from contact import ContactInputError
from contact.setups import CompositeRoughness


def test_apex_defaults_to_the_middle_and_a_track_offset_moves_it():
    rng = np.random.default_rng(7)
    ny, nx, dx, dy = 41, 60, 2e-6, 3e-6
    z = CompositeRoughness(rng.normal(size=(ny, nx)), dx, dy)
    # scan coordinates: column j at X = j dx, row i at Y = i dy
    assert z.apex == pytest.approx(((nx - 1) * dx / 2, (ny - 1) * dy / 2), rel=1e-15)
    moved = z.shifted((10e-6, -6e-6))
    assert moved.apex == pytest.approx(((nx - 1) * dx / 2 + 10e-6, (ny - 1) * dy / 2 - 6e-6))
    assert z.shifted(None) is z
    assert np.array_equal(moved.heights, z.heights) and moved.dy == dy and moved.level


def test_heights_are_a_frozen_copy():
    a = np.zeros((8, 8))
    z = CompositeRoughness(a, 1e-6)
    a[0, 0] = 1.0
    assert z.heights[0, 0] == 0.0
    with pytest.raises(ValueError):
        z.heights[0, 0] = 2.0
    assert z.dy == z.dx == 1e-6


@pytest.mark.parametrize(("args", "kwargs", "match"), [
    ((np.zeros(8), 1e-6), {}, "2D map"),
    ((np.full((8, 8), np.nan), 1e-6), {}, "NaN everywhere"),
    ((np.zeros((8, 8)), -1e-6), {}, "pitch dx"),
    ((np.zeros((8, 8)), 1e-6, 0.0), {}, "pitch dy"),
    ((np.zeros((8, 8)), 1e-6), {"centre": (1e-6,)}, "two lengths"),
    ((np.zeros((8, 8)), 1e-6), {"centre": (1e-6, np.inf)}, "finite"),
])
def test_bad_roughness_is_one_clear_contact_input_error(args, kwargs, match):
    with pytest.raises(ContactInputError, match=match):
        CompositeRoughness(*args, **kwargs)
