"""The analyze_profile pipeline: window, positions, levelling, filters, recorded settings."""

from __future__ import annotations

import json

import numpy as np
import pytest

from profiles import ProfileError, analyze_profile, gaussian_transmission


def _sine_with_tilt(seed, lam=50e-6, dx=0.25e-6, periods=40):
    rng = np.random.default_rng(seed)
    amp = rng.uniform(0.05, 1.0) * 1e-6
    x = np.arange(periods * round(lam / dx)) * dx
    slope = rng.uniform(-5e-3, 5e-3)
    offset = rng.uniform(-10, 10) * 1e-6
    z = amp * np.sin(2 * np.pi * x / lam + rng.uniform(0, 6)) + slope * x + offset
    return x, z, amp, slope


@pytest.mark.parametrize("seed", range(4))
def test_levelling_finds_hidden_tilt(seed):
    x, z, amp, slope = _sine_with_tilt(seed)
    a = analyze_profile(z, x[1], lc=None, level="line")
    assert a.parameters.Ra == pytest.approx(2 * amp / np.pi, rel=1e-3)
    # an LS line through N whole sine periods tilts by at most 12 A / (2 pi N L)
    assert a.settings["level_coefficients"][1] == pytest.approx(slope, abs=0.06 * amp / x[-1])
    assert a.settings["lc"] is None and a.waviness is None
    assert a.settings["parameters_of"].startswith("levelled primary")
    # without levelling the tilt and offset stay in: Ra is numpy's mean |z| of the raw data
    raw = analyze_profile(z, x[1], lc=None, level="none")
    assert raw.parameters.Ra == pytest.approx(np.mean(np.abs(z)), rel=1e-12)
    assert raw.settings["level_coefficients"] == []


@pytest.mark.parametrize("seed", range(3))
def test_lambda_c_removes_hidden_waviness(seed):
    rng = np.random.default_rng(seed)
    lc, dx = 0.8e-3, 1e-6
    x = np.arange(int(6 * lc / dx)) * dx
    lam_r = lc / rng.uniform(8, 15)
    amp = rng.uniform(0.1, 1.0) * 1e-6
    wav_amp = rng.uniform(2, 10) * amp
    z = (
        amp * np.sin(2 * np.pi * x / lam_r + rng.uniform(0, 6))
        + wav_amp * np.sin(2 * np.pi * x / (8 * lc) + rng.uniform(0, 6))
        + rng.uniform(-3e-3, 3e-3) * x
    )
    a = analyze_profile(z, dx, lc=lc, n_sampling=5)
    t = 1 - float(gaussian_transmission(lam_r, lc))
    assert a.parameters.Rq == pytest.approx(t * amp / np.sqrt(2), rel=0.01)
    assert a.settings["lc"] == lc and a.settings["lc_mode"] == "given"
    assert a.settings["evaluation_length"] == pytest.approx(5 * lc, rel=1e-3)
    assert a.settings["sampling_length"] == lc
    assert np.count_nonzero(a.evaluated) == pytest.approx(5 * lc / dx, abs=1)
    # the waviness went into the mean line
    unfiltered = analyze_profile(z, dx, lc=None)
    assert unfiltered.parameters.Rq > 1.5 * a.parameters.Rq


def test_auto_cutoff_filters_long_profile_and_not_short_one():
    rng = np.random.default_rng(4)
    dx = 0.5e-6
    from scipy.ndimage import gaussian_filter1d

    base = gaussian_filter1d(np.diff(rng.normal(size=int(5e-3 / dx) + 1)), 3)
    z = base * 0.45e-6 / np.mean(np.abs(base))  # Ra 0.45 µm -> λc 0.8 mm
    long = analyze_profile(z, dx, lc="auto")
    assert long.settings["lc"] == pytest.approx(0.8e-3)
    assert long.settings["lc_iso4288"]["lc"] == pytest.approx(0.8e-3)
    assert long.waviness is not None
    short = analyze_profile(z[: int(2e-3 / dx)], dx, lc="auto")
    assert short.settings["lc"] is None
    assert short.settings["lc_iso4288"]["lc"] == pytest.approx(0.8e-3)
    assert "no λc filter" in short.settings["lc_note"]
    json.dumps(short.settings)  # plain JSON


def test_window_keeps_nearest_samples_inclusive():
    dx = 1e-6
    z = np.sin(np.arange(2000) * 0.05)
    a = analyze_profile(z, dx, window=(100.4e-6, 899.6e-6), lc=None)
    assert a.settings["window_points"] == [100, 900]
    assert a.x.size == 801
    with pytest.raises(ProfileError, match="outside"):
        analyze_profile(z, dx, window=(3e-3, 4e-3), lc=None)
    with pytest.raises(ProfileError, match="x0 < x1"):
        analyze_profile(z, dx, window=(4e-4, 3e-4), lc=None)


def test_nonuniform_positions_resampled_and_rounded_grids_kept():
    rng = np.random.default_rng(8)
    lam, amp = 40e-6, 0.5e-6
    # genuinely irregular sampling
    x = np.cumsum(rng.uniform(0.1e-6, 0.4e-6, 8000))
    z = amp * np.sin(2 * np.pi * x / lam)
    a = analyze_profile(z, 0.25e-6, x=x, lc=None, level="none")
    assert a.settings["positions"]["method"] == "resampled"
    assert a.parameters.Ra == pytest.approx(2 * amp / np.pi, rel=0.01)
    assert a.parameters.Rsm == pytest.approx(lam, rel=0.01)
    # uniform grid written with rounded positions (a Dektak export): heights untouched
    step = 0.15625e-6
    xr = np.round(np.arange(8000) * step * 1e7) / 1e7
    b = analyze_profile(z, step, x=xr, lc=None, level="none")
    assert b.settings["positions"]["method"] == "uniform-rounded"
    assert b.settings["dx"] == pytest.approx(step, rel=1e-6)
    assert np.array_equal(b.primary, z)


def test_discard_end_treatment_records_run_out():
    rng = np.random.default_rng(2)
    lc, dx = 0.25e-3, 0.5e-6
    x = np.arange(int(6.2 * lc / dx)) * dx
    z = 0.3e-6 * np.sin(2 * np.pi * x / 25e-6 + rng.uniform(0, 6)) + 2e-3 * x
    a = analyze_profile(z, dx, lc=lc, end_treatment="discard")
    assert a.settings["end_treatment"] == "discard"
    assert a.settings["discarded_each_end"] == pytest.approx(lc / 2, rel=1e-3)
    assert np.all(np.isnan(a.roughness[: int(lc / 2 / dx)]))
    assert not np.any(a.evaluated & np.isnan(a.roughness))
    with pytest.raises(ProfileError, match="run-up and run-out"):
        analyze_profile(z[: int(5.5 * lc / dx)], dx, lc=lc, end_treatment="discard")


def test_nan_holes_flow_through_the_pipeline():
    x, z, _amp, _ = _sine_with_tilt(1, periods=200)
    z = z.copy()
    z[1000:1040] = np.nan
    z[5000:5003] = np.nan
    a = analyze_profile(z, x[1], lc=0.8e-3, n_sampling=None)
    assert a.settings["points_not_measured"] == np.count_nonzero(np.isnan(z[a.evaluated]))
    assert np.array_equal(np.isnan(a.roughness), np.isnan(z))
    assert np.isfinite(a.parameters.Ra)


def test_pipeline_errors_are_actionable():
    z = np.random.default_rng(0).normal(size=1000) * 1e-7
    with pytest.raises(ProfileError, match="too short for λc"):
        analyze_profile(z, 1e-6, lc=0.8e-3)
    with pytest.raises(ProfileError, match="all heights are NaN"):
        analyze_profile(np.full(50, np.nan), 1e-6, lc=None)
    with pytest.raises(ProfileError, match="levelling"):
        analyze_profile(z, 1e-6, level="sphere", lc=None)
    with pytest.raises(ProfileError, match="lc must be"):
        analyze_profile(z, 1e-6, lc="big")
    with pytest.raises(ProfileError, match="n_sampling"):
        analyze_profile(z, 1e-6, lc=None, n_sampling=0)
    # fewer sampling lengths make a short profile usable with the same cut-off
    ok = analyze_profile(z, 1e-6, lc=0.25e-3, n_sampling=3)
    assert ok.settings["n_sampling"] == 3
