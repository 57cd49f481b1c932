"""Nanosurf .nid reader against SurfaceTopography's test/IO/test_ezd.py (test_ezd_metadata:
four height channels, 256 x 256, 20 µm x 20 µm, unit m, channel names and rms heights)."""

from __future__ import annotations

import pytest
from _peer_metrics import st_rq, st_sq

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
def test_grid_size_units_and_channels(realdata):
    t = surfmet.read(realdata("nid-1.nid"))
    assert (t.nx, t.ny) == (256, 256)
    assert t.nx * t.dx == pytest.approx(2e-5, rel=1e-6)
    assert t.ny * t.dy == pytest.approx(2e-5, rel=1e-6)
    assert t.metadata["height_unit"] == "m"
    assert len(t.metadata["channels"]) == 4
    assert t.metadata["channels"][:2] == ["Scan forward (Z-Axis)", "Scan forward (Z-AxisSensor)"]
    assert t.metadata["date"] == "2022-11-03T11:46:25"


@pytest.mark.realdata
def test_rms_heights_match_surfacetopography(realdata):
    z = surfmet.read(realdata("nid-1.nid"), channel=0).heights
    assert st_sq(z) == pytest.approx(2.395896706764167e-07, rel=1e-6)
    assert st_rq(z) == pytest.approx(2.294702406191355e-07, rel=1e-6)
    assert st_rq(z.T) == pytest.approx(6.891854644154332e-08, rel=1e-6)
    s = surfmet.read(realdata("nid-1.nid"), channel="Scan forward (Z-AxisSensor)").heights
    assert st_sq(s) == pytest.approx(3.026701737129839e-07, rel=1e-6)


@pytest.mark.realdata
def test_bad_channel_and_truncation_fail_in_one_line(realdata):
    buf = realdata("nid-1.nid").read_bytes()
    for kwargs, msg in (({"channel": 7}, "does not exist"), ({"channel": "Deflection"},
                                                              "no height channel named")):
        with pytest.raises(SurfmetFormatError, match=msg):
            read_bytes(buf, name="a.nid", **kwargs)
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:500_000], name="a.nid")
    with pytest.raises(SurfmetFormatError, match="#!"):
        read_bytes(buf[:3000], name="a.nid", format="nid")
