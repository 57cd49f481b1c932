"""Plain coordinate text: x z profiles and x y z grids with holes, in several dialects."""

from __future__ import annotations

import numpy as np
import pytest

from surfmet._errors import SurfmetFormatError, SurfmetInputError
from surfmet.io import detect_format, read_bytes


def lines(rows, sep=" ", header=None) -> bytes:
    text = "" if header is None else header + "\n"
    text += "\n".join(sep.join(f"{v:.12g}" for v in row) for row in rows) + "\n"
    return text.encode()


@pytest.mark.parametrize("sep", [" ", "\t", ",", ";"])
def test_two_columns_uniform(sep):
    x = 3e-3 + np.arange(25) * 1e-6
    z = np.sin(np.arange(25.0)) * 1e-7
    buf = lines(zip(x, z), sep, header="x,z")
    assert detect_format(buf, "p.txt") == "xyz"
    p = read_bytes(buf, name="p.txt")
    assert p.kind == "profile" and p.is_uniform and p.dx == pytest.approx(1e-6)
    np.testing.assert_allclose(p.z, z, rtol=1e-10)
    assert p.metadata["x_offset"]["value"] == pytest.approx(3e-3)


def test_two_columns_non_uniform_with_units_and_descending():
    rng = np.random.default_rng(4)
    x = np.cumsum(rng.uniform(0.1, 1.0, 30))[::-1]
    z = rng.normal(size=30)
    p = read_bytes(lines(zip(x, z)), format="xyz", unit="um", height_unit="nm")
    assert not p.is_uniform
    np.testing.assert_allclose(p.positions, (x[::-1] - x[-1]) * 1e-6, rtol=1e-9, atol=1e-18)
    np.testing.assert_allclose(p.z, z[::-1] * 1e-9, rtol=1e-10)
    assert p.metadata["lateral_unit"] == "um" and p.metadata["height_unit"] == "nm"
    with pytest.raises((SurfmetFormatError, SurfmetInputError)):
        read_bytes(lines(zip(x, z)), format="xyz", unit="furlong")


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_three_columns_grid_with_missing_nodes(seed):
    rng = np.random.default_rng(seed)
    nx, ny = int(rng.integers(3, 15)), int(rng.integers(3, 15))
    dx, dy = float(rng.uniform(0.1, 2)), float(rng.uniform(0.1, 2))
    X, Y = np.meshgrid(np.arange(nx) * dx + 5, np.arange(ny) * dy - 2)
    Z = rng.normal(size=(ny, nx))
    keep = rng.random((ny, nx)) > rng.uniform(0.0, 0.3)
    keep[0, 0] = keep[-1, -1] = keep[0, -1] = keep[-1, 0] = True
    order = rng.permutation(int(keep.sum()))
    rows = np.stack([X[keep], Y[keep], Z[keep]], -1)[order]
    t = read_bytes(lines(rows, ","), format="xyz", unit="um", height_unit="um")
    assert (t.nx, t.ny) == (nx, ny)
    assert (t.dx, t.dy) == pytest.approx((dx * 1e-6, dy * 1e-6), rel=1e-9)
    np.testing.assert_array_equal(t.mask, ~keep)
    np.testing.assert_allclose(t.heights[keep], Z[keep] * 1e-6, rtol=1e-10)
    assert t.metadata["y_offset"]["value"] == pytest.approx(-2e-6)


def test_grid_errors():
    pts = [(0, 0, 1), (1, 0, 2), (0, 1, 3), (1, 1, 4)]
    with pytest.raises(SurfmetFormatError, match="more than once"):
        read_bytes(lines([*pts, (1, 1, 5)]), format="xyz")
    with pytest.raises(SurfmetFormatError, match="regular grid"):
        read_bytes(lines([*pts, (0.5, 0.37, 5)]), format="xyz")
    with pytest.raises(SurfmetFormatError, match="regular grid"):
        read_bytes(lines([(0, 0, 1), (1, 0, 1), (0, 1, 1), (1000, 1000, 1)]), format="xyz")
    with pytest.raises(SurfmetFormatError, match="columns"):
        read_bytes(b"0 0 1\n1 0 2\n1 1\n", format="xyz")


def test_specific_text_formats_win_over_xyz():
    hfm = b"X;Y;valid\r\n[mm];[mm];[1/0]\r\n1.0;2.0;1\r\n1.5;2.5;1\r\n"
    assert detect_format(hfm, "a.txt") == "hfm"
    assert detect_format(b"h=2 w=4\npixel size=1 um\n1 2 3 4\n5 6 7 8\n", "a.txt") == "asc"
    assert detect_format(b"Scan Parameters\r\nScan Data\r\nLateral um,Raw um,\r\n0,1,,\r\n",
                         "a.csv") == "dektak"
    with pytest.raises(SurfmetFormatError):
        read_bytes(b"just some words\nand more\n", format="xyz")
