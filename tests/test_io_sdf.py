"""ISO 25178-71 SDF reader: the standard's ASCII example and synthetic binary/ASCII files."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes

# The 7 x 4 example of ISO 25178-71 (values in µm, Zscale 1e-6), row by row.
ISO_EXAMPLE = np.array([
    [1.00000, 0.99874, 0.99495, 0.98865, 0.97986, 0.96858, 1.00000],
    [0.99874, 0.99748, 0.99369, 0.98740, 0.97862, 0.96736, 0.99874],
    [0.99495, 0.99369, 0.98993, 0.98366, 0.97491, 0.96369, 0.99495],
    [0.97986, 0.97862, 0.97491, 0.96874, 0.96012, 0.94907, 0.97986],
])


@pytest.mark.realdata
def test_iso_ascii_example(realdata):
    t = surfmet.read(realdata("sdf-1.sdf"))
    assert (t.nx, t.ny) == (7, 4)
    # SurfaceTopography: physical sizes 7.0 x 4.0 µm (rtol 1e-3), unit µm
    assert t.nx * t.dx == pytest.approx(7e-6, rel=1e-3)
    assert t.ny * t.dy == pytest.approx(4e-6, rel=1e-3)
    assert t.metadata["height_unit"] == "um"
    assert t.metadata["lateral_unit"] == "um"
    assert t.metadata["variant"] == "ascii"
    assert t.nan_fraction == 0.0
    np.testing.assert_allclose(t.heights, ISO_EXAMPLE * 1e-6, rtol=1e-12)
    assert t.metadata["trailer"] == {"OperatorName": "Tom Jones",
                                     "PartName": "S2 Softgauges Example"}
    assert t.metadata["date"] == "2010-01-04T08:53"
    assert t.metadata["z_resolution"] == pytest.approx(1e-9)


def make_binary(values: np.ndarray, data_type: int, xs: float, ys: float, zs: float,
                trailer: bytes = b"") -> bytes:
    ny, nx = values.shape
    dtype = {0: "u1", 1: "<u2", 2: "<u4", 3: "<f4", 4: "i1", 5: "<i2", 6: "<i4", 7: "<f8"}
    head = struct.pack("<8s10s12s12sHHddddBBB", b"bISO-1.0", b"TEST", b"010220241230",
                       b"010220241230", nx, ny, xs, ys, zs, -1.0, 0, data_type, 0)
    assert len(head) == 81
    return head + values.astype(dtype[data_type]).tobytes() + trailer


@pytest.mark.parametrize("data_type", [0, 1, 2, 3, 4, 5, 6, 7])
def test_binary_every_data_type(data_type):
    rng = np.random.default_rng(data_type)
    ny, nx = int(rng.integers(2, 20)), int(rng.integers(2, 20))
    vals = rng.integers(0, 100, (ny, nx)).astype(float)
    buf = make_binary(vals, data_type, 1e-6, 2e-6, 1e-9)
    t = read_bytes(buf, name="b.sdf")
    assert t.metadata["format"] == "sdf" and t.metadata["variant"] == "binary"
    assert (t.nx, t.ny, t.dx, t.dy) == (nx, ny, 1e-6, 2e-6)
    np.testing.assert_allclose(t.heights, vals * 1e-9, rtol=1e-6)
    assert t.metadata["height_unit"] == "nm"
    assert t.metadata["date"] == "2024-02-01T12:30"


@pytest.mark.parametrize("data_type, marker", [(5, -(2**15)), (6, -(2**31)), (7, np.nan),
                                               (3, np.nan)])
def test_binary_missing_points(data_type, marker):
    rng = np.random.default_rng(data_type + 10)
    vals = rng.integers(-1000, 1000, (8, 9)).astype(float)
    holes = rng.random(vals.shape) < 0.2
    holes[0, 0] = False
    vals[holes] = marker
    t = read_bytes(make_binary(vals, data_type, 1e-6, 1e-6, 1e-8))
    np.testing.assert_array_equal(t.mask, holes)


def test_ascii_bad_points_and_profile():
    text = ("aISO-1.0\nManufacID = X\nCreateDate = 010120200000\nModDate = 010120200000\n"
            "NumPoints = 5\nNumProfiles = 1\nXscale = 2.0E-6\nYscale = 2.0E-6\n"
            "Zscale = 1.0E-9\nZresolution = -1\nCompression = 0\nDataType = 7\nCheckType = 0\n"
            "*\n1 2 BAD 4 5\n*\n*\n")
    p = read_bytes(text.encode())
    assert p.kind == "profile" and p.n == 5 and p.dx == 2e-6
    np.testing.assert_array_equal(np.isnan(p.z), [False, False, True, False, False])
    assert p.z[3] == pytest.approx(4e-9)


def test_damaged_files():
    good = make_binary(np.ones((4, 5)), 7, 1e-6, 1e-6, 1e-6)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(good[:-3])
    bad_type = bytearray(good)
    bad_type[79] = 9
    with pytest.raises(SurfmetFormatError, match="DataType"):
        read_bytes(bytes(bad_type))
    with pytest.raises(SurfmetFormatError, match="Compression"):
        compressed = bytearray(good)
        compressed[78] = 1
        read_bytes(bytes(compressed))
    ascii_short = ("aISO-1.0\nManufacID = X\nCreateDate = 0\nModDate = 0\nNumPoints = 3\n"
                   "NumProfiles = 2\nXscale = 1\nYscale = 1\nZscale = 1\nZresolution = 1\n"
                   "Compression = 0\nDataType = 7\nCheckType = 0\n*\n1 2 3 4 5\n*\n")
    with pytest.raises(SurfmetFormatError, match="holds 5 values"):
        read_bytes(ascii_short.encode())


@pytest.mark.parametrize("n, problem", [(65535, "absurd"), (40000, "truncated")])
def test_huge_grid_claim_fails_fast(n, problem):
    head = bytearray(make_binary(np.ones((2, 2)), 7, 1e-6, 1e-6, 1e-6))
    head[42:46] = struct.pack("<HH", n, n)
    with pytest.raises(SurfmetFormatError, match=problem):
        read_bytes(bytes(head))
