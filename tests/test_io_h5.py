"""HDF5 maps against SurfaceTopography's test/IO/test_h5.py (multiple_data_sets.h5: detected
as h5; two channels of 256 x 256 and 640 x 480, nx x ny with the first index x)."""

from __future__ import annotations

import io

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_two_channels_as_surfacetopography_reads_them(realdata):
    path = realdata("h5-multiple.h5")
    assert detect_format(path.read_bytes(), "x.bin") == "h5"
    first = surfmet.read(path)
    assert first.metadata["channels"] == ["dataset1", "dataset2"]
    assert (first.nx, first.ny) == (256, 256)
    second = surfmet.read(path, channel=1)
    assert (second.nx, second.ny) == (640, 480)
    assert not second.metadata["lateral_calibrated"]
    with pytest.raises(SurfmetFormatError, match="does not exist"):
        surfmet.read(path, channel=2)


def test_axis_order_units_and_pixel_of_a_written_file():
    h5py = pytest.importorskip("h5py")
    a = np.arange(12.0).reshape(4, 3)  # 4 points along x, 3 along y
    out = io.BytesIO()
    with h5py.File(out, "w") as f:
        f["surface"] = a
    t = read_bytes(out.getvalue(), name="s.h5", dx=2e-6, height_unit="um")
    assert (t.nx, t.ny) == (4, 3)
    assert t.heights[2, 1] == pytest.approx(a[1, 2] * 1e-6)
    assert t.dx == t.dy == 2e-6
    with pytest.raises(SurfmetFormatError):
        read_bytes(out.getvalue()[:600], name="s.h5")
