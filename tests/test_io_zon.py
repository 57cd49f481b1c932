"""Keyence .zon against surfalize 0.19.2's read of its tests/test_files/test_1.zon (the peer's
test only checks that it loads; MANIFEST.tsv records: 769 x 1024, step 23.6311 µm, 2048 NaN,
min -2429.4 µm, max 1926.2 µm, mean 529.957 µm)."""

from __future__ import annotations

import numpy as np
import pytest

import surfmet
from surfmet._errors import SurfmetFormatError
from surfmet.io import read_bytes


@pytest.mark.realdata
def test_grid_step_mask_and_heights_match_surfalize(realdata):
    t = surfmet.read(realdata("zon-surfalize-1.zon"))
    assert t.shape == (769, 1024)
    assert t.dx * 1e6 == pytest.approx(23.6311, abs=5e-5)
    assert int(np.isnan(t.heights).sum()) == 2048
    um = t.heights * 1e6
    assert np.nanmin(um) == pytest.approx(-2429.4, abs=0.05)
    assert np.nanmax(um) == pytest.approx(1926.2, abs=0.05)
    assert np.nanmean(um) == pytest.approx(529.957, abs=5e-4)
    assert t.metadata["instrument"] == "VR-6100"


@pytest.mark.realdata
def test_damaged_zon_fails_in_one_line(realdata):
    buf = realdata("zon-surfalize-1.zon").read_bytes()
    with pytest.raises(SurfmetFormatError, match="zon file"):
        read_bytes(buf[:300_000], name="a.zon")
    with pytest.raises(SurfmetFormatError, match="zon file"):
        read_bytes(buf[:8] + b"XX" + buf[10:], name="a.zon", format="zon")
