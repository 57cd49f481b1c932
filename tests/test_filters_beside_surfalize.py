"""The areal Gaussian L-filter beside surfalize (reference numbers stored, not imported).

tests/data/surfalize_gaussian_l_filter.json holds surfalize 0.19.2's Sa, Sq, Ssk of the
high-pass map at λc = 250 µm of a 1024² map made by benchmarks/surfalize_filter_reference.py
(tool, version, command and date in the file). surfalize mirrors the map at its border
(scipy.ndimage.gaussian_filter, mode "reflect"); no treatment of the ends is the
standard's weighting function there, so the two tools are compared where the Gaussian
weights are complete: the inner area, λc/2 from every border, which surfmet's default
(``edge="discard"``, docs/parameters.md "Filter edges") keeps and nothing else. Measured
over the whole map instead: moment correction Sa -0.88 %, Ssk +20.5 %; renormalised
weights Sa +0.14 %, Ssk -4.2 % (the ends' treatments differ, not the filter).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from surfmet._model import Topography
from surfmet.areal._filters import l_filter

ROOT = Path(__file__).resolve().parents[1]
REF = json.loads((ROOT / "tests" / "data" / "surfalize_gaussian_l_filter.json")
                 .read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def reference_map():
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        from surfalize_filter_reference import reference_map as make
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return Topography(make() * 1e-6, 1e-6, 1e-6)


def _stats(z: np.ndarray) -> dict[str, float]:
    d = z - z.mean()
    sq = float(np.sqrt(np.mean(d * d)))
    return {"Sa": float(np.mean(np.abs(d))), "Sq": sq, "Ssk": float(np.mean(d**3) / sq**3)}


def test_default_filter_keeps_the_complete_weights_and_equals_surfalize_there(reference_map):
    rough, info = l_filter(reference_map, REF["map"]["lambda_c_um"] * 1e-6)
    band = REF["inner_band_px"]
    assert info.edge == "discard" and info.discarded == (band, band)
    kept = rough.heights[np.isfinite(rough.heights)]
    assert kept.size == (REF["map"]["points"] - 2 * band) ** 2
    got = _stats(kept * 1e6)
    for key, tol in (("Sa", 1e-4), ("Sq", 1e-4), ("Ssk", 2e-3)):
        assert got[key] == pytest.approx(REF["inner"][key], rel=tol), key
