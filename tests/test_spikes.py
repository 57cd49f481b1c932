"""Spikes: hidden spikes, form and holes are found and removed; clean data reports none."""

from __future__ import annotations

import math

import numpy as np
import pytest
from areal_synth import gaussian_surface, hide_effects

from surfmet._errors import SurfmetInputError
from surfmet._model import Profile, Topography
from surfmet._spikes import GAUSSIAN_SQ_OVER_SA, remove_spikes, spike_diagnosis
from surfmet.roughness import roughness

DX = 1e-6


def _clean_stats(z):
    d = z - z.mean()
    sq = np.sqrt(np.mean(d**2))
    return sq, np.mean(d**3) / sq**3, np.mean(d**4) / sq**4


@pytest.mark.parametrize("seed", range(6))
def test_pipeline_recovers_clean_statistics_and_reports_the_spikes(seed):
    rng = np.random.default_rng(seed)
    sq_true = rng.uniform(0.1e-6, 3e-6)
    corr = rng.uniform(1.5, 8.0)
    clean = gaussian_surface(rng, 240, 300, sq_true, corr)
    sq0, ssk0, sku0 = _clean_stats(clean)
    corrupt, truth = hide_effects(rng, clean, DX)
    res = roughness(Topography(corrupt, DX, DX), level="poly:2", spikes=True,
                    which="height")
    assert res.value("Sq") == pytest.approx(sq0, rel=0.03)
    assert res.value("Ssk") == pytest.approx(ssk0, abs=0.06)
    assert res.value("Sku") == pytest.approx(sku0, abs=0.15)
    rep = res.spike_report
    assert rep.count == len(truth.spike_pixels)
    found = {tuple(p) for p in rep.pixels}
    for j, i in truth.spike_pixels:
        assert any(abs(j - a) <= 1 and abs(i - b) <= 1 for a, b in found), (j, i)
    assert rep.n_points <= truth.n_spike_points
    assert rep.n_points >= len(truth.spike_pixels)
    # positions are reported in metres
    assert np.allclose(rep.positions, rep.pixels[:, ::-1] * DX)
    # signs of the reported heights match the hidden spikes
    order = {tuple(p): h for p, h in zip(truth.spike_pixels, truth.spike_heights)}
    for (j, i), h in zip(rep.pixels, rep.heights):
        if (j, i) in order:
            assert np.sign(h) == np.sign(order[(j, i)])
    assert not res.spike_diagnosis.suspected
    assert res.settings["spike_diagnosis"]["before_spike_removal"]["suspected"]
    # Without spike removal the diagnosis must point at the spikes.
    raw = roughness(Topography(corrupt, DX, DX), level="poly:2", which="height")
    assert raw.spike_diagnosis.suspected
    assert "spike" in raw.spike_diagnosis.message
    assert raw.value("Sku") > sku0 + 1


@pytest.mark.parametrize("seed", range(6))
def test_clean_data_reports_no_spikes(seed):
    rng = np.random.default_rng(100 + seed)
    clean = gaussian_surface(rng, 256, 256, 1e-6, rng.uniform(1.0, 30.0))
    with_form, _ = hide_effects(rng, clean, DX, spikes=False)
    for z in (clean, with_form):
        _, rep = remove_spikes(Topography(z, DX, DX))
        assert rep.count == 0 and rep.n_points == 0
    res = roughness(Topography(with_form, DX, DX), level="poly:2", spikes=True,
                    which="height")
    assert res.spike_report.count == 0
    assert not res.spike_diagnosis.suspected
    assert res.spike_diagnosis.sq_over_sa == pytest.approx(GAUSSIAN_SQ_OVER_SA, abs=0.05)


def test_paper_like_sq_over_sa_is_explained_by_spikes():
    # Table 1 of Alaci et al. 2022: Sq/Sa up to 4.3 (5.340/1.255). A Gaussian surface with
    # 0.3 % of points turned into ~60 Sq spikes does that; removing them restores 1.25.
    rng = np.random.default_rng(42)
    z = gaussian_surface(rng, 300, 300, 1e-6, 3.0)
    # (not on the outermost rows/columns: there only one direction can be tested, see
    # surfmet._spikes, and such spikes are left alone)
    inner = np.zeros(z.shape, dtype=bool)
    inner[1:-1, 1:-1] = True
    idx = rng.choice(np.flatnonzero(inner), size=int(0.003 * z.size), replace=False)
    zz = z.ravel().copy()
    zz[idx] += rng.choice([-1, 1], idx.size) * rng.uniform(40, 80, idx.size) * 1e-6
    spiky = zz.reshape(z.shape)
    d = spike_diagnosis(spiky)
    assert d.sq_over_sa > 3.0
    assert d.suspected and "spike" in d.message.lower()
    cleaned, rep = remove_spikes(Topography(spiky, DX, DX))
    assert rep.count >= 0.97 * idx.size
    assert np.isnan(cleaned.heights.ravel()[idx]).all()
    after = spike_diagnosis(cleaned)
    assert after.sq_over_sa == pytest.approx(math.sqrt(math.pi / 2), abs=0.03)
    assert not after.suspected


def test_large_features_are_not_spikes():
    # A 10 x 10 pit (a real defect) is larger than max_points and must stay.
    z = np.zeros((100, 100))
    z += 1e-9 * np.random.default_rng(0).standard_normal(z.shape)
    z[40:50, 40:50] -= 1e-6
    _, rep = remove_spikes(Topography(z, DX, DX))
    assert rep.count == 0


def test_profile_spikes_in_the_pipeline():
    rng = np.random.default_rng(9)
    x = np.arange(20000) * 0.5e-6
    z = 1e-7 * np.sin(2 * np.pi * x / 80e-6) + 5e-9 * rng.standard_normal(x.size)
    pos = rng.choice(np.arange(100, x.size - 100), 12, replace=False)
    z[pos] += 3e-6
    res = roughness(Profile(z, 0.5e-6), spikes=True, lc=0.8e-3)
    assert res.spike_report.count == 12
    assert res.kind == "profile" and "Ra" in res.parameters


def test_bad_arguments():
    with pytest.raises(SurfmetInputError):
        remove_spikes(Topography(np.zeros((5, 5)), DX, DX), k=-1)
    with pytest.raises(SurfmetInputError):
        remove_spikes(Topography(np.full((5, 5), np.nan), DX, DX))
