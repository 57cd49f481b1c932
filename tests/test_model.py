"""The data model: immutability, validation, derived properties."""

import numpy as np
import pytest

from surfmet import Profile, SurfmetInputError, Topography


def test_topography_properties_and_read_only():
    rng = np.random.default_rng(1)
    h = rng.normal(size=(4, 6))
    h[1, 2] = np.nan
    t = Topography(h, 2e-6, 3e-6, {"instrument": "x"})
    assert (t.nx, t.ny) == (6, 4)
    assert t.size_x == pytest.approx(12e-6) and t.size_y == pytest.approx(12e-6)
    assert t.nan_fraction == pytest.approx(1 / 24)
    assert t.mask[1, 2] and t.mask.sum() == 1
    assert np.allclose(t.x, np.arange(6) * 2e-6)
    with pytest.raises(ValueError):
        t.heights[0, 0] = 1.0
    # the caller's array stays writable and independent
    h[0, 0] = 42.0
    assert t.heights[0, 0] != 42.0
    with pytest.raises(TypeError):
        t.metadata["new"] = 1  # type: ignore[index]


def test_topography_replace_and_metadata():
    t = Topography(np.zeros((2, 3)), 1e-6, 1e-6)
    t2 = t.with_metadata(format="x3p")
    assert t2.metadata["format"] == "x3p" and "format" not in t.metadata
    t3 = t.replace(dx=5e-6)
    assert t3.dx == 5e-6 and t.dx == 1e-6


@pytest.mark.parametrize(
    "args",
    [
        (np.zeros((2, 2)), 0.0, 1e-6),
        (np.zeros((2, 2)), -1e-6, 1e-6),
        (np.zeros((2, 2)), 1e-6, float("nan")),
        (np.zeros(4), 1e-6, 1e-6),
        (np.zeros((0, 3)), 1e-6, 1e-6),
        (np.array([["a", "b"]]), 1e-6, 1e-6),
    ],
)
def test_topography_rejects_bad_input(args):
    with pytest.raises(SurfmetInputError):
        Topography(*args)


def test_profile_uniform_and_nonuniform():
    p = Profile(np.arange(5.0), 0.5e-6)
    assert p.is_uniform and p.length == pytest.approx(2.5e-6)
    assert np.allclose(p.positions, np.arange(5) * 0.5e-6)
    x = np.array([0.0, 1.0, 2.5, 3.0]) * 1e-6
    q = Profile(np.zeros(4), 1e-6, x=x)
    assert not q.is_uniform and q.length == pytest.approx(3e-6)
    with pytest.raises(SurfmetInputError):
        Profile(np.zeros(4), 1e-6, x=x[::-1])
    with pytest.raises(SurfmetInputError):
        Profile(np.zeros(4), 1e-6, x=x[:3])
