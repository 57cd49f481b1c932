"""MountainsMap .mnt reader: the sample against SurfaceTopography (test/IO/test_mnt.py: one
surface, 960 x 600, unit µm, no undefined point; MANIFEST: physical size 1779.257393 x
1112.732554 µm as SurfaceTopography 1.27.1 reads it) and against the same scan exported by
MountainsMap as BCRF (bcrf-1.bcrf, read by its own reader): equal heights."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
def test_grid_size_unit_and_no_undefined_points(realdata):
    t = surfmet.read(realdata("mnt-1.mnt"))
    assert (t.nx, t.ny) == (960, 600)
    assert t.nx * t.dx == pytest.approx(1779.257393e-6, rel=1e-8)
    assert t.ny * t.dy == pytest.approx(1112.732554e-6, rel=1e-8)
    assert t.metadata["height_unit"] == "µm"
    assert not t.has_nan
    # SurfaceTopography's current test reads the size from another section and asserts
    # 1777.404 µm: that is (n - 1) steps, the width between the first and last pixel centre
    assert (t.nx - 1) * t.dx == pytest.approx(1777.404e-6, abs=0.005e-6)


@pytest.mark.realdata
def test_heights_equal_the_bcrf_export_of_the_same_scan(realdata):
    m = surfmet.read(realdata("mnt-1.mnt")).heights
    b = surfmet.read(realdata("bcrf-1.bcrf")).heights
    # the BCRF stores float32 micrometres: equal to float32 rounding
    np.testing.assert_allclose(m, b, rtol=2e-7, atol=0)


@pytest.mark.realdata
def test_damage_fails_in_one_line(realdata):
    buf = realdata("mnt-1.mnt").read_bytes()
    for bad in (buf[:4096], buf[: len(buf) // 2], buf[:8] + bytes(600) + buf[608:]):
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(bad, name="a.mnt", format="mnt")
        assert "\n" not in str(info.value)
