"""Text height matrices: the interferometer export matrix-4.txt against SurfaceTopography's
stored values, the Gwyddion export header and bare matrices."""

from __future__ import annotations

import numpy as np
import pytest
from _peer_metrics import st_rms_gradient, st_rq

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_matrix4_matches_surfacetopography(realdata):
    t = surfmet.read(realdata("matrix-4.txt"))
    assert t.metadata["format"] == "asc"
    assert (t.nx, t.ny) == (75, 305)  # ST nb_grid_pts (75, 305): w=75 columns, h=305 rows
    assert t.nx * t.dx == pytest.approx(2.773965e-05, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(0.00011280791, rel=1e-6)
    assert t.metadata["height_unit"] == "m"
    assert t.metadata["data_unit"] == "rad"
    assert t.metadata["lateral_calibrated"] is True
    assert t.nan_fraction == 0.0
    h = t.heights
    assert float(np.std(h)) == pytest.approx(1.1745891510991089e-07, rel=1e-6)
    assert st_rq(h) == pytest.approx(7.198047e-08, rel=1e-6)
    assert st_rms_gradient(h, t.dx, t.dy) == pytest.approx(0.06776316911544318, rel=1e-6)
    # the factor was applied: the first value of the file is -4.448661 rad
    assert h[0, 0] == pytest.approx(-4.448661 * 2.91818e-08, rel=1e-12)


def matrix_text(values: np.ndarray, sep: str = " ") -> str:
    return "\n".join(sep.join(f"{v:.10g}" for v in row) for row in values) + "\n"


@pytest.mark.parametrize("sep", [" ", "\t", ",", ";"])
def test_bare_matrix_is_uncalibrated(sep):
    rng = np.random.default_rng(len(sep))
    vals = rng.normal(size=(6, 5))
    buf = matrix_text(vals, sep).encode()
    assert detect_format(buf, "m.txt") == "asc"
    t = read_bytes(buf, name="m.txt")
    assert (t.nx, t.ny, t.dx, t.dy) == (5, 6, 1.0, 1.0)
    assert t.metadata["lateral_calibrated"] is False
    np.testing.assert_allclose(t.heights, vals, rtol=1e-9)
    t2 = read_bytes(buf, format="asc", dx=2e-6, dy=3e-6, height_unit="nm")
    assert (t2.dx, t2.dy) == (2e-6, 3e-6)
    assert t2.metadata["lateral_calibrated"] is True
    np.testing.assert_allclose(t2.heights, vals * 1e-9, rtol=1e-9)


def test_missing_tokens_become_nan():
    rng = np.random.default_rng(3)
    vals = rng.normal(size=(7, 6))
    holes = rng.random(vals.shape) < 0.25
    holes[0, 0] = False
    rows = []
    for r, row in enumerate(vals):
        rows.append(" ".join("NaN" if holes[r, c] else f"{v:.8f}" for c, v in enumerate(row)))
    t = read_bytes(("\n".join(rows) + "\n").encode(), format="asc")
    np.testing.assert_array_equal(t.mask, holes)


def test_header_flavour_with_length_data_unit_and_mismatch():
    head = "h=3 w=4\npixel size=2 um\ndata unit=nm\n"
    vals = np.arange(12.0).reshape(3, 4)
    t = read_bytes((head + matrix_text(vals)).encode())
    assert (t.dx, t.dy) == pytest.approx((2e-6, 2e-6))
    np.testing.assert_allclose(t.heights, vals * 1e-9)
    with pytest.raises(SurfmetFormatError, match="h=3 rows"):
        read_bytes((head + matrix_text(vals[:2])).encode())
    with pytest.raises(SurfmetFormatError, match="rad"):
        read_bytes(("h=3 w=4\npixel size=2 um\ndata unit=rad\n" + matrix_text(vals)).encode())


def test_gwyddion_export_header():
    vals = np.random.default_rng(5).normal(size=(4, 8)) * 1e-8
    text = ("# Channel: Height\n# Width: 16.000 µm\n# Height: 4.000 µm\n# Value units: m\n"
            + matrix_text(vals))
    t = read_bytes(text.encode("utf-8"))
    assert t.metadata["format"] == "asc" and t.metadata["layout"] == "gwyddion"
    assert (t.dx, t.dy) == pytest.approx((2e-6, 1e-6))
    np.testing.assert_allclose(t.heights, vals, rtol=1e-9)


def test_ragged_matrix_is_an_error():
    text = "1 2 3 4\n5 6 7 8\n9 10 11\n"
    with pytest.raises(SurfmetFormatError, match="line 3 has 3 values"):
        read_bytes(text.encode(), format="asc")


def test_coordinate_lists_are_not_matrices():
    assert detect_format(b"0 1\n1 2\n2 3\n3 4\n", "a.txt") == "xyz"
    assert detect_format(b"0 0 1\n1 0 2\n0 1 3\n1 1 4\n", "a.txt") == "xyz"
