"""NetCDF reader: the real file against SurfaceTopography (nb_grid_pts (5, 10), physical size
(5, 10) nm) and, value by value, against SciPy's independent NetCDF-3 reader; files written
with scipy.io.netcdf_file in both classic versions for the options of the layout."""

from __future__ import annotations

import io

import numpy as np
import pytest
from scipy.io import netcdf_file

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_real_file_grid_size_unit_and_values(realdata):
    path = realdata("nc-1.nc")
    t = surfmet.read(path)
    assert (t.nx, t.ny) == (5, 10)
    assert t.nx * t.dx == pytest.approx(5e-9) and t.ny * t.dy == pytest.approx(10e-9)
    assert t.metadata["height_unit"] == "nm"
    with netcdf_file(path, "r", mmap=False) as f:
        ref = np.array(f.variables["heights"][...], dtype=float)
    np.testing.assert_array_equal(t.heights, ref.T * 1e-9)  # heights(x, y): x first


def write(version: int, heights: np.ndarray, **extra) -> bytes:
    buf = io.BytesIO()
    f = netcdf_file(buf, "w", version=version)
    dims = ("x", "y")[: heights.ndim]
    for d, n in zip(dims, heights.shape):
        f.createDimension(d, n)
        v = f.createVariable(d, "f8", (d,))
        v[:] = np.arange(n)
        v.length = float(n) * 0.5
        v.unit = "um"
    h = f.createVariable("heights", extra.pop("dtype", "f8"), dims)
    for k, val in extra.pop("attrs", {}).items():
        setattr(h, k, val)
    h[...] = heights
    if "mask" in extra:
        m = f.createVariable("mask", "i1", dims)
        m[...] = extra.pop("mask")
    h.unit = "nm"
    f.flush()
    out = buf.getvalue()
    f.close()
    return out


@pytest.mark.parametrize("version", [1, 2])
def test_written_areal_file_with_mask_both_versions(version):
    rng = np.random.default_rng(5)
    z = rng.normal(size=(4, 6))
    mask = np.zeros((4, 6), np.int8)
    mask[1, 2] = 1
    buf = write(version, z, mask=mask)
    assert detect_format(buf, "a.bin") == "nc"
    t = read_bytes(buf, name="a.nc")
    assert (t.nx, t.ny) == (4, 6)
    assert t.dx == pytest.approx(0.5e-6) and t.dy == pytest.approx(0.5e-6)
    expect = z.T * 1e-9
    expect[2, 1] = np.nan
    np.testing.assert_array_equal(t.heights, expect)


def test_scale_offset_and_fill_value_and_profile():
    raw = np.array([[1, 2, -99], [4, 5, 6]], dtype=np.int16)
    buf = write(1, raw, dtype="i2", attrs={"scale_factor": 0.5, "add_offset": 1.0,
                                           "_FillValue": np.int16(-99)})
    t = read_bytes(buf, name="a.nc")
    expect = (raw.T * 0.5 + 1.0) * 1e-9
    expect[2, 0] = np.nan
    np.testing.assert_allclose(t.heights, expect, rtol=1e-15)
    p = read_bytes(write(2, np.arange(7.0)), name="p.nc")
    assert p.kind == "profile" and p.n == 7 and p.dx == pytest.approx(0.5e-6)


def test_damaged_files_fail_in_one_line():
    buf = write(1, np.zeros((3, 3)))
    for bad in (buf[:40], buf[:-100], buf.replace(b"heights", b"heigxts")):
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(bad, name="a.nc")
        assert "\n" not in str(info.value)
