"""PicoView .mi reader against SurfaceTopography's test/IO/test_mi.py (four channels and
their names, 256 x 256, 20 µm, unit µm, the height of the first point)."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
def test_header_grid_size_and_first_height(realdata):
    t = surfmet.read(realdata("mi-1.mi"))
    assert t.metadata["channels"] == ["Topography", "Deflection", "Friction", "Friction"]
    assert t.metadata["channel"] == "Topography"
    assert (t.nx, t.ny) == (256, 256)
    assert t.nx * t.dx == pytest.approx(2e-5, rel=1e-12)
    assert t.ny * t.dy == pytest.approx(2e-5, rel=1e-12)
    assert t.metadata["height_unit"] == "um"
    # ST: topography._heights[0, 0] == -0.4986900329589844 µm (rtol 1e-6)
    np.testing.assert_allclose(t.heights[0, 0], -0.4986900329589844e-6, rtol=1e-6)
    # a count is bufferRange / 2^15: every height is a multiple of it
    step = 2.9025000000000003e-6 / 2**15
    np.testing.assert_allclose(t.heights / step, np.round(t.heights / step), atol=1e-6)


@pytest.mark.realdata
def test_voltage_channel_is_refused_and_truncation_named(realdata):
    buf = realdata("mi-1.mi").read_bytes()
    with pytest.raises(SurfmetFormatError, match="not a length"):
        read_bytes(buf, name="a.mi", channel="Deflection")
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[: buf.index(b"data          BINARY") + 100_000], name="a.mi")
    with pytest.raises(SurfmetFormatError, match="data"):
        read_bytes(buf[:2000], name="a.mi")
