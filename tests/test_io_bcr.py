"""BCRF reader against SurfaceTopography's test/IO/test_bcr.py (test_bcr_metadata: 960 x 600,
1777404 nm x 1110878 nm, unit nm, rms heights over the area and along both directions)."""

from __future__ import annotations

import numpy as np
import pytest
from _peer_metrics import st_rq, st_sq

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_grid_size_and_rms_match_surfacetopography(realdata):
    t = surfmet.read(realdata("bcrf-1.bcrf"))
    assert (t.nx, t.ny) == (960, 600)
    assert t.nx * t.dx == pytest.approx(1777404e-9, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(1110878e-9, rel=1e-6)
    assert t.metadata["lateral_unit"] == "nm"
    h = t.heights
    assert st_sq(h) == pytest.approx(24.560207201442292e-9, rel=1e-6)
    assert st_rq(h) == pytest.approx(24.009754961959388e-9, rel=1e-6)
    assert st_rq(h.T) == pytest.approx(24.134045799796326e-9, rel=1e-6)


def bcr(values: np.ndarray, unicode: bool = False, void=None) -> bytes:
    ny, nx = values.shape
    lines = ["fileformat = bcrf_unicode" if unicode else "fileformat = bcrf", "headersize = 2048",
             f"xpixels = {nx}", f"ypixels = {ny}", "xlength = 30", "ylength = 20",
             "xunit = um", "yunit = um", "zunit = nm", "bit2nm = 2", "intelmode = 1"]
    if void is not None:
        lines.append(f"voidpixels = {void}")
    text = "\n".join(lines) + "\n"
    head = text.encode("utf-16-le" if unicode else "latin-1")
    head = head.ljust(4096 if unicode else 2048, b"\0")
    return head + values.astype("<f4").tobytes()


@pytest.mark.parametrize("unicode", [False, True])
def test_hand_built_files_scale_and_voids(unicode):
    v = np.arange(12, dtype=np.float32).reshape(3, 4)
    v[1, 2] = 3.402823e38
    buf = bcr(v, unicode, void="3.402823E+38")
    assert detect_format(buf, "x.dat") == "bcr"
    t = read_bytes(buf, name="x.bcrf")
    assert t.dx == pytest.approx(7.5e-6) and t.dy == pytest.approx(20e-6 / 3)
    assert np.isnan(t.heights[1, 2]) and np.isnan(t.heights).sum() == 1
    ok = ~np.isnan(t.heights)
    np.testing.assert_allclose(t.heights[ok], v[ok].astype(np.float64) * 2e-9, rtol=1e-12)


def test_truncated_and_broken_header_fail_in_one_line():
    buf = bcr(np.zeros((3, 4), np.float32))
    for bad in (buf[:-5], buf.replace(b"headersize = 2048", b"headersize = x048")):
        with pytest.raises(SurfmetFormatError) as info:
            read_bytes(bad, name="x.bcrf")
        assert "\n" not in str(info.value)
