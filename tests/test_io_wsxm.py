"""WSxM reader against SurfaceTopography's test/IO/test_wsxm.py (256 x 256, 600 nm, unit nm,
rms heights 1.654156 nm for .stp and 3.153099 nm for .top)."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
@pytest.mark.parametrize("fname, rms", [("stp-1.stp", 1.654156), ("top-1.top", 3.153099)])
def test_grid_size_unit_and_rms(realdata, fname, rms):
    t = surfmet.read(realdata(fname))
    assert (t.nx, t.ny) == (256, 256)
    assert t.nx * t.dx == pytest.approx(600e-9, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(600e-9, rel=1e-6)
    assert t.metadata["height_unit"] == "nm"
    h = t.heights
    assert np.sqrt(np.mean((h - h.mean()) ** 2)) == pytest.approx(rms * 1e-9, rel=1e-6)


@pytest.mark.realdata
def test_damaged_header_and_data_fail_in_one_line(realdata):
    buf = realdata("top-1.top").read_bytes()
    cases = [buf[:-10], buf.replace(b"Image header size: 2245", b"Image header size: 9e99"),
             buf.replace(b"Maximum: 6900", b"Maximum: 5927")]
    for bad in cases:
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(bad, name="a.top")
        assert "\n" not in str(info.value)
