"""TrueMap .tmd reader against SurfaceTopography's test/IO/test_tmd.py (300 x 300, physical
size 18.9566 in the file's unit, heights in [0, 1) of that unit), plus hand-built files."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_grid_size_and_height_range(realdata):
    t = surfmet.read(realdata("tmd-1.tmd"))
    assert (t.nx, t.ny) == (300, 300)
    assert t.nx * t.dx == pytest.approx(18.9566e-3, rel=1e-3)  # read as mm
    assert t.ny * t.dy == pytest.approx(18.9566e-3, rel=1e-3)
    h = t.heights / 1e-3  # back to the file's unit
    assert np.nanmin(h) >= 0 and np.nanmax(h) < 1
    assert t.metadata["vendor"] == "TrueMap"
    um = surfmet.read(realdata("tmd-1.tmd"), unit="um")
    assert um.nx * um.dx == pytest.approx(18.9566e-6, rel=1e-3)


def tmd(values: np.ndarray, lx=3.0, ly=2.0) -> bytes:
    ny, nx = values.shape
    return (b"Binary TrueMap Data File v2.0\r\n\0".ljust(32, b"\0")
            + b"Created by hand\r\n".ljust(24, b"\0")
            + struct.pack("<IIffff", nx, ny, lx, ly, 0, 0) + values.astype("<f4").tobytes())


def test_hand_built_file_layout():
    v = np.arange(6, dtype=np.float32).reshape(2, 3) / 8
    buf = tmd(v)
    assert detect_format(buf, "x.bin") == "tmd"
    t = read_bytes(buf, name="x.tmd")
    np.testing.assert_array_equal(t.heights, v.astype(np.float64) * 1e-3)
    assert t.dx == pytest.approx(1e-3) and t.dy == pytest.approx(1e-3)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:-3], name="x.tmd")
