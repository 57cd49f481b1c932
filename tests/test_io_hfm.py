"""HFM ``X;Y;valid`` text profiles: the real file against SurfaceTopography's stored values
and synthetic files with invalid points."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


def rq(z):
    return float(np.sqrt(np.nanmean((z - np.nanmean(z)) ** 2)))


def detrend_curvature_1d(x, z):
    # least-squares fit of 1, x, x² (SurfaceTopography's 'curvature' for a line scan)
    a = np.stack([np.ones_like(x), x, x * x], -1)
    coef, *_ = np.linalg.lstsq(a, z, rcond=None)
    return z - a @ coef


@pytest.mark.realdata
def test_real_file_matches_surfacetopography(realdata):
    p = surfmet.read(realdata("hfm-1.hfm"))
    assert p.metadata["format"] == "hfm"
    assert p.kind == "profile" and p.n == 9600
    assert p.is_uniform
    assert p.dx == pytest.approx(0.5e-6, rel=1e-6)
    assert p.length == pytest.approx(4.8e-3, rel=1e-6)  # ST physical size 4.8 (mm)
    assert p.metadata["height_unit"] == "mm" and p.metadata["lateral_unit"] == "mm"
    assert p.metadata["x_offset"]["value"] == pytest.approx(8.6722e-3)
    assert p.nan_fraction == 0.0
    assert rq(p.z) == pytest.approx(0.000906e-3, rel=1e-3)
    assert rq(p.z) == pytest.approx(0.00090569e-3, rel=1e-4)  # ST 1.27.1
    d = detrend_curvature_1d(p.positions, p.z)
    assert rq(d) == pytest.approx(0.000138e-3, rel=1e-3)
    assert p.z[0] == pytest.approx(106.606853e-3, rel=1e-12)


def hfm_text(x, z, valid, units="[mm];[mm];[1/0]") -> bytes:
    rows = [f"{a:.6f};{b:.6f};{v}" for a, b, v in zip(x, z, valid)]
    return ("X;Y;valid\r\n" + units + "\r\n" + "\r\n".join(rows) + "\r\n").encode()


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_invalid_points_become_nan(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(10, 300))
    x = 1.0 + np.arange(n) * 0.002
    z = rng.normal(size=n)
    valid = (rng.random(n) > rng.uniform(0.05, 0.4)).astype(int)
    valid[0] = 1
    p = read_bytes(hfm_text(x, z, valid), name="s.hfm")
    np.testing.assert_array_equal(np.isnan(p.z), valid == 0)
    np.testing.assert_allclose(p.z[valid == 1], np.round(z, 6)[valid == 1] * 1e-3)
    assert p.is_uniform and p.dx == pytest.approx(2e-6)


def test_units_order_and_non_uniform():
    x = np.array([5.0, 4.0, 3.5, 1.0])
    p = read_bytes(hfm_text(x, [1, 2, 3, 4], [1, 1, 1, 1], "[um];[nm];[1/0]"))
    assert not p.is_uniform
    np.testing.assert_allclose(p.positions, [0, 2.5e-6, 3e-6, 4e-6])
    np.testing.assert_allclose(p.z, [4e-9, 3e-9, 2e-9, 1e-9])


def test_detection_and_damage():
    buf = hfm_text(np.arange(5.0), np.zeros(5), [1] * 5)
    assert detect_format(buf, "a.txt") == "hfm"
    with pytest.raises(SurfmetFormatError, match="fields"):
        read_bytes(buf[:-5] + b"\r\n")
    with pytest.raises(SurfmetFormatError, match="not a length"):
        read_bytes(hfm_text([1, 2], [1, 2], [1, 1], "[V];[mm];[1/0]"))
    with pytest.raises(SurfmetFormatError, match="0 and 1"):
        read_bytes(hfm_text([1, 2], [1, 2], [1, 7]))
