"""JPK AFM images against AFMReader's tests/test_jpk.py (sample_0.jpk: channel height_trace,
256 x 256, pixel 1.2770176335964876 nm, image sum 219242202.8256843 nm)."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import detect_format, read_bytes


@pytest.mark.realdata
def test_height_trace_matches_afmreader(realdata):
    path = realdata("jpk-afmreader-0.jpk")
    t = surfmet.read(path)
    assert detect_format(path.read_bytes(), "x.bin") == "jpk"
    assert t.metadata["channel"] == "height_trace"
    assert t.shape == (256, 256)
    assert t.dx * 1e9 == pytest.approx(1.2770176335964876, rel=1e-12)
    assert t.dy == pytest.approx(t.dx, rel=1e-12)
    assert t.heights.dtype == np.float64
    assert (t.heights * 1e9).sum() == pytest.approx(219242202.8256843, rel=1e-12)


@pytest.mark.realdata
def test_channels_and_choice(realdata):
    buf = realdata("jpk-afmreader-0.jpk").read_bytes()
    t = read_bytes(buf, name="a.jpk")
    # volts and degrees channels are not height channels
    assert "phase_trace" not in t.metadata["channels"]
    assert "error_trace" not in t.metadata["channels"]
    retrace = read_bytes(buf, name="a.jpk", channel="height_retrace")
    assert retrace.metadata["channel"] == "height_retrace"
    assert not np.array_equal(retrace.heights, t.heights)
    with pytest.raises(SurfmetFormatError, match="no height channel named"):
        read_bytes(buf, name="a.jpk", channel="phase_trace")
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:1_400_000], name="a.jpk", channel="height_trace")
