"""Nanoscope (.di) reader against SurfaceTopography's test suite: test/test_topography.py
(diSurfaceTest: grid, physical size in nm and rms height per channel, all in nm) and
test/IO/test_di.py (date, instrument); plus hand-made damage."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


def st_rms_area(h):
    # SurfaceTopography's rms_height_from_area: rms about the mean, all points
    return float(np.sqrt(np.mean((h - h.mean()) ** 2)))


# (file, channel index, name, side in nm, rms in nm) from diSurfaceTest.test_read
CASES = [
    ("di-1.di", 0, "Height", 500.0, 9.9459868005603909),
    ("di-1.di", 1, "Height", 500.0, 114.01328027385664),
    ("di-2.di", 0, "Height", 300.0, 24.721922008645919),
    ("di-2.di", 1, "Height", 300.0, 24.807150576054838),
    ("di-2.di", 2, "Deflection", 300.0, 0.13002312109876774),
]


@pytest.mark.realdata
@pytest.mark.parametrize("fname, index, cname, side, rms", CASES)
def test_channels_grid_size_and_rms(realdata, fname, index, cname, side, rms):
    t = surfmet.read(realdata(fname), channel=index)
    assert (t.nx, t.ny) == (512, 512)
    assert t.nx * t.dx == pytest.approx(side * 1e-9, rel=1e-12)
    assert t.ny * t.dy == pytest.approx(side * 1e-9, rel=1e-12)
    assert t.metadata["channel"] == cname
    assert t.metadata["height_unit"] == "nm"
    # assertAlmostEqual in nm: 7 decimals
    assert st_rms_area(t.heights) * 1e9 == pytest.approx(rms, abs=5e-8)


@pytest.mark.realdata
def test_default_is_first_height_channel_with_date_and_instrument(realdata):
    t = surfmet.read(realdata("di-1.di"))
    assert t.metadata["channel"] == "Height"
    assert t.metadata["channels"] == ["Height", "Height", "Phase", "AmplitudeError"]
    assert t.metadata["date"] == "2016-01-12T09:57:48"
    assert t.metadata["instrument"] == "Dimension V"
    assert t.metadata["vendor"] == "Bruker"
    assert surfmet.read(realdata("di-1.di"), channel="height").metadata["channel"] == "Height"


@pytest.mark.realdata
def test_non_height_channel_and_missing_channel_fail_in_one_line(realdata):
    buf = realdata("di-1.di").read_bytes()
    for ch, msg in ((2, "does not hold heights"), (9, "does not exist"),
                    ("Friction", "no channel named")):
        with pytest.raises(SurfmetFormatError, match=msg) as info:
            read_bytes(buf, name="x.di", channel=ch)
        assert "\n" not in str(info.value)


@pytest.mark.realdata
def test_truncated_data_block_is_named(realdata):
    buf = realdata("di-2.di").read_bytes()
    with pytest.raises(SurfmetFormatError, match="truncated"):
        read_bytes(buf[:100_000], name="x.di")
    with pytest.raises(SurfmetFormatError, match="File list end"):
        read_bytes(buf[:2000], name="x.di")
