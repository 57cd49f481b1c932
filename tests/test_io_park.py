"""Park Systems TIFF reader against SurfaceTopography's test/IO/test_ps.py (channel 'Z Height',
512 x 512, 1 µm, unit µm, rms height 0.003933333499668988 µm); the private tags are also read
with tifffile, an independent TIFF parser."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
def test_grid_size_unit_and_rms(realdata):
    t = surfmet.read(realdata("example_ps.tiff"))
    assert t.metadata["channel"] == "Z Height"
    assert (t.nx, t.ny) == (512, 512)
    assert t.nx * t.dx == pytest.approx(1e-6, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(1e-6, rel=1e-6)
    h = t.heights
    assert np.sqrt(np.mean((h - h.mean()) ** 2)) == pytest.approx(0.003933333499668988e-6,
                                                                  rel=1e-6)


@pytest.mark.realdata
def test_tags_agree_with_tifffile(realdata):
    tifffile = pytest.importorskip("tifffile")
    path = realdata("example_ps.tiff")
    with tifffile.TiffFile(path) as tf:
        tags = tf.pages[0].tags
        assert tags[50432].value == 0x0E031301
        raw = np.frombuffer(bytes(tags[50434].value), "<f4", count=512 * 512)
        head = bytes(tags[50435].value)
    gain, scale = np.frombuffer(head[220:236], "<f8")
    t = surfmet.read(path)
    np.testing.assert_allclose(t.heights.ravel(), raw * scale * gain * 1e-6, rtol=1e-12)


@pytest.mark.realdata
def test_plain_tiff_and_truncation_fail_in_one_line(realdata):
    buf = realdata("example_ps.tiff").read_bytes()
    with pytest.raises(SurfmetFormatError) as info:
        read_bytes(buf[:5000], name="a.tiff", format="park")
    assert "\n" not in str(info.value)
    plain = b"II*\0" + (8).to_bytes(4, "little") + (0).to_bytes(2, "little") + bytes(8)
    with pytest.raises(SurfmetFormatError, match="missing"):
        read_bytes(plain, name="b.tiff", format="park")
